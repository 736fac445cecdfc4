// The headless window with its own framebuffers left unused: the float
// capture pass draws the same pixels, and VTK's render, display and resolve
// framebuffers stay at one pixel instead of the window's size.
#include "headless/vtkShadelabCapturePass.h"
#include "headless/vtkShadelabOSMesaRenderWindow.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <array>
#include <vector>

VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace
{
constexpr int Width = 160;
constexpr int Height = 120;

struct Frame
{
  std::vector<float> Pixels;
  std::array<int, 2> RenderFramebuffer{};
  std::array<int, 2> DisplayFramebuffer{};
};

// An opaque sphere and a translucent one before it (blended in VTK's
// translucent step), drawn twice as a batch would.
Frame Draw(bool framebuffersUnused)
{
  vtkNew<vtkShadelabOSMesaRenderWindow> window;
  window->SetFramebuffersUnused(framebuffersUnused);
  window->SetMultiSamples(0);
  window->SetSize(Width, Height);
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkShadelabCapturePass> capture;
  capture->SetDelegatePass(vtkNew<vtkRenderStepsPass>());
  renderer->SetPass(capture);
  window->AddRenderer(renderer);
  window->Initialize();
  EXPECT_TRUE(window->GetContextReady());
  for (const double z : { 0.0, 0.8 })
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(0.3 * z, 0, z);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetOpacity(z > 0 ? 0.5 : 1.0);
    renderer->AddActor(actor);
  }
  renderer->ResetCamera();
  window->Render();
  window->Render();
  Frame frame;
  frame.Pixels = capture->TakePixels();
  window->GetRenderFramebuffer()->GetLastSize(frame.RenderFramebuffer.data());
  window->GetDisplayFramebuffer()->GetLastSize(frame.DisplayFramebuffer.data());
  window->Finalize();
  return frame;
}
}

TEST(HeadlessWindow, UnusedFramebuffersChangeNoPixelAndStayAtOnePixel)
{
  const Frame full = Draw(false);
  const Frame small = Draw(true);
  ASSERT_EQ(full.Pixels.size(), static_cast<std::size_t>(Width) * Height * 4);
  // A picture, not a cleared target: the spheres cover part of it.
  EXPECT_NE(std::count(full.Pixels.begin(), full.Pixels.end(), full.Pixels[0]),
    static_cast<std::ptrdiff_t>(full.Pixels.size()));
  EXPECT_EQ(full.Pixels, small.Pixels);
  EXPECT_EQ(full.RenderFramebuffer, (std::array<int, 2>{ Width, Height }));
  EXPECT_EQ(full.DisplayFramebuffer, (std::array<int, 2>{ Width, Height }));
  EXPECT_EQ(small.RenderFramebuffer, (std::array<int, 2>{ 1, 1 }));
  EXPECT_EQ(small.DisplayFramebuffer, (std::array<int, 2>{ 1, 1 }));
}
