// vtkShadelabPolyDataMapper: the same picture as VTK's own mapper, bit for
// bit, without the CPU copy of the vertex buffers that VTK's keeps after
// uploading them, and with the triangle index buffer built in place (the
// same indices as VTK's).
#include "headless/headless_renderer.h"
#include "shadelabTriangleIndexBuffer.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOpenGLIndexBufferObject.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkOpenGLVertexBufferObjectGroup.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <vector>

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

// The pictures of `mesh` drawn as a surface, a wireframe, a surface, a
// wireframe again, a surface with its edges and a surface: each time the
// index buffers are rebuilt, by VTK's mapper or by this one, and each
// must know when the other's buffers stand.
template <class Base>
std::vector<FloatImage> Render(vtkPolyData* mesh, std::size_t& packedBytes)
{
  HeadlessRenderer renderer;
  EXPECT_EQ(renderer.Start(320, 240), "");
  vtkSmartPointer<Held<Base>> mapper = vtkSmartPointer<Held<Base>>::New();
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer.GetRenderer()->AddActor(actor);
  renderer.GetRenderer()->ResetCamera();
  std::vector<FloatImage> pictures;
  for (const int way : { 0, 1, 0, 1, 2, 0 })
  {
    actor->GetProperty()->SetRepresentation(way == 1 ? VTK_WIREFRAME : VTK_SURFACE);
    actor->GetProperty()->SetEdgeVisibility(way == 2);
    pictures.push_back(renderer.Render());
    EXPECT_EQ(renderer.GetError(), "");
  }
  packedBytes = mapper->PackedBytes();
  return pictures;
}

TEST(PolyDataMapper, DrawsAsVtksWithoutItsCopyOfTheVertexBuffers)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((std::filesystem::path(SHADELAB_TEST_MESHES) / "teapot-fine.ply").c_str());
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
  const std::vector<FloatImage> vtks = Render<vtkOpenGLPolyDataMapper>(mesh, vtkKeeps);
  const std::vector<FloatImage> ours = Render<vtkShadelabPolyDataMapper>(mesh, oursKeeps);
  // VTK keeps 12 bytes a point for the (double) points it packed to float:
  // what this mapper exists to free.
  EXPECT_GE(vtkKeeps, 12U * mesh->GetNumberOfPoints());
  EXPECT_EQ(oursKeeps, 0U);
  ASSERT_EQ(vtks.size(), ours.size());
  for (std::size_t i = 0; i < vtks.size(); ++i)
  {
    SCOPED_TRACE("picture " + std::to_string(i));
    ASSERT_EQ(vtks[i].Rgba.size(), ours[i].Rgba.size());
    EXPECT_EQ(
      std::memcmp(vtks[i].Rgba.data(), ours[i].Rgba.data(), vtks[i].Rgba.size() * sizeof(float)),
      0);
  }
  // Each way shows: the wireframe and the edges are not the surface.
  for (const std::size_t i : { 1, 4 })
  {
    EXPECT_NE(
      std::memcmp(ours[0].Rgba.data(), ours[i].Rgba.data(), ours[0].Rgba.size() * sizeof(float)),
      0);
  }
}

// Points whose positions repeat (two corners at one position make a
// triangle VTK leaves out), and a NaN coordinate, of type Array.
template <class Array>
vtkSmartPointer<vtkPoints> Positions()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double xyz[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 1, 0, 0 },
    { 2, 0, 0 }, { nan, 0, 0 }, { 2, 1, 0 } };
  auto values = vtkSmartPointer<Array>::New();
  values->SetNumberOfComponents(3);
  for (const auto& p : xyz)
  {
    values->InsertNextTuple(p);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(values);
  return points;
}

// Cells of every size from 0 to 5, among them triangles with a repeated id,
// with two ids at one position (1 and 4), and with a NaN corner.
vtkSmartPointer<vtkCellArray> Cells(bool storage64)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (storage64)
  {
    cells->Use64BitStorage();
  }
  else
  {
    cells->Use32BitStorage();
  }
  const std::vector<std::vector<vtkIdType>> lists = { { 0, 1, 2 }, {}, { 3 }, { 0, 2 }, { 0, 2, 3 },
    { 0, 1, 4 }, { 0, 0, 2 }, { 1, 5, 7, 2 }, { 0, 1, 4, 2, 3 }, { 6, 5, 7 }, { 7, 6, 6 } };
  for (const auto& list : lists)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(list.size()), list.data());
  }
  return cells;
}

TEST(PolyDataMapper, TriangleIndicesAreVtks)
{
  for (const bool storage64 : { false, true })
  {
    for (const vtkSmartPointer<vtkPoints>& points :
      { Positions<vtkFloatArray>(), Positions<vtkDoubleArray>() })
    {
      SCOPED_TRACE(
        std::string(storage64 ? "64" : "32") + "-bit cells, " + points->GetData()->GetClassName());
      vtkSmartPointer<vtkCellArray> cells = Cells(storage64);
      std::vector<unsigned int> vtks{ 42 }, ours{ 42 }; // appended to what is there
      vtkOpenGLIndexBufferObject::AppendTriangleIndexBuffer(
        vtks, cells, points, 0, nullptr, nullptr);
      ASSERT_TRUE(shadelab::AppendTriangleIndices(cells, points->GetData(), ours));
      EXPECT_EQ(ours, vtks);
      // Some triangles are left out, and some are not.
      EXPECT_LT(vtks.size(), 1 + 3 * 11u);
      EXPECT_GT(vtks.size(), 1 + 3 * 6u);
    }
  }
  // Integer points are VTK's to draw.
  vtkSmartPointer<vtkPoints> integers = Positions<vtkIntArray>();
  ASSERT_TRUE(vtkIntArray::SafeDownCast(integers->GetData()));
  std::vector<unsigned int> indices;
  EXPECT_FALSE(shadelab::AppendTriangleIndices(Cells(false), integers->GetData(), indices));
  EXPECT_TRUE(indices.empty());
}
}
