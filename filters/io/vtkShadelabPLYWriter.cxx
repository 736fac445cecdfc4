#include "vtkShadelabPLYWriter.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkShadelabPLYWriter);

vtkShadelabPLYWriter::~vtkShadelabPLYWriter()
{
  this->SetFileName(nullptr);
}

int vtkShadelabPLYWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

namespace
{
template <typename T>
void Put(std::vector<char>& out, T value)
{
  // Written as the host stores it: binary_little_endian, which the
  // static_assert below requires of the host.
  const char* p = reinterpret_cast<const char*>(&value);
  out.insert(out.end(), p, p + sizeof value);
}
static_assert(sizeof(float) == 4 && sizeof(double) == 8, "PLY float and double sizes");
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "a little-endian host");
}

void vtkShadelabPLYWriter::WriteData()
{
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(this->GetInput());
  if (!this->FileName || !mesh)
  {
    vtkErrorMacro("no file name or no polydata to write");
    return;
  }
  vtkCellArray* polys = mesh->GetPolys();
  const vtkIdType points = mesh->GetNumberOfPoints();
  const vtkIdType faces = polys->GetNumberOfCells();
  if (polys->GetNumberOfConnectivityIds() != 3 * faces)
  {
    vtkErrorMacro("PLY output takes triangles only");
    return;
  }
  vtkDataArray* pointNormals = mesh->GetPointData()->GetNormals();
  vtkDataArray* cellNormals = mesh->GetCellData()->GetNormals();

  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by shadelab\n"
                       "element vertex " +
    std::to_string(points) + "\nproperty double x\nproperty double y\nproperty double z\n";
  if (pointNormals)
  {
    header += "property float nx\nproperty float ny\nproperty float nz\n";
  }
  header += "element face " + std::to_string(faces) + "\nproperty list uchar int vertex_indices\n";
  if (cellNormals)
  {
    header += "property float nx\nproperty float ny\nproperty float nz\n";
  }
  header += "end_header\n";

  std::vector<char> body;
  body.reserve(static_cast<size_t>(points) * (24 + 12) + static_cast<size_t>(faces) * (13 + 12));
  for (vtkIdType i = 0; i < points; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    Put(body, p[0]);
    Put(body, p[1]);
    Put(body, p[2]);
    if (pointNormals)
    {
      const double* n = pointNormals->GetTuple3(i);
      Put(body, static_cast<float>(n[0]));
      Put(body, static_cast<float>(n[1]));
      Put(body, static_cast<float>(n[2]));
    }
  }
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType face = 0;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids); ++face)
  {
    if (npts != 3) // (the count above can balance a 2-gon with a 4-gon)
    {
      vtkErrorMacro("PLY output takes triangles only");
      return;
    }
    Put(body, static_cast<uint8_t>(3));
    for (int k = 0; k < 3; ++k)
    {
      Put(body, static_cast<int32_t>(ids[k]));
    }
    if (cellNormals)
    {
      const double* n = cellNormals->GetTuple3(face);
      Put(body, static_cast<float>(n[0]));
      Put(body, static_cast<float>(n[1]));
      Put(body, static_cast<float>(n[2]));
    }
  }

  std::ofstream out(this->FileName, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  out.write(body.data(), static_cast<std::streamsize>(body.size()));
  out.close();
  if (!out)
  {
    vtkErrorMacro("cannot write " << this->FileName << ": " << std::strerror(errno));
  }
}

void vtkShadelabPLYWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
