// The edges or points of a triangle mesh as a camera sees them, drawn as
// OpenGL draws aliased lines and points (doc/design.md, "Representations"):
// which element covers a pixel, and where on it the pixel's fragment lies.
// What the oracle tests expect of a wireframe or points picture and what
// `shadelab probe` explains.
#ifndef shadelabPictureElements_h
#define shadelabPictureElements_h

#include "shadelabPixelRays.h"
#include "shadelabRepresentation.h"

namespace shadelab
{
class PictureElements
{
public:
  /**
   * The elements of `mesh`'s triangles drawn as `drawn` (not Surface), each
   * once (DrawnElements), as lines `pixels` wide or squares `pixels` on a
   * side. `mesh` must outlive this.
   */
  PictureElements(const PictureTriangles& mesh, Representation drawn, int pixels);

  struct Hit
  {
    std::int64_t Element = -1; // in DrawnElements' order; -1: none covers the sample point
    std::int64_t Owner = -1;   // the triangle that owns it
    // The owner's corners turned so that the element's provoking corner is
    // the last (ShadeElementFragment), and the fragment's weights of them,
    // perspective-correct: on a line, where it is at the sample point's
    // step along its major axis (OpenGL's wide lines), on a point, the point.
    TriangleCorners Corners{};
    std::array<double, 3> Weights{};
    // Pixels from the sample point to the nearest place where coverage
    // changes: the edge of the element's footprint, or the footprint of
    // another, where the rasteriser and the depth test may decide otherwise.
    double Margin = 0;
  };

  /** The element drawn at picture point (x, y): the nearest that covers it. */
  Hit Under(double x, double y) const;

  const DrawnElements& GetElements() const { return this->Elements; }

private:
  // Pixels the sample point lies inside element e's footprint (> 0) or
  // outside it (< 0), and on a line the parameter of its projection.
  double Inside(std::size_t e, double x, double y, double& t) const;

  const PictureTriangles& Mesh;
  Representation Drawn;
  double HalfWidth;
  DrawnElements Elements;
};
}

#endif
