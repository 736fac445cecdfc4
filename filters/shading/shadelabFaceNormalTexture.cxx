#include "shadelabFaceNormalTexture.h"

#include "shadelabFaceNormals.h"

#include <vtkCellArray.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtk_glew.h>

#include <algorithm>
#include <vector>

namespace shadelab
{
std::string UploadFaceNormals(
  vtkPolyData* mesh, vtkOpenGLRenderWindow* window, FaceNormalTexture& uploaded)
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
  GLint most = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
  if (triangles > most)
  {
    return "flat shading reads one face normal per triangle from a buffer texture, which holds "
           "at most " +
      std::to_string(most) + " here; the mesh has " + std::to_string(triangles) + " triangles";
  }
  // Computed and uploaded a slice at a time, so that the normals are in
  // memory once (OpenGL's copy) rather than twice.
  constexpr vtkIdType Slice = 1 << 20;
  std::vector<float> slice(3 * std::min(triangles, Slice));
  FaceNormalTexture made;
  made.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  made.Buffer->GenerateBuffer(vtkOpenGLBufferObject::TextureBuffer);
  made.Buffer->Bind();
  const auto bytes = [](vtkIdType n) { return static_cast<GLsizeiptr>(3 * sizeof(float) * n); };
  const vtkIdType texels = std::max<vtkIdType>(triangles, 1); // OpenGL's buffers are not empty
  glBufferData(GL_TEXTURE_BUFFER, bytes(texels), nullptr, GL_STATIC_DRAW);
  vtkIdType drawn = 0;
  for (vtkIdType first = 0; first < triangles; first += Slice)
  {
    const vtkIdType count =
      ComputeFaceNormals(mesh, first, std::min(Slice, triangles - first), slice.data());
    glBufferSubData(GL_TEXTURE_BUFFER, bytes(drawn), bytes(count), slice.data());
    drawn += count;
  }
  made.Buffer->Release();
  made.Texture = vtkSmartPointer<vtkTextureObject>::New();
  made.Texture->SetContext(window);
  made.Texture->CreateTextureBuffer(static_cast<unsigned int>(texels), 3, VTK_FLOAT, made.Buffer);
  uploaded = made;
  return "";
}
}
