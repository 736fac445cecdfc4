// Reads a mesh with the installed filters and computes its normals: one unit
// normal per output point, every input triangle kept. Exit status 0 only then.
#include <vtkShadelabMeshNormals.h>
#include <vtkShadelabMeshReader.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cmath>
#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: consumer MESH\n";
    return 2;
  }
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName(argv[1]);
  vtkNew<vtkShadelabMeshNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  normals->Update();
  vtkPolyData* input = reader->GetOutput();
  vtkPolyData* output = normals->GetOutput();
  vtkDataArray* vectors = output->GetPointData()->GetNormals();
  if (input->GetNumberOfPolys() == 0 || !vectors ||
    vectors->GetNumberOfTuples() != output->GetNumberOfPoints() ||
    output->GetNumberOfPolys() != input->GetNumberOfPolys())
  {
    std::cerr << "consumer: no normals for " << argv[1] << "\n";
    return 1;
  }
  for (vtkIdType i = 0; i < vectors->GetNumberOfTuples(); ++i)
  {
    double n[3];
    vectors->GetTuple(i, n);
    if (std::abs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) > 1e-6)
    {
      std::cerr << "consumer: normal " << i << " is not of unit length\n";
      return 1;
    }
  }
  std::cout << output->GetNumberOfPolys() << " triangles, " << vectors->GetNumberOfTuples()
            << " unit normals\n";
  return 0;
}
