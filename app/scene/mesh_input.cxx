#include "scene/mesh_input.h"

#include "core/errors.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVertexTangents.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkCleanPolyData.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace shadelab
{
namespace
{
// A mesh whose picture would be blank, said instead of drawn: points so far
// apart that their extent overflows (vertices at 1e308, a glTF node scaled
// by 1e308), or all on one line or at one point (an all-zero node matrix),
// where no triangle has any area.
std::string Undrawable(vtkPolyData* mesh)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  double diagonal = 0;
  int flat = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double extent = bounds[2 * axis + 1] - bounds[2 * axis];
    diagonal += extent * extent;
    flat += extent == 0;
  }
  if (!std::isfinite(diagonal))
  {
    char span[64];
    std::snprintf(span, sizeof span, "%g to %g", std::min({ bounds[0], bounds[2], bounds[4] }),
      std::max({ bounds[1], bounds[3], bounds[5] }));
    return std::string("its points span more than a double can measure (") + span +
      "): nothing can be drawn";
  }
  if (flat >= 2)
  {
    return "all its points lie on one line: no triangle has an area to draw";
  }
  return {};
}
}

bool FileMapsNormals(vtkPolyData* mesh)
{
  vtkDataArray* maps = mesh->GetFieldData()->GetArray(PartNormalTextureArrayName);
  for (vtkIdType p = 0; maps && p < maps->GetNumberOfTuples(); ++p)
  {
    if (maps->GetComponent(p, 0) >= 0)
    {
      return true;
    }
  }
  return false;
}

ComputedNormals ComputeNormals(vtkPolyData* mesh, const NormalsSettings& settings, bool cellNormals)
{
  auto normals = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  normals->SetInputData(mesh);
  normals->SetComputeCellNormals(cellNormals);
  normals->SetWeightingByName(settings.Weighting.c_str());
  normals->SetSplitting(settings.FeatureAngle.has_value());
  normals->SetFeatureAngle(settings.FeatureAngle.value_or(0));
  normals->SetConsistency(settings.Orient);
  const MessageScope messages;
  ComputedNormals result;
  if (normals->GetExecutive()->Update())
  {
    // A copy of the output's arrays without its pipeline information: that
    // refers to the filter, whose cache (OpenMesh's mesh and the face
    // geometry, where splitting or Loop normals built them) would otherwise
    // live as long as the mesh.
    result.Mesh = vtkSmartPointer<vtkPolyData>::New();
    result.Mesh->ShallowCopy(normals->GetOutput());
    result.DuplicatedFaces = normals->GetNumberOfDuplicatedFaces();
  }
  else
  {
    result.Error = messages.ErrorOr("cannot be computed");
  }
  result.Warnings = messages.Warnings();
  return result;
}

vtkSmartPointer<vtkPolyData> LoopSubdivided(vtkPolyData* mesh, int levels)
{
  auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
  clean->SetInputData(mesh);
  auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
  loop->SetInputConnection(clean->GetOutputPort());
  loop->SetNumberOfSubdivisions(levels);
  loop->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(loop->GetOutput());
  if (result->GetPoints()->GetDataType() != VTK_DOUBLE)
  {
    auto xyz = vtkSmartPointer<vtkDoubleArray>::New();
    xyz->DeepCopy(result->GetPoints()->GetData()); // converts
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(xyz);
    result->SetPoints(points);
  }
  return result;
}

LoadedMesh LoadMesh(const SceneOptions& options, PhaseTimer* timer, bool cellNormals)
{
  const auto lap = [timer](const char* phase)
  {
    if (timer)
    {
      timer->Lap(phase);
    }
  };
  LoadedMesh result;
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(options.Mesh.c_str());
  // Normals to be computed need not split an OBJ's vertices by its vn:
  // computed on the file's vertices (FileVertex), the split points would
  // only get their vertex's normal again.
  reader->SetReadNormals(options.Normals != NormalsMode::Compute);
  reader->SetAllowOutsideReferences(options.AllowOutsideReferences);
  {
    const MessageScope messages;
    const bool read = reader->GetExecutive()->Update();
    ReportWarnings(options.Mesh, messages.Warnings());
    if (!read)
    {
      result.Error = messages.ErrorOr("cannot be read");
      return result;
    }
  }
  lap("read");
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
  result.NormalsFromFile = mesh->GetPointData()->GetNormals() != nullptr;
  if (const std::string problem = Undrawable(mesh); !problem.empty())
  {
    result.Error = problem;
    return result;
  }

  if (options.Normals == NormalsMode::File && !result.NormalsFromFile)
  {
    result.Error = "has no vertex normals (--normals file)";
    return result;
  }
  const bool lit = UsesVertexNormals(options.ShadingRule);
  bool compute = false;
  switch (options.Normals)
  {
    case NormalsMode::Auto:
      compute = !result.NormalsFromFile;
      break;
    case NormalsMode::File:
      compute = false;
      break;
    case NormalsMode::Compute:
      compute = true;
      break;
  }
  if (lit && compute)
  {
    const ComputedNormals normals = ComputeNormals(mesh, options.Computed, cellNormals);
    ReportWarnings(options.Mesh, normals.Warnings);
    if (!normals.Mesh)
    {
      result.Error = "normals: " + normals.Error;
      return result;
    }
    mesh = normals.Mesh;
    result.DuplicatedFaces = normals.DuplicatedFaces;
    result.NormalsFromFile = false;
  }
  lap("normals");
  // A normal map's frame, where there are texture coordinates to make it
  // of (the scene says so where there are none).
  if (options.MapsNormals(FileMapsNormals(mesh)) &&
    mesh->GetPointData()->GetArray(TextureCoordinatesArrayName))
  {
    auto withTangents = vtkSmartPointer<vtkPolyData>::New();
    withTangents->ShallowCopy(mesh);
    withTangents->GetPointData()->AddArray(VertexTangents(mesh));
    mesh = withTangents;
    lap("tangents");
  }
  result.Mesh = mesh;
  return result;
}
}
