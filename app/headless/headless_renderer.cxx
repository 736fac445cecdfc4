#include "headless/headless_renderer.h"

#include "core/errors.h"
#include "headless/vtkShadelabFloatCapturePass.h"
#include "headless/vtkShadelabOSMesaRenderWindow.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkAutoInit.h>
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
  , Capture(vtkSmartPointer<vtkShadelabFloatCapturePass>::New())
{
  this->Capture->SetDelegatePass(vtkSmartPointer<vtkRenderStepsPass>::New());
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

FloatImage HeadlessRenderer::Render()
{
  const MessageScope messages;
  this->Window->Render();
  this->Error = messages.FirstError();
  ReportWarnings("render", messages.Warnings());
  FloatImage samples{ this->Capture->GetWidth(), this->Capture->GetHeight(),
    this->Capture->TakePixels() };
  return this->Samples > 1 ? BoxAverage(samples, this->Samples) : samples;
}
}
