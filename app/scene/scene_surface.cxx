#include "scene/scene_surface.h"

#include "scene/scene.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVertexTangents.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace shadelab
{
SceneSurface::SceneSurface(
  const SceneOptions& options, vtkPolyData* mesh, const SceneImages& images)
  : Parts(SceneParts(options, mesh, images))
  , CellParts(PartOfCells(mesh))
  , Environment(SceneEnvironment(options, images))
{
  if (UsesVertexKd(options, mesh))
  {
    vtkDataArray* colors = mesh->GetPointData()->GetArray(ColorsArrayName);
    this->Kd.resize(colors->GetNumberOfTuples());
    for (vtkIdType i = 0; i < colors->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        this->Kd[i][c] = colors->GetComponent(i, c);
      }
    }
  }
  vtkDataArray* coordinates = mesh->GetPointData()->GetArray(TextureCoordinatesArrayName);
  if (coordinates &&
    std::any_of(this->Parts.begin(), this->Parts.end(),
      [](const ScenePart& part) { return part.Texture.Used() || part.Relief; }))
  {
    this->TexCoords.resize(coordinates->GetNumberOfTuples());
    for (vtkIdType i = 0; i < coordinates->GetNumberOfTuples(); ++i)
    {
      this->TexCoords[i] = { coordinates->GetComponent(i, 0), coordinates->GetComponent(i, 1) };
    }
  }
  if (vtkDataArray* tangents = mesh->GetPointData()->GetArray(TangentsArrayName))
  {
    this->Tangents.resize(tangents->GetNumberOfTuples());
    for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
    {
      tangents->GetTuple(i, this->Tangents[i].data());
    }
  }
  if (vtkDataArray* normals = mesh->GetPointData()->GetNormals())
  {
    this->Normals.resize(normals->GetNumberOfTuples());
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      normals->GetTuple(i, this->Normals[i].data());
    }
  }
}

TriangleFragment SceneSurface::Fragment(const TriangleCorners& corners,
  const std::array<double, 3>& w, bool front, const std::vector<Vec3>& points) const
{
  TriangleFragment f;
  for (int k = 0; k < 3; ++k)
  {
    f.Positions[k] = points[corners[k]];
    if (this->HasNormals())
    {
      f.Normals[k] = this->Normals[corners[k]];
    }
    if (this->Textured())
    {
      f.TexCoords[k] = this->TexCoords[corners[k]];
    }
    if (!this->Tangents.empty())
    {
      f.Tangents[k] = this->Tangents[corners[k]];
    }
  }
  if (this->VertexKd())
  {
    f.VertexKd = { this->Kd[corners[0]], this->Kd[corners[1]], this->Kd[corners[2]] };
  }
  f.Weights = w;
  f.Front = front;
  return f;
}

IlluminationInputs SceneSurface::InputsOf(IlluminationInputs in, std::int64_t t) const
{
  const ScenePart& part = this->PartOf(t);
  in.Surface = part.Surface;
  in.Texture = part.Texture;
  in.Environment = this->Environment;
  in.NormalTexture = part.Relief;
  return in;
}
}
