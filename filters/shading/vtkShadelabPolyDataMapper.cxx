#include "vtkShadelabPolyDataMapper.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLVertexBufferObjectGroup.h>

#include <vector>

vtkStandardNewMacro(vtkShadelabPolyDataMapper);

void vtkShadelabPolyDataMapper::BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* mesh)
{
  // The attributes vtkOpenGLPolyDataMapper::BuildBufferObjects uploads, and
  // those mapped by name (MapDataArrayToVertexAttribute).
  std::vector<std::string> attributes{ "vertexMC", "normalMC", "scalarColor", "tcoord",
    "tangentMC" };
  for (const auto& extra : this->ExtraAttributes)
  {
    attributes.push_back(extra.first);
  }
  for (const std::string& attribute : attributes)
  {
    if (vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO(attribute.c_str()))
    {
      std::vector<float>().swap(vbo->GetPackedVBO());
    }
  }
  this->Superclass::BuildIBO(renderer, actor, mesh);
}
