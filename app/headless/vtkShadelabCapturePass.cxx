#include "headless/vtkShadelabCapturePass.h"

#include "image/image_pixels.h"
#include "shadelabEightBitStep.h"

#include <vtkAbstractMapper.h>
#include <vtkActor.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkProp.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtk_glew.h>

#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkShadelabCapturePass);

namespace
{

// v as the 8-bit target stores it from k/255 (k = Quantised(v, 255)), for the clear colour.
double QuantisedToEightBits(double v)
{
  return shadelab::Quantised(static_cast<float>(v), 255) / 255;
}
}

const std::array<float, 255>& vtkShadelabCapturePass::HalfSteps()
{
  static const std::array<float, 255> steps = []
  {
    std::array<float, 255> s{};
    constexpr float down = -std::numeric_limits<float>::infinity();
    constexpr float up = std::numeric_limits<float>::infinity();
    for (int j = 1; j <= 255; ++j)
    {
      float v = static_cast<float>((j - 0.5) / 255);
      while (shadelab::Quantised(v, 255) >= j)
      {
        v = std::nextafter(v, down);
      }
      while (shadelab::Quantised(v, 255) < j)
      {
        v = std::nextafter(v, up);
      }
      s[j - 1] = v;
    }
    return s;
  }();
  return steps;
}

vtkShadelabCapturePass::~vtkShadelabCapturePass()
{
  this->SetDelegatePass(nullptr);
  if (this->Framebuffer)
  {
    this->Framebuffer->Delete();
  }
}

void vtkShadelabCapturePass::SetDelegatePass(vtkRenderPass* delegatePass)
{
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, delegatePass);
}

bool vtkShadelabCapturePass::PrepareTarget(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
  }
  if (width == this->Width && height == this->Height && this->EightBit == this->TargetEightBit &&
    this->Framebuffer->GetNumberOfColorAttachments() > 0)
  {
    return true;
  }
  this->Framebuffer->Bind();
  // One colour texture and a 24-bit depth buffer, no multisampling: pixels
  // must be exact and repeatable.
  if (!this->Framebuffer->PopulateFramebuffer(
        width, height, true, 1, this->EightBit ? VTK_UNSIGNED_CHAR : VTK_FLOAT, true, 24, 0))
  {
    vtkErrorMacro("cannot create a " << width << "x" << height
                                     << (this->EightBit ? " 8-bit" : " float") << " framebuffer");
    return false;
  }
  this->Width = width;
  this->Height = height;
  this->TargetEightBit = this->EightBit;
  return true;
}

bool vtkShadelabCapturePass::CheckEightBitScene(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  if (renderer->GetGradientBackground() || renderer->GetTexturedBackground())
  {
    vtkErrorMacro("an 8-bit capture needs a plain background");
    return false;
  }
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    // Only actors' polydata mappers take the 8-bit step; blending happens in the target's bits.
    if (!vtkActor::SafeDownCast(prop) || prop->HasTranslucentPolygonalGeometry())
    {
      vtkErrorMacro("an 8-bit capture needs opaque actors only; " << prop->GetClassName()
                                                                  << " needs the float target");
      return false;
    }
  }
  return true;
}

void vtkShadelabCapturePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkErrorMacro("no delegate pass to render");
    return;
  }
  if (this->EightBit && !this->CheckEightBitScene(s))
  {
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  int width = 0, height = 0, x = 0, y = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);

  state->PushFramebufferBindings();
  if (!this->PrepareTarget(window, width, height))
  {
    state->PopFramebufferBindings();
    return;
  }
  this->Framebuffer->Bind();
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Framebuffer->ActivateReadBuffer(0);

  double background[3];
  renderer->GetBackground(background);
  const double backgroundAlpha = renderer->GetBackgroundAlpha();
  if (this->EightBit)
  {
    this->PreRender(s); // the props' mappers take the 8-bit step
    renderer->SetBackground(QuantisedToEightBits(background[0]),
      QuantisedToEightBits(background[1]), QuantisedToEightBits(background[2]));
    renderer->SetBackgroundAlpha(QuantisedToEightBits(backgroundAlpha));
  }
  vtkRenderState delegateState(renderer);
  delegateState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  delegateState.SetFrameBuffer(this->Framebuffer);
  this->DelegatePass->Render(&delegateState);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  if (this->EightBit)
  {
    this->PostRender(s);
    renderer->SetBackground(background);
    renderer->SetBackgroundAlpha(backgroundAlpha);
  }

  const std::size_t values = static_cast<std::size_t>(width) * height * 4;
  state->vtkglPixelStorei(GL_PACK_ALIGNMENT, 1);
  if (this->EightBit)
  {
    this->Pixels8.resize(values);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, this->Pixels8.data());
  }
  else
  {
    this->Pixels.resize(values);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, this->Pixels.data());
  }
  state->PopFramebufferBindings();
}

bool vtkShadelabCapturePass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp*)
{
  if (!shadelab::AddEightBitStep(fragmentShader))
  {
    vtkErrorMacro(
      "the fragment shader of " << mapper->GetClassName() << " has no place for the 8-bit step");
    return false;
  }
  return true;
}

bool vtkShadelabCapturePass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  const std::array<float, 255>& steps = HalfSteps();
  return program->SetUniform1fv("shadelabHalfSteps", static_cast<int>(steps.size()), steps.data());
}

void vtkShadelabCapturePass::ReleaseGraphicsResources(vtkWindow* w)
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

void vtkShadelabCapturePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "EightBit: " << this->EightBit << "\n";
  os << indent << "Size: " << this->Width << "x" << this->Height << "\n";
}
