// Flat shading's picture from vtkShadelabFlatTriangles (provoking points of
// their own, the other points shared) against the picture from the exploded
// mesh (every triangle three points of its own), in one OpenGL context, bit
// for bit: the same triangles in the same order, the same positions, the
// same face normal at the same provoking vertex, so nothing may differ. On
// the bunny with vertex colours (per-vertex kd) and a point that no triangle
// uses, just off the bunny (the exploded mesh has no such point; the
// filter leaves it out).
#include "exploded_flat_mesh.h"
#include "headless/headless_renderer.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"
#include "shadelabTriangleMesh.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

namespace
{
namespace fs = std::filesystem;
using namespace shadelab;

// The bunny as shadelab reads it, with colours from the points' positions
// and one more point, used by no triangle.
vtkSmartPointer<vtkPolyData> ColouredBunnyWithUnusedPoint(const SceneOptions& options)
{
  const LoadedMesh loaded = LoadMesh(options);
  EXPECT_TRUE(loaded.Mesh) << loaded.Error;
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(loaded.Mesh);
  mesh->GetPoints()->InsertNextPoint(0.08, 0.2, 0.08); // just beyond the bunny;
  auto colors = vtkSmartPointer<vtkFloatArray>::New();
  colors->SetName(ColorsArrayName);
  colors->SetNumberOfComponents(4);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const double* p = mesh->GetPoint(i);
    colors->InsertNextTuple4(0.5 + 4 * p[0], 0.5 + 4 * p[1], 0.5 + 4 * p[2], 1);
  }
  mesh->GetPointData()->Initialize();
  mesh->GetPointData()->AddArray(colors);
  return mesh;
}

TEST(FlatTrianglesRender, BitIdenticalToTheExplodedMesh)
{
  SceneOptions options;
  options.Mesh = (fs::path(SHADELAB_TEST_MESHES) / "stanford-bunny.obj").string();
  options.ShadingRule = Shading::Flat;
  options.Size = { 480, 360 };
  const vtkSmartPointer<vtkPolyData> mesh = ColouredBunnyWithUnusedPoint(options);
  HeadlessRenderer renderer;
  ASSERT_EQ(renderer.Start(options.Size.Width, options.Size.Height), "");
  const BuiltScene scene = BuildScene(options, mesh, renderer.GetRenderer());
  ASSERT_EQ(scene.Error, "");
  ASSERT_EQ(scene.Drawn.size(), 1U);
  const FloatImage shared = renderer.Render();
  ASSERT_EQ(renderer.GetError(), "");

  vtkPolyDataMapper::SafeDownCast(scene.Drawn.front().Actor->GetMapper())
    ->SetInputData(ExplodedFlatMesh(mesh));
  const FloatImage exploded = renderer.Render();
  ASSERT_EQ(renderer.GetError(), "");

  ASSERT_EQ(shared.Rgba.size(), exploded.Rgba.size());
  // Not a blank picture: the bunny covers about a quarter of it, in many
  // colours (the vertex colours vary across it).
  int covered = 0;
  for (size_t i = 0; i < shared.Rgba.size(); i += 4)
  {
    covered += shared.Rgba[i] != shared.Rgba[0] || shared.Rgba[i + 1] != shared.Rgba[1];
  }
  EXPECT_GT(covered, options.Size.Width * options.Size.Height / 10);
  EXPECT_EQ(
    std::memcmp(shared.Rgba.data(), exploded.Rgba.data(), shared.Rgba.size() * sizeof(float)), 0);
}
}
