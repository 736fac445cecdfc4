// Numerical stability at the extremes: pictures and normals where
// float arithmetic is pushed hardest, each against the double-precision
// oracle with a stated bound, and never a NaN or an Inf.
//
// Pictures: oracle_scene.h's planar scenes rendered by `shadelab render`,
// compared pixel by pixel with the oracle (its tolerances and their reasons
// are there): slivers, faces of no area and nearly coincident vertices with
// normals computed by shadelab, coordinates around 1e-8 and 1e8 and offset by 1e6, light within
// 1e-6 of the surface's plane, distance attenuation at those scales and with coefficients of 1e-6
// and 1e6, shininess from 1e-3 to 1e6.
// Normals: vtkShadelabMeshNormals on meshes built in double against the
// same weighting's sums taken in long double.
#include "oracle_scene.h"
#include "shadelabAnalyticSurface.h"
#include "vtkShadelabMeshNormals.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace shadelab_test;

namespace
{
// ---------------------------------------------------------------- pictures

std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);

  // Slivers of aspect ratio 1e6, faces of no area (repeated vertices,
  // collinear ones) and nearly coincident vertices (1e-12 apart) in a plane, normals computed by
  // shadelab with each weighting: every vertex normal must come out as the plane's, so the picture
  // is the plane's (the oracle lights it with the plane's normal).
  for (Shading r : LitRules)
  {
    for (const char* weighting : { "uniform", "area", "angle", "max", "loop" })
    {
      if (r == Shading::Flat && std::string(weighting) != "angle")
      {
        continue; // flat lights with face normals, whatever the weighting
      }
      Scene s;
      s.Rule = r;
      s.Geometry.Bump = 0;
      s.Geometry.Slivers = true;
      s.Geometry.Degenerate = true;
      s.Normals = "compute";
      s.Weighting = weighting;
      add("slivers_degenerate_" + std::string(ToString(r)) + "_" + weighting, s);
    }
  }

  // The bowl at 1e-8 and 1e8 and offset by 1e6 lights as at unit scale.
  // The grid's coordinates are multiples of 1/16, so float holds them at
  // 1e6 (ulp 1/16) and at 1e8 (multiples of 6.25e6, ulp 8) exactly.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Scale = 1e-8;
    add("scale_1em8_" + std::string(ToString(r)), s);
    s.Scale = 1e8;
    add("scale_1e8_" + std::string(ToString(r)), s);
    s.Scale = 1;
    s.Offset = { 1e6, -1e6, 1e6 };
    add("offset_1e6_" + std::string(ToString(r)), s);
  }

  // Light within 1e-6 of the surface's plane: a directional light with
  // N.L = 1e-6, and a point light 1e-6 above the plane beside the mesh. The
  // lecture's case N.L <= 0 decides (the oracle takes N.L <= 1e-5 as 0, so
  // that float rounding of N.L cannot flip it); ambient only, no NaN.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Geometry.SlopeX = s.Geometry.SlopeY = s.Geometry.Bump = 0;
    s.Lights = { Directional({ -std::sqrt(1 - 1e-12), 0, -1e-6 }) };
    add("grazing_directional_1em6_" + std::string(ToString(r)), s);
    s.Lights = { Point({ -3, 0.5, 1e-6 }) };
    add("grazing_point_1em6_" + std::string(ToString(r)), s);
  }

  // Distance attenuation at the extremes: the bowl at 1e-8 and 1e8 under a
  // light that falls off with d^2 only, its coefficient scaled alike (d^2
  // of 1e-16 and 1e16 in float); and coefficients that make the light a
  // million times as bright (C0 = 1e-6) and a millionth as bright (C2 = 1e6).
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Attenuation = { 0, 0, 1 };
    s.Scale = 1e-8;
    add("attenuation_quadratic_1em8_" + std::string(ToString(r)), s);
    s.Scale = 1e8;
    add("attenuation_quadratic_1e8_" + std::string(ToString(r)), s);
    s.Scale = 1;
    s.Attenuation = { 1e-6, 0, 0 };
    add("attenuation_c0_1em6_" + std::string(ToString(r)), s);
    s.Attenuation = { 0, 0, 1e6 };
    add("attenuation_c2_1e6_" + std::string(ToString(r)), s);
  }

  // Shininess from 1e-3 to 1e6, per fragment (phong) with both reflection
  // models, on the bowl under a point light close above it, so that every
  // exponent has a highlight in view. ns = 1e6 takes the looser bound
  // oracle_scene.h gives for it (HighExponent).
  const std::vector<std::pair<double, const char*>> exponents{ { 1e-3, "1em3" }, { 1e-1, "0p1" },
    { 1, "1" }, { 1e1, "10" }, { 1e2, "100" }, { 1e3, "1e3" }, { 1e4, "1e4" }, { 1e5, "1e5" },
    { 1e6, "1e6" } };
  for (const auto& [ns, label] : exponents)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = Shading::Phong;
      s.Model = m;
      s.Surface = TestMaterial(ns);
      s.Lights = { Point({ 0.2, -0.1, 0.8 }) };
      add(std::string("ns_") + label + "_" + ToString(m), s, ns >= 1e6 ? HighExponent : Standard);
    }
  }
  return cases;
}

class Extremes : public testing::TestWithParam<Case>
{
};

// ---------------------------------------------------------------- normals

using Triangle = std::array<vtkIdType, 3>;

vtkSmartPointer<vtkPolyData> MakeMesh(
  const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  auto xyz = vtkSmartPointer<vtkPoints>::New();
  xyz->SetDataTypeToDouble();
  for (const Vec3& p : points)
  {
    xyz->InsertNextPoint(p.data());
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const Triangle& t : triangles)
  {
    cells->InsertNextCell(3, t.data());
  }
  mesh->SetPoints(xyz);
  mesh->SetPolys(cells);
  return mesh;
}

// The angle-weighted vertex normals of doc/design.md in long double: the sum
// over a vertex's faces of the face's angle there times its unit normal,
// normalised; faces of no area add nothing.
std::vector<Vec3> AngleWeightedOracle(
  const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  using L3 = std::array<long double, 3>;
  auto sub = [](const Vec3& a, const Vec3& b)
  {
    return L3{ static_cast<long double>(a[0]) - b[0], static_cast<long double>(a[1]) - b[1],
      static_cast<long double>(a[2]) - b[2] };
  };
  auto dotL = [](const L3& a, const L3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto crossL = [](const L3& a, const L3& b) {
    return L3{ a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
  };
  std::vector<L3> sums(points.size(), L3{ 0, 0, 0 });
  for (const Triangle& t : triangles)
  {
    const L3 n = crossL(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]));
    const long double length = std::sqrt(dotL(n, n));
    if (length == 0)
    {
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      const L3 a = sub(points[t[(k + 1) % 3]], points[t[k]]);
      const L3 b = sub(points[t[(k + 2) % 3]], points[t[k]]);
      const long double angle = std::atan2(std::sqrt(dotL(crossL(a, b), crossL(a, b))), dotL(a, b));
      for (int c = 0; c < 3; ++c)
      {
        sums[t[k]][c] += angle * n[c] / length;
      }
    }
  }
  std::vector<Vec3> normals;
  for (const L3& s : sums)
  {
    const long double length = std::sqrt(dotL(s, s));
    normals.push_back(length > 0
        ? Vec3{ static_cast<double>(s[0] / length), static_cast<double>(s[1] / length),
            static_cast<double>(s[2] / length) }
        : Vec3{ 0, 0, 0 });
  }
  return normals;
}

// The largest |filter - oracle| over the vertices' normal components.
double NormalsDeviation(
  const std::vector<Vec3>& points, const std::vector<Triangle>& triangles, bool& allFinite)
{
  auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  filter->SetInputData(MakeMesh(points, triangles));
  filter->SetWeighting(vtkShadelabMeshNormals::Angle);
  filter->Update();
  vtkDataArray* normals = filter->GetOutput()->GetPointData()->GetNormals();
  const std::vector<Vec3> expected = AngleWeightedOracle(points, triangles);
  double worst = 0;
  allFinite = normals && normals->GetNumberOfTuples() == static_cast<vtkIdType>(points.size());
  for (vtkIdType p = 0; allFinite && p < normals->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = normals->GetComponent(p, c);
      allFinite = allFinite && std::isfinite(v);
      worst = std::max(worst, std::abs(v - expected[p][c]));
    }
  }
  return worst;
}

// A level-2 icosphere (320 triangles) through p -> scale * p + offset.
void Sphere(
  double scale, const Vec3& offset, std::vector<Vec3>& points, std::vector<Triangle>& triangles)
{
  auto mesh = shadelab::AnalyticSurface(shadelab::AnalyticSurface::Kind::Sphere).Tessellate(1);
  points.clear();
  triangles.clear();
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    Vec3 x;
    mesh->GetPoint(p, x.data());
    points.push_back(offset + scale * x);
  }
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    triangles.push_back({ ids->GetId(0), ids->GetId(1), ids->GetId(2) });
  }
}

// The filter stores normals as float: each component within half an ulp of
// 1 (6e-8) of its double value. Its double sums differ from long double's by
// a few ulps of double (1e-16) times the condition of the normalisation,
// which stays far below that for every mesh here. 2e-7 is that float
// rounding with room; a weighting gone wrong at an extreme (a sliver's
// normal from cancelling differences, a cancellation at 1e8) is off by
// 1e-3 or more.
constexpr double NormalsBound = 2e-7;
}

TEST_P(Extremes, PictureMatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Pictures, Extremes, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

TEST(ExtremeNormals, ScaledAndOffsetSpheresMatchTheLongDoubleOracle)
{
  for (const double scale : { 1e-8, 1.0, 1e8 })
  {
    for (const Vec3& offset : { Vec3{ 0, 0, 0 }, Vec3{ 1e6, -1e6, 1e6 } })
    {
      std::vector<Vec3> points;
      std::vector<Triangle> triangles;
      Sphere(scale, scale * offset, points, triangles);
      bool finite = false;
      const double deviation = NormalsDeviation(points, triangles, finite);
      std::cout << "[extremes] normals: sphere at scale " << scale << ", offset "
                << scale * offset[0] << ": max deviation " << deviation << std::endl;
      EXPECT_TRUE(finite);
      EXPECT_LE(deviation, NormalsBound) << "scale " << scale << ", offset " << offset[0];
    }
  }
}

TEST(ExtremeNormals, SliversNearTwinsAndZeroAreaFacesMatchTheLongDoubleOracle)
{
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  Sphere(1, { 0, 0, 0 }, points, triangles);
  std::vector<Triangle> extreme;
  for (const Triangle& t : triangles)
  {
    const Vec3 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    const Vec3 middle = 0.5 * (a + b);
    // A sliver of aspect ratio 1e6: m 1e-6 of the way from the edge's middle to c.
    points.push_back(middle + 1e-6 * (c - middle));
    const vtkIdType m = static_cast<vtkIdType>(points.size() - 1);
    extreme.push_back({ t[0], t[1], m });
    extreme.push_back({ t[1], t[2], m });
    extreme.push_back({ t[2], t[0], m });
    // A near twin of a, 1e-12 away along the edge to b, in a triangle of
    // its own with a and c: nearly coincident vertices.
    points.push_back(a + 1e-12 * (b - a));
    extreme.push_back({ t[0], static_cast<vtkIdType>(points.size() - 1), t[2] });
    // No area: a repeated vertex.
    extreme.push_back({ t[0], t[0], t[1] });
  }
  bool finite = false;
  const double deviation = NormalsDeviation(points, extreme, finite);
  std::cout << "[extremes] normals: slivers, near twins, zero-area faces: max deviation "
            << deviation << std::endl;
  EXPECT_TRUE(finite);
  EXPECT_LE(deviation, NormalsBound);
}
