// vtkShadelabMeshNormals on points that a reader split at a texture's seams
// (the point data FileVertex): the normals are the file vertices' own,
// exactly those of the same file without its vt, for every weighting, with
// and without feature-angle splitting and consistent orientation, while the
// texture coordinates stay split; a malformed FileVertex is an error.
#include "shadelabTriangleMesh.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using Triangle = std::array<vtkIdType, 3>;

const fs::path TestMeshes = fs::path(SHADELAB_TEST_MESHES);

std::string FileText(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

// An OBJ's text with its lines changed by `edit` (a line for each line;
// "" drops it).
std::string EditLines(const std::string& text, const std::function<std::string(std::string)>& edit)
{
  std::istringstream in(text);
  std::string result, line;
  while (std::getline(in, line))
  {
    const std::string edited = edit(line);
    if (!edited.empty())
    {
      result += edited + "\n";
    }
  }
  return result;
}

// The OBJ without its texture coordinates: no vt lines, corners v only.
std::string WithoutVt(const std::string& text)
{
  return EditLines(text,
    [](const std::string& line)
    {
      if (line.compare(0, 3, "vt ") == 0)
      {
        return std::string();
      }
      if (line.compare(0, 2, "f ") != 0)
      {
        return line;
      }
      std::istringstream corners(line.substr(2));
      std::string face = "f", corner;
      while (corners >> corner)
      {
        face += " " + corner.substr(0, corner.find('/'));
      }
      return face;
    });
}

// The first face turned round (its last two corners swapped): what
// Consistency turns back.
std::string FirstFaceReversed(const std::string& text)
{
  bool done = false;
  return EditLines(text,
    [&](const std::string& line)
    {
      if (done || line.compare(0, 2, "f ") != 0)
      {
        return line;
      }
      done = true;
      std::istringstream corners(line.substr(2));
      std::string a, b, c;
      corners >> a >> b >> c;
      return "f " + a + " " + c + " " + b;
    });
}

class FileVertexNormals : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern = (fs::temp_directory_path() / "shadelab-file-vertices-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    this->Dir = pattern;
  }
  void TearDown() override { fs::remove_all(this->Dir); }

  vtkSmartPointer<vtkPolyData> Read(const std::string& name, const std::string& text) const
  {
    const fs::path path = this->Dir / name;
    std::ofstream(path, std::ios::binary) << text;
    auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
    reader->SetFileName(path.c_str());
    EXPECT_TRUE(reader->GetExecutive()->Update()) << name;
    return reader->GetOutput();
  }

  fs::path Dir;
};

struct Settings
{
  const char* Weighting;
  bool Splitting;
  bool Consistency;
};

vtkSmartPointer<vtkPolyData> Normals(vtkPolyData* mesh, const Settings& settings)
{
  auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  filter->SetInputData(mesh);
  filter->SetWeightingByName(settings.Weighting);
  filter->SetSplitting(settings.Splitting);
  filter->SetFeatureAngle(30);
  filter->SetConsistency(settings.Consistency);
  EXPECT_TRUE(filter->GetExecutive()->Update());
  return filter->GetOutput();
}

std::vector<Triangle> Triangles(vtkPolyData* mesh)
{
  std::vector<Triangle> triangles;
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cell->GetCurrentCell(size, ids);
    triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  return triangles;
}

// Corner by corner, `split`'s normals (computed on the points a seam split)
// are exactly `whole`'s (the file without vt), at the same positions; each
// corner of `split` keeps the texture coordinates that the input's corner
// at that position had in the same face.
void ExpectSameNormalsPerCorner(vtkPolyData* input, vtkPolyData* split, vtkPolyData* whole)
{
  const auto inputTriangles = Triangles(input);
  const auto splitTriangles = Triangles(split);
  const auto wholeTriangles = Triangles(whole);
  ASSERT_EQ(splitTriangles.size(), wholeTriangles.size());
  vtkDataArray* splitNormals = split->GetPointData()->GetNormals();
  vtkDataArray* wholeNormals = whole->GetPointData()->GetNormals();
  vtkDataArray* inputST = input->GetPointData()->GetTCoords();
  vtkDataArray* splitST = split->GetPointData()->GetTCoords();
  ASSERT_TRUE(splitNormals && wholeNormals && inputST && splitST);
  int differences = 0;
  for (std::size_t f = 0; f < splitTriangles.size() && differences < 10; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType s = splitTriangles[f][k], w = wholeTriangles[f][k];
      double ps[3], pw[3], ns[3], nw[3];
      split->GetPoint(s, ps);
      whole->GetPoint(w, pw);
      splitNormals->GetTuple(s, ns);
      wholeNormals->GetTuple(w, nw);
      const bool same = ps[0] == pw[0] && ps[1] == pw[1] && ps[2] == pw[2] && ns[0] == nw[0] &&
        ns[1] == nw[1] && ns[2] == nw[2];
      int sameST = 0;
      for (const vtkIdType i : inputTriangles[f])
      {
        double pi[3];
        input->GetPoint(i, pi);
        sameST += pi[0] == ps[0] && pi[1] == ps[1] && pi[2] == ps[2] &&
          inputST->GetTuple2(i)[0] == splitST->GetTuple2(s)[0] &&
          inputST->GetTuple2(i)[1] == splitST->GetTuple2(s)[1];
      }
      EXPECT_TRUE(same && sameST == 1)
        << "face " << f << " corner " << k << " normal " << ns[0] << " " << ns[1] << " " << ns[2]
        << " without vt " << nw[0] << " " << nw[1] << " " << nw[2];
      differences += !same || sameST != 1;
    }
  }
}

// teapot.obj's vt split its 3,241 vertices into 3,864 where its patches
// meet; normals computed there are the same as on the file without vt, for
// every weighting, splitting and orientation. The first face is turned
// round so that Consistency has a face to turn back.
TEST_F(FileVertexNormals, NormalsAreTheSameWithAndWithoutTextureCoordinates)
{
  const std::string teapot = FirstFaceReversed(FileText(TestMeshes / "teapot.obj"));
  const vtkSmartPointer<vtkPolyData> withVt = this->Read("teapot.obj", teapot);
  const vtkSmartPointer<vtkPolyData> withoutVt = this->Read("plain.obj", WithoutVt(teapot));
  ASSERT_EQ(withVt->GetNumberOfPoints(), 3864);
  ASSERT_EQ(withoutVt->GetNumberOfPoints(), 3241);
  ASSERT_NE(withVt->GetPointData()->GetArray(shadelab::FileVertexArrayName), nullptr);
  for (const char* weighting : { "uniform", "area", "angle", "max", "loop" })
  {
    for (const bool splitting : { false, true })
    {
      for (const bool consistency : { false, true })
      {
        SCOPED_TRACE(std::string(weighting) + (splitting ? " splitting" : "") +
          (consistency ? " consistency" : ""));
        const Settings settings{ weighting, splitting, consistency };
        const vtkSmartPointer<vtkPolyData> split = Normals(withVt, settings);
        ExpectSameNormalsPerCorner(withVt, split, Normals(withoutVt, settings));
        if (!splitting)
        {
          // The seams' points stay, with their texture coordinates.
          EXPECT_EQ(split->GetNumberOfPoints(), 3864);
        }
      }
    }
  }
}

// Without FileVertex the seams crease: what the welding is for (and proof
// that the test above can tell).
TEST_F(FileVertexNormals, WithoutFileVertexTheSeamsCrease)
{
  const std::string teapot = FileText(TestMeshes / "teapot.obj");
  const vtkSmartPointer<vtkPolyData> withVt = this->Read("teapot.obj", teapot);
  withVt->GetPointData()->RemoveArray(shadelab::FileVertexArrayName);
  const Settings settings{ "angle", false, false };
  const vtkSmartPointer<vtkPolyData> split = Normals(withVt, settings);
  const vtkSmartPointer<vtkPolyData> whole =
    Normals(this->Read("plain.obj", WithoutVt(teapot)), settings);
  const auto splitTriangles = Triangles(split);
  const auto wholeTriangles = Triangles(whole);
  int creased = 0;
  for (std::size_t f = 0; f < splitTriangles.size(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double* n = split->GetPointData()->GetNormals()->GetTuple3(splitTriangles[f][k]);
      const double* m = whole->GetPointData()->GetNormals()->GetTuple3(wholeTriangles[f][k]);
      creased += std::abs(n[0] - m[0]) + std::abs(n[1] - m[1]) + std::abs(n[2] - m[2]) > 1e-3;
    }
  }
  EXPECT_GT(creased, 100);
}

// A cube whose every face has its own texture: each corner is split in
// three by its vt. With splitting at 30 degrees each point takes its face's
// normal, without it the corner's mean, exactly as for the cube without vt.
TEST_F(FileVertexNormals, ATexturedCubesNormalsAreTheCubes)
{
  const std::string cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\n"
                           "v 0 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                           "f 1/1 4/2 3/3 2/4\nf 5/1 6/2 7/3 8/4\nf 1/1 2/2 6/3 5/4\n"
                           "f 2/1 3/2 7/3 6/4\nf 3/1 4/2 8/3 7/4\nf 4/1 1/2 5/3 8/4\n";
  const vtkSmartPointer<vtkPolyData> withVt = this->Read("cube.obj", cube);
  EXPECT_GT(withVt->GetNumberOfPoints(), 8);
  const vtkSmartPointer<vtkPolyData> withoutVt = this->Read("plain.obj", WithoutVt(cube));
  for (const bool splitting : { false, true })
  {
    SCOPED_TRACE(splitting ? "splitting" : "smooth");
    const Settings settings{ "angle", splitting, false };
    ExpectSameNormalsPerCorner(withVt, Normals(withVt, settings), Normals(withoutVt, settings));
  }
}

TEST_F(FileVertexNormals, AMalformedFileVertexIsAnError)
{
  const vtkSmartPointer<vtkPolyData> mesh = this->Read(
    "cube.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 1\nf 1/1 2/1 3/1\nf 1/2 3/1 2/1\n");
  auto* fileVertices =
    vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray(shadelab::FileVertexArrayName));
  ASSERT_NE(fileVertices, nullptr);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the captured line is enough
  const auto expectError = [&](const char* expected)
  {
    auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
    filter->SetInputData(mesh);
    const shadelab::MessageScope messages;
    EXPECT_FALSE(filter->GetExecutive()->Update());
    EXPECT_NE(messages.ErrorOr("").find(expected), std::string::npos) << messages.ErrorOr("");
  };
  fileVertices->SetValue(3, 4);
  fileVertices->Modified();
  expectError("FileVertex of point 3 is 4, not a point's number");
  vtkNew<vtkFloatArray> floats;
  floats->SetName(shadelab::FileVertexArrayName);
  floats->SetNumberOfValues(mesh->GetNumberOfPoints());
  mesh->GetPointData()->AddArray(floats);
  expectError("FileVertex is not one id per point");
}
}
