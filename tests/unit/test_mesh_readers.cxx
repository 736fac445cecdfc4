// The mesh readers: every test mesh (tests/data/meshes), small hand-made files of each format
// and form, and bad input of every kind (one-line error, no partial mesh).
#include "mesh_reader_fixture.h"
#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPLYReader.h"

#include <vtkByteSwap.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkLogger.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace shadelab::test;

// A file's lines that start with `keyword`, counted by their number of tokens.
std::vector<std::size_t> StatementSizes(const fs::path& path, const std::string& keyword)
{
  std::ifstream in(path);
  std::vector<std::size_t> sizes;
  std::string line, word;
  while (std::getline(in, line))
  {
    std::istringstream tokens(line);
    if (tokens >> word && word == keyword)
    {
      std::size_t count = 0;
      while (tokens >> word)
      {
        ++count;
      }
      sizes.push_back(count);
    }
  }
  return sizes;
}

// ---------------------------------------------------------------------------
// A file's bytes

// Every size, the sizes around the growth step included, reads back whole;
// a file of the size it says is held in that size (not a buffer grown on
// spec to twice it, which stayed resident); a file that says no size
// (/proc's) is read on to its end.
TEST_F(MeshReaders, FileBytesAreTheFileInItsOwnSize)
{
  for (std::size_t size : { 0, 1, 65535, 65536, 65537, 1 << 20 })
  {
    std::string bytes(size, '\0');
    for (std::size_t i = 0; i < size; ++i)
    {
      bytes[i] = static_cast<char>('a' + i % 26);
    }
    const fs::path path = this->Write("bytes-" + std::to_string(size), bytes);
    const std::string read = vtkShadelabFileReader::ReadFileBytes(path.c_str());
    EXPECT_EQ(read, bytes) << size;
    EXPECT_LE(read.capacity(), size + 64) << size;
  }
  const std::string status = vtkShadelabFileReader::ReadFileBytes("/proc/self/status");
  EXPECT_NE(status.find("VmRSS:"), std::string::npos);
}

// ---------------------------------------------------------------------------
// The test meshes

TEST_F(MeshReaders, EveryMadeMeshLoadsWithItsTriangleCount)
{
  // meshes/make_meshes_main.cxx: the teapot's 32 patches at 10 x 10 cells
  // less the 80 cells that close to a point (6,320); at 32 x 32 less 256;
  // at 6 x 6 as 1,104 quads and 48 triangles; the torus 12 x 24 cells.
  const std::vector<std::pair<std::string, vtkIdType>> expected = { { "teapot.obj", 6320 },
    { "teapot.stl", 6320 }, { "teapot.off", 6320 }, { "teapot-textured.obj", 6320 },
    { "teapot-fine.obj", 65280 }, { "teapot-fine.ply", 65280 },
    { "teapot-quads.obj", 2 * 1104 + 48 }, { "torus.obj", 576 } };
  std::set<std::string> covered;
  for (const auto& [name, triangles] : expected)
  {
    SCOPED_TRACE(name);
    const ReadResult result = Read(TestMeshes / name);
    ASSERT_TRUE(result.Ok) << result.Error;
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), triangles);
    ExpectTriangleMesh(result.Mesh);
    // Ids that fit are stored in 32 bits: half the memory of a large mesh.
    EXPECT_FALSE(result.Mesh->GetPolys()->IsStorage64Bit());
    covered.insert(name);
  }
  for (const auto& entry : fs::directory_iterator(TestMeshes))
  {
    const fs::path extension = entry.path().extension();
    if (extension == ".mtl" || extension == ".png")
    {
      continue; // materials, textures
    }
    EXPECT_EQ(covered.count(entry.path().filename().string()), 1u)
      << entry.path() << " is not in this test's table";
  }
}

TEST_F(MeshReaders, QuadsBecomeTwoTrianglesAndTheFilesNormalsAreKept)
{
  const fs::path path = TestMeshes / "teapot-quads.obj";
  std::size_t quads = 0, triangles = 0;
  for (const std::size_t corners : StatementSizes(path, "f"))
  {
    quads += corners == 4;
    triangles += corners == 3;
  }
  EXPECT_EQ(quads, 1104u);
  EXPECT_EQ(quads + triangles, 1152u);

  const ReadResult result = Read(path);
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), static_cast<vtkIdType>(2 * quads + triangles));
  vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    EXPECT_NEAR(vtkMath::Norm(normals->GetTuple3(i)), 1.0, 1e-3) << i;
  }
}

TEST_F(MeshReaders, AnObjWithoutVnHasNoNormals)
{
  const fs::path path = TestMeshes / "teapot-fine.obj";
  EXPECT_TRUE(StatementSizes(path, "vn").empty());
  const ReadResult result = Read(path);
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
}

TEST_F(MeshReaders, TheSameMeshAsObjAndPlyAgrees)
{
  const ReadResult obj = Read(TestMeshes / "teapot-fine.obj");
  const ReadResult ply = Read(TestMeshes / "teapot-fine.ply");
  ASSERT_TRUE(obj.Ok && ply.Ok) << obj.Error << ply.Error;
  EXPECT_EQ(obj.Mesh->GetNumberOfPolys(), ply.Mesh->GetNumberOfPolys());
  EXPECT_EQ(obj.Mesh->GetNumberOfPoints(), ply.Mesh->GetNumberOfPoints());
  // The PLY's 32-bit coordinates stay float, in half the memory; the OBJ's
  // decimals are parsed to double.
  EXPECT_EQ(ply.Mesh->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(obj.Mesh->GetPoints()->GetDataType(), VTK_DOUBLE);
  // An ASCII PLY's decimals stay double even where it says float: float
  // would round them.
  const ReadResult ascii = Read(this->Write("ascii.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0.1234567891 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_TRUE(ascii.Ok) << ascii.Error;
  EXPECT_EQ(ascii.Mesh->GetPoints()->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(ascii.Mesh->GetPoint(0)[0], 0.1234567891);
  double a[6], b[6];
  obj.Mesh->GetBounds(a);
  ply.Mesh->GetBounds(b);
  for (int k = 0; k < 6; ++k)
  {
    // The PLY stores floats; the OBJ's decimals round to the same floats.
    EXPECT_NEAR(a[k], b[k], 1e-6 * std::abs(a[k]) + 1e-9) << k;
  }
}

TEST_F(MeshReaders, TheTeapotStlWeldsToTheObjsDistinctPositions)
{
  // teapot.obj's 3,241 places are 3,864 points once its vt split them
  // where patches meet; the STL has no indices, so welding can only give
  // the distinct places, each as the float the STL stores.
  const ReadResult obj = Read(TestMeshes / "teapot.obj");
  const ReadResult stl = Read(TestMeshes / "teapot.stl");
  ASSERT_TRUE(obj.Ok && stl.Ok) << obj.Error << stl.Error;
  std::set<std::array<float, 3>> places;
  double p[3];
  for (vtkIdType i = 0; i < obj.Mesh->GetNumberOfPoints(); ++i)
  {
    obj.Mesh->GetPoint(i, p);
    places.insert({ static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]) });
  }
  EXPECT_EQ(obj.Mesh->GetNumberOfPoints(), 3864); // split by vt where patches meet
  EXPECT_EQ(stl.Mesh->GetNumberOfPoints(), static_cast<vtkIdType>(places.size()));
  EXPECT_EQ(stl.Mesh->GetNumberOfPolys(), obj.Mesh->GetNumberOfPolys());
}

TEST_F(MeshReaders, TheFormatReadersWorkAloneAndPrintTheirFileName)
{
  vtkNew<vtkShadelabPLYReader> reader;
  const ReadResult result = ReadWith(reader, TestMeshes / "teapot-fine.ply");
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 65280);
  std::ostringstream printed;
  reader->Print(printed);
  EXPECT_NE(printed.str().find("FileName: " + (TestMeshes / "teapot-fine.ply").string()),
    std::string::npos);
}

// ---------------------------------------------------------------------------
// Hand-made PLY: the unit square as two triangles, a quad and a strip

// A PLY body in any of the three encodings, from the same calls.
class PlyBody
{
public:
  explicit PlyBody(const std::string& format)
    : Ascii(format == "ascii")
    , BigEndian(format == "binary_big_endian")
  {
  }

  template <typename T>
  PlyBody& Add(T value)
  {
    if (this->Ascii)
    {
      std::ostringstream text;
      text << +value << ' '; // + prints chars as numbers
      this->Bytes += text.str();
    }
    else
    {
      Put(this->Bytes, value, this->BigEndian);
    }
    return *this;
  }

  PlyBody& End()
  {
    if (this->Ascii)
    {
      this->Bytes += '\n';
    }
    return *this;
  }

  std::string Bytes;

private:
  bool Ascii;
  bool BigEndian;
};

enum class SquareForm
{
  Triangles,
  Quad,
  Strip
};

// Vertices (0,0,0) (1,0,0) (1,1,0) (0,1,0) with a colour, a skipped list
// property and normals (0,0,1); an "edge" element to skip before the faces.
std::string SquarePly(const std::string& format, SquareForm form)
{
  const char* faces = form == SquareForm::Triangles ? "element face 2\n"
                                                      "property list uchar int vertex_indices\n"
    : form == SquareForm::Quad                      ? "element face 1\n"
                                                      "property list uint8 uint32 vertex_index\n"
                                                    : "element tristrips 1\n"
                                                      "property list int int vertex_indices\n";
  std::string header = "ply\nformat " + format +
    " 1.0\n"
    "comment the unit square\n"
    "element vertex 4\n"
    "property float x\nproperty double y\nproperty short z\n"
    "property uchar red\n"
    "property list uchar float extra\n"
    "property float32 nx\nproperty float32 ny\nproperty float32 nz\n"
    "element edge 1\n"
    "property list uint16 int16 vertex_pair\nproperty int8 crease\n" +
    faces + "end_header\n";
  PlyBody body(format);
  const float corners[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (const auto& corner : corners)
  {
    body.Add(corner[0]).Add(static_cast<double>(corner[1])).Add(std::int16_t{ 0 });
    body.Add(std::uint8_t{ 200 }).Add(std::uint8_t{ 2 }).Add(0.5f).Add(0.25f);
    body.Add(0.0f).Add(0.0f).Add(1.0f).End();
  }
  body.Add(std::uint16_t{ 2 }).Add(std::int16_t{ 0 }).Add(std::int16_t{ 1 });
  body.Add(std::int8_t{ -1 }).End();
  switch (form)
  {
    case SquareForm::Triangles:
      body.Add(std::uint8_t{ 3 }).Add(0).Add(1).Add(2).End();
      body.Add(std::uint8_t{ 3 }).Add(0).Add(2).Add(3).End();
      break;
    case SquareForm::Quad:
      body.Add(std::uint8_t{ 4 }).Add(0u).Add(1u).Add(2u).Add(3u).End();
      break;
    case SquareForm::Strip: // 0 1 3 2: triangles (0 1 3) and (1 3 2), the second turned
      body.Add(5).Add(0).Add(1).Add(3).Add(2).Add(-1).End();
      break;
  }
  return header + body.Bytes;
}

// Two triangles covering the unit square, both facing +z.
void ExpectUnitSquare(const ReadResult& result)
{
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 4);
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 2u);
  double area = 0;
  for (const auto& triangle : triangles)
  {
    const auto n = AreaNormal(result.Mesh, triangle);
    EXPECT_GT(n[2], 0.0);
    EXPECT_EQ(n[0], 0.0);
    EXPECT_EQ(n[1], 0.0);
    area += n[2] / 2;
  }
  EXPECT_DOUBLE_EQ(area, 1.0);
}

TEST_F(MeshReaders, PlyInEveryEncodingAndFormGivesTheSameSquare)
{
  for (const char* format : { "ascii", "binary_little_endian", "binary_big_endian" })
  {
    for (const SquareForm form : { SquareForm::Triangles, SquareForm::Quad, SquareForm::Strip })
    {
      SCOPED_TRACE(std::string(format) + " form " + std::to_string(static_cast<int>(form)));
      const ReadResult result = Read(this->Write("square.PLY", SquarePly(format, form)));
      ExpectUnitSquare(result);
      vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
      ASSERT_NE(normals, nullptr);
      EXPECT_EQ(normals->GetTuple3(2)[2], 1.0);
    }
  }
}

// Rhinoceros 6 ends its lines in a bare CR: the header's, and an ASCII body's.
TEST_F(MeshReaders, PlyLinesEndingInABareCarriageReturnReadAsLines)
{
  for (const std::string format : { "ascii", "binary_little_endian" })
  {
    SCOPED_TRACE(format);
    std::string bytes = SquarePly(format.c_str(), SquareForm::Quad);
    const std::size_t headerEnd = bytes.find("end_header\n") + std::strlen("end_header\n");
    std::replace(
      bytes.begin(), format == "ascii" ? bytes.end() : bytes.begin() + headerEnd, '\n', '\r');
    ExpectUnitSquare(Read(this->Write("rhino.ply", bytes)));
  }
}

TEST_F(MeshReaders, PlyWithoutAllThreeNormalComponentsHasNoNormals)
{
  const ReadResult result = Read(this->Write("square.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0\n1 0 0 0 0\n0 1 0 0 0\n3 0 1 2\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
}

// Vertex colours: integers as a fraction of their type's largest value,
// floats as they are, alpha 1 when absent; without all of red, green and
// blue no colours.
TEST_F(MeshReaders, PlyVertexColorsAreFractionsOfTheirTypesLargestValue)
{
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string xyz = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                          "property float y\nproperty float z\n";
  struct Case
  {
    std::string Properties, Values;
    std::array<float, 4> First; // the first vertex's colour
  };
  const std::vector<Case> cases{
    { "property uchar red\nproperty uchar green\nproperty uchar blue\n", "255 51 0",
      { 1, 0.2f, 0, 1 } },
    { "property ushort red\nproperty ushort green\nproperty ushort blue\nproperty ushort alpha\n",
      "65535 0 13107 32768", { 1, 0, 0.2f, static_cast<float>(32768 / 65535.0) } },
    { "property float red\nproperty float green\nproperty float blue\n", "0.25 2 0.5",
      { 0.25f, 2, 0.5f, 1 } },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Properties);
    const ReadResult result = Read(this->Write("colors.ply",
      xyz + c.Properties + faces + "0 0 0 " + c.Values + "\n1 0 0 " + c.Values + "\n0 1 0 " +
        c.Values + "\n3 0 1 2\n"));
    ASSERT_TRUE(result.Ok) << result.Error;
    vtkDataArray* colors = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
    ASSERT_NE(colors, nullptr);
    ASSERT_EQ(colors->GetNumberOfComponents(), 4);
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_FLOAT_EQ(colors->GetComponent(0, k), c.First[k]) << "component " << k;
    }
  }
  const ReadResult partial = Read(this->Write("partial.ply",
    xyz + "property uchar red\nproperty uchar green\n" + faces +
      "0 0 0 1 2\n1 0 0 1 2\n0 1 0 1 2\n3 0 1 2\n"));
  ASSERT_TRUE(partial.Ok) << partial.Error;
  EXPECT_EQ(partial.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName), nullptr);
}

TEST_F(MeshReaders, PlyStripsSeparatedByMinusOneAndJoinTrianglesDropped)
{
  // Two squares as two strips: separated by -1 in the first list, joined in
  // the second by repeated vertices, which make 4 zero-area triangles
  // (2 3 3, 3 3 1, 3 1 1, 1 1 4) that are no part of the surface.
  const ReadResult result = Read(this->Write("strips.ply",
    "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
    "property float z\nelement tristrips 2\nproperty list int int vertex_indices\n"
    "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n2 1 0\n"
    "9 0 1 2 3 -1 1 4 3 5\n"
    "10 0 1 2 3 3 1 1 4 3 5\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 8u);
  for (const auto& triangle : triangles)
  {
    EXPECT_GT(AreaNormal(result.Mesh, triangle)[2], 0.0);
  }
}

// ---------------------------------------------------------------------------
// Hand-made OBJ

TEST_F(MeshReaders, ObjNegativeIndicesCountBackFromTheLastVertex)
{
  const ReadResult result = Read(
    this->Write("relative.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2 -1\n"));
  ExpectUnitSquare(result);
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (std::array<vtkIdType, 3>{ 0, 1, 2 }));
  EXPECT_EQ(triangles[1], (std::array<vtkIdType, 3>{ 0, 2, 3 }));
}

TEST_F(MeshReaders, ObjQuadBecomesTwoTriangles)
{
  ExpectUnitSquare(
    Read(this->Write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n")));
}

TEST_F(MeshReaders, ObjConcavePolygonIsTriangulatedInsideItsOutline)
{
  // An L of area 3, starting at a vertex that does not see the whole
  // polygon: a fan from it would fold a triangle over (wrong area, flipped).
  const ReadResult result = Read(this->Write(
    "concave.obj", "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 4u);
  double area = 0;
  for (const auto& triangle : triangles)
  {
    const auto n = AreaNormal(result.Mesh, triangle);
    EXPECT_GT(n[2], 0.0);
    area += n[2] / 2;
  }
  EXPECT_DOUBLE_EQ(area, 3.0);
}

// A square with a square hole, joined to it by a bridge edge that the
// polygon runs along both ways (vertices 1 and 5 twice; LightWave writes
// such faces): a ring of area 16 - 4, every triangle facing +z and none
// over the hole. A fan from vertex 1 would cover the hole.
TEST_F(MeshReaders, ObjPolygonWithAHoleJoinedByABridgeKeepsItsHole)
{
  const ReadResult result = Read(this->Write("keyhole.obj",
    "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 1 1 0\nv 1 3 0\nv 3 3 0\nv 3 1 0\n"
    "f 1 2 3 4 1 5 6 7 8 5\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  double area = 0;
  for (const auto& triangle : Triangles(result.Mesh))
  {
    const auto n = AreaNormal(result.Mesh, triangle);
    EXPECT_GE(n[2], 0.0);
    area += n[2] / 2;
    double centroid[3] = { 0, 0, 0 };
    for (const vtkIdType p : triangle)
    {
      for (int k = 0; k < 3; ++k)
      {
        centroid[k] += result.Mesh->GetPoint(p)[k] / 3;
      }
    }
    EXPECT_FALSE(
      n[2] > 0 && centroid[0] > 1 && centroid[0] < 3 && centroid[1] > 1 && centroid[1] < 3)
      << "a triangle over the hole, centred at " << centroid[0] << " " << centroid[1];
  }
  EXPECT_DOUBLE_EQ(area, 12.0);
}

TEST_F(MeshReaders, ObjVertexUsedWithTwoNormalsIsSplit)
{
  const ReadResult result = Read(this->Write("split.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "vn 0 0 1\nvn 0 -1 0\n"
    "f 1//1 2//1 3//1\n"
    "f 1//2 4//2 2//2\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  // Vertices 1 and 2 each get a second point for normal 2.
  ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 6);
  vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (std::array<vtkIdType, 3>{ 0, 1, 2 }));
  EXPECT_EQ(triangles[1], (std::array<vtkIdType, 3>{ 4, 3, 5 }));
  for (vtkIdType point : { 0, 1, 2 })
  {
    EXPECT_EQ(normals->GetTuple3(point)[2], 1.0) << point;
  }
  for (vtkIdType point : { 3, 4, 5 })
  {
    EXPECT_EQ(normals->GetTuple3(point)[1], -1.0) << point;
  }
  double p[3];
  result.Mesh->GetPoint(4, p);
  EXPECT_EQ(p[0] + p[1] + p[2], 0.0); // the copy of vertex 1
  result.Mesh->GetPoint(5, p);
  EXPECT_EQ(p[0], 1.0); // the copy of vertex 2
  auto* fileVertices = vtkIdTypeArray::SafeDownCast(
    result.Mesh->GetPointData()->GetArray(shadelab::FileVertexArrayName));
  ASSERT_NE(fileVertices, nullptr);
  for (vtkIdType point = 0; point < 6; ++point)
  {
    EXPECT_EQ(fileVertices->GetValue(point), (std::array<vtkIdType, 6>{ 0, 1, 2, 3, 0, 1 })[point]);
  }
}

// usemtl: a part per material name in the order of first use, the faces
// before the first in a part of their own named "".
TEST_F(MeshReaders, ObjMaterialsMakeParts)
{
  const ReadResult result = Read(this->Write("parts.obj",
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\n"
    "f 1 2 3\nusemtl red\nf 1 3 4\nusemtl blue # a comment\nf 2 5 3\nusemtl red\nf 4 3 1\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  vtkDataArray* parts = result.Mesh->GetCellData()->GetArray(shadelab::PartArrayName);
  ASSERT_NE(parts, nullptr);
  ASSERT_EQ(parts->GetNumberOfTuples(), 4);
  for (vtkIdType i = 0; i < 4; ++i)
  {
    EXPECT_EQ(parts->GetComponent(i, 0), (std::array<int, 4>{ 0, 1, 2, 1 })[i]) << i;
  }
  auto* names = vtkStringArray::SafeDownCast(
    result.Mesh->GetFieldData()->GetAbstractArray(shadelab::PartMaterialsArrayName));
  auto* indices = vtkIntArray::SafeDownCast(
    result.Mesh->GetFieldData()->GetArray(shadelab::PartMaterialIndicesArrayName));
  ASSERT_TRUE(names && indices);
  ASSERT_EQ(names->GetNumberOfValues(), 3);
  EXPECT_EQ(names->GetValue(0), "");
  EXPECT_EQ(names->GetValue(1), "red");
  EXPECT_EQ(names->GetValue(2), "blue");
  for (vtkIdType part = 0; part < 3; ++part)
  {
    EXPECT_EQ(indices->GetValue(part), -1) << part; // no mtllib: no material defined
  }

  const ReadResult plain = Read(this->Write("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(plain.Ok) << plain.Error;
  EXPECT_EQ(plain.Mesh->GetCellData()->GetArray(shadelab::PartArrayName), nullptr);
}

// The lecture's equation with ns = 0 makes the highlight ks wherever the
// surface is lit: right, but a white surface to a user, so it is said.
TEST_F(MeshReaders, MtlMaterialsOfNsZeroWithASpecularColourAreWarnedOfOnce)
{
  const shadelab::MtlLibrary library = shadelab::ParseMtl("newmtl shiny\nKs 1 1 1\nNs 0\n"
                                                          "newmtl unset\nKs 0 0.5 0\n"
                                                          "newmtl matte\nKs 0 0 0\nNs 0\n"
                                                          "newmtl sharp\nKs 1 1 1\nNs 10\n");
  ASSERT_EQ(library.Warnings.size(), 2u);
  EXPECT_EQ(library.Warnings[0],
    "newmtl 'shiny': Ns is 0 and Ks above 0, so the specular term is Ks wherever the surface "
    "is lit (cos^0 = 1)");
  EXPECT_NE(library.Warnings[1].find("newmtl 'unset'"), std::string::npos);
}

// mtllib: the parts' materials from the libraries beside the OBJ; one
// that is missing is a warning, a name they do not define has index -1.
TEST_F(MeshReaders, ObjMaterialLibrariesGiveThePartsTheirMaterials)
{
  this->Write("lib.mtl",
    "# a library\nnewmtl green\nKd 0 1 0\n\nnewmtl red\nKa 0.1\n"
    "Kd 1 0 0 # red\nKs 0.5 0.25 0.125\nNs 20\nillum 2\nmap_Kd red.png\n");
  const ReadResult result = Read(this->Write("lib.obj",
    "mtllib lib.mtl missing.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "usemtl red\nf 1 2 3\nusemtl blue\nf 1 3 4\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ASSERT_EQ(result.Warnings.size(), 1u);
  EXPECT_NE(
    result.Warnings[0].find("material library 'missing.mtl': cannot open"), std::string::npos)
    << result.Warnings[0];
  vtkFieldData* field = result.Mesh->GetFieldData();
  auto* indices =
    vtkIntArray::SafeDownCast(field->GetArray(shadelab::PartMaterialIndicesArrayName));
  ASSERT_NE(indices, nullptr);
  EXPECT_EQ(indices->GetValue(0), 1);  // red, the library's second
  EXPECT_EQ(indices->GetValue(1), -1); // blue, defined nowhere
  const auto tuple = [&](const char* name, vtkIdType part)
  {
    vtkDataArray* array = field->GetArray(name);
    std::array<double, 3> v{};
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      v[c] = array->GetComponent(part, c);
    }
    return v;
  };
  EXPECT_EQ(tuple(shadelab::PartKaArrayName, 0), (std::array<double, 3>{ 0.1, 0.1, 0.1 }));
  EXPECT_EQ(tuple(shadelab::PartKdArrayName, 0), (std::array<double, 3>{ 1, 0, 0 }));
  EXPECT_EQ(tuple(shadelab::PartKsArrayName, 0), (std::array<double, 3>{ 0.5, 0.25, 0.125 }));
  EXPECT_EQ(tuple(shadelab::PartNsArrayName, 0)[0], 20);
  EXPECT_EQ(tuple(shadelab::PartKdArrayName, 1), (std::array<double, 3>{ 0, 0, 0 }));
}

TEST_F(MeshReaders, MtlCoefficientsDefaultsAndMistakes)
{
  const auto library = shadelab::ParseMtl("newmtl a\nKd 0.5\nTr 0.25\nnewmtl b\nd 0.5\n");
  ASSERT_EQ(library.Materials.size(), 2u);
  const shadelab::Material& a = library.Materials[0].Coefficients;
  EXPECT_EQ(a.Name, "a");
  EXPECT_EQ(a.Kd, (shadelab::Rgb{ 0.5, 0.5, 0.5 }));
  EXPECT_EQ(a.Ka, (shadelab::Rgb{ 0, 0, 0 }));
  EXPECT_EQ(a.Ns, 0);
  EXPECT_EQ(a.Translucency, 0.75);
  EXPECT_EQ(library.Materials[1].Coefficients.Translucency, 0.5);
  const std::vector<std::pair<std::string, std::string>> mistakes{
    { "Kd 1 1 1\n", "line 1: Kd before any newmtl" },
    { "newmtl\n", "line 1: newmtl without a material name" },
    { "newmtl a\nKd 1 x 1\n", "line 2: malformed Kd 'x'" },
    { "newmtl a\nKd 1 1\n", "line 2: missing Kd" },
    { "newmtl a\nKs 1 1 1 1\n", "line 2: unexpected '1' after Ks" },
    { "newmtl a\nNs -1\n", "line 2: negative Ns" },
    { "newmtl a\nKa nan\n", "line 2: non-finite Ka" },
  };
  ExpectMtlErrors(mistakes);
}

// A material's normal map: norm, or else bump / map_Bump (which may name a
// height map), with -bm as its scale; norm wins whichever comes first, and
// -bm on another map is skipped with a warning.
TEST_F(MeshReaders, MtlNormalMapsFromNormOrBump)
{
  const auto library = shadelab::ParseMtl(
    "newmtl norm\nbump b.png\nnorm -bm 0.5 n.png\nbump c.png\n"
    "newmtl bump\nmap_Bump -bm -2 -clamp on h.png\nnewmtl none\nmap_Kd -bm 3 k.png\n");
  ASSERT_EQ(library.Materials.size(), 3u);
  const shadelab::MtlMaterial& norm = library.Materials[0];
  EXPECT_EQ(norm.NormalMap.File, "n.png");
  EXPECT_EQ(norm.NormalMap.Scale, 0.5);
  EXPECT_FALSE(norm.NormalFromBump);
  const shadelab::MtlMaterial& bump = library.Materials[1];
  EXPECT_EQ(bump.NormalMap.File, "h.png");
  EXPECT_EQ(bump.NormalMap.Scale, -2);
  EXPECT_TRUE(bump.NormalMap.Clamp);
  EXPECT_TRUE(bump.NormalFromBump);
  EXPECT_EQ(library.Materials[2].NormalMap.File, "");
  ASSERT_EQ(library.Warnings.size(), 1u);
  EXPECT_NE(library.Warnings[0].find("map_Kd option -bm is not supported"), std::string::npos);
  ExpectMtlErrors({ { "newmtl a\nnorm -bm x n.png\n", "line 2: malformed norm -bm 'x'" } });
}

// d is the opacity a; Tr alone its complement, except Tr 1, which MeshLab
// and others write for an opaque material; d wins over a Tr after it.
TEST_F(MeshReaders, MtlOpacityFromDOrTr)
{
  const auto library = shadelab::ParseMtl(
    "newmtl meshlab\nTr 1.000000\nnewmtl clear\nTr 0.9\nnewmtl both\nd 0.5\nTr 0.9\n"
    "newmtl over\nd 1.5\nnewmtl under\nd -0.5\n");
  ASSERT_EQ(library.Materials.size(), 5u);
  const double expected[] = { 1, 1 - 0.9, 0.5, 1, 0 };
  for (std::size_t k = 0; k < 5; ++k)
  {
    EXPECT_DOUBLE_EQ(library.Materials[k].Coefficients.Translucency, expected[k])
      << library.Materials[k].Coefficients.Name;
  }
}

TEST_F(MeshReaders, ObjIgnoresWhatItDoesNotRender)
{
  const ReadResult result = Read(this->Write("noise.obj",
    "# a comment\r\nmtllib square.mtl\r\no square\r\ng group\r\ns 1\r\nusemtl red\r\n"
    "v 0 0 0 1\r\nv +1 0 0 0.5 0.5 0.5\r\nv 1 1 0 # corner\r\nv 0 1 0\r\n"
    "vt 0 0\r\nvt 1 0\r\nvt 1 1\r\nvp 0.5\r\ncstype bezier\r\nl 1 2\r\np 3\r\n"
    "\r\n   \r\nf 1/1 2/2 3/3 # first\r\nf 1/1 3/3 4/1\r\n"));
  ExpectUnitSquare(result);
}

// The common extension `v x y z r g b`: each point's colour is its file
// vertex's, copies made for a second vt included.
TEST_F(MeshReaders, ObjVertexColoursFollowTheirVerticesIntoEveryPoint)
{
  const std::string vertices =
    "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 0.5 0.25 0.125\n";
  const std::array<std::array<double, 4>, 4> file{ { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 },
    { 0.5, 0.25, 0.125, 1 } } };
  const ReadResult plain = Read(this->Write("colours.obj", vertices + "f 1 2 3\nf 1 3 4\n"));
  ExpectUnitSquare(plain);
  EXPECT_TRUE(plain.Warnings.empty());
  // Vertex 1 twice, with vt 1 and vt 5: the copy is point 4.
  const ReadResult split = Read(this->Write("split.obj",
    vertices + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\nf 1/1 2/2 3/3\nf 1/5 3/3 4/4\n"));
  ASSERT_TRUE(split.Ok) << split.Error;
  ASSERT_EQ(split.Mesh->GetNumberOfPoints(), 5);
  for (const ReadResult* result : { &plain, &split })
  {
    vtkDataArray* colours = result->Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
    ASSERT_NE(colours, nullptr);
    for (vtkIdType p = 0; p < result->Mesh->GetNumberOfPoints(); ++p)
    {
      const std::size_t v = p < 4 ? static_cast<std::size_t>(p) : 0;
      for (int c = 0; c < 4; ++c)
      {
        EXPECT_EQ(colours->GetComponent(p, c), file[v][c]) << "point " << p << " component " << c;
      }
    }
  }

  const ReadResult some = Read(this->Write(
    "some.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0 0 1\nv 0 1 0 1\nf 1 2 3\nf 1 3 4\n"));
  ExpectUnitSquare(some);
  EXPECT_EQ(some.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName), nullptr);
  ASSERT_EQ(some.Warnings.size(), 1u);
  EXPECT_NE(some.Warnings[0].find("some vertices have no r g b colour"), std::string::npos);
}

TEST_F(MeshReaders, ObjMixingFacesWithAndWithoutNormalsDropsThemWithAWarning)
{
  const ReadResult result = Read(this->Write(
    "mixed.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\n"));
  ExpectUnitSquare(result);
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
  ASSERT_EQ(result.Warnings.size(), 1u);
  EXPECT_NE(result.Warnings[0].find("normals are ignored"), std::string::npos);
}

// ---------------------------------------------------------------------------
// Hand-made STL

std::string BinaryStl(const std::string& header, std::uint32_t declared,
  const std::vector<std::array<float, 9>>& triangles)
{
  std::string bytes = header;
  bytes.resize(80, ' ');
  Put(bytes, declared);
  for (const auto& triangle : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      Put(bytes, 0.0f); // the facet normal, ignored
    }
    for (const float value : triangle)
    {
      Put(bytes, value);
    }
    Put(bytes, std::uint16_t{ 0 });
  }
  return bytes;
}

const std::vector<std::array<float, 9>> SquareTriangles = {
  { 0, 0, 0, 1, 0, 0, 1, 1, 0 }, { -0.0f, 0, 0, 1, 1, 0, 0, 1, 0 } // -0 welds with +0
};

TEST_F(MeshReaders, AsciiStlIsWelded)
{
  ExpectUnitSquare(Read(this->Write("square.stl",
    "solid square\n"
    "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
    "      vertex 1 1 0\n    endloop\n  endfacet\n"
    "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 1 0\n"
    "      vertex 0 1 0\n    endloop\n  endfacet\n"
    "endsolid square\n")));
}

TEST_F(MeshReaders, BinaryStlWhoseHeaderStartsWithSolidIsReadAsBinary)
{
  ExpectUnitSquare(Read(this->Write("square.stl", BinaryStl("solid square", 2, SquareTriangles))));
}

// ---------------------------------------------------------------------------
// .vtp and .vtk through VTK's readers

// A quad and a 4-point strip over two unit squares, float points and
// normals, and what a reader must skip: a vertex and a line cell, other
// point and cell attributes (one with component names, written as METADATA)
// and field data.
vtkSmartPointer<vtkPolyData> QuadAndStrip()
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  for (const double x : { 0.0, 1.0, 2.0 })
  {
    points->InsertNextPoint(x, 0, 0);
    points->InsertNextPoint(x, 1, 0);
  }
  vtkNew<vtkCellArray> verts;
  verts->InsertNextCell({ 0 });
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 0, 5 });
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 2, 3, 1 });
  vtkNew<vtkCellArray> strips;
  strips->InsertNextCell({ 2, 4, 3, 5 });
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);

  vtkNew<vtkFloatArray> normals;
  normals->SetName("N");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetName("velocity");
  vectors->SetNumberOfComponents(3);
  vectors->SetComponentName(0, "u");
  vtkNew<vtkIntArray> scalars;
  scalars->SetName("label");
  for (vtkIdType i = 0; i < 6; ++i)
  {
    normals->InsertNextTuple3(0, 0, 1);
    vectors->InsertNextTuple3(i, -i, 0.5);
    scalars->InsertNextValue(static_cast<int>(i));
  }
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetVectors(vectors);
  mesh->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFloatArray> cellNormals;
  cellNormals->SetName("faces");
  cellNormals->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfCells(); ++i)
  {
    cellNormals->InsertNextTuple3(0, 0, 1);
  }
  mesh->GetCellData()->SetNormals(cellNormals);
  vtkNew<vtkIntArray> field;
  field->SetName("version");
  field->InsertNextValue(3);
  mesh->GetFieldData()->AddArray(field);
  return mesh;
}

void ExpectQuadAndStrip(const ReadResult& result)
{
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 4u);
  for (const auto& triangle : triangles)
  {
    EXPECT_GT(AreaNormal(result.Mesh, triangle)[2], 0.0);
  }
  ASSERT_NE(result.Mesh->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals()->GetTuple3(5)[2], 1.0);
}

TEST_F(MeshReaders, VtpIsTriangulatedLikeTheRest)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(QuadAndStrip());
  writer->SetFileName((this->Dir / "mesh.vtp").c_str());
  ASSERT_TRUE(writer->Write());
  ExpectQuadAndStrip(Read(this->Dir / "mesh.vtp"));
}

TEST_F(MeshReaders, LegacyVtkInEveryEncodingAndCellLayout)
{
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(QuadAndStrip());
  for (const int type : { VTK_ASCII, VTK_BINARY })
  {
    // 4.2: cells as counts and ids; 5.1 (VTK 9's default): offsets and connectivity.
    for (const auto version : { vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2,
           vtkDataWriter::VTK_LEGACY_READER_VERSION_5_1 })
    {
      SCOPED_TRACE(std::to_string(type) + " " + std::to_string(version));
      writer->SetFileType(type);
      writer->SetFileVersion(version);
      writer->SetFileName((this->Dir / "mesh.VTK").c_str());
      ASSERT_TRUE(writer->Write());
      ExpectQuadAndStrip(Read(this->Dir / "mesh.VTK"));
    }
  }
}

// ---------------------------------------------------------------------------
// Bad input

TEST_F(MeshReaders, FilesThatCannotBeOpened)
{
  this->ExpectError(this->Dir / "missing.obj", { "cannot open: No such file or directory" });
  fs::create_directory(this->Dir / "folder.ply");
  this->ExpectError(this->Dir / "folder.ply", { "cannot open: Is a directory" });
  this->ExpectError(this->Dir / "missing.vtp", { "cannot open: No such file or directory" });
  EXPECT_EQ(Read(this->Dir / "missing.stl").ErrorCode, vtkErrorCode::FileNotFoundError);

  vtkNew<vtkShadelabMeshReader> reader;
  const shadelab::MessageScope messages;
  EXPECT_EQ(reader->GetExecutive()->Update(), 0);
  EXPECT_NE(messages.FirstError().find("no file name"), std::string::npos);
}

TEST_F(MeshReaders, EachMessageScopeHasItsOwnErrorsAndWarnings)
{
  // Two broken files read one after the other: each read's scope hands back
  // its own first error, not the one before it.
  this->Write("first.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n");
  EXPECT_NE(Read(this->Dir / "first.ply").Error, "");
  const ReadResult second = Read(this->Dir / "second.obj");
  EXPECT_EQ(second.Error, "cannot open: No such file or directory");

  // A scope inside another takes the messages while it is open; the outer
  // one gets those before and after it.
  const shadelab::MessageScope outer;
  vtkNew<vtkShadelabMeshReader> reader;
  {
    const shadelab::MessageScope inner;
    reader->SetFileName((this->Dir / "second.obj").c_str());
    reader->GetExecutive()->Update();
    EXPECT_EQ(inner.FirstError(), "cannot open: No such file or directory");
  }
  EXPECT_EQ(outer.FirstError(), "");
  reader->SetFileName((this->Dir / "first.ply").c_str());
  reader->GetExecutive()->Update();
  EXPECT_NE(outer.FirstError(), "");

  // A warning goes to the scope that is open while it is reported.
  this->Write(
    "some-vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n");
  const ReadResult partly = Read(this->Dir / "some-vn.obj");
  ASSERT_TRUE(partly.Ok) << partly.Error;
  ASSERT_EQ(partly.Warnings.size(), 1u);
  EXPECT_EQ(partly.Warnings[0], "some faces have no vn normals, so the file's normals are ignored");
  EXPECT_EQ(Read(this->Dir / "some-vn.obj").Warnings.size(), 1u);
}

TEST_F(MeshReaders, UnknownExtensions)
{
  this->ExpectError("points.xyz", "0 0 0\n",
    { "unknown mesh format \".xyz\" (known: .obj .ply .stl .off .gltf .glb .vtp .vtk)" });
  this->ExpectError("mesh", "v 0 0 0\n", { "unknown mesh format \"\"" });
  EXPECT_EQ(Read(this->Dir / "points.xyz").ErrorCode, vtkErrorCode::UnrecognizedFileTypeError);
}

TEST_F(MeshReaders, AFailedReadLeavesNoMeshFromBefore)
{
  vtkNew<vtkShadelabMeshReader> reader;
  ASSERT_TRUE(ReadWith(reader, TestMeshes / "torus.obj").Ok);
  const ReadResult result = ReadWith(reader, this->Write("bad.obj", "v 0 0 0\nf 1 2 3\n"));
  EXPECT_FALSE(result.Ok);
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 0);
  EXPECT_EQ(result.Mesh->GetNumberOfCells(), 0);
}

TEST_F(MeshReaders, BadObj)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  this->ExpectError("range.obj", square + "\n# c\nf 1 2 99\n",
    { "line 6: face refers to vertex 99, but only 3 vertices are defined" });
  this->ExpectError("zero.obj", square + "f 0 1 2\n", { "line 4", "vertex 0" });
  this->ExpectError("relative.obj", square + "f -1 -2 -4\n", { "line 4", "vertex -4", "only 3" });
  this->ExpectError("normal.obj", square + "vn 0 0 1\nf 1//1 2//1 3//2\n",
    { "line 5", "normal 2", "only 1 normals" });
  this->ExpectError("two.obj", square + "f 1 2\n", { "line 4", "2 vertices", "at least 3" });
  this->ExpectError(
    "corner.obj", square + "f 1 2 3x\n", { "line 4", "malformed face vertex '3x'" });
  this->ExpectError("slashes.obj", square + "f 1/1/1/1 2 3\n", { "malformed face vertex" });
  this->ExpectError("trailing.obj", square + "f 1/ 2 3\n", { "malformed face vertex" });
  this->ExpectError("number.obj", "v 0 0 0\nv 1 0,5 0\n", { "line 2", "malformed", "'0,5'" });
  this->ExpectError("short.obj", "v 0 0\n", { "line 1", "missing vertex coordinate" });
  this->ExpectError("extra.obj", "v 0 0 0 zero\n", { "line 1", "malformed number 'zero'" });
  this->ExpectError("nan.obj", square + "v nan 0 0\nf 1 2 4\n", { "NaN coordinate in vertex 4" });
  this->ExpectError(
    "inf.obj", "v 0 0 0\nv 0 -inf 0\nv 1 1 0\nf 1 2 3\n", { "infinite coordinate in vertex 2" });
  this->ExpectError("normalnan.obj", square + "vn 0 nan 1\nf 1//1 2//1 3//1\n", { "NaN normal" });
  this->ExpectError(
    "usemtl.obj", square + "usemtl\n", { "line 4", "usemtl without a material name" });
  this->Write("bad.mtl", "newmtl a\nKd 1 0,5 0\n");
  this->ExpectError("badmtl.obj", "mtllib bad.mtl\n" + square + "usemtl a\nf 1 2 3\n",
    { "material library 'bad.mtl' line 2: malformed Kd '0,5'" });
  this->ExpectError("empty.obj", "", { "no triangles" });
  this->ExpectError("lines.obj", square + "l 1 2 3\np 1\n", { "no triangles" });
  this->ExpectError("binary.obj",
    std::string("\x7f"
                "ELF\0\0\x01",
      7),
    { "no triangles" });
}

// The square's header and body for the bad-PLY cases below.
const std::string AsciiPlyHeader = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                   "property float y\nproperty float z\nelement face 2\n"
                                   "property list uchar int vertex_indices\nend_header\n";
const std::string AsciiPlyVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

std::string BinaryPly(std::uint32_t vertices, std::uint32_t faces, const std::string& body)
{
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
    "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
    std::to_string(faces) + "\nproperty list uchar int vertex_indices\nend_header\n" + body;
}

std::string BinarySquareBody(float nan = 0.0f)
{
  std::string body;
  for (const float value :
    { 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, nan, 0.0f, 0.0f, 1.0f, 0.0f })
  {
    Put(body, value);
  }
  return body;
}

std::string BinaryTriangle(int a, int b, int c)
{
  std::string bytes;
  Put(bytes, std::uint8_t{ 3 });
  for (const int index : { a, b, c })
  {
    Put(bytes, index);
  }
  return bytes;
}

TEST_F(MeshReaders, BadPly)
{
  this->ExpectError("range.ply", AsciiPlyHeader + AsciiPlyVertices + "3 0 1 2\n3 0 2 7\n",
    { "face 1 refers to vertex 7, but only 4 vertices are defined" });
  this->ExpectError("negative.ply", AsciiPlyHeader + AsciiPlyVertices + "3 0 1 2\n3 0 -2 3\n",
    { "face 1 refers to vertex -2" });
  // Beyond 32 bits: the cells stay 64-bit, so the error names the file's number.
  this->ExpectError("far.ply", AsciiPlyHeader + AsciiPlyVertices + "3 0 1 2\n3 0 3000000000 3\n",
    { "face 1 refers to vertex 3000000000" });
  this->ExpectError("below.ply", AsciiPlyHeader + AsciiPlyVertices + "3 0 1 2\n3 0 -3000000000 3\n",
    { "face 1 refers to vertex -3000000000" });
  this->ExpectError(
    "two.ply", AsciiPlyHeader + AsciiPlyVertices + "2 0 1\n3 0 2 3\n", { "face 0 has 2 vertices" });
  this->ExpectError("number.ply", AsciiPlyHeader + "0 0 0\n1 0 0\n1 1 zero\n",
    { "line 12", "malformed number 'zero'" });
  this->ExpectError("few.ply", AsciiPlyHeader + "0 0 0\n1 0\n", { "line 11", "missing number" });
  this->ExpectError(
    "many.ply", AsciiPlyHeader + "0 0 0 0\n", { "line 10", "unexpected '0' after the values" });
  this->ExpectError("cut.ply", AsciiPlyHeader + AsciiPlyVertices + "3 0 1 2\n",
    { "truncated: header declares 2 faces but the file ends after 1" });
  this->ExpectError("nan.ply", AsciiPlyHeader + "0 0 0\n1 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n3 0 2 3\n",
    { "NaN coordinate in vertex 2" });
  this->ExpectError("normal.ply",
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 inf 1\n3 0 1 2\n",
    { "infinite normal in vertex 2" });
  this->ExpectError("count.ply",
    "ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n0 0 0\n",
    { "header declares 4294967295 vertices, more than a", "-byte file can hold" });

  // Binary: the square with 4 vertices, then faces.
  const std::string faces = BinaryTriangle(0, 1, 2) + BinaryTriangle(0, 2, 3);
  ASSERT_TRUE(Read(this->Write("good.ply", BinaryPly(4, 2, BinarySquareBody() + faces))).Ok);
  this->ExpectError("cut.ply", BinaryPly(4, 2, BinarySquareBody() + faces.substr(0, 20)),
    { "truncated: header declares 2 faces but the file ends after 1" });
  this->ExpectError("cutvertices.ply", BinaryPly(4, 0, BinarySquareBody().substr(0, 40)),
    { "truncated: header declares 4 vertices but the file ends after 3" });
  this->ExpectError("nan.ply",
    BinaryPly(4, 2, BinarySquareBody(std::numeric_limits<float>::quiet_NaN()) + faces),
    { "NaN coordinate in vertex 2" });
  this->ExpectError("range.ply",
    BinaryPly(4, 2, BinarySquareBody() + BinaryTriangle(0, 1, 2) + BinaryTriangle(0, 2, 4)),
    { "face 1 refers to vertex 4, but only 4 vertices are defined" });
  // A list length that runs past the end allocates nothing for itself.
  std::string lying = BinarySquareBody() + faces;
  lying[lying.size() - 13] = static_cast<char>(255);
  this->ExpectError("list.ply", BinaryPly(4, 2, lying), { "truncated", "2 faces", "after 1" });
  // 2^32 - 1 faces in a file of a few hundred bytes: refused from the header.
  const fs::path huge =
    this->Write("huge.ply", BinaryPly(4, 4294967295u, BinarySquareBody() + faces));
  this->ExpectError(huge,
    { ("header declares 4294967295 faces, more than a " + std::to_string(fs::file_size(huge)) +
      "-byte file can hold")
        .c_str() });
}

TEST_F(MeshReaders, BadPlyHeaders)
{
  const std::string element = "element vertex 1\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n";
  this->ExpectError("magic.ply", "pyl\nformat ascii 1.0\n" + element, { "not a PLY file" });
  this->ExpectError(
    "format.ply", "ply\nformat text 1.0\n" + element, { "line 2", "unknown PLY format 'text'" });
  this->ExpectError("version.ply", "ply\nformat ascii 2.0\n" + element, { "version '2.0'" });
  this->ExpectError("noformat.ply", "ply\n" + element, { "end_header before any format" });
  this->ExpectError("type.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n",
    { "line 4", "unknown property type 'real'" });
  this->ExpectError("keyword.ply", "ply\nformat ascii 1.0\nelemnt vertex 1\nend_header\n",
    { "line 3", "unknown header line 'elemnt'" });
  this->ExpectError(
    "end.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", { "no end_header" });
  this->ExpectError("xyz.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 "
    "0\n",
    { "lacks x, y or z" });
  this->ExpectError("nofaces.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int corners\nend_header\n0 0 0\n3 0 0 "
    "0\n",
    { "face element has no vertex_indices list" });
  this->ExpectError("floats.ply",
    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n"
    "0 0 0\n3 0 0 0\n",
    { "does not hold integers" });
  this->ExpectError("novertex.ply", "ply\nformat ascii 1.0\nend_header\n", { "no vertex element" });
  this->ExpectError("points.ply", "ply\nformat ascii 1.0\n" + element, { "no triangles" });
}

TEST_F(MeshReaders, BadStl)
{
  // 2^32 - 1 triangles declared in a 200-byte file: refused from the size.
  std::string lying = BinaryStl("binary", 4294967295u, SquareTriangles);
  lying.resize(200, '\0');
  this->ExpectError(
    "lying.stl", lying, { "header declares 4294967295 triangles", "but the file has 200 bytes" });
  this->ExpectError(
    "short.stl", BinaryStl("solid but binary", 3, SquareTriangles), { "declares 3 triangles" });
  this->ExpectError("tiny.stl", "abc", { "not an STL file" });
  this->ExpectError("nan.stl",
    BinaryStl("x", 2,
      { SquareTriangles[0], { 0, 0, 0, 1, 1, 0, 0, std::numeric_limits<float>::infinity(), 0 } }),
    { "infinite coordinate in triangle 1" });

  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                            "vertex 1 1 0\nendloop\nendfacet\n";
  this->ExpectError("noend.stl", "solid s\n" + facet, { "truncated", "endsolid" });
  this->ExpectError("cut.stl", "solid s\n" + facet.substr(0, 43), { "truncated", "triangle 0" });
  this->ExpectError("loop.stl", "solid s\nfacet normal 0 0 1\nvertex 0 0 0\n",
    { "line 3", "expected 'outer loop', found 'vertex'" });
  this->ExpectError("nan.stl", "solid s\n" + facet + facet.substr(0, 50) + "nan 0 0\n",
    { "line 12", "NaN coordinate in triangle 1" });
  this->ExpectError("number.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 O\n",
    { "line 4", "malformed vertex coordinate 'O'" });
  this->ExpectError("empty.stl", "solid s\nendsolid s\n", { "no triangles" });
}

TEST_F(MeshReaders, BadLegacyVtk)
{
  const std::string header = "# vtk DataFile Version 3.0\nsquare\nASCII\nDATASET POLYDATA\n";
  const std::string points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n";
  ASSERT_TRUE(
    Read(this->Write("good.vtk", header + points + "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\n")).Ok);
  // Each of these crashed, over-read or half-read VTK 9.1's vtkPolyDataReader.
  this->ExpectError("cut.vtk", header + points + "POLYGONS 2 8\n3 0 1 2\n",
    { "truncated: POLYGONS declares 8 values but the file ends after 4" });
  this->ExpectError("cell.vtk", header + points + "POLYGONS 2 8\n3 0 1 2\n9 0 2 3\n",
    { "POLYGONS cell 1 does not fit the section's 8 values" });
  // A binary uint64 point id beyond int64 is an error, not an undefined cast.
  std::string huge =
    "# vtk DataFile Version 5.1\nsquare\nBINARY\nDATASET POLYDATA\nPOINTS 4 float\n";
  for (float v : { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 })
  {
    Put(huge, v, true);
  }
  huge += "\nPOLYGONS 3 6\nOFFSETS vtktypeint64\n";
  for (std::int64_t v : { 0, 3, 6 })
  {
    Put(huge, v, true);
  }
  huge += "\nCONNECTIVITY vtktypeuint64\n";
  for (std::uint64_t v : { 0ull, 1ull, 2ull, 0ull, 2ull, ~0ull })
  {
    Put(huge, v, true);
  }
  this->ExpectError("huge.vtk", huge + "\n", { "face 1 refers to vertex -1" });
  this->ExpectError("size.vtk", header + points + "POLYGONS 2 99999999999\n3 0 1 2\n",
    { "POLYGONS declares 99999999999 values, more than a", "-byte file can hold" });
  this->ExpectError("normals.vtk",
    header + points +
      "POLYGONS 2 8\n3 0 1 2\n3 0 2 3\nPOINT_DATA 4\nNORMALS n float\n0 0 1 0 0 1\n",
    { "truncated: NORMALS declares 4 normals but the file ends after 2" });
  this->ExpectError("count.vtk", header + "POINTS 99999999999 float\n0 0 0\n",
    { "POINTS declares 99999999999 points, more than a" });
  this->ExpectError("binary.vtk",
    "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET POLYDATA\nPOINTS 4 float\n" +
      std::string(4, '\0'),
    { "truncated: POINTS declares 4 points but the file ends after 0" });
  this->ExpectError("offsets.vtk",
    "# vtk DataFile Version 5.1\nsquare\nASCII\nDATASET POLYDATA\n" + points +
      "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 3 7\nCONNECTIVITY vtktypeint64\n0 1 2 0 2 3\n",
    { "POLYGONS offsets do not run from 0 up to its 6 connectivity entries" });
  this->ExpectError("index.vtk", header + points + "POLYGONS 2 8\n3 0 1 2\n3 0 2 4\n",
    { "face 1 refers to vertex 4, but only 4 vertices are defined" });
  this->ExpectError("value.vtk", header + "POINTS 4 float\n0 0 0 1 0 0 1 one 0 0 1 0\n",
    { "line 6", "malformed value 'one' in POINTS" });
  this->ExpectError("data.vtk", header + points + "POINT_DATA 3\n",
    { "POINT_DATA declares 3 values for 4 points" });
  this->ExpectError(
    "keyword.vtk", header + points + "POLYGON 2 8\n", { "line 7", "unexpected 'polygon'" });
  this->ExpectError("string.vtk", header + points + "FIELD f 1\nnames 1 1 string\nx\n",
    { "unsupported data type 'string'" });
  this->ExpectError("grid.vtk",
    "# vtk DataFile Version 3.0\ngrid\nASCII\nDATASET STRUCTURED_POINTS\n"
    "DIMENSIONS 2 2 1\nORIGIN 0 0 0\nSPACING 1 1 1\n",
    { "STRUCTURED_POINTS", "not POLYDATA" });
  this->ExpectError("magic.vtk", "garbage", { "not a legacy VTK file" });
  this->ExpectError("components.vtk",
    header + points + "FIELD f 1\nbig 1000000000 3 float\n0 0 0\n",
    { "FIELD array big declares 3000000000 values, more than a" });
  this->ExpectError("lines.vtk", header + points + "LINES 1 3\n2 0 1\n", { "no triangles" });
}

TEST_F(MeshReaders, BadVtp)
{
  this->ExpectError("garbage.vtp", "this is not XML", { "Error parsing XML" });

  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  lines->SetPoints(points);
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell({ 0, 1 });
  lines->SetLines(cells);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(lines);
  writer->SetFileName((this->Dir / "nan.vtp").c_str());
  ASSERT_TRUE(writer->Write());
  this->ExpectError(this->Dir / "nan.vtp", { "NaN coordinate in vertex 1" });

  points->SetPoint(1, 1, 0, 0);
  writer->SetFileName((this->Dir / "lines.vtp").c_str());
  ASSERT_TRUE(writer->Write());
  this->ExpectError(this->Dir / "lines.vtp", { "no triangles" });
}
}
