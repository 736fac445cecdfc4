// Each weighting's accuracy against the exact normals of a sphere and a
// torus, on regular and irregular meshes of them.
#include "bench/bench_normals.h"

#include "shadelabVec3.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace shadelab
{
namespace bench_normals
{
namespace
{
using Vec = Vec3;
using namespace vec3;

// A surface by its parameters: the point at (u, v) in [0,1]^2 and the exact
// unit normal at a point on it.
struct Surface
{
  std::string Name;
  int Columns; // u divisions (periodic)
  int Rows;    // v divisions
  bool Sphere; // poles at v = 0 and v = 1; otherwise periodic in v (torus)
  std::function<Vec(double, double)> Point;
  std::function<Vec(const Vec&)> Normal;
};

// A triangulated grid on the surface. With jitter > 0 each grid vertex moves
// by up to `jitter` of a cell in u and in v (a tangential move), so the
// triangles vary in shape and size while every vertex stays exactly on the
// surface.
vtkSmartPointer<vtkPolyData> Tessellate(const Surface& s, double jitter, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const int rings = s.Sphere ? s.Rows - 1 : s.Rows; // rows of vertices, poles aside
  for (int j = 0; j < rings; ++j)
  {
    for (int i = 0; i < s.Columns; ++i)
    {
      const double u = (i + offset(random)) / s.Columns;
      const double v = (j + (s.Sphere ? 1 : 0) + offset(random)) / s.Rows;
      points->InsertNextPoint(s.Point(u, v).data());
    }
  }
  auto at = [&](int i, int j) -> vtkIdType
  { return ((j + rings) % rings) * s.Columns + (i + s.Columns) % s.Columns; };
  auto triangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    const vtkIdType ids[3] = { a, b, c };
    polys->InsertNextCell(3, ids);
  };
  const int quadRows = s.Sphere ? rings - 1 : rings;
  for (int j = 0; j < quadRows; ++j)
  {
    for (int i = 0; i < s.Columns; ++i)
    {
      // The diagonal alternates, so that vertices have 4 or 8 neighbours:
      // uniform weighting is then visibly biased even on the regular grid.
      if ((i + j) % 2)
      {
        triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
      else
      {
        triangle(at(i, j), at(i + 1, j), at(i, j + 1));
        triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }
  if (s.Sphere)
  {
    const vtkIdType south = points->InsertNextPoint(s.Point(0, 0).data());
    const vtkIdType north = points->InsertNextPoint(s.Point(0, 1).data());
    for (int i = 0; i < s.Columns; ++i)
    {
      triangle(south, at(i + 1, 0), at(i, 0));
      triangle(north, at(i, rings - 1), at(i + 1, rings - 1));
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// Calls visit(id, nextId, p, next, previous) for every corner of every
// cell: the corner's point id, the next one's, and the three positions.
template <typename Visit>
void ForEachCorner(vtkPolyData* mesh, Visit visit)
{
  vtkIdType size;
  const vtkIdType* ids;
  for (auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
       !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      Vec p, next, previous;
      mesh->GetPoint(ids[k], p.data());
      mesh->GetPoint(ids[(k + 1) % size], next.data());
      mesh->GetPoint(ids[(k + size - 1) % size], previous.data());
      visit(ids[k], ids[(k + 1) % size], p, next, previous);
    }
  }
}

// Moves each vertex of a mesh on the unit sphere tangentially, in a random
// direction, by up to `jitter` of its shortest edge, and back onto the
// sphere. Relative to the shortest edge, so that the thin cells by a UV
// sphere's poles get irregular without folding or turning into slivers.
void JitterOnSphere(vtkPolyData* mesh, double jitter, unsigned seed)
{
  const vtkIdType count = mesh->GetNumberOfPoints();
  std::vector<double> shortest(count, std::numeric_limits<double>::infinity());
  ForEachCorner(mesh,
    [&](vtkIdType id, vtkIdType nextId, const Vec& p, const Vec& next, const Vec&)
    {
      const double l = length(next - p);
      shortest[id] = std::min(shortest[id], l);
      shortest[nextId] = std::min(shortest[nextId], l);
    });
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (vtkIdType i = 0; i < count; ++i)
  {
    Vec p;
    mesh->GetPoint(i, p.data());
    // A tangent basis at p: t1 across the axis p is least aligned with.
    const int least = std::fabs(p[0]) < std::fabs(p[1])
      ? (std::fabs(p[0]) < std::fabs(p[2]) ? 0 : 2)
      : (std::fabs(p[1]) < std::fabs(p[2]) ? 1 : 2);
    Vec axis = { 0, 0, 0 };
    axis[least] = 1;
    const Vec t1 = normalize(cross(p, axis));
    const Vec t2 = cross(p, t1);
    const double direction = 2 * M_PI * unit(random);
    const double distance = jitter * shortest[i] * unit(random);
    p = normalize(p + distance * (std::cos(direction) * t1 + std::sin(direction) * t2));
    mesh->GetPoints()->SetPoint(i, p.data());
  }
}

// Angle between two vectors in degrees; atan2 stays accurate for tiny
// angles, where acos does not.
double Degrees(const Vec& a, const Vec& b)
{
  return std::atan2(length(cross(a, b)), dot(a, b)) * 180 / M_PI;
}

struct Error
{
  double Mean = 0;
  double Max = 0;
};

// Angles in degrees between the output's point normals and the exact ones.
// A missing or zero normal counts as 180 degrees: wrong, not exempt.
Error AngleError(vtkPolyData* output, const Surface& s)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  const vtkIdType count = output->GetNumberOfPoints();
  Error e;
  for (vtkIdType i = 0; i < count; ++i)
  {
    Vec p;
    output->GetPoint(i, p.data());
    Vec n = { 0, 0, 0 };
    if (normals)
    {
      normals->GetTuple(i, n.data());
    }
    const double degrees = n == Vec{ 0, 0, 0 } ? 180 : Degrees(n, s.Normal(p));
    e.Mean += degrees / count;
    e.Max = std::max(e.Max, degrees);
  }
  return e;
}

// The smallest and largest inner angle of the mesh's triangles, degrees:
// slivers (angles near 180) are where the weightings differ most.
std::pair<double, double> TriangleAngles(vtkPolyData* mesh)
{
  std::pair<double, double> range{ 180, 0 };
  ForEachCorner(mesh,
    [&](vtkIdType, vtkIdType, const Vec& p, const Vec& next, const Vec& previous)
    {
      const double degrees = Degrees(next - p, previous - p);
      range.first = std::min(range.first, degrees);
      range.second = std::max(range.second, degrees);
    });
  return range;
}

// The torus's radii: of its core circle and of its tube.
constexpr double TorusR = 1;
constexpr double Torusr = 0.35;

// How irregular: tangential moves up to 0.3 of a vertex's shortest edge on
// the sphere, 0.2 of a cell in each parameter on the torus, so that both
// meshes' worst triangles are alike (about 140 degrees at most) and neither
// turns into slivers, which would measure the slivers instead.
constexpr double SphereJitter = 0.3;
constexpr double TorusJitter = 0.2;

Surface Sphere()
{
  return { "sphere", 48, 32, true,
    [](double u, double v)
    {
      const double theta = 2 * M_PI * u;
      const double phi = M_PI * v;
      return Vec{ std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
        -std::cos(phi) };
    },
    [](const Vec& p) { return normalize(p); } };
}

Surface Torus()
{
  const double R = TorusR;
  const double r = Torusr;
  return { "torus", 64, 24, false,
    [R, r](double u, double v)
    {
      const double a = 2 * M_PI * u;
      const double b = 2 * M_PI * v;
      return Vec{ (R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
        r * std::sin(b) };
    },
    [R](const Vec& p)
    {
      // Away from the nearest point of the core circle.
      const double l = std::hypot(p[0], p[1]);
      return normalize({ p[0] - R * p[0] / l, p[1] - R * p[1] / l, p[2] });
    } };
}

struct Column
{
  std::string Name;
  std::vector<Error> Errors;        // the weightings in order, then vtkPolyDataNormals
  std::pair<double, double> Angles; // the triangles' smallest and largest angles
};

// One surface, regular or irregular: each weighting's error.
Column MeasureColumn(const Surface& s, bool irregular)
{
  const double j = irregular ? (s.Sphere ? SphereJitter : TorusJitter) : 0;
  std::fprintf(
    stderr, "bench-normals: accuracy: %s%s\n", s.Name.c_str(), j > 0 ? ", jittered" : "");
  // The sphere by tangential moves projected back, as a move in its
  // parameters would make slivers of the thin cells at its poles; the
  // torus's cells are near square, so it moves in its own.
  vtkSmartPointer<vtkPolyData> mesh = Tessellate(s, s.Sphere ? 0 : j, 1999);
  if (s.Sphere && j > 0)
  {
    JitterOnSphere(mesh, j, 1999);
  }
  Column c;
  c.Name = s.Name + " " + std::to_string(s.Columns) + "x" + std::to_string(s.Rows) +
    (j > 0 ? " irregular" : " regular") + " (" + std::to_string(mesh->GetNumberOfPolys()) + " tri)";
  for (int w = vtkShadelabMeshNormals::Uniform; w <= vtkShadelabMeshNormals::Loop; ++w)
  {
    auto ours = OurNormals(mesh, w, false, false);
    ours->Update();
    c.Errors.push_back(AngleError(ours->GetOutput(), s));
  }
  auto vtk = VtkNormals(mesh, false);
  vtk->Update();
  c.Errors.push_back(AngleError(vtk->GetOutput(), s));
  c.Angles = TriangleAngles(mesh);
  return c;
}

void PrintAccuracy(const std::vector<Column>& columns)
{
  std::printf("\n### Accuracy: mean / largest angle to the exact normal, degrees\n\n");
  std::printf("Irregular sphere: every vertex moved tangentially, in a random direction, by up "
              "to %.1f of its shortest edge, then projected back onto the sphere. Irregular "
              "torus (R = %g, r = %g): every grid vertex moved by up to %.1f of a cell in each "
              "parameter, so exactly on the surface. Uniform random, seed 1999.\n\n",
    SphereJitter, TorusR, Torusr, TorusJitter);
  std::printf("| weighting |");
  for (const Column& c : columns)
  {
    std::printf(" %s |", c.Name.c_str());
  }
  std::printf("\n|---|");
  for (size_t i = 0; i < columns.size(); ++i)
  {
    std::printf("---:|");
  }
  std::printf("\n");
  for (int k = 0; k <= vtkShadelabMeshNormals::Loop + 1; ++k)
  {
    std::printf("| %s |",
      k <= vtkShadelabMeshNormals::Loop ? WeightingName(k)
                                        : "vtkPolyDataNormals (no splitting, no consistency)");
    for (const Column& c : columns)
    {
      std::printf(" %.3f / %.3f |", c.Errors[k].Mean, c.Errors[k].Max);
    }
    std::printf("\n");
  }
  std::printf("| (the triangles' smallest / largest angle) |");
  for (const Column& c : columns)
  {
    std::printf(" %.1f / %.1f |", c.Angles.first, c.Angles.second);
  }
  std::printf("\n");
}
}

void AccuracyTable()
{
  std::vector<Column> columns;
  for (const Surface& s : { Sphere(), Torus() })
  {
    for (const bool irregular : { false, true })
    {
      columns.push_back(MeasureColumn(s, irregular));
    }
  }
  PrintAccuracy(columns);
  std::fflush(stdout);
}
}
}
