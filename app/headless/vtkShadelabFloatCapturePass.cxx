#include "headless/vtkShadelabFloatCapturePass.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtk_glew.h>

vtkStandardNewMacro(vtkShadelabFloatCapturePass);

vtkShadelabFloatCapturePass::~vtkShadelabFloatCapturePass()
{
  this->SetDelegatePass(nullptr);
  if (this->Framebuffer)
  {
    this->Framebuffer->Delete();
  }
}

void vtkShadelabFloatCapturePass::SetDelegatePass(vtkRenderPass* delegatePass)
{
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, delegatePass);
}

void vtkShadelabFloatCapturePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkErrorMacro("no delegate pass to render");
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);

  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
  }
  state->PushFramebufferBindings();
  if (width != this->Width || height != this->Height ||
    this->Framebuffer->GetNumberOfColorAttachments() == 0)
  {
    this->Framebuffer->Bind();
    // One RGBA32F colour texture and a 24-bit depth buffer, no multisampling:
    // pixels must be exact and repeatable.
    if (!this->Framebuffer->PopulateFramebuffer(width, height, true, 1, VTK_FLOAT, true, 24, 0))
    {
      state->PopFramebufferBindings();
      vtkErrorMacro("cannot create a " << width << "x" << height << " float framebuffer");
      return;
    }
    this->Width = width;
    this->Height = height;
  }
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Framebuffer->ActivateReadBuffer(0);

  vtkRenderState delegateState(renderer);
  delegateState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  delegateState.SetFrameBuffer(this->Framebuffer);
  this->DelegatePass->Render(&delegateState);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();

  this->Pixels.resize(static_cast<size_t>(width) * height * 4);
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, this->Pixels.data());
  state->PopFramebufferBindings();
}

void vtkShadelabFloatCapturePass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer->Delete();
    this->Framebuffer = nullptr;
  }
  this->Width = this->Height = 0;
}

void vtkShadelabFloatCapturePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "Size: " << this->Width << "x" << this->Height << "\n";
}
