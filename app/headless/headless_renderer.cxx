#include "headless/headless_renderer.h"

#include "core/errors.h"
#include "headless/vtkShadelabCapturePass.h"
#include "headless/vtkShadelabOSMesaRenderWindow.h"
#include "shadelabEnvironmentBackground.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPeelingPass.h"

#include <vtkAutoInit.h>
#include <vtkPropCollection.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>

// vtkRenderer::New and vtkPolyDataMapper::New return the OpenGL2 classes only
// once this module's object factory is registered.
VTK_MODULE_INIT(vtkRenderingOpenGL2);

namespace shadelab
{
HeadlessRenderer::HeadlessRenderer()
  : Window(vtkSmartPointer<vtkShadelabOSMesaRenderWindow>::New())
  , Renderer(vtkSmartPointer<vtkRenderer>::New())
  , Capture(vtkSmartPointer<vtkShadelabCapturePass>::New())
  , Peeling(vtkSmartPointer<vtkShadelabPeelingPass>::New())
{
  auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
  steps->SetTranslucentPass(this->Peeling);
  this->Capture->SetDelegatePass(steps);
  this->Renderer->SetPass(this->Capture);
  this->Window->SetFramebuffersUnused(true);
  this->Window->AddRenderer(this->Renderer);
}

HeadlessRenderer::~HeadlessRenderer()
{
  this->Window->Finalize();
}

std::string HeadlessRenderer::Start(int width, int height, int samples)
{
  vtkShadelabOSMesaRenderWindow::ChooseRasterizerThreads();
  this->Window->SetMultiSamples(0); // exact, repeatable pixels
  this->Samples = samples;
  this->Window->SetSize(width * samples, height * samples);
  const MessageScope messages;
  this->Window->Initialize();
  if (!this->Window->GetContextReady())
  {
    return "headless OpenGL: " + messages.ErrorOr("no OSMesa context");
  }
  return {};
}

void HeadlessRenderer::RenderFrame(bool eightBit)
{
  const MessageScope messages;
  this->Capture->SetEightBit(eightBit);
  this->Window->Render();
  this->Error = messages.FirstError();
  ReportWarnings("render", messages.Warnings());
}

FloatImage HeadlessRenderer::Render(const EnvironmentMap* behind)
{
  this->RenderFrame(false);
  FloatImage samples{ this->Capture->GetWidth(), this->Capture->GetHeight(),
    this->Capture->TakePixels() };
  if (behind && this->Error.empty())
  {
    OverEnvironment(samples.Rgba, samples.Width, samples.Height,
      PinholeCameraOf(this->Renderer->GetActiveCamera()), *behind);
  }
  return this->Samples > 1 ? BoxAverage(samples, this->Samples) : samples;
}

void HeadlessRenderer::SetMaximumNumberOfPeels(int peels)
{
  this->Peeling->SetMaximumNumberOfPeels(peels);
}

bool HeadlessRenderer::Translucent() const
{
  vtkPropCollection* props = this->Renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry())
    {
      return true;
    }
  }
  return false;
}

Image8 HeadlessRenderer::RenderEightBit(bool alpha)
{
  // Composited in floats, then quantised: blending in 8 bits would not be that.
  if (this->Samples > 1 || this->Translucent())
  {
    FloatImage average = this->Render();
    average.Alpha = alpha;
    return QuantiseToImage8(average);
  }
  this->RenderFrame(true);
  const int width = this->Capture->GetWidth(), height = this->Capture->GetHeight();
  const std::vector<std::uint8_t> rgba = this->Capture->TakePixels8();
  if (rgba.empty())
  {
    return {};
  }
  return { width, height,
    ToTopDown<std::uint8_t>(rgba.data(), width, height, alpha, [](std::uint8_t v) { return v; }),
    alpha };
}
}
