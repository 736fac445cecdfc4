// The OFF reader: the real file in tests/data/meshes, small files of each
// form written here (headers, prefixes, colours, normals, texture
// coordinates, polygons), and bad input of every kind.
#include "mesh_reader_fixture.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabOFFReader.h"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace
{
using namespace shadelab::test;

// The unit square's corners, counter-clockwise seen from +z.
const std::string SquareVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

double TotalArea(vtkPolyData* mesh)
{
  double area = 0;
  for (const auto& triangle : Triangles(mesh))
  {
    const auto n = AreaNormal(mesh, triangle);
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

void ExpectAllFacePlusZ(vtkPolyData* mesh)
{
  for (const auto& triangle : Triangles(mesh))
  {
    EXPECT_GT(AreaNormal(mesh, triangle)[2], 0.0);
  }
}

std::array<double, 4> Tuple4(vtkDataArray* array, vtkIdType i)
{
  std::array<double, 4> tuple{};
  array->GetTuple(i, tuple.data());
  return tuple;
}

TEST_F(MeshReaders, AnOffKeepsTheFilesVerticesAndFaces)
{
  const fs::path path = TestMeshes / "teapot.off";
  std::ifstream in(path);
  std::string keyword;
  std::size_t vertices = 0, faces = 0, edges = 0;
  in >> keyword >> vertices >> faces >> edges;
  double first[3];
  in >> first[0] >> first[1] >> first[2];

  const ReadResult result = Read(path);
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(keyword, "OFF");
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), static_cast<vtkIdType>(vertices));
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), static_cast<vtkIdType>(faces));
  double p[3];
  result.Mesh->GetPoint(0, p);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_EQ(p[k], first[k]); // the same decimal, parsed the same way
  }
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
}

TEST_F(MeshReaders, OffHeaderCountsOnTheirOwnLineOrTheKeywordsWithCommentsAndBlankLines)
{
  const std::string face = "4 0 1 2 3\n";
  for (const std::string& text : std::vector<std::string>{
         "OFF\n4 1 0\n" + SquareVertices + face, "OFF 4 1 0\n" + SquareVertices + face,
         "OFF 4 1\n" + SquareVertices + face,  // no edge count
         "OFF4 1 0\n" + SquareVertices + face, // ModelNet's glued count
         "# written by hand\n\nOFF # keyword\n\n# counts:\n4 1 0\n0 0 0\n1 0 0 # x\n\n1 1 0\n"
         "0 1 0\n# the face\n4 0 1 2 3 # a quad\n\n# end\n",
         "OFF\r\n4 1 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n4 0 1 2 3\r\n", // CRLF
         "OFF\n4 1 0\n" + SquareVertices + "4 0 1 2 3",                       // no final newline
       })
  {
    SCOPED_TRACE(text);
    const ReadResult result = Read(this->Write("square.off", text));
    ASSERT_TRUE(result.Ok) << result.Error;
    ExpectTriangleMesh(result.Mesh);
    EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 4);
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 2);
    EXPECT_NEAR(TotalArea(result.Mesh), 1.0, 1e-12);
    ExpectAllFacePlusZ(result.Mesh);
  }
}

TEST_F(MeshReaders, OffConcavePolygonIsTriangulatedInsideItsOutline)
{
  // An L of area 3: a fan from vertex 0 would cover the notch (area 4 - 1
  // counted twice would show as a total above 3).
  const ReadResult result = Read(
    this->Write("l.off", "OFF\n6 1 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 2 3 4 5 0 1\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 4);
  EXPECT_NEAR(TotalArea(result.Mesh), 3.0, 1e-12);
  ExpectAllFacePlusZ(result.Mesh);
}

TEST_F(MeshReaders, OffFaceColoursAreIgnored)
{
  const ReadResult result = Read(this->Write("faces.off",
    "OFF\n4 4 0\n" + SquareVertices +
      "3 0 1 2 255 0 0\n3 0 2 3 0.5 0.5 0.5 1\n3 0 1 2 7\n3 0 2 3 1 1 1 1\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 4);
  EXPECT_EQ(result.Mesh->GetPointData()->GetNumberOfArrays(), 0);
}

TEST_F(MeshReaders, CoffIntegerColoursAreScaledFrom255AndFloatColoursKept)
{
  // Integers: 0..255; RGB without alpha is opaque.
  ReadResult result = Read(this->Write(
    "int.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 51 0 128\n0 1 0 0 0 255 255\n3 0 1 2\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  vtkDataArray* colors = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(Tuple4(colors, 0), (std::array<double, 4>{ 1, 0, 0, 1 }));
  EXPECT_NEAR(Tuple4(colors, 1)[1], 0.2, 1e-7);
  EXPECT_NEAR(Tuple4(colors, 1)[3], 128.0 / 255, 1e-7);
  EXPECT_EQ(Tuple4(colors, 2), (std::array<double, 4>{ 0, 0, 1, 1 }));

  // One value written as a fraction makes the file's colours 0..1, even
  // those written as integers.
  result = Read(this->Write(
    "float.off", "COFF\n3 1 0\n0 0 0 1 0 0\n1 0 0 0 0.25 0\n0 1 0 0 0 1 0.5\n3 0 1 2\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  colors = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(Tuple4(colors, 0), (std::array<double, 4>{ 1, 0, 0, 1 }));
  EXPECT_EQ(Tuple4(colors, 1), (std::array<double, 4>{ 0, 0.25, 0, 1 }));
  EXPECT_EQ(Tuple4(colors, 2), (std::array<double, 4>{ 0, 0, 1, 0.5 }));
}

TEST_F(MeshReaders, OffPrefixesGiveNormalsColoursAndTextureCoordinatesInGeomviewsOrder)
{
  // x y z, nx ny nz, r g b a, s t; the prefixes in either order.
  for (const std::string& keyword : { std::string("STCNOFF"), std::string("NCSTOFF") })
  {
    SCOPED_TRACE(keyword);
    const ReadResult result = Read(this->Write("all.off",
      keyword +
        "\n3 1 0\n0 0 0 0 0 1 255 0 0 255 0 0\n1 0 0 0 0.6 0.8 0 255 0 255 1 0\n"
        "0 1 0 0 0 1 0 0 255 255 0 1\n3 0 1 2\n"));
    ASSERT_TRUE(result.Ok) << result.Error;
    ExpectTriangleMesh(result.Mesh);
    vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
    vtkDataArray* colors = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
    vtkDataArray* uv = result.Mesh->GetPointData()->GetTCoords();
    ASSERT_TRUE(normals && colors && uv);
    EXPECT_STREQ(uv->GetName(), shadelab::TextureCoordinatesArrayName);
    EXPECT_NEAR(normals->GetComponent(1, 1), 0.6, 1e-7);
    EXPECT_EQ(Tuple4(colors, 1), (std::array<double, 4>{ 0, 1, 0, 1 }));
    EXPECT_EQ(uv->GetComponent(1, 0), 1.0);
    EXPECT_EQ(uv->GetComponent(2, 1), 1.0);
  }

  vtkNew<vtkShadelabOFFReader> reader;
  reader->ReadNormalsOff();
  const ReadResult result = ReadWith(
    reader, this->Write("n.off", "NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
}

TEST_F(MeshReaders, BadOffHeaders)
{
  const std::string body = SquareVertices + "4 0 1 2 3\n";
  this->ExpectError("empty.off", "", { "not an OFF file", "no keyword" });
  this->ExpectError("comments.off", "# nothing\n\n", { "not an OFF file" });
  this->ExpectError("ply.off", "ply\nformat ascii 1.0\n", { "not an OFF file", "'ply'" });
  this->ExpectError("prefix.off", "XOFF\n4 1 0\n" + body, { "line 1", "unknown keyword 'XOFF'" });
  this->ExpectError("twice.off", "CCOFF\n4 1 0\n" + body, { "line 1", "repeats C" });
  this->ExpectError(
    "4d.off", "4OFF\n4 1 0\n" + body, { "line 1", "4D vertices are not supported" });
  this->ExpectError("nd.off", "nOFF\n3\n4 1 0\n" + body, { "nD vertices are not supported" });
  this->ExpectError("binary.off", "OFF BINARY\n", { "line 1", "binary OFF is not supported" });
  this->ExpectError("glued.off", "OFF4x 1 0\n" + body, { "unknown keyword 'OFF4x'" });
  this->ExpectError("nocounts.off", "OFF\n", { "truncated", "before the vertex and face counts" });
  this->ExpectError("onecount.off", "OFF\n4\n" + body, { "line 2", "missing face count" });
  this->ExpectError(
    "negative.off", "OFF\n-4 1 0\n" + body, { "line 2", "malformed vertex count '-4'" });
  this->ExpectError("word.off", "OFF\n4 one 0\n" + body, { "malformed face count 'one'" });
  this->ExpectError("edges.off", "OFF\n4 1 x\n" + body, { "malformed edge count 'x'" });
  this->ExpectError(
    "extra.off", "OFF\n4 1 0 9\n" + body, { "line 2", "unexpected '9' after the counts" });
  // Counts that a file of this size could not hold fail before anything is allocated.
  this->ExpectError("huge.off", "OFF\n4000000000000 1 0\n" + body,
    { "header declares 4000000000000 vertices and 1 faces, more than a", "-byte file can hold" });
  this->ExpectError(
    "hugefaces.off", "OFF\n4 9223372036854775807 0\n" + body, { "9223372036854775807 faces" });
}

TEST_F(MeshReaders, BadOffBodies)
{
  const std::string header = "OFF\n4 1 0\n";
  // The header lies: fewer or more vertices or faces than it says.
  this->ExpectError("fewfaces.off", "OFF\n4 2 0\n" + SquareVertices + "3 0 1 2\n",
    { "truncated: the header declares 2 faces but the file ends after 1" });
  this->ExpectError("fewvertices.off", "OFF\n5 0 0\n" + SquareVertices,
    { "truncated: the header declares 5 vertices but the file ends after 4" });
  this->ExpectError("morefaces.off", header + SquareVertices + "3 0 1 2\n3 0 2 3\n",
    { "line 8: more than the 1 faces the header declares" });
  this->ExpectError("morevertices.off", header + SquareVertices + "0.5 0.5 0\n3 0 1 2\n",
    { "line 7", "malformed face 0's vertex count '0.5'" });
  this->ExpectError("lessvertices.off", "OFF\n5 1 0\n" + SquareVertices + "3 0 1 2\n",
    { "line 7: vertex 4 has 4 values, not x y z" });
  // Faces.
  this->ExpectError("range.off", header + SquareVertices + "3 0 1 4\n",
    { "line 7: face 0 refers to vertex 4, but only 4 vertices are defined" });
  this->ExpectError(
    "negidx.off", header + SquareVertices + "3 0 -1 2\n", { "refers to vertex -1" });
  this->ExpectError("two.off", header + SquareVertices + "2 0 1\n",
    { "line 7: face 0 has 2 vertices, at least 3 are needed" });
  this->ExpectError("short.off", header + SquareVertices + "4 0 1 2\n",
    { "line 7: face 0 ends after 3 of its 4 vertex indices" });
  this->ExpectError("index.off", header + SquareVertices + "3 0 1 2.0\n",
    { "malformed vertex index '2.0' in face 0" });
  this->ExpectError("facecolour.off", header + SquareVertices + "3 0 1 2 1 1\n",
    { "face 0 has 2 values after its vertex indices; a face colour has 1, 3 or 4" });
  this->ExpectError(
    "facecolour5.off", header + SquareVertices + "3 0 1 2 1 1 1 1 1\n", { "has 5 values" });
  this->ExpectError(
    "facered.off", header + SquareVertices + "3 0 1 2 red\n", { "malformed colour value 'red'" });
  // Vertices.
  this->ExpectError("nan.off", header + "0 0 0\n1 nan 0\n1 1 0\n0 1 0\n3 0 1 2\n",
    { "line 4: NaN value 'nan' in vertex 1" });
  this->ExpectError("inf.off", header + "0 0 0\n1 0 0\n1 1 -inf\n0 1 0\n3 0 1 2\n",
    { "line 5: infinite value '-inf' in vertex 2" });
  this->ExpectError("normalnan.off",
    "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 NaN 1\n0 1 0 0 0 1\n3 0 1 2\n",
    { "line 4", "NaN value 'NaN' in vertex 1" });
  this->ExpectError("comma.off", header + "0 0 0\n1 0,5 0\n1 1 0\n0 1 0\n3 0 1 2\n",
    { "line 4: malformed number '0,5' in vertex 1" });
  this->ExpectError("values.off", header + "0 0 0\n1 0 5 0\n1 1 0\n0 1 0\n3 0 1 2\n",
    { "line 4: vertex 1 has 4 values, not x y z" });
  this->ExpectError("nonormal.off", "NOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    { "line 3: vertex 0 has 3 values, not x y z nx ny nz" });
  this->ExpectError("nocolour.off", "COFF\n3 1 0\n0 0 0 1 0\n1 0 0\n0 1 0\n3 0 1 2\n",
    { "vertex 0 has 5 values, not x y z r g b [a]" });
  this->ExpectError("255.off", "COFF\n3 1 0\n0 0 0 255 0 0\n1 0 0 0 256 0\n0 1 0 0 0 0\n3 0 1 2\n",
    { "colour of vertex 1 has 256, outside 0..255 (the file writes its colours as integers)" });
  this->ExpectError("fraction.off",
    "COFF\n3 1 0\n0 0 0 0.5 0 0\n1 0 0 0 2 0\n0 1 0 0 0 0\n3 0 1 2\n",
    { "colour of vertex 1 has 2, outside 0..1 (the file writes its colours as fractions)" });
  this->ExpectError("negcolour.off",
    "COFF\n3 1 0\n0 0 0 0 0 0 -1\n1 0 0 0 0 0\n0 1 0 0 0 0\n3 0 1 2\n",
    { "colour of vertex 0 has -1" });
  // Nothing to draw.
  this->ExpectError("nofaces.off", "OFF\n4 0 0\n" + SquareVertices, { "no triangles" });
  this->ExpectError("nothing.off", "OFF\n0 0 0\n", { "no triangles" });
}
}
