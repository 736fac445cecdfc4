#include "mesh_reader_fixture.h"

#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLogger.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

namespace shadelab::test
{
namespace
{
// VTK 9.1 also logs each error, several lines long, to stderr; the captured
// one line is what the tests look at.
[[maybe_unused]] const bool QuietLogger = []
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  return true;
}();

void ExpectPointArray(vtkPolyData* mesh, const char* name, int components)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name);
  if (array)
  {
    EXPECT_TRUE(vtkFloatArray::SafeDownCast(array)) << name;
    EXPECT_EQ(array->GetNumberOfComponents(), components) << name;
    EXPECT_EQ(array->GetNumberOfTuples(), mesh->GetNumberOfPoints()) << name;
  }
}
}

ReadResult ReadWith(vtkShadelabFileReader* reader, const fs::path& path)
{
  const shadelab::MessageScope messages;
  reader->SetFileName(path.c_str());
  ReadResult result;
  result.Ok = reader->GetExecutive()->Update() != 0;
  result.Mesh = reader->GetOutput();
  result.Error = messages.FirstError();
  result.ErrorCode = reader->GetErrorCode();
  result.Warnings = messages.Warnings();
  return result;
}

ReadResult Read(const fs::path& path)
{
  vtkNew<vtkShadelabMeshReader> reader;
  return ReadWith(reader, path);
}

std::vector<std::array<vtkIdType, 3>> Triangles(vtkPolyData* mesh)
{
  std::vector<std::array<vtkIdType, 3>> triangles;
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cell->GetCurrentCell(size, ids);
    EXPECT_EQ(size, 3);
    triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  return triangles;
}

std::array<double, 3> AreaNormal(vtkPolyData* mesh, const std::array<vtkIdType, 3>& triangle)
{
  double a[3], b[3], c[3], ab[3], ac[3];
  mesh->GetPoint(triangle[0], a);
  mesh->GetPoint(triangle[1], b);
  mesh->GetPoint(triangle[2], c);
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
  }
  std::array<double, 3> n;
  vtkMath::Cross(ab, ac, n.data());
  return n;
}

void ExpectTriangleMesh(vtkPolyData* mesh)
{
  ASSERT_NE(mesh->GetPoints(), nullptr);
  // Double, or float where the file stores 32-bit floats (kept exactly).
  EXPECT_TRUE(mesh->GetPoints()->GetDataType() == VTK_DOUBLE ||
    mesh->GetPoints()->GetDataType() == VTK_FLOAT);
  EXPECT_EQ(mesh->GetNumberOfVerts() + mesh->GetNumberOfLines() + mesh->GetNumberOfStrips(), 0);
  EXPECT_GT(mesh->GetNumberOfPolys(), 0);
  EXPECT_EQ(mesh->GetPolys()->IsHomogeneous(), 3);
  double p[3];
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, p);
    ASSERT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << i;
  }
  vtkPointData* pointData = mesh->GetPointData();
  vtkDataArray* normals = pointData->GetNormals();
  const int named = (normals ? 1 : 0) + (pointData->GetArray(ColorsArrayName) ? 1 : 0) +
    (pointData->GetArray(TextureCoordinatesArrayName) ? 1 : 0) +
    (pointData->GetArray(FileVertexArrayName) ? 1 : 0);
  EXPECT_EQ(pointData->GetNumberOfArrays(), named);
  if (normals)
  {
    EXPECT_STREQ(normals->GetName(), "Normals");
  }
  ExpectPointArray(mesh, "Normals", 3);
  ExpectPointArray(mesh, ColorsArrayName, 4);
  ExpectPointArray(mesh, TextureCoordinatesArrayName, 2);
  if (auto* fileVertices = vtkIdTypeArray::SafeDownCast(pointData->GetArray(FileVertexArrayName)))
  {
    const vtkIdType points = mesh->GetNumberOfPoints();
    ASSERT_EQ(fileVertices->GetNumberOfTuples(), points);
    for (vtkIdType i = 0; i < points; ++i)
    {
      // A copy of a file vertex, at its position.
      const vtkIdType vertex = fileVertices->GetValue(i);
      ASSERT_TRUE(vertex >= 0 && vertex < points) << i;
      double a[3], b[3];
      mesh->GetPoint(i, a);
      mesh->GetPoint(vertex, b);
      EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << i;
    }
  }
  else
  {
    EXPECT_EQ(pointData->GetArray(FileVertexArrayName), nullptr) << "not vtkIdType";
  }
}

void MeshReaders::SetUp()
{
  std::string pattern = (fs::temp_directory_path() / "shadelab-readers-XXXXXX").string();
  ASSERT_NE(mkdtemp(pattern.data()), nullptr);
  this->Dir = pattern;
}

void MeshReaders::TearDown()
{
  fs::remove_all(this->Dir);
}

fs::path MeshReaders::Write(const std::string& name, const std::string& bytes) const
{
  const fs::path path = this->Dir / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

void MeshReaders::ExpectError(
  const std::string& name, const std::string& bytes, std::initializer_list<const char*> keyWords)
{
  this->ExpectError(this->Write(name, bytes), keyWords);
}

void MeshReaders::ExpectError(const fs::path& path, std::initializer_list<const char*> keyWords)
{
  SCOPED_TRACE(path.filename().string());
  const ReadResult result = Read(path);
  EXPECT_FALSE(result.Ok);
  EXPECT_NE(result.ErrorCode, vtkErrorCode::NoError);
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 0);
  EXPECT_EQ(result.Mesh->GetNumberOfCells(), 0);
  ASSERT_FALSE(result.Error.empty());
  EXPECT_EQ(result.Error.find('\n'), std::string::npos);
  for (const char* word : keyWords)
  {
    EXPECT_NE(result.Error.find(word), std::string::npos)
      << "'" << word << "' not in: " << result.Error;
  }
}

void ExpectMtlErrors(const std::vector<std::pair<std::string, std::string>>& mistakes)
{
  for (const auto& [text, message] : mistakes)
  {
    try
    {
      ParseMtl(text);
      ADD_FAILURE() << "no error for " << text;
    }
    catch (const MeshReadError& e)
    {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}
}
