// Rays through a picture's pixels and the triangles they meet, in double
// precision, for a camera as vtkCamera defines one: how the exact pictures,
// the oracle tests and `shadelab probe` know what lies under a pixel.
//
// Picture coordinates are in pixels, x from the left and y from the top of
// the picture: pixel (X, Y) covers [X, X + 1) x [Y, Y + 1), and OpenGL
// samples it at its centre (X + 0.5, Y + 0.5).
#ifndef shadelabPixelRays_h
#define shadelabPixelRays_h

#include "shadelabIllumination.h"

#include <array>
#include <cstdint>
#include <vector>

class vtkCamera;

namespace shadelab
{
/** A camera as vtkCamera defines one (no shear, window centre 0). */
struct PinholeCamera
{
  Vec3 Position{ 0, 0, 1 };
  Vec3 FocalPoint{};
  Vec3 ViewUp{ 0, 1, 0 };
  double ViewAngle = 30; // perspective: vertical, degrees
  bool Orthographic = false;
  double ParallelScale = 1; // orthographic: half the view height in world units

  bool operator==(const PinholeCamera& o) const
  {
    return this->Position == o.Position && this->FocalPoint == o.FocalPoint &&
      this->ViewUp == o.ViewUp && this->ViewAngle == o.ViewAngle &&
      this->Orthographic == o.Orthographic && this->ParallelScale == o.ParallelScale;
  }
};

/** vtkCamera's position, focal point, view-up, view angle and projection. */
PinholeCamera PinholeCameraOf(vtkCamera* camera);

struct Ray
{
  Vec3 Origin{};
  Vec3 Direction{}; // unit
};

/**
 * The ray that samples picture point (x, y) of a width x height picture:
 * from the camera position (perspective), or from the camera's plane along
 * the direction of view (orthographic).
 */
Ray PictureRay(const PinholeCamera& camera, int width, int height, double x, double y);

/** Where a ray meets a triangle's plane. */
struct TriangleHit
{
  // The point lies in the triangle (its edges included) and ahead of the
  // ray's origin; false too for a triangle of no area or edge-on.
  bool Inside = false;
  double T = 0;                    // the point is origin + T * direction
  std::array<double, 3> Weights{}; // its barycentric weights of a, b, c
};

TriangleHit IntersectTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c);

/** A triangle's three point indices, in draw order. */
using TriangleCorners = std::array<std::int64_t, 3>;

/** A triangle mesh as a camera sees it in a width x height picture. */
class PictureTriangles
{
public:
  PictureTriangles(const PinholeCamera& camera, int width, int height, std::vector<Vec3> points,
    std::vector<TriangleCorners> triangles);

  struct Hit
  {
    std::int64_t Triangle = -1; // -1: the ray meets none
    std::array<double, 3> Weights{};
    bool Front = true; // counter-clockwise on the screen
    // Pixels from the sample point to the nearest projected edge of the
    // triangle met or of one that may cover it (a corner nearer to the
    // camera), where the rasteriser may decide otherwise; with no triangle
    // met, to the nearest edge of any. Triangles with a corner behind a
    // perspective camera are left out.
    double EdgeDistance = 0;
  };

  /** What the ray through picture point (x, y) meets first. */
  Hit Under(double x, double y) const;

  /**
   * Every triangle the ray through picture point (x, y) meets, nearest
   * first (at the same distance, in draw order): the layers that
   * translucency composites. Each one's EdgeDistance is the same, to the
   * nearest projected edge of any triangle, since every layer shows.
   */
  std::vector<Hit> Through(double x, double y) const;

  Ray RayAt(double x, double y) const;

  const std::vector<Vec3>& GetPoints() const { return this->Points; }
  const std::vector<TriangleCorners>& GetTriangles() const { return this->Triangles; }
  const PinholeCamera& GetCamera() const { return this->Camera; }
  /** Point p in the picture: x, y, and its depth along the direction of view. */
  const std::array<double, 3>& Projected(std::size_t p) const { return this->Projections[p]; }

private:
  // The triangles ray (through picture point (x, y)) meets, each with the
  // distance along the ray, in draw order.
  std::vector<std::pair<double, Hit>> Met(const Ray& ray, double x, double y) const;
  // Pixels from (x, y) to the nearest projected edge of triangle `met` or of
  // one with a corner nearer than depth along the view.
  double NearestEdge(double x, double y, double depth, std::int64_t met) const;
  // Pixels from (x, y) to the boundary of triangle t's projection.
  double EdgeDistance(std::size_t t, double x, double y) const;

  // A triangle's projection: its bounding box in the picture (the ray
  // through a point outside it misses the triangle), its nearest corner's
  // depth, and whether every corner is ahead of a perspective camera (else
  // neither box nor edges are known).
  struct Footprint
  {
    double Left, Right, Top, Bottom, Nearest;
    bool Projects;
  };

  PinholeCamera Camera;
  int Width, Height;
  std::vector<Vec3> Points;
  std::vector<TriangleCorners> Triangles;
  Vec3 Forward;
  std::vector<std::array<double, 3>> Projections; // per point: x, y, depth along the view
  std::vector<Footprint> Footprints;              // per triangle
};
}

#endif
