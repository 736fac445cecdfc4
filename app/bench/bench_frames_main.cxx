// shadelab-bench-frames: ms per frame of each shading rule through the
// OSMesa backend, side by side in one run with VTK's own flat, Gouraud and
// Phong (the peer a user would pick instead), with the all-features
// program that per-scene generation is measured against, and with VTK's
// unlit surface (one colour, positions alone: no normals, no lighting), the
// least any shading rule's frame can cost through this mapper; and ours with
// distance attenuation (1, 0.05, 0.01 on the light at the camera) and with
// fog (exp2:0.1), each effect's cost against the same rule without it; and
// the wireframe (1 pixel) and points (1 pixel) under each of ours, beside
// VTK's own Phong wireframe through VTK's own mapper (a shared edge drawn
// once for each of its triangles), the picture a user would get instead.
//
//   shadelab-bench-frames MESH [--size WxH] [--frames N] [--subdivide LEVELS]
//                         [--vertex-colors] [--texture] [--parts N]
//
// --vertex-colors gives every point a colour (from its position in the
// bounding box), which our variants light as per-vertex kd: the cost of
// vertex colours against the same run without them. --texture gives every
// point texture coordinates (its x and y in the bounding box) and our
// variants a 1024 x 1024 float checker for kd and ka (as --texture IMAGE,
// bilinear, repeat): the cost of a texture. --parts N deals the triangles
// into N parts, each with a material of its own (an actor each): the cost of
// many parts against the same run with one; VTK's variants and the
// all-features program are left out then (they draw one actor).
// Each variant gets a fresh OpenGL context, so its first frame includes
// compiling its programs; run with MESA_SHADER_CACHE_DISABLE=true to measure
// compilation (scripts/bench-shading does).
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/options.h"
#include "headless/headless_renderer.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVertexTangents.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkLight.h>
#include <vtkLogger.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

using namespace shadelab;

namespace
{
struct Variant
{
  std::string Name;
  Shading Rule;
  bool VtkOwn = false;
  bool AllFeatures = false;
  bool Unlit = false;      // VTK's own, lighting off, drawn from positions alone
  bool Attenuated = false; // ours with distance attenuation: its cost against the same rule's
  bool Fogged = false;     // ours with fog: the same
  Representation Drawn = Representation::Surface;
  bool Reflecting = false; // ours with an environment (a 1024 checker): the same
  bool Mapping = false;    // ours with a normal map (a 1024 checker): the same
  bool Bumping = false;    // ours with a bump map (the grey checker as heights): the same
};

// VTK's own lighting for rule: its per-fragment Phong-model code, its
// interpolation setting, one positional VTK light where ours would be.
void UseVtkLighting(const SceneOptions& o, Shading rule, vtkRenderer* renderer, vtkActor* actor)
{
  const Material m = o.EffectiveMaterial();
  vtkProperty* p = actor->GetProperty();
  actor->GetShaderProperty()->ClearAllShaderReplacements();
  vtkPolyDataMapper::SafeDownCast(actor->GetMapper())->RemoveAllVertexAttributeMappings();
  switch (rule)
  {
    case Shading::None:
    case Shading::Flat:
      p->SetInterpolation(VTK_FLAT);
      break;
    case Shading::Gouraud:
      p->SetInterpolation(VTK_GOURAUD);
      break;
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
      p->SetInterpolation(VTK_PHONG);
      break;
  }
  p->SetAmbient(1);
  p->SetAmbientColor(m.Ka[0] * o.Ambient[0], m.Ka[1] * o.Ambient[1], m.Ka[2] * o.Ambient[2]);
  p->SetDiffuse(1);
  p->SetDiffuseColor(m.Kd.data());
  p->SetSpecular(1);
  p->SetSpecularColor(m.Ks.data());
  p->SetSpecularPower(m.Ns);
  renderer->RemoveAllLights();
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->PositionalOn();
  light->SetConeAngle(180);
  light->SetPosition(renderer->GetActiveCamera()->GetPosition());
  renderer->AddLight(light);
}

// A point array `name` from each point's position in the mesh's bounding
// box, scaled to [0, 1]: colours r, g, b (and alpha 1) with 4 components,
// texture coordinates x, y with 2.
void AddPositionArray(vtkPolyData* mesh, const char* name, int components)
{
  double b[6];
  mesh->GetBounds(b);
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    float value[4] = { 0, 0, 0, 1 };
    for (int c = 0; c < std::min(components, 3); ++c)
    {
      value[c] = static_cast<float>((p[c] - b[2 * c]) / std::max(b[2 * c + 1] - b[2 * c], 1e-30));
    }
    array->SetTypedTuple(i, value);
  }
  mesh->GetPointData()->AddArray(array);
}

// A side x side checker of 32 squares a side, linear 0.8 and 0.2.
std::shared_ptr<const TextureImage> Checker(int side)
{
  auto image = std::make_shared<TextureImage>();
  image->Width = image->Height = side;
  for (int j = 0; j < side; ++j)
  {
    for (int i = 0; i < side; ++i)
    {
      const float v = ((i * 32 / side) + (j * 32 / side)) % 2 ? 0.8f : 0.2f;
      image->Pixels.insert(image->Pixels.end(), { v, v, v });
    }
  }
  return image;
}

// n parts in bands of cell indices (as an OBJ's usemtl runs are), each with
// a material of its own: the lecture's table in turn, each ns different, so
// that no two parts share an actor.
void AddParts(vtkPolyData* mesh, int n)
{
  auto part = vtkSmartPointer<vtkIntArray>::New();
  part->SetName(PartArrayName);
  const vtkIdType cells = mesh->GetNumberOfCells();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    part->InsertNextValue(static_cast<int>(c * n / cells));
  }
  mesh->GetCellData()->AddArray(part);
  std::vector<PartMaterial> materials;
  for (int p = 0; p < n; ++p)
  {
    PartMaterial m;
    m.Name = "part" + std::to_string(p);
    m.Index = p;
    m.Coefficients = LectureMaterials()[p % LectureMaterials().size()];
    m.Coefficients.Ns += p;
    materials.push_back(m);
  }
  AddPartMaterials(materials, mesh);
}
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app(
    "ms per frame of each shading rule, ours against VTK's own", "shadelab-bench-frames");
  SceneOptions o;
  std::string size = "1920x1080";
  int frames = 10;
  int subdivide = 0;
  bool vertexColors = false;
  int parts = 1;
  bool texture = false;
  app.add_option("MESH", o.Mesh)->required();
  app.add_option("--size", size);
  app.add_option("--frames", frames)->check(CLI::Range(1, 1000));
  app.add_option("--subdivide", subdivide, "Loop subdivision levels first")
    ->check(CLI::Range(0, 4));
  app.add_flag("--vertex-colors", vertexColors, "Colour the points, lit as per-vertex kd");
  app.add_option("--parts", parts, "Deal the triangles into N parts of their own materials")
    ->check(CLI::Range(1, 1000));
  app.add_flag("--texture", texture, "A checker texture for kd and ka of our variants");
  CLI11_PARSE(app, argc, argv);
  o.Size = ParseSize(size);

  o.ShadingRule = Shading::Phong; // normals for the lit rules
  LoadedMesh loaded = LoadMesh(o);
  if (!loaded.Mesh)
  {
    return ReportError(o.Mesh, loaded.Error);
  }
  vtkSmartPointer<vtkPolyData> mesh = loaded.Mesh;
  if (subdivide > 0)
  {
    mesh = ComputeNormals(LoopSubdivided(mesh, subdivide), o.Computed).Mesh;
  }
  if (vertexColors || texture || parts > 1)
  {
    auto added = vtkSmartPointer<vtkPolyData>::New();
    added->ShallowCopy(mesh); // its own attributes, sharing the arrays
    if (vertexColors)
    {
      AddPositionArray(added, ColorsArrayName, 4);
    }
    if (texture)
    {
      AddPositionArray(added, TextureCoordinatesArrayName, 2);
    }
    if (parts > 1)
    {
      AddParts(added, parts);
    }
    mesh = added;
  }
  std::shared_ptr<const TextureImage> checker;
  if (texture)
  {
    o.Texture = "checker"; // decoded already: Checker
    checker = Checker(1024);
  }

  const std::shared_ptr<const TextureImage> environment = Checker(1024);
  // The normal and bump maps' variants: texture coordinates where the mesh has none,
  // and the tangents of its frame.
  auto mapped = vtkSmartPointer<vtkPolyData>::New();
  mapped->ShallowCopy(mesh);
  if (!mapped->GetPointData()->GetArray(TextureCoordinatesArrayName))
  {
    AddPositionArray(mapped, TextureCoordinatesArrayName, 2);
  }
  mapped->GetPointData()->AddArray(VertexTangents(mapped));
  const std::vector<Variant> variants = { { "vtk-flat", Shading::Flat, true },
    { "vtk-gouraud", Shading::Gouraud, true }, { "vtk-phong", Shading::Phong, true },
    { "vtk-unlit", Shading::Phong, true, false, true }, { "flat", Shading::Flat },
    { "gouraud", Shading::Gouraud }, { "phong", Shading::Phong },
    { "flat-allfeatures", Shading::Flat, false, true },
    { "gouraud-allfeatures", Shading::Gouraud, false, true },
    { "phong-allfeatures", Shading::Phong, false, true },
    { "flat-attenuated", Shading::Flat, false, false, false, true },
    { "gouraud-attenuated", Shading::Gouraud, false, false, false, true },
    { "phong-attenuated", Shading::Phong, false, false, false, true },
    { "flat-fogged", Shading::Flat, false, false, false, false, true },
    { "gouraud-fogged", Shading::Gouraud, false, false, false, false, true },
    { "phong-fogged", Shading::Phong, false, false, false, false, true },
    { "vtk-phong-wireframe", Shading::Phong, true, false, false, false, false,
      Representation::Wireframe },
    { "flat-wireframe", Shading::Flat, false, false, false, false, false,
      Representation::Wireframe },
    { "gouraud-wireframe", Shading::Gouraud, false, false, false, false, false,
      Representation::Wireframe },
    { "phong-wireframe", Shading::Phong, false, false, false, false, false,
      Representation::Wireframe },
    { "phong-points", Shading::Phong, false, false, false, false, false, Representation::Points },
    { "flat-environment", Shading::Flat, false, false, false, false, false, Representation::Surface,
      true },
    { "gouraud-environment", Shading::Gouraud, false, false, false, false, false,
      Representation::Surface, true },
    { "phong-environment", Shading::Phong, false, false, false, false, false,
      Representation::Surface, true },
    { "flat-normal-map", Shading::Flat, false, false, false, false, false, Representation::Surface,
      false, true },
    { "gouraud-normal-map", Shading::Gouraud, false, false, false, false, false,
      Representation::Surface, false, true },
    { "phong-normal-map", Shading::Phong, false, false, false, false, false,
      Representation::Surface, false, true },
    { "flat-bump-map", Shading::Flat, false, false, false, false, false, Representation::Surface,
      false, false, true },
    { "gouraud-bump-map", Shading::Gouraud, false, false, false, false, false,
      Representation::Surface, false, false, true },
    { "phong-bump-map", Shading::Phong, false, false, false, false, false,
      Representation::Surface, false, false, true } };

  std::printf(
    "| variant | first frame ms | median ms/frame | min | max |\n|---|---:|---:|---:|---:|\n");
  for (const Variant& v : variants)
  {
    if (parts > 1 && (v.VtkOwn || v.AllFeatures))
    {
      continue;
    }
    SceneOptions scene = o;
    scene.ShadingRule = v.Rule;
    if (v.Attenuated)
    {
      scene.Attenuation = { 1, 0.05, 0.01 };
    }
    if (v.Fogged)
    {
      scene.Fogging = ParseFog("exp2:0.1");
    }
    scene.Drawn = v.Drawn;
    if (v.Reflecting)
    {
      scene.Environment = "checker"; // decoded already: environment below
    }
    if (v.Mapping)
    {
      scene.NormalMap = ScaledImage{ "checker", 1 }; // decoded already: environment's image
    }
    if (v.Bumping)
    {
      scene.BumpMap = ScaledImage{ "checker", 1 }; // the same
    }
    const bool relief = v.Mapping || v.Bumping;
    HeadlessRenderer renderer;
    if (const std::string error = renderer.Start(o.Size.Width, o.Size.Height); !error.empty())
    {
      return ReportError("render", error);
    }
    // One actor but with --parts, where only ours run.
    const DrawnParts built =
      BuildScene(scene, relief ? mapped : mesh, renderer.GetRenderer(), nullptr,
        SceneImages{
          checker, {}, v.Reflecting ? environment : nullptr, relief ? environment : nullptr })
        .Drawn.front();
    if (v.VtkOwn)
    {
      built.Actor->GetMapper()->RemoveAllObservers();
      vtkSmartPointer<vtkPolyData> drawn = mesh;
      if (v.Unlit)
      {
        drawn = vtkSmartPointer<vtkPolyData>::New();
        drawn->SetPoints(mesh->GetPoints());
        drawn->SetPolys(mesh->GetPolys());
      }
      if (v.Drawn != Representation::Surface)
      {
        built.Actor->SetMapper(vtkSmartPointer<vtkOpenGLPolyDataMapper>::New());
      }
      vtkPolyDataMapper::SafeDownCast(built.Actor->GetMapper())->SetInputData(drawn);
      UseVtkLighting(scene, v.Rule, renderer.GetRenderer(), built.Actor);
      built.Actor->GetProperty()->SetLighting(!v.Unlit);
    }
    else if (v.AllFeatures)
    {
      built.Shading->SetAllFeatures(true);
      built.Shading->Attach(built.Actor, renderer.GetRenderer());
    }
    auto t0 = std::chrono::steady_clock::now();
    renderer.Render();
    auto t1 = std::chrono::steady_clock::now();
    std::vector<double> times;
    for (int i = 0; i < frames; ++i)
    {
      // A new camera position each frame, so nothing can be reused.
      renderer.GetRenderer()->GetActiveCamera()->Azimuth(0.5);
      const auto a = std::chrono::steady_clock::now();
      renderer.Render();
      times.push_back(Milliseconds(a, std::chrono::steady_clock::now()));
    }
    std::sort(times.begin(), times.end());
    std::printf("| %s | %.1f | %.1f | %.1f | %.1f |\n", v.Name.c_str(), Milliseconds(t0, t1),
      times[times.size() / 2], times.front(), times.back());
    std::fflush(stdout);
  }
  return 0;
}
