#include "shadelabFaceNormalTexture.h"

#include "shadelabFaceNormals.h"
#include "shadelabTriangleIndexBuffer.h"

#include <vtkCellArray.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtk_glew.h>

#include <algorithm>
#include <vector>

namespace shadelab
{
namespace
{
// Edges or points: their owners' normals, one texel each (DrawnElements).
std::vector<float> OwnersNormals(vtkPolyData* mesh, Representation drawn)
{
  std::vector<unsigned int> corners; // three a drawn triangle
  if (!mesh->GetPoints() ||
    !AppendTriangleIndices(mesh->GetPolys(), mesh->GetPoints()->GetData(), corners))
  {
    return {};
  }
  std::vector<float> faces(corners.size()); // three floats a drawn triangle
  ComputeFaceNormals(mesh, 0, mesh->GetPolys()->GetNumberOfCells(), faces.data());
  const std::vector<unsigned int> owners = ElementsOf(drawn, corners).Owners;
  std::vector<float> normals(3 * owners.size());
  for (std::size_t e = 0; e < owners.size(); ++e)
  {
    std::copy_n(faces.begin() + 3 * owners[e], 3, normals.begin() + 3 * e);
  }
  return normals;
}
}

std::string UploadFaceNormals(vtkPolyData* mesh, Representation drawn,
  vtkOpenGLRenderWindow* window, FaceNormalTexture& uploaded)
{
  vtkCellArray* polys = mesh->GetPolys();
  const vtkIdType triangles = polys->GetNumberOfCells();
  // VTK would split a polygon, and draw points, lines and strips apart.
  if (polys->GetNumberOfConnectivityIds() != 3 * triangles ||
    (triangles > 0 && polys->GetMaxCellSize() != 3) || mesh->GetNumberOfVerts() > 0 ||
    mesh->GetNumberOfLines() > 0 || mesh->GetNumberOfStrips() > 0)
  {
    return "flat shading draws triangles only, and the mesh has other cells";
  }
  const std::vector<float> elements =
    drawn == Representation::Surface ? std::vector<float>() : OwnersNormals(mesh, drawn);
  const vtkIdType count =
    drawn == Representation::Surface ? triangles : static_cast<vtkIdType>(elements.size() / 3);
  GLint most = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
  if (count > most)
  {
    return "flat shading reads one face normal per " +
      std::string(drawn == Representation::Surface ? "triangle" : ToString(drawn)) +
      " element from a buffer texture, which holds at most " + std::to_string(most) +
      " here; the mesh has " + std::to_string(count);
  }
  FaceNormalTexture made;
  made.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  made.Buffer->GenerateBuffer(vtkOpenGLBufferObject::TextureBuffer);
  made.Buffer->Bind();
  const auto bytes = [](vtkIdType n) { return static_cast<GLsizeiptr>(3 * sizeof(float) * n); };
  const vtkIdType texels = std::max<vtkIdType>(count, 1); // OpenGL's buffers are not empty
  glBufferData(GL_TEXTURE_BUFFER, bytes(texels), nullptr, GL_STATIC_DRAW);
  if (drawn == Representation::Surface)
  {
    // Computed and uploaded a slice at a time, so that the normals are in
    // memory once (OpenGL's copy) rather than twice.
    constexpr vtkIdType Slice = 1 << 20;
    std::vector<float> slice(3 * std::min(triangles, Slice));
    vtkIdType done = 0;
    for (vtkIdType first = 0; first < triangles; first += Slice)
    {
      const vtkIdType n =
        ComputeFaceNormals(mesh, first, std::min(Slice, triangles - first), slice.data());
      glBufferSubData(GL_TEXTURE_BUFFER, bytes(done), bytes(n), slice.data());
      done += n;
    }
  }
  else if (count > 0)
  {
    glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes(count), elements.data());
  }
  made.Buffer->Release();
  made.Texture = vtkSmartPointer<vtkTextureObject>::New();
  made.Texture->SetContext(window);
  made.Texture->CreateTextureBuffer(static_cast<unsigned int>(texels), 3, VTK_FLOAT, made.Buffer);
  uploaded = made;
  return "";
}
}
