// The lecture's cheaper pictures of a mesh: its edges (wireframe) or its
// points instead of its surface, lit by the same rule and the same equation
// (doc/design.md, "Representations"). Which edges and points are drawn,
// each once, and which triangle owns each: the GPU's index buffer, flat's
// face normals, the oracle and `probe` all take them from here.
#ifndef shadelabRepresentation_h
#define shadelabRepresentation_h

#include "shadelabTriangleFragment.h"

#include <array>
#include <utility>
#include <vector>

namespace shadelab
{
enum class Representation
{
  Surface,
  Wireframe,
  Points
};

template <>
struct NameTable<Representation>
{
  static constexpr std::array<std::pair<Representation, const char*>, 3> Entries{
    { { Representation::Surface, "surface" }, { Representation::Wireframe, "wireframe" },
      { Representation::Points, "points" } }
  };
};

/** The edges or points of a mesh's drawn triangles, each once. */
struct DrawnElements
{
  // Wireframe: two point ids an edge, in the direction its owner walks it
  // (a to b, b to c, c to a), so that the second, GL's provoking vertex of
  // a line, is the owner's corner after the first; points: one id a point.
  // In the order the triangles first use them; an edge whose two ids are
  // one point is not drawn.
  std::vector<unsigned int> Corners;
  // The triangle (its index among those given) that first uses each one:
  // flat lights an edge or a point with that face's normal.
  std::vector<unsigned int> Owners;
};

/**
 * The elements of `triangles` (three point ids a triangle) drawn as
 * `representation`; for Surface, none.
 */
DrawnElements ElementsOf(Representation representation, const std::vector<unsigned int>& triangles);

/**
 * A fragment of an edge or a point, lit by `rule` as the generated shaders
 * light it. `f` is the owning triangle with its corners turned so that the
 * element's provoking corner is the last (an edge a to b: b last, a before
 * it; a point: the point last), with the fragment's weights (on the edge,
 * the third corner's is 0; a point's are 0, 0, 1). A line or a point has
 * no facing (GL's gl_FrontFacing is true for them), so the normal that
 * lights is turned towards the viewer, as two-sided lighting turns a back
 * face's: flat, the owner's face normal at the provoking corner; gouraud,
 * each vertex's normal at that vertex; phong, the interpolated normal at
 * the fragment, and where that has no usable length the fragment is lit
 * by ka*Ia alone (a line or a point has no face to fall back to). f.Front
 * is ignored, and so is a normal map (ShaderFeatures::MapsNormals).
 */
ShadedFragment ShadeElementFragment(
  const IlluminationInputs& in, Shading rule, const TriangleFragment& f);
}

#endif
