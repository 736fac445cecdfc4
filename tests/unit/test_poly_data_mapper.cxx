// vtkShadelabPolyDataMapper: the same picture as VTK's own mapper, bit for
// bit, without the CPU copy of the vertex buffers that VTK's keeps after
// uploading them.
#include "headless/headless_renderer.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLVertexBufferObjectGroup.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

namespace
{
using namespace shadelab;

// A mapper of class Base that tells how much memory its packed vertex
// buffers still hold.
template <class Base>
class Held : public Base
{
public:
  static Held* New()
  {
    auto* mapper = new Held;
    mapper->InitializeObjectBase();
    return mapper;
  }
  std::size_t PackedBytes()
  {
    std::size_t bytes = 0;
    for (const char* attribute : { "vertexMC", "normalMC" })
    {
      if (vtkOpenGLVertexBufferObject* vbo = this->VBOs->GetVBO(attribute))
      {
        bytes += vbo->GetPackedVBO().capacity() * sizeof(float);
      }
    }
    return bytes;
  }
};

template <class Base>
FloatImage Render(vtkPolyData* mesh, std::size_t& packedBytes)
{
  HeadlessRenderer renderer;
  EXPECT_EQ(renderer.Start(320, 240), "");
  vtkSmartPointer<Held<Base>> mapper = vtkSmartPointer<Held<Base>>::New();
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer.GetRenderer()->AddActor(actor);
  renderer.GetRenderer()->ResetCamera();
  FloatImage picture = renderer.Render();
  EXPECT_EQ(renderer.GetError(), "");
  packedBytes = mapper->PackedBytes();
  return picture;
}

TEST(PolyDataMapper, DrawsAsVtksWithoutItsCopyOfTheVertexBuffers)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((std::filesystem::path(SHADELAB_TEST_MESHES) / "stanford-bunny.ply").c_str());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(reader->GetOutputPort());
  ASSERT_TRUE(normals->GetExecutive()->Update());
  // Double points, which VTK packs into a float buffer of its own.
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(normals->GetOutput());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(normals->GetOutput()->GetPoints());
  mesh->SetPoints(points);

  std::size_t vtkKeeps = 0, oursKeeps = 0;
  const FloatImage vtks = Render<vtkOpenGLPolyDataMapper>(mesh, vtkKeeps);
  const FloatImage ours = Render<vtkShadelabPolyDataMapper>(mesh, oursKeeps);
  // VTK keeps 12 bytes a point for the (double) points it packed to float:
  // what this mapper exists to free.
  EXPECT_GE(vtkKeeps, 12U * mesh->GetNumberOfPoints());
  EXPECT_EQ(oursKeeps, 0U);
  ASSERT_EQ(vtks.Rgba.size(), ours.Rgba.size());
  EXPECT_EQ(std::memcmp(vtks.Rgba.data(), ours.Rgba.data(), vtks.Rgba.size() * sizeof(float)), 0);
}
}
