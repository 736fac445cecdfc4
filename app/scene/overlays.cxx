#include "scene/overlays.h"

#include "scene/mesh_cache.h"

#include <vtkActor.h>
#include <vtkBoundingBox.h>
#include <vtkExtractEdges.h>
#include <vtkHedgeHog.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace
{
// An unlit actor of lines' output.
vtkSmartPointer<vtkActor> Lines(vtkAlgorithm* lines, const Rgb& colour, double width)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(lines->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}
}

vtkSmartPointer<vtkActor> MakeEdges(vtkPolyData* mesh, const Rgb& colour, double width)
{
  vtkNew<vtkExtractEdges> edges;
  edges->SetInputData(mesh);
  return Lines(edges, colour, width);
}

vtkSmartPointer<vtkActor> MakeNormalGlyphs(vtkPolyData* mesh, const double bounds[6])
{
  vtkNew<vtkHedgeHog> hedgehog;
  hedgehog->SetInputData(mesh);
  hedgehog->SetVectorModeToUseNormal();
  // n points spread over the mesh's extent are about diagonal/sqrt(n) apart.
  const double diagonal = vtkBoundingBox(bounds).GetDiagonalLength();
  const double spacing =
    diagonal / std::sqrt(static_cast<double>(std::max<vtkIdType>(mesh->GetNumberOfPoints(), 1)));
  hedgehog->SetScaleFactor(std::clamp(2 * spacing, 0.004 * diagonal, 0.05 * diagonal));
  return Lines(hedgehog, { 0.2, 0.9, 1.0 }, 1);
}

vtkPolyData* LitMesh(const SceneOptions& options, MeshCache& meshes)
{
  SceneOptions lit = options;
  lit.ShadingRule = Shading::Phong;
  return meshes.Get(lit).Mesh;
}

SceneOverlays::SceneOverlays(
  const SceneOptions& options, vtkPolyData* shown, MeshCache& meshes, vtkRenderer* renderer)
  : Renderer(renderer)
{
  if (options.Edges)
  {
    this->Edges = MakeEdges(shown, options.EdgeColor, options.EdgeWidth);
    renderer->AddActor(this->Edges);
  }
  if (options.NormalGlyphs)
  {
    if (vtkPolyData* normals = LitMesh(options, meshes))
    {
      this->Glyphs = MakeNormalGlyphs(normals, shown->GetBounds());
      renderer->AddActor(this->Glyphs);
    }
  }
}

SceneOverlays::~SceneOverlays()
{
  for (vtkActor* actor : { this->Edges.Get(), this->Glyphs.Get() })
  {
    if (actor)
    {
      this->Renderer->RemoveActor(actor);
    }
  }
}
}
