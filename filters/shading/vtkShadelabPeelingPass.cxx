#include "vtkShadelabPeelingPass.h"

#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLActor.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkProp.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkTranslucentPass.h>
#include <vtk_glew.h>

#include <vector>

vtkStandardNewMacro(vtkShadelabPeelingPass);

namespace
{
const char* const OpaqueDepthName = "shadelabOpaqueDepth";
const char* const PeeledDepthName = "shadelabPeeledDepth";
const char* const PeeledName = "shadelabPeeled";

// Declared before VTK's depth-peeling tags, which stay for any other pass.
const char* const PeelDeclaration =
  R"glsl(// Depth peeling: only the nearest fragment not yet composited, before the opaque surface.
uniform sampler2D shadelabOpaqueDepth;
uniform sampler2D shadelabPeeledDepth; // the last peel's depth
uniform int shadelabPeeled;            // peels before this one
)glsl";

std::string PeelTest(const char* depth)
{
  return std::string("  if (") + depth +
    " >= texelFetch(shadelabOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r ||\n"
    "    (shadelabPeeled > 0 && " +
    depth +
    " <= texelFetch(shadelabPeeledDepth, ivec2(gl_FragCoord.xy), 0).r))\n"
    "  {\n"
    "    discard;\n"
    "  }\n";
}

// A full-screen pass over the texture named `sampler`, its texel at the pixel as `f`
// (texCoord, the pixel's centre, names it; the quad's vertex stage needs it read).
std::string QuadSource(const char* sampler, const char* output)
{
  std::string source = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
  vtkShaderProgram::Substitute(
    source, "//VTK::FSQ::Decl", std::string("uniform sampler2D ") + sampler + ";\n");
  vtkShaderProgram::Substitute(source, "//VTK::FSQ::Impl",
    std::string("  vec4 f = texelFetch(") + sampler + ", ivec2(texCoord * vec2(textureSize(" +
      sampler + ", 0))), 0);\n" + output);
  return source;
}

vtkTextureObject* NewTexture(vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* t = vtkTextureObject::New();
  t->SetContext(window);
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  return t;
}

void Release(vtkTextureObject*& t)
{
  if (t)
  {
    t->Delete();
    t = nullptr;
  }
}
}

vtkShadelabPeelingPass::vtkShadelabPeelingPass()
  : TranslucentPass(vtkTranslucentPass::New())
{
}

void vtkShadelabPeelingPass::ReleaseTextures()
{
  Release(this->PeelColor);
  Release(this->Accumulated);
  Release(this->PeelDepths[0]);
  Release(this->PeelDepths[1]);
  Release(this->CopiedDepth);
}

vtkShadelabPeelingPass::~vtkShadelabPeelingPass()
{
  this->TranslucentPass->Delete();
  this->ReleaseTextures();
  if (this->Framebuffer)
  {
    this->Framebuffer->Delete();
  }
}

void vtkShadelabPeelingPass::PrepareTargets(vtkOpenGLRenderWindow* window, int width, int height)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkOpenGLFramebufferObject::New();
    this->Framebuffer->SetContext(window);
    glGenQueries(1, &this->Query);
  }
  if (this->PeelColor && width == this->Width && height == this->Height)
  {
    return;
  }
  for (vtkTextureObject** colour : { &this->PeelColor, &this->Accumulated })
  {
    Release(*colour);
    *colour = NewTexture(window);
    (*colour)->SetInternalFormat(GL_RGBA32F);
    (*colour)->SetFormat(GL_RGBA);
    (*colour)->Allocate2D(width, height, 4, VTK_FLOAT);
  }
  for (vtkTextureObject** depth :
    { &this->PeelDepths[0], &this->PeelDepths[1], &this->CopiedDepth })
  {
    Release(*depth);
    *depth = NewTexture(window);
    (*depth)->AllocateDepth(width, height, vtkTextureObject::Float32);
  }
  this->Width = width;
  this->Height = height;
}

void vtkShadelabPeelingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfPeels = 0;
  std::vector<vtkProp*> translucent;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (s->GetPropArray()[i]->HasTranslucentPolygonalGeometry())
    {
      translucent.push_back(s->GetPropArray()[i]);
    }
  }
  if (translucent.empty())
  {
    return;
  }
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = static_cast<vtkOpenGLRenderWindow*>(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  // The opaque surfaces' depth: the capture target's own texture, or (a
  // window's renderer, drawn into the framebuffer bound now) a copy of its
  // viewport.
  auto* target = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer());
  int width = 0, height = 0, x = 0, y = 0;
  if (target)
  {
    width = target->GetLastSize()[0];
    height = target->GetLastSize()[1];
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  }
  this->PrepareTargets(window, width, height);
  this->OpaqueDepth = target ? target->GetDepthAttachmentAsTextureObject() : this->CopiedDepth;
  if (!this->OpaqueDepth)
  {
    vtkErrorMacro("translucency needs a framebuffer with a depth texture to peel against");
    return;
  }
  if (!target)
  {
    unsigned int drawn = 0, buffer = 0;
    state->GetCurrentDrawFramebufferState(drawn, buffer);
    state->PushReadFramebufferBinding();
    state->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawn);
    this->CopiedDepth->CopyFromFrameBuffer(x, y, 0, 0, width, height);
    state->PopReadFramebufferBinding();
  }

  // Only the translucent props take the peel's test (the opaque ones keep
  // their programs), and they write depth (vtkOpenGLActor's override).
  vtkRenderState peeled(renderer);
  peeled.SetPropArrayAndCount(translucent.data(), static_cast<int>(translucent.size()));
  peeled.SetFrameBuffer(target);
  this->PreRender(&peeled);
  for (vtkProp* prop : translucent)
  {
    prop->GetPropertyKeys()->Set(vtkOpenGLActor::GLDepthMaskOverride(), 1);
  }

  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglViewport viewport(state);
  state->vtkglDisable(GL_SCISSOR_TEST); // the peels fill their own targets from 0, 0
  state->vtkglViewport(0, 0, width, height);
  state->PushFramebufferBindings();
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->Accumulated);
  this->Framebuffer->ActivateDrawBuffer(0);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
  while (this->MaximumNumberOfPeels == 0 || this->NumberOfPeels < this->MaximumNumberOfPeels)
  {
    const bool drew = this->Peel(&peeled);
    ++this->NumberOfPeels;
    if (!drew)
    {
      break;
    }
    this->AccumulatePeel(window);
  }
  state->PopFramebufferBindings();
  state->vtkglViewport(x, y, width, height);
  this->CompositeOverOpaque(window);

  for (vtkProp* prop : translucent)
  {
    prop->GetPropertyKeys()->Remove(vtkOpenGLActor::GLDepthMaskOverride());
  }
  this->PostRender(&peeled);
  this->NumberOfRenderedProps = static_cast<int>(translucent.size());
}

bool vtkShadelabPeelingPass::Peel(const vtkRenderState* s)
{
  vtkOpenGLState* state =
    static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow())->GetState();
  const int current = this->NumberOfPeels % 2;
  this->Framebuffer->AddColorAttachment(0, this->PeelColor);
  this->Framebuffer->AddDepthAttachment(this->PeelDepths[current]);
  this->Framebuffer->ActivateDrawBuffer(0);
  state->vtkglClearColor(0, 0, 0, 0);
  state->vtkglClearDepth(1.0);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglDisable(GL_BLEND); // the peel keeps the fragment's own I and a

  this->OpaqueDepth->Activate();
  this->PeelDepths[1 - current]->Activate();
  glBeginQuery(GL_SAMPLES_PASSED, this->Query);
  this->TranslucentPass->Render(s);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint samples = 0;
  glGetQueryObjectuiv(this->Query, GL_QUERY_RESULT, &samples);
  this->PeelDepths[1 - current]->Deactivate();
  this->OpaqueDepth->Deactivate();
  this->Framebuffer->RemoveDepthAttachment();
  return samples > 0;
}

void vtkShadelabPeelingPass::AccumulatePeel(vtkOpenGLRenderWindow* window)
{
  this->Framebuffer->AddColorAttachment(0, this->Accumulated);
  this->Framebuffer->ActivateDrawBuffer(0);
  // Under: C += (1-A) * a*I, A += (1-A) * a.
  this->BlendTexture(window, this->AccumulateQuad, "  gl_FragData[0] = vec4(f.rgb * f.a, f.a);\n",
    this->PeelColor, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
}

void vtkShadelabPeelingPass::CompositeOverOpaque(vtkOpenGLRenderWindow* window)
{
  // Over: C + (1-A) * opaque, A + (1-A) * opaque alpha.
  this->BlendTexture(window, this->CompositeQuad, "  gl_FragData[0] = f;\n", this->Accumulated,
    GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void vtkShadelabPeelingPass::BlendTexture(vtkOpenGLRenderWindow* window,
  std::unique_ptr<vtkOpenGLQuadHelper>& quad, const char* output, vtkTextureObject* texture,
  unsigned int source, unsigned int destination)
{
  vtkOpenGLState* state = window->GetState();
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(source, destination, source, destination);
  if (!quad)
  {
    quad = std::make_unique<vtkOpenGLQuadHelper>(
      window, nullptr, QuadSource("shadelabLayer", output).c_str(), nullptr);
  }
  window->GetShaderCache()->ReadyShaderProgram(quad->Program);
  texture->Activate();
  quad->Program->SetUniformi("shadelabLayer", texture->GetTextureUnit());
  quad->Render();
  texture->Deactivate();
}

bool vtkShadelabPeelingPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // A stage of one's own dumped from a translucent scene holds the test already.
  if (fragmentShader.find(PeelDeclaration) != std::string::npos)
  {
    return true;
  }
  // The depth the fragment writes: its own, or the one the stage gives it
  // (lines drawn over the surface push the surface back).
  const char* depth =
    fragmentShader.find("gl_FragDepth =") != std::string::npos ? "gl_FragDepth" : "gl_FragCoord.z";
  return vtkShaderProgram::Substitute(fragmentShader, "//VTK::DepthPeeling::Dec",
           std::string(PeelDeclaration) + "//VTK::DepthPeeling::Dec") &&
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::DepthPeeling::PreColor",
      PeelTest(depth) + "//VTK::DepthPeeling::PreColor");
}

bool vtkShadelabPeelingPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  const int current = this->NumberOfPeels % 2;
  return program->SetUniformi(OpaqueDepthName, this->OpaqueDepth->GetTextureUnit()) &&
    program->SetUniformi(PeeledDepthName, this->PeelDepths[1 - current]->GetTextureUnit()) &&
    program->SetUniformi(PeeledName, this->NumberOfPeels);
}

void vtkShadelabPeelingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->TranslucentPass->ReleaseGraphicsResources(w);
  for (auto* quad : { this->AccumulateQuad.get(), this->CompositeQuad.get() })
  {
    if (quad)
    {
      quad->ReleaseGraphicsResources(w);
    }
  }
  this->AccumulateQuad.reset();
  this->CompositeQuad.reset();
  this->ReleaseTextures();
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer->Delete();
    this->Framebuffer = nullptr;
    glDeleteQueries(1, &this->Query);
    this->Query = 0;
  }
  this->Width = this->Height = 0;
}

void vtkShadelabPeelingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaximumNumberOfPeels: " << this->MaximumNumberOfPeels << "\n";
  os << indent << "NumberOfPeels: " << this->NumberOfPeels << "\n";
}
