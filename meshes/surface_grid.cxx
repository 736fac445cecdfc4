#include "surface_grid.h"

#include <cmath>
#include <map>

namespace shadelab::meshes
{
namespace
{
// Positions equal to 1e-9 are one point: grids meet at equal control
// points, whose sums of products may differ in the last bits.
std::array<long long, 3> WeldKey(const Vec3& p)
{
  return { std::llround(p[0] * 1e9), std::llround(p[1] * 1e9), std::llround(p[2] * 1e9) };
}
}

SurfaceMesh MeshFromGrids(const std::vector<SurfaceGrid>& grids, bool quads)
{
  SurfaceMesh mesh;
  std::map<std::array<long long, 3>, int> welded;
  for (const SurfaceGrid& grid : grids)
  {
    const int first = static_cast<int>(mesh.Uv.size());
    std::vector<int> points;
    for (std::size_t s = 0; s < grid.Points.size(); ++s)
    {
      const auto [at, added] =
        welded.emplace(WeldKey(grid.Points[s]), static_cast<int>(mesh.Points.size()));
      if (added)
      {
        mesh.Points.push_back(grid.Points[s]);
      }
      points.push_back(at->second);
      mesh.Uv.push_back(grid.Uv[s]);
      mesh.Normals.push_back(grid.Normals[s]);
    }
    const auto corner = [&](int row, int column)
    {
      const int s = row * grid.Columns + column;
      return Corner{ points[s], first + s, first + s };
    };
    for (int i = 0; i + 1 < grid.Rows; ++i)
    {
      for (int j = 0; j + 1 < grid.Columns; ++j)
      {
        // Counter-clockwise about dv x du, the side the normals point to.
        const Corner cell[4] = { corner(i, j), corner(i, j + 1), corner(i + 1, j + 1),
          corner(i + 1, j) };
        std::vector<Corner> face;
        for (const Corner& c : cell)
        {
          if (face.empty() || (c.Point != face.back().Point && c.Point != face.front().Point))
          {
            face.push_back(c);
          }
        }
        if (face.size() < 3)
        {
          continue;
        }
        if (quads || face.size() == 3)
        {
          mesh.Faces.push_back(face);
        }
        else
        {
          mesh.Faces.push_back({ face[0], face[1], face[2] });
          mesh.Faces.push_back({ face[0], face[2], face[3] });
        }
      }
    }
  }
  return mesh;
}

SurfaceGrid TorusGrid(double R, double r, int rows, int columns)
{
  SurfaceGrid grid;
  grid.Rows = rows + 1;
  grid.Columns = columns + 1;
  const double pi = std::acos(-1.0);
  for (int i = 0; i <= rows; ++i)
  {
    // Rows go round the tube, columns round the axis, so that dv x du
    // points out of the tube.
    const double tube = 2 * pi * i / rows;
    for (int j = 0; j <= columns; ++j)
    {
      const double axis = 2 * pi * j / columns;
      const Vec3 n{ std::cos(tube) * std::cos(axis), std::cos(tube) * std::sin(axis),
        std::sin(tube) };
      grid.Points.push_back({ (R + r * std::cos(tube)) * std::cos(axis),
        (R + r * std::cos(tube)) * std::sin(axis), r * std::sin(tube) });
      grid.Normals.push_back(n);
      grid.Uv.push_back({ static_cast<double>(j) / columns, static_cast<double>(i) / rows });
    }
  }
  return grid;
}
}
