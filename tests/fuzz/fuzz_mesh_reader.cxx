// libFuzzer target: bytes as a mesh file of one format, read by
// vtkShadelabMeshReader exactly as `shadelab render` reads it, then given to
// the normals filter. Built once per format with SHADELAB_FUZZ_EXTENSION
// (".obj", ".ply", ".stl", ".vtk", ".off", ".gltf", ".glb"; ".dae", ".ac", ".x"
// through assimp, which runs in a child process: libFuzzer sees none of
// the child's coverage, so those three mutate blindly inside assimp and
// hold the program's side, a crash of assimp's being one error). A finding is a
// crash, a sanitizer report, or a mesh that reads but holds out-of-range
// point ids, non-finite points, attributes (colours, texture coordinates,
// parts) that are not one per point or per triangle, or file vertices that
// are not points.
#include "shadelabTriangleMesh.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
// One file per fuzzing process, rewritten for every input.
const std::string& InputPath()
{
  static const std::string path =
    "/tmp/shadelab-fuzz-" + std::to_string(getpid()) + SHADELAB_FUZZ_EXTENSION;
  return path;
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff(); // errors are expected; printing them is slow
  std::atexit([] { std::remove(InputPath().c_str()); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  FILE* file = std::fopen(InputPath().c_str(), "wb");
  if (!file || std::fwrite(data, 1, size, file) != size || std::fclose(file) != 0)
  {
    std::abort(); // the harness itself failed
  }
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(InputPath().c_str());
  if (!reader->GetExecutive()->Update())
  {
    return 0; // refused with an error: what bad input should get
  }
  vtkPolyData* mesh = reader->GetOutput();
  const vtkIdType points = mesh->GetNumberOfPoints();
  for (vtkIdType p = 0; p < points; ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      std::abort(); // the readers refuse non-finite coordinates
    }
  }
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    cells->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (ids[k] < 0 || ids[k] >= points)
      {
        std::abort(); // the readers refuse out-of-range indices
      }
    }
  }
  vtkPointData* pointData = mesh->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    if (pointData->GetArray(a)->GetNumberOfTuples() != points)
    {
      std::abort(); // a point attribute is one tuple per point
    }
  }
  if (vtkDataArray* fileVertices = pointData->GetArray(shadelab::FileVertexArrayName))
  {
    for (vtkIdType p = 0; p < points; ++p)
    {
      const double vertex = fileVertices->GetComponent(p, 0);
      if (vertex < 0 || vertex >= points)
      {
        std::abort(); // a file vertex is one of the points
      }
    }
  }
  vtkDataArray* parts = mesh->GetCellData()->GetArray(shadelab::PartArrayName);
  if (parts && parts->GetNumberOfTuples() != mesh->GetNumberOfPolys())
  {
    std::abort(); // a part per triangle
  }
  auto normals = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  normals->SetInputData(mesh);
  normals->SetSplitting(true);
  normals->SetFeatureAngle(30);
  normals->GetExecutive()->Update();
  return 0;
}
