// The 8-bit capture: where round(255*clamp(I)) steps up, the shader's step
// must decide as the CPU's quantisation of the float picture does, value for
// value. A grid of unlit squares puts intensities exactly on each half step,
// one float below and one above it, and beyond [0, 1]; the background sits
// on the first half step, where llvmpipe's own conversion of a clear colour
// to 8 bits (f * 255/256 + 2^15, in float) gives 0 instead of 1.
#include "headless/headless_renderer.h"
#include "headless/vtkShadelabCapturePass.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace
{
using namespace shadelab;

constexpr int Columns = 32;
constexpr int Rows = 24;
constexpr int Cell = 6; // pixels a square's cell is wide and high; the square leaves a border

float Below(float v)
{
  return std::nextafter(v, -std::numeric_limits<float>::infinity());
}

float Above(float v)
{
  return std::nextafter(v, std::numeric_limits<float>::infinity());
}

// Each square's colour: around every half step in turn, the channels
// rotating which of (on it, below it, above it) they take; then values
// outside [0, 1], NaN, and the ends.
std::vector<std::array<float, 3>> SquareColours()
{
  std::vector<std::array<float, 3>> colours;
  for (const float h : vtkShadelabCapturePass::HalfSteps())
  {
    colours.push_back({ h, Below(h), Above(h) });
    colours.push_back({ Below(h), Above(h), h });
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  colours.push_back({ -0.25f, 1.5f, nan });
  colours.push_back({ 0.0f, 1.0f, Below(0.0f) });
  colours.push_back({ Above(1.0f), Below(1.0f), 0.5f });
  return colours;
}

// The squares, each with its colour at all four corners (kd per vertex),
// in a Columns x Rows grid of unit cells.
vtkNew<vtkPolyData> Squares(const std::vector<std::array<float, 3>>& colours)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> kd;
  kd->SetName(ColorsArrayName);
  kd->SetNumberOfComponents(4);
  for (std::size_t i = 0; i < colours.size(); ++i)
  {
    const double x = static_cast<double>(i % Columns), y = static_cast<double>(i / Columns);
    const vtkIdType first = points->GetNumberOfPoints();
    for (const auto& [dx, dy] : { std::array{ 0.2, 0.2 }, std::array{ 0.8, 0.2 },
           std::array{ 0.8, 0.8 }, std::array{ 0.2, 0.8 } })
    {
      points->InsertNextPoint(x + dx, y + dy, 0);
      kd->InsertNextTuple4(colours[i][0], colours[i][1], colours[i][2], 1);
    }
    const vtkIdType a[3] = { first, first + 1, first + 2 }, b[3] = { first, first + 2, first + 3 };
    triangles->InsertNextCell(3, a);
    triangles->InsertNextCell(3, b);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  mesh->GetPointData()->AddArray(kd);
  return mesh;
}

struct Pictures
{
  FloatImage Floats;
  Image8 Bytes;
};

// The squares rendered unlit (kd as it is), in floats and in 8 bits.
Pictures Render(vtkPolyData* mesh)
{
  HeadlessRenderer renderer;
  EXPECT_EQ(renderer.Start(Columns * Cell, Rows * Cell), "");
  vtkNew<vtkShadelabShading> shading;
  EXPECT_TRUE(shading->SetShadingRuleByName("none"));
  shading->SetVertexKd(true);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shading->PrepareMesh(mesh));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkRenderer* r = renderer.GetRenderer();
  r->AddActor(actor);
  shading->Attach(actor, r);
  const double step = vtkShadelabCapturePass::HalfSteps()[0];
  r->SetBackground(step, step, step);
  vtkCamera* camera = r->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(Columns / 2.0, Rows / 2.0, 0);
  camera->SetPosition(Columns / 2.0, Rows / 2.0, 10);
  camera->SetParallelScale(Rows / 2.0);
  r->ResetCameraClippingRange();
  Pictures pictures;
  pictures.Floats = renderer.Render();
  EXPECT_EQ(renderer.GetError(), "");
  pictures.Bytes = renderer.RenderEightBit(false);
  EXPECT_EQ(renderer.GetError(), "");
  return pictures;
}
}

TEST(EightBitCapture, HalfStepsAreWhereQuantisationStepsUp)
{
  const std::array<float, 255>& steps = vtkShadelabCapturePass::HalfSteps();
  for (int j = 1; j <= 255; ++j)
  {
    const float h = steps[j - 1];
    EXPECT_EQ(Quantised(h, 255), j) << "half step " << j;
    EXPECT_EQ(Quantised(Below(h), 255), j - 1) << "half step " << j;
  }
}

TEST(EightBitCapture, EveryByteIsTheFloatPictureQuantised)
{
  const std::vector<std::array<float, 3>> colours = SquareColours();
  ASSERT_LE(colours.size(), static_cast<std::size_t>(Columns * Rows));
  const Pictures pictures = Render(Squares(colours));
  const std::vector<std::uint8_t> expected = Quantise<std::uint8_t>(pictures.Floats, 255);
  ASSERT_EQ(pictures.Bytes.Pixels.size(), expected.size());
  EXPECT_EQ(pictures.Bytes.Width, Columns * Cell);
  EXPECT_EQ(pictures.Bytes.Height, Rows * Cell);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    differing += pictures.Bytes.Pixels[i] != expected[i];
  }
  EXPECT_EQ(differing, 0u) << "of " << expected.size() << " values";

  // The float picture holds the values put on and around every half step,
  // exactly (so the comparison above is at the steps, not near them).
  std::set<float> wanted;
  for (const float h : vtkShadelabCapturePass::HalfSteps())
  {
    wanted.insert({ h, Below(h), Above(h) });
  }
  std::set<float> found;
  for (const float v : pictures.Floats.Rgba)
  {
    if (wanted.count(v))
    {
      found.insert(v);
    }
  }
  EXPECT_EQ(found.size(), wanted.size());
  EXPECT_GT(std::count_if(pictures.Floats.Rgba.begin(), pictures.Floats.Rgba.end(),
              [](float v) { return std::isnan(v); }),
    0)
    << "the NaN square";
}

TEST(EightBitCapture, TranslucentActorsAreCompositedInFloatThenQuantised)
{
  // Blending in 8 bits would not be the floats' blend quantised: a
  // translucent scene's 8-bit picture is the float one, quantised.
  HeadlessRenderer renderer;
  ASSERT_EQ(renderer.Start(32, 24), "");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(Squares({ { 0.2f, 0.4f, 0.6f } }));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(0.5);
  renderer.GetRenderer()->AddActor(actor);
  renderer.GetRenderer()->ResetCamera();
  const Image8 eight = renderer.RenderEightBit(false);
  EXPECT_EQ(renderer.GetError(), "");
  FloatImage floats = renderer.Render();
  EXPECT_EQ(renderer.GetError(), "");
  EXPECT_EQ(eight.Pixels, QuantiseToImage8(floats).Pixels);
  EXPECT_NE(std::count(eight.Pixels.begin(), eight.Pixels.end(), 0), eight.Pixels.size())
    << "nothing drawn";
}
