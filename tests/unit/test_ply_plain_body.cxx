// The binary PLY reader's direct path (shadelabPLYPlainBody): which bodies
// take it, that they read to exactly what the general parser makes of the
// same mesh, and that anything unusual is left to the general parser's
// words.
#include "mesh_reader_fixture.h"
#include "shadelabPLYHeader.h"
#include "shadelabPLYPlainBody.h"
#include "shadelabTextScanner.h"

#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace
{
using namespace shadelab::test;

// A small mesh of triangles, a quad and a pentagon over an uneven grid of
// 4 x 3 points (coordinates with all of a float's bits in use).
const int Columns = 4;
const std::vector<std::vector<int>> Faces = { { 0, 1, 5 }, { 0, 5, 4 }, { 1, 2, 6, 5 },
  { 2, 3, 7, 11, 6 }, { 4, 5, 9 }, { 4, 9, 8 }, { 5, 6, 10 }, { 5, 10, 9 } };

float Coordinate(int point, int axis)
{
  return static_cast<float>((point % Columns) * (axis == 0) + (point / Columns) * (axis == 1)) +
    1.0f / static_cast<float>(3 + 7 * point + axis);
}

// The list types: PLY's name, and a writer of one value of it.
struct ListType
{
  const char* Name;
  void (*Put)(std::string&, long long, bool);
};

template <typename T>
void PutAs(std::string& bytes, long long value, bool bigEndian)
{
  Put(bytes, static_cast<T>(value), bigEndian);
}

const ListType Char{ "char", &PutAs<std::int8_t> };
const ListType UChar{ "uchar", &PutAs<std::uint8_t> };
const ListType Short{ "short", &PutAs<std::int16_t> };
const ListType UInt16{ "uint16", &PutAs<std::uint16_t> };
const ListType Int{ "int", &PutAs<std::int32_t> };
const ListType UInt32{ "uint32", &PutAs<std::uint32_t> };

struct PlyFile
{
  bool BigEndian = false;
  ListType Count = UChar;
  ListType Index = Int;
  // A second face property: the body is then not plain.
  bool FaceFlag = false;
  std::vector<std::vector<long long>> Lists;
};

// The mesh as a binary PLY: vertices x y z and a skipped "quality" between
// them, a skipped "edge" element, then the faces.
std::string Bytes(const PlyFile& file)
{
  const int points = 12;
  std::string bytes = std::string("ply\nformat ") +
    (file.BigEndian ? "binary_big_endian" : "binary_little_endian") + " 1.0\nelement vertex " +
    std::to_string(points) +
    "\nproperty float x\nproperty uchar quality\nproperty float y\nproperty float z\n"
    "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
    "element face " +
    std::to_string(file.Lists.size()) + "\nproperty list " + file.Count.Name + " " +
    file.Index.Name + " vertex_indices\n" + (file.FaceFlag ? "property uchar flags\n" : "") +
    "end_header\n";
  for (int p = 0; p < points; ++p)
  {
    Put(bytes, Coordinate(p, 0), file.BigEndian);
    Put(bytes, std::uint8_t{ 9 }, file.BigEndian);
    Put(bytes, Coordinate(p, 1), file.BigEndian);
    Put(bytes, Coordinate(p, 2), file.BigEndian);
  }
  Put(bytes, std::int32_t{ 0 }, file.BigEndian);
  Put(bytes, std::int32_t{ 1 }, file.BigEndian);
  for (const auto& list : file.Lists)
  {
    file.Count.Put(bytes, static_cast<long long>(list.size()), file.BigEndian);
    for (const long long index : list)
    {
      file.Index.Put(bytes, index, file.BigEndian);
    }
    if (file.FaceFlag)
    {
      Put(bytes, std::uint8_t{ 1 }, file.BigEndian);
    }
  }
  return bytes;
}

PlyFile MeshFile()
{
  PlyFile file;
  for (const auto& face : Faces)
  {
    file.Lists.emplace_back(face.begin(), face.end());
  }
  return file;
}

// Whether the direct path reads `bytes`'s body (header parsed as the reader does).
bool ReadsPlain(const std::string& bytes)
{
  shadelab::TextScanner scanner(bytes);
  shadelab::ply::Header header = shadelab::ply::ReadHeader(bytes, scanner);
  shadelab::ply::AssignRoles(header);
  return shadelab::ply::ReadPlainBody(
           std::string_view(bytes).substr(scanner.GetNextLineOffset()), header) != nullptr;
}

TEST_F(MeshReaders, PlainPlyBodiesReadAsTheGeneralParserReadsThem)
{
  const std::vector<std::pair<ListType, ListType>> types = { { UChar, Int }, { UChar, UInt32 },
    { Char, Short }, { UInt16, UInt16 }, { Int, Int }, { UInt32, UInt32 } };
  for (const bool bigEndian : { false, true })
  {
    for (const auto& [count, index] : types)
    {
      SCOPED_TRACE(std::string(bigEndian ? "big" : "little") + " endian, list " + count.Name + " " +
        index.Name);
      PlyFile file = MeshFile();
      file.BigEndian = bigEndian;
      file.Count = count;
      file.Index = index;
      const std::string plainBytes = Bytes(file);
      file.FaceFlag = true;
      const std::string generalBytes = Bytes(file);
      ASSERT_TRUE(ReadsPlain(plainBytes));
      ASSERT_FALSE(ReadsPlain(generalBytes));

      const ReadResult plain = Read(this->Write("plain.ply", plainBytes));
      const ReadResult general = Read(this->Write("general.ply", generalBytes));
      ASSERT_TRUE(plain.Ok) << plain.Error;
      ASSERT_TRUE(general.Ok) << general.Error;
      ExpectTriangleMesh(plain.Mesh);
      ASSERT_EQ(plain.Mesh->GetNumberOfPoints(), 12);
      ASSERT_EQ(general.Mesh->GetNumberOfPoints(), 12);
      EXPECT_EQ(plain.Mesh->GetPoints()->GetDataType(), VTK_FLOAT);
      for (vtkIdType p = 0; p < 12; ++p)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          EXPECT_EQ(plain.Mesh->GetPoint(p)[axis], Coordinate(static_cast<int>(p), axis));
          EXPECT_EQ(general.Mesh->GetPoint(p)[axis], Coordinate(static_cast<int>(p), axis));
        }
      }
      // 6 triangles, a quad's 2 and a pentagon's 3, in the file's order.
      EXPECT_EQ(Triangles(plain.Mesh).size(), 11u);
      EXPECT_EQ(Triangles(plain.Mesh), Triangles(general.Mesh));
    }
  }
}

TEST_F(MeshReaders, PlyBodiesThatAreNotPlainOrNotUsualGoToTheGeneralParser)
{
  PlyFile file = MeshFile();
  file.Count = Char;
  file.Lists[3] = {};
  // Face 3's length byte, before the 4 triangles of 1 + 3 * 4 bytes after it, said -1.
  std::string negative = Bytes(file);
  negative[negative.size() - 4 * 13 - 1] = static_cast<char>(-1);
  EXPECT_FALSE(ReadsPlain(negative));
  this->ExpectError("negative.ply", negative, { "face 3 has a negative list length" });

  file = MeshFile();
  file.Index = UInt32;
  file.Lists[2][1] = 3000000000;
  EXPECT_FALSE(ReadsPlain(Bytes(file)));
  this->ExpectError("far.ply", Bytes(file), { "face 2 refers to vertex 3000000000" });

  // In 32 bits but out of range: read as it is, and refused after.
  file.Index = Int;
  file.Lists[2][1] = 12;
  EXPECT_TRUE(ReadsPlain(Bytes(file)));
  this->ExpectError("range.ply", Bytes(file), { "face 2 refers to vertex 12, but only 12" });

  file = MeshFile();
  const std::string whole = Bytes(file);
  const std::string cut = whole.substr(0, whole.size() - 5);
  EXPECT_FALSE(ReadsPlain(cut));
  this->ExpectError(
    "cut.ply", cut, { "truncated: header declares 8 faces but the file ends after 7" });

  // Double coordinates are the general parser's.
  std::string doubles = whole;
  doubles.replace(doubles.find("float z"), 7, "float64 z");
  EXPECT_FALSE(ReadsPlain(doubles));
}
}
