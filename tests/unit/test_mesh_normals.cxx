// vtkShadelabMeshNormals: each weighting against its definition computed
// here, accuracy against the analytic normals of irregular spheres and tori,
// Loop normals, feature splitting (a cube; fandisk where ../shared/data is),
// non-manifold and degenerate input, consistent orientation, a file's own
// normals, the
// connectivity cache, and the same bits whatever the number of chunks the
// sums run in and whether the points are float or double.
#include "shadelabMeshConnectivity.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVec3.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkLogger.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace fs = std::filesystem;

const fs::path TestMeshes = fs::path(SHADELAB_TEST_MESHES);

// The output normals are floats: a unit vector rounded to float is off by at
// most 2^-24 (6e-8) a component. 1e-6 leaves room for summing in another
// order (or even in float), while the weightings differ from each other by
// 1e-3 or more on the meshes below (each test checks that it can tell them
// apart).
constexpr double Tolerance = 1e-6;

const char* const WeightingNames[] = { "uniform", "area", "angle", "max", "loop" };
constexpr int Weightings = 5;

// ---------------------------------------------------------------------------
// Vectors in double

using Vec = shadelab::Vec3;
using namespace shadelab::vec3;
using Triangle = std::array<vtkIdType, 3>;

double MaxDifference(const Vec& a, const Vec& b)
{
  return std::max({ std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2]) });
}
// Accurate for tiny angles too (acos of a dot product is not).
double AngleDegrees(const Vec& a, const Vec& b)
{
  return vtkMath::DegreesFromRadians(std::atan2(length(cross(a, b)), dot(a, b)));
}
bool IsFinite(const Vec& a)
{
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
std::string Str(const Vec& a)
{
  std::ostringstream text;
  text << std::setprecision(9) << '(' << a[0] << ", " << a[1] << ", " << a[2] << ')';
  return text.str();
}

// The same numbers with every standard library (std::uniform_real_distribution
// is not specified bit for bit; std::mt19937 is).
class Random
{
public:
  explicit Random(std::uint32_t seed)
    : Engine(seed)
  {
  }
  double Uniform(double low, double high)
  {
    return low + (high - low) * (static_cast<double>(this->Engine()) / 4294967296.0);
  }
  Vec InBall(double radius)
  {
    for (;;)
    {
      const Vec v = { this->Uniform(-1, 1), this->Uniform(-1, 1), this->Uniform(-1, 1) };
      if (dot(v, v) <= 1)
      {
        return radius * v;
      }
    }
  }

private:
  std::mt19937 Engine;
};

// ---------------------------------------------------------------------------
// Meshes made here

struct Mesh
{
  std::vector<Vec> Points;
  std::vector<Triangle> Triangles;
  std::vector<Vec> Exact; // the analytic normals of a generated surface, if any

  const Vec& Point(vtkIdType i) const { return this->Points[static_cast<std::size_t>(i)]; }
  // (p1 - p0) x (p2 - p0): along the face normal, twice the face's area long.
  Vec AreaNormal(const Triangle& t) const
  {
    return cross(this->Point(t[1]) - this->Point(t[0]), this->Point(t[2]) - this->Point(t[0]));
  }
  double MeanEdgeLength() const
  {
    double sum = 0;
    for (const Triangle& t : this->Triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        sum += length(this->Point(t[(k + 1) % 3]) - this->Point(t[k]));
      }
    }
    return sum / (3.0 * this->Triangles.size());
  }
};

vtkSmartPointer<vtkPolyData> ToPolyData(const Mesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec& p : mesh.Points)
  {
    points->InsertNextPoint(p.data());
  }
  vtkNew<vtkCellArray> triangles;
  for (const Triangle& t : mesh.Triangles)
  {
    triangles->InsertNextCell(3, t.data());
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(triangles);
  return polyData;
}

Mesh FromPolyData(vtkPolyData* polyData)
{
  Mesh mesh;
  for (vtkIdType i = 0; i < polyData->GetNumberOfPoints(); ++i)
  {
    Vec p;
    polyData->GetPoint(i, p.data());
    mesh.Points.push_back(p);
  }
  auto cell = vtk::TakeSmartPointer(polyData->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cell->GetCurrentCell(size, ids);
    EXPECT_EQ(size, 3);
    mesh.Triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  return mesh;
}

std::vector<Vec> Tuples(vtkDataArray* array)
{
  std::vector<Vec> tuples;
  for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
  {
    Vec v;
    array->GetTuple(i, v.data());
    tuples.push_back(v);
  }
  return tuples;
}

// An icosahedron, each triangle split in 4 `subdivisions` times, on the unit
// sphere; outward (counter-clockwise seen from outside).
Mesh Icosphere(int subdivisions)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  Mesh mesh;
  mesh.Points = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
    { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  mesh.Triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  for (int level = 0; level < subdivisions; ++level)
  {
    std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> midpoints;
    auto midpoint = [&](vtkIdType a, vtkIdType b)
    {
      const auto key = std::minmax(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        return found->second;
      }
      mesh.Points.push_back(0.5 * (mesh.Point(a) + mesh.Point(b)));
      const auto id = static_cast<vtkIdType>(mesh.Points.size() - 1);
      midpoints.emplace(key, id);
      return id;
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : mesh.Triangles)
    {
      const vtkIdType ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]),
                      ca = midpoint(f[2], f[0]);
      finer.insert(
        finer.end(), { { f[0], ab, ca }, { f[1], bc, ab }, { f[2], ca, bc }, { ab, bc, ca } });
    }
    mesh.Triangles = finer;
  }
  for (Vec& p : mesh.Points)
  {
    p = normalize(p);
  }
  mesh.Exact = mesh.Points;
  return mesh;
}

// Moves each point of a unit sphere mesh by up to `fraction` of the mean edge
// length along the sphere and puts it back on the sphere: irregular triangles
// whose corners lie exactly on the surface.
Mesh JitteredOnSphere(Mesh mesh, double fraction, Random& random)
{
  const double radius = fraction * mesh.MeanEdgeLength();
  for (Vec& p : mesh.Points)
  {
    const Vec offset = random.InBall(radius);
    p = normalize(p + (offset - dot(offset, p) * p));
  }
  mesh.Exact = mesh.Points;
  return mesh;
}

// Splits the quad a b c d (counter-clockwise) by a random diagonal.
void AddQuad(Mesh& mesh, vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, Random& random)
{
  if (random.Uniform(0, 1) < 0.5)
  {
    mesh.Triangles.insert(mesh.Triangles.end(), { { a, b, c }, { a, c, d } });
  }
  else
  {
    mesh.Triangles.insert(mesh.Triangles.end(), { { a, b, d }, { b, c, d } });
  }
}

// A torus (radii R and r, about z) from a nu x nv grid of parameters each
// moved by up to `jitter` cells: the points lie exactly on the surface, the
// triangles vary in shape and the diagonals at random. Outward.
Mesh Torus(int nu, int nv, double R, double r, double jitter, Random& random)
{
  Mesh mesh;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * vtkMath::Pi() * (i + random.Uniform(-jitter, jitter)) / nu;
      const double v = 2 * vtkMath::Pi() * (j + random.Uniform(-jitter, jitter)) / nv;
      mesh.Points.push_back({ (R + r * std::cos(v)) * std::cos(u),
        (R + r * std::cos(v)) * std::sin(u), r * std::sin(v) });
      mesh.Exact.push_back({ std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v) });
    }
  }
  const auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % nu) * nv + j % nv); };
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      AddQuad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), random);
    }
  }
  return mesh;
}

// An open, bumpy n x n height field on a grid jittered by up to 0.2 cells
// (too little to fold a triangle), random diagonals: triangles of many
// shapes and sizes, facing up, and a boundary.
Mesh HeightField(int n, Random& random)
{
  Mesh mesh;
  for (int i = 0; i <= n; ++i)
  {
    for (int j = 0; j <= n; ++j)
    {
      const double x = i + random.Uniform(-0.2, 0.2), y = j + random.Uniform(-0.2, 0.2);
      mesh.Points.push_back(
        { x, y, 0.8 * std::sin(0.7 * x) * std::cos(0.5 * y) + random.Uniform(-0.2, 0.2) });
    }
  }
  const auto id = [&](int i, int j) { return static_cast<vtkIdType>(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      AddQuad(mesh, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), random);
    }
  }
  return mesh;
}

// The unit cube [0,1]^3, point x + 2y + 4z, 12 outward triangles; the faces'
// diagonals go both ways, so corners touch 1 or 2 triangles of a side.
Mesh Cube()
{
  Mesh mesh;
  for (int i = 0; i < 8; ++i)
  {
    mesh.Points.push_back({ double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1) });
  }
  const int quads[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 },
    { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
  const Vec center = { 0.5, 0.5, 0.5 };
  for (int f = 0; f < 6; ++f)
  {
    const int* q = quads[f];
    const Triangle pair[2][2] = { { { q[0], q[1], q[2] }, { q[0], q[2], q[3] } },
      { { q[0], q[1], q[3] }, { q[1], q[2], q[3] } } };
    for (Triangle t : pair[f % 2])
    {
      if (dot(mesh.AreaNormal(t), mesh.Point(t[0]) - center) < 0)
      {
        std::swap(t[1], t[2]);
      }
      mesh.Triangles.push_back(t);
    }
  }
  return mesh;
}

Mesh Read(const fs::path& path, std::vector<Vec>* fileNormals = nullptr)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName(path.c_str());
  EXPECT_TRUE(reader->GetExecutive()->Update()) << path;
  if (fileNormals)
  {
    *fileNormals = Tuples(reader->GetOutput()->GetPointData()->GetNormals());
  }
  return FromPolyData(reader->GetOutput());
}

// ---------------------------------------------------------------------------
// The definitions, computed here in plain loops

// What face t adds at its corner k, by the contract's definitions (a is
// p_next - v, b is p_prev - v, so a x b points along the face normal). A
// zero-area face adds nothing.
Vec CornerContribution(const Mesh& mesh, const Triangle& t, int k, int weighting)
{
  const Vec areaNormal = mesh.AreaNormal(t);
  if (length(areaNormal) == 0)
  {
    return { 0, 0, 0 };
  }
  const Vec n = normalize(areaNormal);
  const Vec v = mesh.Point(t[k]);
  const Vec a = mesh.Point(t[(k + 1) % 3]) - v;
  const Vec b = mesh.Point(t[(k + 2) % 3]) - v;
  switch (weighting)
  {
    case vtkShadelabMeshNormals::Uniform:
      return n;
    case vtkShadelabMeshNormals::Area:
      return 0.5 * length(areaNormal) * n;
    case vtkShadelabMeshNormals::Max:
      return (1 / (dot(a, a) * dot(b, b))) * cross(a, b);
    default: // the face's interior angle at v
      return std::atan2(length(cross(a, b)), dot(a, b)) * n;
  }
}

// Normalized sums of the corner contributions, grouped by key[3 t + k]; a
// sum shorter than 1e-12 of its terms' lengths is terms that cancel, left
// over as rounding in no particular direction: (0,0,0), as the contract says.
std::vector<Vec> GroupNormals(
  const Mesh& mesh, int weighting, const std::vector<std::size_t>& key, std::size_t keys)
{
  std::vector<Vec> sums(keys, Vec{ 0, 0, 0 });
  std::vector<double> lengths(keys, 0);
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Vec term = CornerContribution(mesh, mesh.Triangles[t], k, weighting);
      sums[key[3 * t + k]] = sums[key[3 * t + k]] + term;
      lengths[key[3 * t + k]] += length(term);
    }
  }
  for (std::size_t i = 0; i < keys; ++i)
  {
    sums[i] = length(sums[i]) > 1e-12 * lengths[i] ? normalize(sums[i]) : Vec{ 0, 0, 0 };
  }
  return sums;
}

// Uniform, area, angle or max vertex normals; (0,0,0) where no face of
// positive area touches the vertex.
std::vector<Vec> ReferenceNormals(const Mesh& mesh, int weighting)
{
  std::vector<std::size_t> vertexOfCorner;
  for (const Triangle& t : mesh.Triangles)
  {
    for (const vtkIdType v : t)
    {
      vertexOfCorner.push_back(static_cast<std::size_t>(v));
    }
  }
  return GroupNormals(mesh, weighting, vertexOfCorner, mesh.Points.size());
}

std::vector<std::vector<std::size_t>> FacesOfVertices(const Mesh& mesh)
{
  std::vector<std::vector<std::size_t>> faces(mesh.Points.size());
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    for (const vtkIdType v : mesh.Triangles[t])
    {
      faces[static_cast<std::size_t>(v)].push_back(t);
    }
  }
  return faces;
}

// OpenMesh's calc_vertex_normal_loop, normalized: with the one-ring p_0 ..
// p_{n-1} counter-clockwise about the outside, t_v = sum cos(2 pi i/n) p_i and
// t_w = sum sin(2 pi i/n) p_i are the limit surface's tangents and t_v x t_w
// its outward normal (independent of where the ring starts). Nothing where
// the fan around v is not closed (a boundary vertex).
std::optional<Vec> LoopNormal(
  const Mesh& mesh, vtkIdType v, const std::vector<std::size_t>& facesOfVertex)
{
  std::map<vtkIdType, vtkIdType> following; // next -> prev of each face, seen from v
  for (const std::size_t f : facesOfVertex)
  {
    const Triangle& t = mesh.Triangles[f];
    const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    following[t[(k + 1) % 3]] = t[(k + 2) % 3];
  }
  if (facesOfVertex.empty() || following.size() != facesOfVertex.size())
  {
    return std::nullopt;
  }
  std::vector<vtkIdType> ring = { following.begin()->first };
  for (;;)
  {
    const auto next = following.find(ring.back());
    if (next == following.end())
    {
      return std::nullopt;
    }
    if (next->second == ring.front())
    {
      break;
    }
    if (ring.size() == facesOfVertex.size())
    {
      return std::nullopt; // a loop that misses the start
    }
    ring.push_back(next->second);
  }
  if (ring.size() != facesOfVertex.size())
  {
    return std::nullopt;
  }
  Vec tv = { 0, 0, 0 }, tw = { 0, 0, 0 };
  const double n = static_cast<double>(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i)
  {
    tv = tv + std::cos(2 * vtkMath::Pi() * i / n) * mesh.Point(ring[i]);
    tw = tw + std::sin(2 * vtkMath::Pi() * i / n) * mesh.Point(ring[i]);
  }
  return normalize(cross(tv, tw));
}

// Feature splitting, as the contract says: the corners of the faces around
// a vertex are joined across each edge that exactly two faces share and
// whose faces' normals are at most `featureAngle` degrees apart. Returns, for
// corner 3 t + k, its group: the lowest corner id in it.
std::vector<std::size_t> SplitGroups(const Mesh& mesh, double featureAngle)
{
  std::vector<std::size_t> parent(3 * mesh.Triangles.size());
  std::iota(parent.begin(), parent.end(), std::size_t{ 0 });
  const auto find = [&](std::size_t c)
  {
    while (parent[c] != c)
    {
      c = parent[c] = parent[parent[c]];
    }
    return c;
  };
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<std::size_t>> facesOfEdge;
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const Triangle& f = mesh.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      facesOfEdge[std::minmax(f[k], f[(k + 1) % 3])].push_back(t);
    }
  }
  const auto corner = [&](std::size_t t, vtkIdType v)
  {
    const Triangle& f = mesh.Triangles[t];
    return 3 * t + (f[0] == v ? 0 : f[1] == v ? 1 : 2);
  };
  for (const auto& [edge, faces] : facesOfEdge)
  {
    if (faces.size() == 2 &&
      AngleDegrees(mesh.AreaNormal(mesh.Triangles[faces[0]]),
        mesh.AreaNormal(mesh.Triangles[faces[1]])) <= featureAngle)
    {
      for (const vtkIdType v : { edge.first, edge.second })
      {
        const std::size_t a = find(corner(faces[0], v)), b = find(corner(faces[1], v));
        parent[std::max(a, b)] = std::min(a, b);
      }
    }
  }
  std::vector<std::size_t> group(parent.size());
  for (std::size_t c = 0; c < parent.size(); ++c)
  {
    group[c] = find(c);
  }
  return group;
}

// The same corners in the same cyclic order (any rotation of it).
bool SameTurn(const Triangle& a, const Triangle& b)
{
  return a == b || a == Triangle{ b[1], b[2], b[0] } || a == Triangle{ b[2], b[0], b[1] };
}

// ---------------------------------------------------------------------------
// Running the filter

struct Options
{
  int Weighting = vtkShadelabMeshNormals::Angle;
  bool Splitting = false;
  double FeatureAngle = 30;
  bool Consistency = false;
};

struct Output
{
  Mesh Geometry;
  std::vector<Vec> PointNormals;
  std::vector<Vec> CellNormals;
  vtkIdType DuplicatedFaces = 0;
};

// The output of a run, with what every output must be: float unit point
// normals "Normals" (active), unit cell normals "Normals", (0,0,0) exactly
// where no face of positive area touches a point, nothing NaN, every triangle
// kept; without splitting the input's points unchanged.
Output Collect(vtkShadelabMeshNormals* filter, const Mesh& input, const Options& options)
{
  Output out;
  vtkPolyData* data = filter->GetOutput();
  out.Geometry = FromPolyData(data);
  out.DuplicatedFaces = filter->GetNumberOfDuplicatedFaces();

  vtkDataArray* normals = data->GetPointData()->GetNormals();
  EXPECT_NE(normals, nullptr) << "no active point normals";
  if (normals)
  {
    EXPECT_TRUE(vtkFloatArray::SafeDownCast(normals)) << normals->GetClassName();
    EXPECT_STREQ(normals->GetName(), "Normals");
    EXPECT_EQ(normals->GetNumberOfComponents(), 3);
    EXPECT_EQ(normals->GetNumberOfTuples(), data->GetNumberOfPoints());
    out.PointNormals = Tuples(normals);
  }
  vtkDataArray* cellNormals = data->GetCellData()->GetArray("Normals");
  EXPECT_NE(cellNormals, nullptr) << "no cell normals";
  if (cellNormals)
  {
    EXPECT_EQ(cellNormals->GetNumberOfComponents(), 3);
    EXPECT_EQ(cellNormals->GetNumberOfTuples(), data->GetNumberOfCells());
    out.CellNormals = Tuples(cellNormals);
  }

  const Mesh& mesh = out.Geometry;
  EXPECT_EQ(data->GetNumberOfCells(), static_cast<vtkIdType>(input.Triangles.size()));
  EXPECT_EQ(data->GetNumberOfPolys(), data->GetNumberOfCells());
  if (!options.Splitting)
  {
    EXPECT_EQ(mesh.Points, input.Points) << "points changed without splitting";
  }
  else
  {
    EXPECT_GE(mesh.Points.size(), input.Points.size());
    EXPECT_TRUE(std::equal(input.Points.begin(), input.Points.end(), mesh.Points.begin()))
      << "the input's points do not come first";
  }
  if (!options.Consistency && mesh.Triangles.size() == input.Triangles.size())
  {
    // Same triangles, or (splitting) ones whose corners sit where the input's do.
    std::size_t moved = 0;
    for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = mesh.Triangles[t][k];
        moved += options.Splitting ? !(id >= 0 && id < static_cast<vtkIdType>(mesh.Points.size()) &&
                                       mesh.Point(id) == input.Point(input.Triangles[t][k]))
                                   : id != input.Triangles[t][k];
      }
    }
    EXPECT_EQ(moved, 0u) << "triangle corners changed";
  }

  // Points touched by a face of positive area get unit normals, others zero.
  // One exception, in the contract: a triangle and the same triangle
  // reversed (modellers' files hold such pairs) cancel in every weighting's sum, so
  // a point with only such pairs gets (0,0,0) too. Faces are compared by
  // where their corners are, not by ids: a point repeated under another id
  // makes the same face.
  std::vector<vtkIdType> first(mesh.Points.size());
  for (std::size_t i = 0; i < first.size(); ++i)
  {
    first[i] = static_cast<vtkIdType>(
      std::find(mesh.Points.begin(), mesh.Points.end(), mesh.Points[i]) - mesh.Points.begin());
  }
  std::vector<std::map<Triangle, int>> faces(mesh.Points.size()); // sorted corners -> turns
  for (const Triangle& t : mesh.Triangles)
  {
    Triangle sorted = t;
    for (vtkIdType& v : sorted)
    {
      v = v >= 0 && v < static_cast<vtkIdType>(first.size()) ? first[v] : v;
    }
    const Triangle placed = sorted;
    std::sort(sorted.begin(), sorted.end());
    const int turn = SameTurn(placed, sorted) ? 1 : -1;
    for (const vtkIdType v : t)
    {
      if (v >= 0 && v < static_cast<vtkIdType>(faces.size()) && length(mesh.AreaNormal(t)) > 0)
      {
        faces[static_cast<std::size_t>(v)][sorted] += turn;
      }
    }
  }
  for (std::size_t i = 0; i < out.PointNormals.size() && i < faces.size(); ++i)
  {
    const Vec& n = out.PointNormals[i];
    const bool unit = std::abs(length(n) - 1) <= Tolerance, zero = n == Vec{ 0, 0, 0 };
    const bool cancelled = std::all_of(
      faces[i].begin(), faces[i].end(), [](const auto& face) { return face.second == 0; });
    if (!IsFinite(n) || (faces[i].empty() && !zero) || (!cancelled && !unit) || !(unit || zero))
    {
      ADD_FAILURE() << "point " << i << " normal " << Str(n)
                    << (faces[i].empty() ? " is not (0,0,0)" : " is not unit");
      break;
    }
  }
  // Cell normals: the normalized cross product of the output's triangles.
  for (std::size_t t = 0; t < out.CellNormals.size() && t < mesh.Triangles.size(); ++t)
  {
    const Vec expected = normalize(mesh.AreaNormal(mesh.Triangles[t]));
    if (!IsFinite(out.CellNormals[t]) || MaxDifference(out.CellNormals[t], expected) > Tolerance)
    {
      ADD_FAILURE() << "cell " << t << " normal " << Str(out.CellNormals[t]) << ", expected "
                    << Str(expected);
      break;
    }
  }
  return out;
}

Output Compute(vtkPolyData* input, const Mesh& mesh, const Options& options)
{
  vtkNew<vtkShadelabMeshNormals> filter;
  filter->SetWeighting(options.Weighting);
  filter->SetSplitting(options.Splitting);
  filter->SetFeatureAngle(options.FeatureAngle);
  filter->SetConsistency(options.Consistency);
  filter->SetInputData(input);
  EXPECT_TRUE(filter->GetExecutive()->Update());
  return Collect(filter, mesh, options);
}

Output Compute(const Mesh& mesh, const Options& options)
{
  return Compute(ToPolyData(mesh), mesh, options);
}

// The largest component difference between two lists of normals; the first
// point where it exceeds `tolerance` is in `where`.
double WorstDifference(const std::vector<Vec>& got, const std::vector<Vec>& expected,
  double tolerance, std::string& where)
{
  EXPECT_EQ(got.size(), expected.size());
  double worst = 0;
  for (std::size_t i = 0; i < got.size() && i < expected.size(); ++i)
  {
    const double difference = IsFinite(got[i]) ? MaxDifference(got[i], expected[i])
                                               : std::numeric_limits<double>::infinity();
    if (difference > tolerance && where.empty())
    {
      where =
        "point " + std::to_string(i) + ": got " + Str(got[i]) + ", expected " + Str(expected[i]);
    }
    worst = std::max(worst, difference);
  }
  return worst;
}

void ExpectNormalsNear(const std::vector<Vec>& got, const std::vector<Vec>& expected)
{
  std::string where;
  const double worst = WorstDifference(got, expected, Tolerance, where);
  EXPECT_LE(worst, Tolerance) << where;
}

// Mean and largest angle (degrees) between normals and the exact ones.
std::pair<double, double> AngleErrors(
  const std::vector<Vec>& normals, const std::vector<Vec>& exact)
{
  double sum = 0, worst = 0;
  for (std::size_t i = 0; i < normals.size(); ++i)
  {
    const double angle = IsFinite(normals[i]) ? AngleDegrees(normals[i], exact[i]) : 180;
    sum += angle;
    worst = std::max(worst, angle);
  }
  return { sum / normals.size(), worst };
}

// Every test's meshes, from fixed seeds.
Mesh IrregularSphere(int subdivisions = 3)
{
  Random random(7);
  return JitteredOnSphere(Icosphere(subdivisions), 0.3, random);
}

Mesh IrregularTorus()
{
  Random random(11);
  return Torus(48, 24, 1.0, 0.4, 0.2, random);
}

Mesh RandomHeightField()
{
  Random random(5);
  return HeightField(12, random);
}

// The generators' own promise: faces facing the way of the exact normals.
void ExpectOutward(const Mesh& mesh)
{
  std::size_t inward = 0;
  for (const Triangle& t : mesh.Triangles)
  {
    inward += dot(mesh.AreaNormal(t), mesh.Exact[static_cast<std::size_t>(t[0])]) <= 0;
  }
  EXPECT_EQ(inward, 0u) << "the test's generator made folded triangles";
}

// ---------------------------------------------------------------------------
// 1. The definitions

TEST(MeshNormals, EachWeightingMatchesItsDefinition)
{
  const std::pair<const char*, Mesh> meshes[] = { { "irregular sphere", IrregularSphere(2) },
    { "height field", RandomHeightField() } };
  for (const auto& [name, mesh] : meshes)
  {
    std::vector<std::vector<Vec>> references;
    for (int weighting = vtkShadelabMeshNormals::Uniform; weighting <= vtkShadelabMeshNormals::Max;
         ++weighting)
    {
      SCOPED_TRACE(std::string(name) + ", " + WeightingNames[weighting]);
      references.push_back(ReferenceNormals(mesh, weighting));
      Options options;
      options.Weighting = weighting;
      ExpectNormalsNear(Compute(mesh, options).PointNormals, references.back());
    }
    // The test can tell the weightings apart: each pair differs somewhere by
    // far more than the tolerance.
    for (std::size_t a = 0; a < references.size(); ++a)
    {
      for (std::size_t b = a + 1; b < references.size(); ++b)
      {
        std::string where;
        EXPECT_GT(WorstDifference(references[a], references[b], 0, where), 1e3 * Tolerance)
          << name << ": " << WeightingNames[a] << " and " << WeightingNames[b] << " agree";
      }
    }
  }
}

// ---------------------------------------------------------------------------
// 2. Accuracy against analytic normals

TEST(MeshNormals, AccuracyOnIrregularSpheresAndTori)
{
  const std::pair<const char*, Mesh> surfaces[] = { { "sphere", IrregularSphere() },
    { "torus", IrregularTorus() } };
  std::map<std::string, double> mean;
  for (const auto& [name, mesh] : surfaces)
  {
    ExpectOutward(mesh);
    std::cout << "[ accuracy ] " << name << ", " << mesh.Points.size() << " points, "
              << mesh.Triangles.size() << " triangles: mean / max angle to the exact normal"
              << std::endl;
    for (int weighting = 0; weighting < Weightings; ++weighting)
    {
      Options options;
      options.Weighting = weighting;
      const auto [meanError, maxError] =
        AngleErrors(Compute(mesh, options).PointNormals, mesh.Exact);
      const std::string key = std::string(name) + "_" + WeightingNames[weighting];
      mean[key] = meanError;
      std::cout << "[ accuracy ]   " << std::setw(8) << WeightingNames[weighting] << std::fixed
                << std::setprecision(6) << std::setw(12) << meanError << std::setw(12) << maxError
                << " deg" << std::defaultfloat << std::endl;
      RecordProperty(key + "_mean_deg", std::to_string(meanError));
      RecordProperty(key + "_max_deg", std::to_string(maxError));
      // Every weighting is a fair estimate on these smooth, finely sampled
      // surfaces (edges of ~9 degrees of arc, jittered by 30%): all measured
      // within 2.5 degrees on average; a mean over 5 degrees means a wrong
      // formula (a reversed weight or a missed face gives tens).
      EXPECT_LT(meanError, 5.0) << key;
    }
  }
  // On a sphere Max's weights are exact for any triangulation: only the
  // float output remains (6e-8 rad = 3e-6 degrees). The angle weighting
  // beats the plain average on irregular triangles (Thuermer & Wuethrich).
  EXPECT_LT(mean["sphere_max"], 1e-4);
  EXPECT_LT(mean["sphere_max"], mean["sphere_angle"]);
  EXPECT_LT(mean["sphere_angle"], mean["sphere_uniform"]);
}

// ---------------------------------------------------------------------------
// 3. Loop

TEST(MeshNormals, LoopNormalsPointOutwardOnASmoothClosedMesh)
{
  const Mesh sphere = Icosphere(3);
  Options options;
  options.Weighting = vtkShadelabMeshNormals::Loop;
  const Output out = Compute(sphere, options);
  std::size_t inward = 0;
  for (std::size_t i = 0; i < out.PointNormals.size(); ++i)
  {
    // The limit normal of a fine sphere is the radial direction to within a
    // degree or so; 0.99 is 8 degrees, a reversed or tangent normal is far off.
    inward += !(dot(out.PointNormals[i], sphere.Exact[i]) > 0.99);
    EXPECT_NEAR(length(out.PointNormals[i]), 1.0, Tolerance) << i;
  }
  EXPECT_EQ(inward, 0u);
}

TEST(MeshNormals, LoopNormalsFollowTheLimitTangentsAndAngleAtTheBoundary)
{
  const std::pair<const char*, Mesh> meshes[] = { { "irregular sphere", IrregularSphere() },
    { "height field", RandomHeightField() } };
  for (const auto& [name, mesh] : meshes)
  {
    SCOPED_TRACE(name);
    const auto faces = FacesOfVertices(mesh);
    const std::vector<Vec> angle = ReferenceNormals(mesh, vtkShadelabMeshNormals::Angle);
    std::vector<Vec> expected = angle;
    std::size_t interior = 0;
    for (std::size_t v = 0; v < mesh.Points.size(); ++v)
    {
      if (const auto loop = LoopNormal(mesh, static_cast<vtkIdType>(v), faces[v]))
      {
        expected[v] = *loop;
        ++interior;
      }
    }
    EXPECT_GT(interior, mesh.Points.size() / 2);
    Options options;
    options.Weighting = vtkShadelabMeshNormals::Loop;
    ExpectNormalsNear(Compute(mesh, options).PointNormals, expected);
    // Loop is not the angle weighting in disguise on these irregular meshes.
    std::string where;
    EXPECT_GT(WorstDifference(expected, angle, 0, where), 1e3 * Tolerance);
  }
}

// ---------------------------------------------------------------------------
// Splitting: the output against the groups computed here

// Each output corner refers to a point of its own group (one point a group,
// the input's points first and the extra ones in vertex order) whose normal
// is the group's reference normal.
void ExpectSplitAsReference(const Mesh& input, const Output& out, const Options& options)
{
  const std::vector<std::size_t> group = SplitGroups(input, options.FeatureAngle);
  const std::vector<Vec> normals =
    GroupNormals(input, options.Weighting, group, 3 * input.Triangles.size());
  std::set<std::size_t> groups(group.begin(), group.end());
  std::set<vtkIdType> usedVertices;
  for (const Triangle& t : input.Triangles)
  {
    usedVertices.insert(t.begin(), t.end());
  }
  EXPECT_EQ(out.Geometry.Points.size(), input.Points.size() + groups.size() - usedVertices.size())
    << "not one point a group of faces";
  ASSERT_EQ(out.Geometry.Triangles.size(), input.Triangles.size());

  std::map<std::size_t, vtkIdType> pointOfGroup;
  std::map<vtkIdType, std::size_t> groupOfPoint;
  std::map<vtkIdType, vtkIdType> vertexOfPoint;
  std::size_t mismatched = 0;
  std::string where;
  for (std::size_t t = 0; t < input.Triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::size_t g = group[3 * t + k];
      const vtkIdType point = out.Geometry.Triangles[t][k];
      mismatched += pointOfGroup.emplace(g, point).first->second != point;
      mismatched += groupOfPoint.emplace(point, g).first->second != g;
      vertexOfPoint.emplace(point, input.Triangles[t][k]);
      if (static_cast<std::size_t>(point) < out.PointNormals.size() && where.empty() &&
        MaxDifference(out.PointNormals[static_cast<std::size_t>(point)], normals[g]) > Tolerance)
      {
        where = "triangle " + std::to_string(t) + " corner " + std::to_string(k) + ": got " +
          Str(out.PointNormals[static_cast<std::size_t>(point)]) + ", expected " + Str(normals[g]);
      }
    }
  }
  EXPECT_EQ(mismatched, 0u) << "corners of one group on different points, or of two on one";
  EXPECT_TRUE(where.empty()) << where;
  // The input's vertex v keeps id v; the extra points come in vertex order.
  vtkIdType previous = -1;
  std::size_t misplaced = 0;
  std::string extra;
  for (const auto& [point, vertex] : vertexOfPoint)
  {
    if (point < static_cast<vtkIdType>(input.Points.size()))
    {
      misplaced += point != vertex;
    }
    else
    {
      misplaced += vertex < previous;
      previous = vertex;
      extra += " " + std::to_string(vertex);
    }
  }
  EXPECT_EQ(misplaced, 0u)
    << "points not in the input's order, then the extra ones in vertex order; the extra "
       "points are copies of vertices"
    << extra;
}

// ---------------------------------------------------------------------------
// 4. The cube

TEST(MeshNormals, CubeCornersSplitIntoAxisNormals)
{
  const Mesh cube = Cube();
  Options options;
  options.Splitting = true;
  const Output split = Compute(cube, options);
  EXPECT_EQ(split.Geometry.Points.size(), 24u);
  ExpectSplitAsReference(cube, split, options);
  // Every corner's normal is its side's axis, the triangle's own normal.
  for (std::size_t t = 0; t < split.Geometry.Triangles.size(); ++t)
  {
    const Vec axis = normalize(cube.AreaNormal(cube.Triangles[t]));
    EXPECT_DOUBLE_EQ(std::abs(axis[0]) + std::abs(axis[1]) + std::abs(axis[2]), 1.0);
    for (const vtkIdType point : split.Geometry.Triangles[t])
    {
      ASSERT_LT(point, static_cast<vtkIdType>(split.PointNormals.size()));
      EXPECT_LE(MaxDifference(split.PointNormals[static_cast<std::size_t>(point)], axis), Tolerance)
        << "triangle " << t << " point " << point;
    }
  }

  // Unsplit, uniform: each corner's normal is the normalized sum of the unit
  // normals of the triangles there (corner (1,1,1) is point 7).
  options = Options();
  options.Weighting = vtkShadelabMeshNormals::Uniform;
  const Output whole = Compute(cube, options);
  EXPECT_EQ(whole.Geometry.Points.size(), 8u);
  Vec sum = { 0, 0, 0 };
  for (const Triangle& t : cube.Triangles)
  {
    if (std::count(t.begin(), t.end(), 7))
    {
      sum = sum + normalize(cube.AreaNormal(t));
    }
  }
  ASSERT_EQ(whole.PointNormals.size(), 8u);
  EXPECT_LE(MaxDifference(whole.PointNormals[7], normalize(sum)), Tolerance)
    << Str(whole.PointNormals[7]) << " vs " << Str(normalize(sum));
  ExpectNormalsNear(whole.PointNormals, ReferenceNormals(cube, options.Weighting));
}

// ---------------------------------------------------------------------------
// 5. Fandisk's sharp edges

TEST(MeshNormals, FandiskSharpEdgesStaySharpWhenSplitting)
{
  // Hoppe's fandisk is another project's file: read where it is.
  const fs::path file = fs::path(SHADELAB_SHARED_DATA) / "meshes/fandisk.obj";
  if (!fs::is_regular_file(file))
  {
    GTEST_SKIP() << file << " is not here";
  }
  const Mesh fandisk = Read(file);
  ASSERT_FALSE(fandisk.Triangles.empty());
  // The edges whose two triangles meet at more than 60 degrees.
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<std::size_t>> facesOfEdge;
  for (std::size_t t = 0; t < fandisk.Triangles.size(); ++t)
  {
    const Triangle& f = fandisk.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      facesOfEdge[std::minmax(f[k], f[(k + 1) % 3])].push_back(t);
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> sharp;
  for (const auto& [edge, faces] : facesOfEdge)
  {
    if (faces.size() == 2 &&
      AngleDegrees(fandisk.AreaNormal(fandisk.Triangles[faces[0]]),
        fandisk.AreaNormal(fandisk.Triangles[faces[1]])) > 60)
    {
      sharp.emplace_back(faces[0], faces[1]);
    }
  }
  EXPECT_GT(sharp.size(), 500u); // fandisk has 700

  // A sharp edge stays sharp when its triangles share no output point and
  // each triangle's corner normals are within 25 degrees of its own normal.
  // Splitting at 30 degrees leaves at most ~18 degrees (angle-weighted
  // normals of fandisk's smooth patches); an unsplit point's single normal
  // cannot be within 25 degrees of two faces more than 60 apart.
  const auto softened = [&](const Output& out)
  {
    std::size_t count = 0;
    for (const auto& [f, g] : sharp)
    {
      const Triangle& a = out.Geometry.Triangles[f];
      const Triangle& b = out.Geometry.Triangles[g];
      bool soft = std::any_of(
        a.begin(), a.end(), [&](vtkIdType p) { return std::count(b.begin(), b.end(), p) > 0; });
      for (const std::size_t t : { f, g })
      {
        const Vec n = normalize(fandisk.AreaNormal(fandisk.Triangles[t]));
        for (const vtkIdType p : out.Geometry.Triangles[t])
        {
          soft = soft || AngleDegrees(out.PointNormals[static_cast<std::size_t>(p)], n) > 25;
        }
      }
      count += soft;
    }
    return count;
  };

  Options options;
  options.Splitting = true;
  options.FeatureAngle = 30;
  const Output split = Compute(fandisk, options);
  ASSERT_EQ(split.Geometry.Triangles.size(), fandisk.Triangles.size());
  ASSERT_EQ(split.PointNormals.size(), split.Geometry.Points.size());
  ExpectSplitAsReference(fandisk, split, options);
  EXPECT_EQ(softened(split), 0u) << "of " << sharp.size() << " sharp edges";

  options.Splitting = false;
  const Output unsplit = Compute(fandisk, options);
  ASSERT_EQ(unsplit.Geometry.Triangles.size(), fandisk.Triangles.size());
  ASSERT_EQ(unsplit.PointNormals.size(), unsplit.Geometry.Points.size());
  EXPECT_EQ(softened(unsplit), sharp.size());
  std::cout << "[ fandisk  ] " << sharp.size() << " sharp edges; points " << fandisk.Points.size()
            << " -> " << split.Geometry.Points.size() << " split at 30 degrees" << std::endl;
}

// ---------------------------------------------------------------------------
// 6. Non-manifold and degenerate input

// Every weighting, split or not: all faces kept and finite normals
// (Collect's checks), the definitions' sums over all the faces at a point
// (not for Loop, which falls back to angle at some of these points) and,
// unless `zeroAreaFaces` (whose grouping the contract leaves open), the
// contract's split groups. Returns the duplicated-face counts.
std::vector<vtkIdType> RunEveryWay(const Mesh& mesh, bool zeroAreaFaces = false)
{
  std::vector<vtkIdType> duplicated;
  for (const bool splitting : { false, true })
  {
    for (int weighting = 0; weighting < Weightings; ++weighting)
    {
      SCOPED_TRACE(std::string(WeightingNames[weighting]) + (splitting ? ", split" : ""));
      Options options;
      options.Weighting = weighting;
      options.Splitting = splitting;
      const Output out = Compute(mesh, options);
      if (splitting || weighting == vtkShadelabMeshNormals::Loop)
      {
        duplicated.push_back(out.DuplicatedFaces); // counted where OpenMesh's mesh is used
      }
      if (weighting != vtkShadelabMeshNormals::Loop && !splitting)
      {
        ExpectNormalsNear(out.PointNormals, ReferenceNormals(mesh, weighting));
      }
      if (weighting != vtkShadelabMeshNormals::Loop && splitting && !zeroAreaFaces)
      {
        ExpectSplitAsReference(mesh, out, options);
      }
    }
  }
  return duplicated;
}

TEST(MeshNormals, ThreeTrianglesOnOneEdgeAreKept)
{
  // Edge 0-1 has three faces: a non-manifold edge, which separates groups
  // when splitting, so points 0 and 1 become three points each (9 in all),
  // although faces 0 and 1 meet at only 11 degrees.
  Mesh mesh;
  mesh.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0.2 }, { 0.5, 0.3, 1 } };
  mesh.Triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  for (const vtkIdType duplicated : RunEveryWay(mesh))
  {
    EXPECT_GT(duplicated, 0);
  }
}

TEST(MeshNormals, TwoConesTouchingAtOneVertexAreKept)
{
  // Closed fans around the shared apex 0: one opening up, one (narrower,
  // off-centre, so that nothing cancels) opening down.
  Mesh mesh;
  mesh.Points.push_back({ 0, 0, 0 });
  for (int k = 0; k < 6; ++k)
  {
    const double a = 2 * vtkMath::Pi() * k / 6;
    mesh.Points.push_back({ std::cos(a), std::sin(a), 1 });
    mesh.Triangles.push_back({ 0, 1 + k, 1 + (k + 1) % 6 });
  }
  for (int k = 0; k < 5; ++k)
  {
    const double a = 2 * vtkMath::Pi() * k / 5;
    mesh.Points.push_back({ 0.3 + 0.7 * std::cos(a), 0.7 * std::sin(a), -1.2 });
    mesh.Triangles.push_back({ 0, 7 + (k + 1) % 5, 7 + k });
  }
  for (const vtkIdType duplicated : RunEveryWay(mesh))
  {
    EXPECT_GT(duplicated, 0);
  }
}

TEST(MeshNormals, ZeroAreaFacesAndIsolatedVerticesGiveZeroNotNaN)
{
  // The unit square (faces 0, 1) facing +z, a sliver of three collinear
  // points on its edge 0-1 (face 2, reusing that edge the right way round),
  // a face with a repeated vertex (face 3) and the unused point 5.
  Mesh mesh;
  mesh.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0.5, 0, 0 }, { 3, 3, 3 } };
  mesh.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 1, 0, 4 }, { 2, 3, 3 } };
  RunEveryWay(mesh, true);
  for (int weighting = 0; weighting < Weightings; ++weighting)
  {
    SCOPED_TRACE(WeightingNames[weighting]);
    Options options;
    options.Weighting = weighting;
    const Output out = Compute(mesh, options);
    ASSERT_EQ(out.PointNormals.size(), 6u);
    // The zero-area faces add nothing: the square's corners face +z exactly.
    for (std::size_t v = 0; v < 4; ++v)
    {
      EXPECT_LE(MaxDifference(out.PointNormals[v], { 0, 0, 1 }), Tolerance)
        << v << ": " << Str(out.PointNormals[v]);
    }
    EXPECT_EQ(out.PointNormals[4], (Vec{ 0, 0, 0 })); // only in the sliver
    EXPECT_EQ(out.PointNormals[5], (Vec{ 0, 0, 0 })); // in no face
    ASSERT_EQ(out.CellNormals.size(), 4u);
    EXPECT_EQ(out.CellNormals[2], (Vec{ 0, 0, 0 }));
    EXPECT_EQ(out.CellNormals[3], (Vec{ 0, 0, 0 }));
  }
}

// A bent strip of four triangles; the second one reversed against both its
// neighbours.
Mesh BentStripWithOneFlipped()
{
  Mesh mesh;
  mesh.Points = { { 0, 0, 0 }, { 1, 0, 0.1 }, { 0, 1, 0.3 }, { 1, 1, 0 }, { 0, 2, 0.2 },
    { 1, 2, 0.4 } };
  mesh.Triangles = { { 0, 1, 2 }, { 1, 2, 3 }, { 2, 3, 4 }, { 3, 5, 4 } };
  return mesh;
}

TEST(MeshNormals, InconsistentlyOrientedNeighboursAreKept)
{
  for (const vtkIdType duplicated : RunEveryWay(BentStripWithOneFlipped()))
  {
    EXPECT_GT(duplicated, 0);
  }
}

TEST(MeshNormals, ConsistencyOrientsEachPartLikeItsLowestFace)
{
  // Two parts: a closed irregular sphere, then a height field above it.
  // About a third of the faces are reversed, including the sphere's first
  // (so the whole sphere must come out reversed) but not the height field's
  // first (so it must come out as generated).
  Mesh original = IrregularSphere(2);
  const std::size_t sphereFaces = original.Triangles.size();
  const Mesh field = RandomHeightField();
  const auto offset = static_cast<vtkIdType>(original.Points.size());
  for (const Vec& p : field.Points)
  {
    original.Points.push_back(p + Vec{ 0, 0, 10 });
  }
  for (const Triangle& t : field.Triangles)
  {
    original.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  Mesh flipped = original, expected = original;
  Random random(13);
  for (std::size_t t = 0; t < original.Triangles.size(); ++t)
  {
    const bool flip = t == 0 || (t != sphereFaces && random.Uniform(0, 1) < 0.35);
    if (flip)
    {
      std::swap(flipped.Triangles[t][1], flipped.Triangles[t][2]);
    }
    if (t < sphereFaces)
    {
      std::swap(expected.Triangles[t][1], expected.Triangles[t][2]);
    }
  }

  Options options;
  options.Consistency = true;
  const Output out = Compute(flipped, options);
  ASSERT_EQ(out.Geometry.Triangles.size(), expected.Triangles.size());
  // Same corners, each face turned the expected way.
  std::size_t wrong = 0;
  for (std::size_t t = 0; t < expected.Triangles.size(); ++t)
  {
    wrong += !SameTurn(out.Geometry.Triangles[t], expected.Triangles[t]);
  }
  EXPECT_EQ(wrong, 0u) << "faces not oriented like their part's first face";
  // Each edge of two faces is used once each way.
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  for (const Triangle& t : out.Geometry.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  std::size_t disagreeing = 0;
  for (const auto& [edge, count] : directed)
  {
    disagreeing += count != 1;
  }
  EXPECT_EQ(disagreeing, 0u) << "directed edges used twice";
  // And the normals are those of the consistent mesh.
  ExpectNormalsNear(out.PointNormals, ReferenceNormals(expected, options.Weighting));

  // Without Consistency the reversed faces stay as they are.
  options.Consistency = false;
  const Output kept = Compute(flipped, options);
  EXPECT_EQ(kept.Geometry.Triangles, flipped.Triangles);
  // OpenMesh refuses some of them: splitting, which builds its mesh, says so.
  options.Splitting = true;
  EXPECT_GT(Compute(flipped, options).DuplicatedFaces, 0);
}

// ---------------------------------------------------------------------------
// 7. A quad mesh against its file normals

TEST(MeshNormals, AQuadMeshAgreesWithItsFileNormals)
{
  std::vector<Vec> fileNormals;
  const Mesh quads = Read(TestMeshes / "teapot-quads.obj", &fileNormals);
  ASSERT_EQ(fileNormals.size(), quads.Points.size());
  for (int weighting = 0; weighting < Weightings; ++weighting)
  {
    Options options;
    options.Weighting = weighting;
    const Output out = Compute(quads, options);
    ASSERT_EQ(out.PointNormals.size(), fileNormals.size());
    std::size_t agreeing = 0;
    for (std::size_t i = 0; i < fileNormals.size(); ++i)
    {
      agreeing += dot(out.PointNormals[i], fileNormals[i]) > 0;
    }
    const double fraction = static_cast<double>(agreeing) / fileNormals.size();
    std::cout << "[ quads    ] " << WeightingNames[weighting] << ": " << agreeing << " of "
              << fileNormals.size() << " normals agree with the file's" << std::endl;
    // The file's normals are the teapot's exact ones (meshes/teapot.cxx);
    // ours from the triangles: they may differ in detail, not in side.
    EXPECT_GE(fraction, 0.95) << WeightingNames[weighting];
  }
}

// ---------------------------------------------------------------------------
// 8. The connectivity cache

TEST(MeshNormals, ConnectivityIsBuiltOncePerInput)
{
  const Mesh cube = Cube();
  vtkSmartPointer<vtkPolyData> input = ToPolyData(cube);
  vtkNew<vtkShadelabMeshNormals> filter;
  filter->SetInputData(input);
  filter->SplittingOn();
  filter->SetFeatureAngle(30);
  Options options;
  options.Splitting = true;
  const auto update = [&]()
  {
    EXPECT_TRUE(filter->GetExecutive()->Update());
    options.Weighting = filter->GetWeighting();
    options.FeatureAngle = filter->GetFeatureAngle();
    return Collect(filter, cube, options);
  };
  EXPECT_EQ(update().Geometry.Points.size(), 24u);
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), 1);

  // A new feature angle or weighting recomputes the normals, not the
  // connectivity.
  filter->SetFeatureAngle(100);
  EXPECT_EQ(update().Geometry.Points.size(), 8u);
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), 1);
  filter->SetWeighting(vtkShadelabMeshNormals::Uniform);
  ExpectNormalsNear(update().PointNormals, ReferenceNormals(cube, vtkShadelabMeshNormals::Uniform));
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), 1);
  filter->SetWeighting(vtkShadelabMeshNormals::Area);
  ExpectNormalsNear(update().PointNormals, ReferenceNormals(cube, vtkShadelabMeshNormals::Area));
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), 1);

  // The input modified: built again.
  input->Modified();
  update();
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), 2);

  // A point moved in place (its vtkPoints modified): the normals follow.
  filter->SplittingOff();
  options.Splitting = false;
  Mesh moved = cube;
  moved.Points[7] = { 1.5, 1.5, 1.5 };
  input->GetPoints()->SetPoint(7, moved.Points[7].data());
  input->GetPoints()->Modified();
  EXPECT_TRUE(filter->GetExecutive()->Update());
  const Output afterMove = Collect(filter, moved, options);
  ExpectNormalsNear(afterMove.PointNormals, ReferenceNormals(moved, vtkShadelabMeshNormals::Area));
  EXPECT_GE(filter->GetNumberOfConnectivityBuilds(), 2);
  const int builds = filter->GetNumberOfConnectivityBuilds();

  // A new input: built again.
  const Mesh sphere = Icosphere(1);
  filter->SetInputData(ToPolyData(sphere));
  EXPECT_TRUE(filter->GetExecutive()->Update());
  ExpectNormalsNear(Collect(filter, sphere, options).PointNormals,
    ReferenceNormals(sphere, vtkShadelabMeshNormals::Area));
  EXPECT_EQ(filter->GetNumberOfConnectivityBuilds(), builds + 1);

  // Consistency switched on and off on the same input: the orientation
  // follows (whether the connectivity is rebuilt for it is the filter's
  // business).
  const Mesh strip = BentStripWithOneFlipped();
  filter->SetInputData(ToPolyData(strip));
  EXPECT_TRUE(filter->GetExecutive()->Update());
  EXPECT_EQ(FromPolyData(filter->GetOutput()).Triangles, strip.Triangles);
  filter->ConsistencyOn();
  EXPECT_TRUE(filter->GetExecutive()->Update());
  const auto turned = FromPolyData(filter->GetOutput()).Triangles;
  ASSERT_EQ(turned.size(), 4u);
  EXPECT_TRUE(SameTurn(turned[0], strip.Triangles[0])) << "the lowest face turned";
  EXPECT_TRUE(SameTurn(turned[1], { 1, 3, 2 })) << "face 1 not turned to agree with face 0";
  filter->ConsistencyOff();
  EXPECT_TRUE(filter->GetExecutive()->Update());
  EXPECT_EQ(FromPolyData(filter->GetOutput()).Triangles, strip.Triangles);
}

// The bytes of an array's values.
std::vector<unsigned char> Bytes(vtkDataArray* array)
{
  EXPECT_NE(array, nullptr);
  if (!array)
  {
    return {};
  }
  const auto* begin = static_cast<const unsigned char*>(array->GetVoidPointer(0));
  return { begin, begin + array->GetDataSize() * array->GetDataTypeSize() };
}

// Summed normals (every weighting but Loop, no splitting) are computed
// without OpenMesh's mesh; they must be the very bits that the same filter
// gives from the geometry it keeps beside that mesh (built for a split run
// first): on the real meshes, and on non-manifold, degenerate and
// inconsistently oriented ones, where OpenMesh duplicates faces.
TEST(MeshNormals, SummedNormalsWithoutConnectivityAreTheSameBits)
{
  std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> inputs;
  for (const char* file : { "teapot-fine.ply", "teapot.off", "teapot.obj", "torus.obj",
         "teapot-quads.obj", "teapot.stl" })
  {
    vtkNew<vtkShadelabMeshReader> reader;
    reader->SetFileName((TestMeshes / file).c_str());
    reader->SetReadNormals(false);
    ASSERT_TRUE(reader->GetExecutive()->Update()) << file;
    inputs.emplace_back(file, reader->GetOutput());
  }
  Mesh nonManifold;
  nonManifold.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0.2 }, { 0.5, 0.3, 1 },
    { 0.5, 0, 0 }, { 3, 3, 3 } };
  nonManifold.Triangles = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 }, { 1, 0, 5 }, { 2, 3, 3 },
    { 0, 1, 2 }, { 0, 2, 1 } };
  inputs.emplace_back(
    "three faces on an edge, a sliver, a repeated vertex, a face twice", ToPolyData(nonManifold));
  inputs.emplace_back("one face flipped", ToPolyData(BentStripWithOneFlipped()));

  for (const auto& [name, input] : inputs)
  {
    for (const bool consistency : { false, true })
    {
      for (int weighting = 0; weighting < Weightings; ++weighting)
      {
        if (weighting == vtkShadelabMeshNormals::Loop)
        {
          continue; // Loop's limit normals need the connectivity
        }
        SCOPED_TRACE(name + ", " + WeightingNames[weighting] + (consistency ? ", oriented" : ""));
        vtkNew<vtkShadelabMeshNormals> fast;
        fast->SetInputData(input);
        fast->SetWeighting(weighting);
        fast->SetConsistency(consistency);
        ASSERT_TRUE(fast->GetExecutive()->Update());

        vtkNew<vtkShadelabMeshNormals> connected;
        connected->SetInputData(input);
        connected->SetWeighting(weighting);
        connected->SetConsistency(consistency);
        connected->SplittingOn();
        ASSERT_TRUE(connected->GetExecutive()->Update());
        connected->SplittingOff();
        ASSERT_TRUE(connected->GetExecutive()->Update());
        ASSERT_EQ(connected->GetNumberOfConnectivityBuilds(), 1);

        EXPECT_TRUE(Bytes(fast->GetOutput()->GetPointData()->GetNormals()) ==
          Bytes(connected->GetOutput()->GetPointData()->GetNormals()))
          << "point normals differ";
        EXPECT_TRUE(Bytes(fast->GetOutput()->GetCellData()->GetNormals()) ==
          Bytes(connected->GetOutput()->GetCellData()->GetNormals()))
          << "cell normals differ";
        EXPECT_EQ(FromPolyData(fast->GetOutput()).Triangles,
          FromPolyData(connected->GetOutput()).Triangles);
      }
    }
  }
}

// The cell normals are each output face's unit normal (shadelab::FaceNormal
// of its points, in double) rounded to float: the very bits, whether the sum
// wrote them as it computed each face's geometry (no connectivity) or from
// the geometry stored beside the connectivity (splitting, Loop); with
// ComputeCellNormals off there are none, and the point normals keep their
// bits.
TEST(MeshNormals, CellNormalsAreEachFacesNormalInFloat)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((TestMeshes / "teapot.obj").c_str());
  reader->SetReadNormals(false);
  ASSERT_TRUE(reader->GetExecutive()->Update());
  Mesh degenerate;
  degenerate.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 2, 0, 0 }, { 0.5, 0.3, 1 } };
  degenerate.Triangles = { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 }, { 2, 2, 4 }, { 0, 2, 1 } };
  // The reader's ids in 32-bit storage, ToPolyData's in 64-bit.
  const vtkSmartPointer<vtkPolyData> inputs[] = { reader->GetOutput(), ToPolyData(degenerate) };
  for (vtkPolyData* input : inputs)
  {
    for (const bool consistency : { false, true })
    {
      for (const int weighting : { vtkShadelabMeshNormals::Angle, vtkShadelabMeshNormals::Loop })
      {
        for (const bool splitting : { false, true })
        {
          SCOPED_TRACE(std::string(WeightingNames[weighting]) + (splitting ? ", split" : "") +
            (consistency ? ", oriented" : "") + ", " + std::to_string(input->GetNumberOfPolys()) +
            " faces");
          const auto run = [&](bool cellNormals)
          {
            auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
            filter->SetInputData(input);
            filter->SetWeighting(weighting);
            filter->SetSplitting(splitting);
            filter->SetConsistency(consistency);
            filter->SetComputeCellNormals(cellNormals);
            EXPECT_TRUE(filter->GetExecutive()->Update());
            return filter;
          };
          const auto with = run(true);
          const auto without = run(false);
          vtkPolyData* output = with->GetOutput();
          const Mesh faces = FromPolyData(output);
          auto* cellNormals = vtkFloatArray::SafeDownCast(output->GetCellData()->GetNormals());
          ASSERT_NE(cellNormals, nullptr);
          ASSERT_EQ(
            cellNormals->GetNumberOfTuples(), static_cast<vtkIdType>(faces.Triangles.size()));
          for (std::size_t f = 0; f < faces.Triangles.size(); ++f)
          {
            const Triangle& t = faces.Triangles[f];
            Vec unit;
            shadelab::FaceNormal(faces.Points[t[0]], faces.Points[t[1]], faces.Points[t[2]], unit);
            for (int k = 0; k < 3; ++k)
            {
              ASSERT_EQ(cellNormals->GetValue(3 * static_cast<vtkIdType>(f) + k),
                static_cast<float>(unit[k]))
                << "face " << f << " component " << k;
            }
          }
          EXPECT_EQ(without->GetOutput()->GetCellData()->GetNormals(), nullptr);
          EXPECT_TRUE(Bytes(output->GetPointData()->GetNormals()) ==
            Bytes(without->GetOutput()->GetPointData()->GetNormals()))
            << "point normals differ without cell normals";
        }
      }
    }
  }
}

// The filter reads 32-bit ids where they are (the readers' storage) and
// copies 64-bit ones, and ids that welding (an OBJ's file vertices) or
// Consistency rewrite: the same mesh in either storage gives the same bits,
// and the input's own ids are never changed.
TEST(MeshNormals, IdsReadInPlaceOrCopiedGiveTheSameBitsAndKeepTheInput)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((TestMeshes / "teapot.obj").c_str());
  ASSERT_TRUE(reader->GetExecutive()->Update());
  ASSERT_NE(reader->GetOutput()->GetPointData()->GetArray(shadelab::FileVertexArrayName), nullptr)
    << "teapot.obj's texture seams should split its vertices";
  const std::pair<std::string, vtkSmartPointer<vtkPolyData>> meshes[] = {
    { "teapot.obj", reader->GetOutput() },
    { "one face flipped", ToPolyData(BentStripWithOneFlipped()) },
  };
  for (const auto& [name, mesh] : meshes)
  {
    vtkNew<vtkPolyData> narrow, wide;
    narrow->DeepCopy(mesh);
    wide->DeepCopy(mesh);
    ASSERT_TRUE(narrow->GetPolys()->ConvertTo32BitStorage());
    ASSERT_TRUE(wide->GetPolys()->ConvertTo64BitStorage());
    const std::vector<unsigned char> ids = Bytes(narrow->GetPolys()->GetConnectivityArray());
    for (const bool consistency : { false, true })
    {
      for (const bool splitting : { false, true })
      {
        SCOPED_TRACE(name + (consistency ? ", oriented" : "") + (splitting ? ", split" : ""));
        const auto run = [&](vtkPolyData* input)
        {
          auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
          filter->SetInputData(input);
          filter->SetConsistency(consistency);
          filter->SetSplitting(splitting);
          EXPECT_TRUE(filter->GetExecutive()->Update());
          return filter;
        };
        const auto fromNarrow = run(narrow);
        const auto fromWide = run(wide);
        EXPECT_TRUE(ids == Bytes(narrow->GetPolys()->GetConnectivityArray()))
          << "the input's ids changed";
        vtkPolyData* a = fromNarrow->GetOutput();
        vtkPolyData* b = fromWide->GetOutput();
        EXPECT_TRUE(
          Bytes(a->GetPointData()->GetNormals()) == Bytes(b->GetPointData()->GetNormals()));
        EXPECT_TRUE(Bytes(a->GetCellData()->GetNormals()) == Bytes(b->GetCellData()->GetNormals()));
        EXPECT_EQ(FromPolyData(a).Triangles, FromPolyData(b).Triangles);
      }
    }
  }
}

// The face geometry that the normals sum (shadelab::normals::FaceGeometry)
// computes through shadelab::FaceNormal, the project's one face normal; it
// was OpenMesh's vector arithmetic before, written out here: the same bits,
// on triangles of every scale from 1e-300 to 1e200 (where the cross product
// overflows), slivers and triangles of no area.
TEST(MeshNormals, FaceGeometryHasOpenMeshsBits)
{
  using OpenMesh::Vec3d;
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<double> xyz;
  for (const double scale : { 1e-300, 1e-150, 1e-20, 1e-3, 1.0, 1e3, 1e20, 1e150, 1e200 })
  {
    for (int i = 0; i < 3000; ++i)
    {
      xyz.push_back(scale * unit(random));
    }
  }
  const vtkIdType points = static_cast<vtkIdType>(xyz.size() / 3);
  std::vector<shadelab::normals::Id> triangles;
  std::uniform_int_distribution<vtkIdType> point(0, points - 1);
  for (vtkIdType f = 0; f < 3 * points; ++f)
  {
    const vtkIdType a = point(random);
    // Every 10th face repeats a point (no area), every 10th has its third
    // point near its first (a sliver), the others are random.
    const vtkIdType c = f % 10 == 0 ? a : f % 10 == 1 ? (a + 1) % points : point(random);
    for (const vtkIdType id : { a, point(random), c })
    {
      triangles.push_back(static_cast<shadelab::normals::Id>(id));
    }
  }
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int usable = 0;
  for (vtkIdType f = 0; f < static_cast<vtkIdType>(triangles.size() / 3); ++f)
  {
    const auto at = [&](int k)
    {
      const vtkIdType i = triangles[3 * f + k];
      return Vec3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    };
    const Vec3d n = OpenMesh::cross(at(1) - at(0), at(2) - at(0));
    const double length = n.norm();
    const bool ok = length > 0 && std::isfinite(length);
    const Vec3d expected = ok ? n / length : Vec3d(0, 0, 0);
    usable += ok;

    Vec3d got;
    const double doubleArea = shadelab::normals::FaceGeometry(xyz.data(), triangles.data(), f, got);
    ASSERT_TRUE(same(doubleArea, ok ? length : 0)) << "face " << f;
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_TRUE(same(got[k], expected[k])) << "face " << f << " component " << k;
    }
  }
  // Many faces have a normal (not those of no area, nor those with a 1e200
  // or 1e-300 point, whose cross product overflows or underflows): the
  // comparison is not of zeros.
  EXPECT_GT(usable, static_cast<int>(triangles.size() / 3) / 3);
}

TEST(MeshNormals, WeightingNames)
{
  vtkNew<vtkShadelabMeshNormals> filter;
  EXPECT_EQ(filter->GetWeighting(), vtkShadelabMeshNormals::Angle); // the default
  for (int weighting = Weightings - 1; weighting >= 0; --weighting)
  {
    EXPECT_TRUE(filter->SetWeightingByName(WeightingNames[weighting])) << WeightingNames[weighting];
    EXPECT_EQ(filter->GetWeighting(), weighting) << WeightingNames[weighting];
  }
  for (const char* unknown : { "", "cotan", "angles", "uniform " })
  {
    EXPECT_FALSE(filter->SetWeightingByName(unknown)) << "'" << unknown << "'";
  }
}
}

TEST(MeshNormals, AnEmptyInputGivesAnEmptyOutput)
{
  vtkNew<vtkShadelabMeshNormals> filter;
  filter->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  filter->SplittingOn();
  EXPECT_TRUE(filter->GetExecutive()->Update());
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);

  // Triangles without points are bad input, not an empty mesh.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  auto orphans = vtkSmartPointer<vtkPolyData>::New();
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType ids[3] = { 0, 1, 2 };
  polys->InsertNextCell(3, ids);
  orphans->SetPolys(polys);
  filter->SetInputData(orphans);
  const shadelab::MessageScope messages;
  EXPECT_FALSE(filter->GetExecutive()->Update());
  EXPECT_NE(messages.FirstError().find("refers to point 0 of 0"), std::string::npos)
    << messages.FirstError();
}

TEST(MeshNormals, PolygonsAndBadIdsAreOneLineErrors)
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the captured line is enough
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const Vec& p : std::vector<Vec>{ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } })
  {
    points->InsertNextPoint(p.data());
  }
  const std::vector<std::pair<std::vector<vtkIdType>, std::string>> cases = {
    { { 0, 1, 2, 3 }, "polygon 0 has 4 vertices (triangles only)" },
    { { 0, 1, 7 }, "triangle 0 refers to point 7 of 4" },
    { { 0, -1, 2 }, "triangle 0 refers to point -1 of 4" },
  };
  for (const auto& [ids, message] : cases)
  {
    auto mesh = vtkSmartPointer<vtkPolyData>::New();
    mesh->SetPoints(points);
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    mesh->SetPolys(polys);
    vtkNew<vtkShadelabMeshNormals> filter;
    filter->SetInputData(mesh);
    const shadelab::MessageScope messages;
    EXPECT_FALSE(filter->GetExecutive()->Update()) << message;
    EXPECT_NE(messages.FirstError().find(message), std::string::npos) << messages.FirstError();
    EXPECT_EQ(messages.FirstError().find('\n'), std::string::npos) << messages.FirstError();
  }
}

// Triangle soups drawn at random from a few points: repeated and reversed
// faces, three or more faces on an edge, fans touching at a vertex, repeated
// ids and coincident points, all mixed. Every way of running the filter must
// keep every face and give unit or zero normals, nothing NaN, and the
// definitions' sums wherever nothing is split (RunEveryWay); the filter must
// not crash on any of them (the sanitizer build runs this too).
TEST(MeshNormals, RandomTriangleSoupsKeepEveryFaceAndStayFinite)
{
  Random random(2024);
  for (int soup = 0; soup < 60; ++soup)
  {
    SCOPED_TRACE("soup " + std::to_string(soup));
    Mesh mesh;
    const int points = 4 + static_cast<int>(random.Uniform(0, 10));
    for (int i = 0; i < points; ++i)
    {
      // Every fifth point repeats the one before, to make zero-area faces
      // out of distinct ids too.
      mesh.Points.push_back(i % 5 == 4 ? mesh.Points.back() : random.InBall(1));
    }
    const int faces = 1 + static_cast<int>(random.Uniform(0, 3 * points));
    for (int f = 0; f < faces; ++f)
    {
      auto id = [&] { return static_cast<vtkIdType>(random.Uniform(0, points)); };
      mesh.Triangles.push_back({ id(), id(), id() });
    }
    RunEveryWay(mesh, true);
    Options oriented;
    oriented.Consistency = true;
    oriented.Splitting = soup % 2 == 0;
    Compute(mesh, oriented);
  }
}

namespace
{
// A mesh with its points and faces in a random order (the same faces):
// neighbouring faces far apart, so a point's faces lie in every chunk.
Mesh Shuffled(const Mesh& mesh, Random& random)
{
  const auto permutation = [&random](std::size_t count)
  {
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t i = count; i > 1; --i)
    {
      std::swap(order[i - 1], order[static_cast<std::size_t>(random.Uniform(0, i))]);
    }
    return order;
  };
  const std::vector<std::size_t> point = permutation(mesh.Points.size());
  Mesh shuffled;
  shuffled.Points.resize(mesh.Points.size());
  for (std::size_t i = 0; i < point.size(); ++i)
  {
    shuffled.Points[point[i]] = mesh.Points[i];
  }
  for (const std::size_t f : permutation(mesh.Triangles.size()))
  {
    Triangle t = mesh.Triangles[f];
    for (vtkIdType& id : t)
    {
      id = static_cast<vtkIdType>(point[static_cast<std::size_t>(id)]);
    }
    shuffled.Triangles.push_back(t);
  }
  return shuffled;
}
}

// The sums of the vertex normals are split into chunks of faces summed on
// the cores at once (SumChunks); each point must still receive its terms in
// the faces' order, so every chunk count must give the very bits of one
// chunk (the sum as on one core): point and cell normals compared byte for
// byte, for every weighting, with and without splitting, consistent
// orientation and cell normals, on spot (its file vertices welded or not)
// and on copies of it that defer many terms to the chunks' end: shuffled
// points and faces, every face twice (each point in the first and the
// second half) with faces of no area among them. A real mesh: the float
// normals of a regular synthetic one rarely show the order of the double
// sums, spot's do (each breakage of the order fails here).
TEST(MeshNormals, EveryChunkCountGivesTheBitsOfOneChunk)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((TestMeshes / "teapot.obj").c_str());
  reader->SetReadNormals(false);
  ASSERT_TRUE(reader->GetExecutive()->Update());
  const Mesh spot = FromPolyData(reader->GetOutput());
  Random random(77);
  Mesh shuffled = Shuffled(spot, random);
  for (std::size_t f = 0; f < shuffled.Triangles.size(); f += 5)
  {
    std::swap(shuffled.Triangles[f][1], shuffled.Triangles[f][2]); // for Consistency to reverse
  }
  Mesh twice = spot;
  twice.Triangles.insert(twice.Triangles.end(), spot.Triangles.begin(), spot.Triangles.end());
  for (std::size_t f = 0; f < twice.Triangles.size(); f += 97)
  {
    const Triangle& t = twice.Triangles[f];
    twice.Triangles.insert(twice.Triangles.begin() + static_cast<std::ptrdiff_t>(f) + 1,
      { { t[0], t[1], t[1] }, { t[2], t[0], t[2] } }); // no area: a repeated vertex
  }
  const std::vector<std::pair<std::string, vtkSmartPointer<vtkPolyData>>> inputs = {
    { "spot, file vertices welded", reader->GetOutput() }, { "spot", ToPolyData(spot) },
    { "spot shuffled", ToPolyData(shuffled) },
    { "spot, every face twice, faces of no area", ToPolyData(twice) }
  };

  for (const auto& [name, input] : inputs)
  {
    for (int configuration = 0; configuration < 8 * Weightings; ++configuration)
    {
      const int weighting = configuration % Weightings;
      const bool splitting = configuration / Weightings % 2;
      const bool consistency = configuration / Weightings / 2 % 2;
      const bool cellNormals = configuration / Weightings / 4 % 2 == 0;
      SCOPED_TRACE(name + ", " + WeightingNames[weighting] + (splitting ? ", split" : "") +
        (consistency ? ", oriented" : "") + (cellNormals ? "" : ", no cell normals"));
      std::vector<unsigned char> points, cells;
      for (const int chunks : { 1, 2, 3, 7, 64, 0 })
      {
        SCOPED_TRACE(std::to_string(chunks) + " chunks");
        vtkNew<vtkShadelabMeshNormals> filter;
        filter->SetInputData(input);
        filter->SetWeighting(weighting);
        filter->SetSplitting(splitting);
        filter->SetConsistency(consistency);
        filter->SetComputeCellNormals(cellNormals);
        filter->SetSumChunks(chunks);
        ASSERT_TRUE(filter->GetExecutive()->Update());
        vtkPolyData* output = filter->GetOutput();
        if (chunks == 1)
        {
          points = Bytes(output->GetPointData()->GetNormals());
          cells = cellNormals ? Bytes(output->GetCellData()->GetNormals()) : cells;
          continue;
        }
        const std::vector<unsigned char> chunkPoints = Bytes(output->GetPointData()->GetNormals());
        ASSERT_EQ(chunkPoints.size(), points.size());
        EXPECT_EQ(std::memcmp(chunkPoints.data(), points.data(), points.size()), 0)
          << "point normals differ";
        if (cellNormals)
        {
          const std::vector<unsigned char> chunkCells = Bytes(output->GetCellData()->GetNormals());
          ASSERT_EQ(chunkCells.size(), cells.size());
          EXPECT_EQ(std::memcmp(chunkCells.data(), cells.data(), cells.size()), 0)
            << "cell normals differ";
        }
      }
    }
  }
}

// A float input's points are converted to the filter's double copy on the
// cores: the normals are the very bits of the same values given as double.
TEST(MeshNormals, FloatPointsGiveTheBitsOfTheirValuesInDouble)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((TestMeshes / "teapot.obj").c_str());
  reader->SetReadNormals(false);
  ASSERT_TRUE(reader->GetExecutive()->Update());
  vtkSmartPointer<vtkPolyData> floats = ToPolyData(FromPolyData(reader->GetOutput()));
  vtkNew<vtkPoints> floatPoints;
  floatPoints->SetDataTypeToFloat();
  floatPoints->DeepCopy(floats->GetPoints());
  floats->SetPoints(floatPoints);
  vtkSmartPointer<vtkPolyData> doubles = ToPolyData(FromPolyData(floats)); // the float values
  ASSERT_EQ(doubles->GetPoints()->GetDataType(), VTK_DOUBLE);
  ASSERT_EQ(floats->GetPoints()->GetDataType(), VTK_FLOAT);
  for (int weighting = 0; weighting < Weightings; ++weighting)
  {
    SCOPED_TRACE(WeightingNames[weighting]);
    std::vector<unsigned char> normals[2];
    for (int i = 0; i < 2; ++i)
    {
      vtkNew<vtkShadelabMeshNormals> filter;
      filter->SetInputData(i == 0 ? floats : doubles);
      filter->SetWeighting(weighting);
      ASSERT_TRUE(filter->GetExecutive()->Update());
      normals[i] = Bytes(filter->GetOutput()->GetPointData()->GetNormals());
    }
    ASSERT_FALSE(normals[0].empty());
    EXPECT_TRUE(normals[0] == normals[1]) << "point normals differ";
  }
}
