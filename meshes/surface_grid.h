/**
 * A surface sampled on a grid of parameters, and the polygon mesh that the
 * grids of a shape make once their shared points are welded.
 */
#ifndef shadelab_meshes_surface_grid_h
#define shadelab_meshes_surface_grid_h

#include <array>
#include <vector>

namespace shadelab::meshes
{
using Vec3 = std::array<double, 3>;
using Vec2 = std::array<double, 2>;

/** Rows x Columns samples, row by row: position, unit normal, (u, v). */
struct SurfaceGrid
{
  int Rows = 0;
  int Columns = 0;
  std::vector<Vec3> Points;
  std::vector<Vec3> Normals;
  std::vector<Vec2> Uv;
};

/** One corner of a face: indices into the mesh's points, uv and normals. */
struct Corner
{
  int Point;
  int Uv;
  int Normal;
};

/**
 * Points welded where grids meet (equal to 1e-9), uv and normals kept per
 * grid sample, so that texture coordinates split where grids meet as a
 * mesh from a modeller's UV layout does. Faces are counter-clockwise seen
 * from the side the normals point to.
 */
struct SurfaceMesh
{
  std::vector<Vec3> Points;
  std::vector<Vec2> Uv;
  std::vector<Vec3> Normals;
  std::vector<std::vector<Corner>> Faces;
};

/**
 * The grids' cells as faces: quads (triangles where two corners weld into
 * one), or triangles only (each quad split along its first diagonal).
 * Cells that weld into fewer than three corners are left out.
 */
SurfaceMesh MeshFromGrids(const std::vector<SurfaceGrid>& grids, bool quads);

/** A torus about the z axis, radii R and r, rows x columns cells. */
SurfaceGrid TorusGrid(double R, double r, int rows, int columns);
}

#endif
