#include "vtkShadelabPolyDataMapper.h"

#include "shadelabEightBitStep.h"
#include "shadelabRepresentation.h"
#include "shadelabTriangleIndexBuffer.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLIndexBufferObject.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLVertexBufferObjectGroup.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkShader.h>

#include <vector>

vtkStandardNewMacro(vtkShadelabPolyDataMapper);

void vtkShadelabPolyDataMapper::SetOwnStages(const shadelab::OwnStages& stages)
{
  if (!(stages == this->Own))
  {
    this->Own = stages;
    this->OwnErrors.clear();
    this->Modified(); // the program is built again
  }
}

void vtkShadelabPolyDataMapper::BuildShaders(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor)
{
  this->Superclass::BuildShaders(shaders, renderer, actor);
  this->OwnErrors.clear();
  if (this->Own.Empty())
  {
    return;
  }
  // Last, so that the stage is the given text: nothing of VTK's is
  // substituted into it (the cache's substitutions find nothing to change
  // in a dumped stage), only the render passes' own steps, as they are
  // into the generated fragment stage (the 8-bit capture's where the
  // picture is 8-bit, and only then; a translucent scene's peels).
  vtkShader* vertex = shaders[vtkShader::Vertex];
  vtkShader* fragment = shaders[vtkShader::Fragment];
  vtkShader* geometry = shaders[vtkShader::Geometry];
  const std::string generatedVertex = vertex->GetSource();
  const std::string generatedFragment = fragment->GetSource();
  const std::string geometrySource = geometry->GetSource();
  if (!this->Own.Fragment.empty())
  {
    fragment->SetSource(shadelab::WithoutEightBitStep(this->Own.Fragment));
    this->ReplaceShaderRenderPass(shaders, renderer, actor, true);
    geometry->SetSource(geometrySource);
  }
  vertex->SetSource(this->Own.Vertex.empty() ? generatedVertex : this->Own.Vertex);
  this->OwnErrors =
    shadelab::CheckStages(vertex->GetSource(), fragment->GetSource(), geometrySource);
  if (!this->OwnErrors.empty())
  {
    vertex->SetSource(generatedVertex);
    fragment->SetSource(generatedFragment);
  }
}

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
  if (!this->BuildSurfaceIBO(actor, mesh))
  {
    this->SurfacePolysTime = 0;
    this->Superclass::BuildIBO(renderer, actor, mesh);
  }
}

bool vtkShadelabPolyDataMapper::BuildSurfaceIBO(vtkActor* actor, vtkPolyData* mesh)
{
  vtkProperty* property = actor->GetProperty();
  vtkCellArray* polys = mesh->GetPolys();
  vtkPoints* points = mesh->GetPoints();
  const int representation = property->GetRepresentation();
  if ((representation != VTK_SURFACE && !this->EachElementOnce) || property->GetEdgeVisibility() ||
    property->GetVertexVisibility() || mesh->GetNumberOfVerts() || mesh->GetNumberOfLines() ||
    mesh->GetNumberOfStrips() || !points ||
    mesh->GetPointData()->GetAttribute(vtkDataSetAttributes::EDGEFLAG))
  {
    return false;
  }
  if (polys->GetMTime() == this->SurfacePolysTime && representation == this->SurfaceRepresentation)
  {
    return true; // built from these polys, as VTK's BuildIBO keeps its own
  }
  std::vector<unsigned int> indices;
  if (!shadelab::AppendTriangleIndices(polys, points->GetData(), indices))
  {
    return false;
  }
  if (representation != VTK_SURFACE)
  {
    // Each edge or point once (VTK's would draw a shared edge once for
    // each triangle, in either direction), so that gl_PrimitiveID counts
    // the elements flat's face normals are given for (DrawnElements).
    indices =
      shadelab::ElementsOf(representation == VTK_POINTS ? shadelab::Representation::Points
                                                        : shadelab::Representation::Wireframe,
        indices)
        .Corners;
  }
  // VTK's BuildIBO must rebuild after this, even for a state it built before.
  this->IBOBuildState.Clear();
  this->SurfacePolysTime = polys->GetMTime();
  this->SurfaceRepresentation = representation;
  this->EdgeValues.clear();
  // The other primitives have no cells: their buffers are emptied as VTK empties them.
  this->Primitives[PrimitivePoints].IBO->CreatePointIndexBuffer(mesh->GetVerts());
  this->Primitives[PrimitiveLines].IBO->CreateLineIndexBuffer(mesh->GetLines());
  this->Primitives[PrimitiveTriStrips].IBO->CreateStripIndexBuffer(mesh->GetStrips(), false);
  vtkOpenGLIndexBufferObject* triangles = this->Primitives[PrimitiveTris].IBO;
  triangles->IndexCount = indices.size();
  if (!indices.empty())
  {
    triangles->Upload(indices, vtkOpenGLIndexBufferObject::ElementArrayBuffer);
  }
  return true;
}
