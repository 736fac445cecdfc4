#include "headless/vtkShadelabOSMesaRenderWindow.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>

#include <GL/osmesa.h>

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <string>

vtkStandardNewMacro(vtkShadelabOSMesaRenderWindow);

vtkShadelabOSMesaRenderWindow::vtkShadelabOSMesaRenderWindow()
{
  this->SetReadyForRendering(false);
  this->OffScreenRenderingOn();
}

vtkShadelabOSMesaRenderWindow::~vtkShadelabOSMesaRenderWindow()
{
  this->Finalize();
}

void vtkShadelabOSMesaRenderWindow::ChooseRasterizerThreads()
{
  if (std::getenv("LP_NUM_THREADS"))
  {
    return;
  }
  cpu_set_t set;
  int count = 1;
  if (sched_getaffinity(0, sizeof(set), &set) == 0)
  {
    count = CPU_COUNT(&set);
  }
  // llvmpipe's own cap is 32 rasteriser threads.
  count = std::clamp(count, 1, 32);
  setenv("LP_NUM_THREADS", std::to_string(count).c_str(), 0);
}

void vtkShadelabOSMesaRenderWindow::Initialize()
{
  if (this->Context)
  {
    return;
  }
  const int attributes[] = { OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS,
    8, OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
    OSMESA_CONTEXT_MINOR_VERSION, 2, 0 };
  this->Context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!this->Context)
  {
    vtkErrorMacro("OSMesa could not create an OpenGL 3.2 core-profile context");
    return;
  }
  if (!this->BindBuffer())
  {
    return;
  }
  this->SetIsCurrent(true);
  this->SetReadyForRendering(true);
  // Runs glewInit through glx_shim.cxx and sets VTK's GL state.
  if (!this->InitializeFromCurrentContext())
  {
    vtkErrorMacro("VTK could not initialise OpenGL in the OSMesa context");
    this->SetReadyForRendering(false);
    return;
  }
  this->ContextReady = true;
}

void vtkShadelabOSMesaRenderWindow::Start()
{
  if (!this->FramebuffersUnused)
  {
    this->Superclass::Start();
    return;
  }
  // vtkOpenGLRenderWindow::Start with framebuffers of one pixel: an owned
  // context, so no state to reset; the size stays the window's (renderers
  // take their viewports from it).
  this->Initialize();
  this->MakeCurrent();
  this->GetState()->vtkglEnable(GL_BLEND);
  this->GetState()->vtkglBlendFuncSeparate(
    GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  this->CreateFramebuffers(1, 1);
  this->GetState()->PushFramebufferBindings();
  this->RenderFramebuffer->Bind();
  this->RenderFramebuffer->ActivateDrawBuffer(0);
}

bool vtkShadelabOSMesaRenderWindow::BindBuffer()
{
  if (!OSMesaMakeCurrent(
        static_cast<OSMesaContext>(this->Context), this->Buffer.data(), GL_UNSIGNED_BYTE, 1, 1))
  {
    vtkErrorMacro("OSMesa could not make its context current");
    return false;
  }
  return true;
}

void vtkShadelabOSMesaRenderWindow::Finalize()
{
  if (!this->Context)
  {
    return;
  }
  this->MakeCurrent();
  this->ReleaseGraphicsResources(this);
  OSMesaDestroyContext(static_cast<OSMesaContext>(this->Context));
  this->Context = nullptr;
  this->ContextReady = false;
  this->SetReadyForRendering(false);
}

void vtkShadelabOSMesaRenderWindow::MakeCurrent()
{
  if (this->Context && !this->IsCurrent())
  {
    this->BindBuffer();
  }
}

bool vtkShadelabOSMesaRenderWindow::IsCurrent()
{
  return this->Context && OSMesaGetCurrentContext() == this->Context;
}

void vtkShadelabOSMesaRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << this->Context << "\n";
  os << indent << "ContextReady: " << this->ContextReady << "\n";
}
