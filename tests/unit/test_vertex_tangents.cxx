// The tangents a normal map is read in the frame of (shadelabVertexTangents.h):
// along dP/ds, with the handedness of the texture's mapping, and one
// tangent for the copies of a point that only its texture coordinates
// split, so that a seam shows no crease.
#include "shadelabTriangleMesh.h"
#include "shadelabVec3.h"
#include "shadelabVertexTangents.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using shadelab::Vec3;
using namespace shadelab::vec3;

namespace
{
struct Vertex
{
  Vec3 P;
  double S, T;
  Vec3 N{ 0, 0, 0 }; // none where all are zero
};

vtkSmartPointer<vtkPolyData> MeshOf(
  const std::vector<Vertex>& vertices, const std::vector<std::array<vtkIdType, 3>>& triangles)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto st = vtkSmartPointer<vtkFloatArray>::New();
  st->SetName(shadelab::TextureCoordinatesArrayName);
  st->SetNumberOfComponents(2);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetNumberOfComponents(3);
  bool anyNormal = false;
  for (const Vertex& v : vertices)
  {
    points->InsertNextPoint(v.P.data());
    st->InsertNextTuple2(v.S, v.T);
    normals->InsertNextTuple(v.N.data());
    anyNormal = anyNormal || length(v.N) > 0;
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& t : triangles)
  {
    polys->InsertNextCell(3, t.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->AddArray(st);
  if (anyNormal)
  {
    mesh->GetPointData()->SetNormals(normals);
  }
  return mesh;
}

std::array<double, 4> TangentOf(vtkFloatArray* tangents, vtkIdType p)
{
  std::array<double, 4> t{};
  tangents->GetTuple(p, t.data());
  return t;
}
}

// On a slanted plane the tangent is dP/ds, unit, of handedness +1; with s
// running the other way (a mirrored texture) it turns round with it and
// its handedness is -1, since (n x T).B turns over.
TEST(VertexTangents, AreDPDsWithTheMappingsHandedness)
{
  for (double sign : { 1.0, -1.0 })
  {
    SCOPED_TRACE(sign);
    const auto mesh = MeshOf({ { { 0, 0, 0 }, 0, 0 }, { { 2, 0, 1 }, sign, 0 },
                               { { 2, 1, 1 }, sign, 1 }, { { 0, 1, 0 }, 0, 1 } },
      { { 0, 1, 2 }, { 0, 2, 3 } });
    const auto tangents = shadelab::VertexTangents(mesh);
    ASSERT_EQ(tangents->GetNumberOfTuples(), 4);
    ASSERT_EQ(tangents->GetNumberOfComponents(), 4);
    EXPECT_STREQ(tangents->GetName(), shadelab::TangentsArrayName);
    const Vec3 expected = sign * normalize(Vec3{ 2, 0, 1 });
    for (vtkIdType p = 0; p < 4; ++p)
    {
      const auto t = TangentOf(tangents, p);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(t[c], expected[c], 1e-7) << p;
      }
      EXPECT_EQ(t[3], sign) << p;
    }
  }
}

// A cylinder of 8 facets whose texture wraps once around: the points at
// s = 0 and s = 1 lie on one another with one normal, split only by s.
// Each copy's triangles turn the other way, so their own sums would lean
// apart; both get the sum over all of them, the circle's tangent there.
TEST(VertexTangents, FollowTheWeldedPointsAcrossASeam)
{
  constexpr int Facets = 8;
  constexpr double Pi = 3.14159265358979323846;
  std::vector<Vertex> vertices;
  for (int i = 0; i <= Facets; ++i)
  {
    const double a = 2 * Pi * (i % Facets) / Facets;
    const Vec3 n{ std::cos(a), std::sin(a), 0 };
    for (int j = 0; j < 2; ++j)
    {
      vertices.push_back(
        { { n[0], n[1], static_cast<double>(j) }, double(i) / Facets, static_cast<double>(j), n });
    }
  }
  std::vector<std::array<vtkIdType, 3>> triangles;
  for (vtkIdType i = 0; i < Facets; ++i)
  {
    const vtkIdType a = 2 * i, b = a + 2;
    triangles.push_back({ a, b, b + 1 });
    triangles.push_back({ a, b + 1, a + 1 });
  }
  const auto tangents = shadelab::VertexTangents(MeshOf(vertices, triangles));
  for (vtkIdType j = 0; j < 2; ++j)
  {
    const auto first = TangentOf(tangents, j), last = TangentOf(tangents, 2 * Facets + j);
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_EQ(first[c], last[c]) << c;
    }
    // The circle's tangent at angle 0, (0, 1, 0), as at every other point
    // its own (symmetric neighbours).
    EXPECT_NEAR(first[0], 0, 1e-7);
    EXPECT_NEAR(first[1], 1, 1e-7);
    EXPECT_NEAR(first[2], 0, 1e-7);
    EXPECT_EQ(first[3], 1);
  }
}

// Texture coordinates that span no area give no tangent: (0, 0, 0, 1),
// which leaves the normal as it is.
TEST(VertexTangents, NoneWhereTheTextureSpansNoArea)
{
  const auto tangents = shadelab::VertexTangents(
    MeshOf({ { { 0, 0, 0 }, 0.5, 0.5 }, { { 1, 0, 0 }, 0.5, 0.5 }, { { 0, 1, 0 }, 0.5, 0.5 } },
      { { 0, 1, 2 } }));
  for (vtkIdType p = 0; p < 3; ++p)
  {
    const auto t = TangentOf(tangents, p);
    EXPECT_EQ(t, (std::array<double, 4>{ 0, 0, 0, 1 })) << p;
  }
}
