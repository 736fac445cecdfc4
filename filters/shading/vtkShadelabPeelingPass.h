/**
 * @class   vtkShadelabPeelingPass
 * @brief   translucent surfaces composited in exact depth order, in floats
 *
 * The translucent step of vtkRenderStepsPass for translucency: each
 * translucent fragment's colour I and opacity a (the shader writes
 * fragOutput0 = vec4(I, a)) are composited over what lies behind it as
 * a*I + (1-a)*behind, every fragment of every translucent prop, nearest
 * last. VTK 9.1's dual depth peeling is not exact: it accumulates in 8 bits
 * (clamping intensities above 1), merges fragments within 1e-7 of each
 * other's depth by a per-channel maximum, and takes a maximum of 0 peels
 * for none at all. This pass peels front to back instead:
 *
 * - peel k draws the translucent props into a float colour target and a
 *   32-bit float depth (test GL_LESS), each fragment discarded unless it
 *   lies in front of the opaque surface's depth and strictly behind peel
 *   k-1's depth at its pixel: the nearest fragment not yet composited. The
 *   same program draws every peel, so a fragment's depth repeats exactly
 *   and needs no epsilon;
 * - the peel goes under what is composited so far, in an RGBA float
 *   accumulator (C += (1-A)*a*I, A += (1-A)*a): front to back, so that a
 *   limit on the peels loses the farthest layers;
 * - peeling stops when a peel draws no fragment (an occlusion query), or
 *   at the limit; then C + (1-A)*opaque, A + (1-A)*opaque alpha is the
 *   picture, the same as compositing back to front.
 *
 * Fragments at the same depth at a pixel (coincident translucent
 * surfaces): the first drawn is composited, the others are not.
 *
 * The opaque depth is the state's framebuffer's depth texture (the capture
 * pass's) or, without one (a window's renderer), a copy of the bound
 * framebuffer's depth in the renderer's viewport, where the result goes.
 * With no translucent prop it does nothing.
 */
#ifndef vtkShadelabPeelingPass_h
#define vtkShadelabPeelingPass_h

#include "shadelab_filtersModule.h" // the export macro

#include <vtkOpenGLRenderPass.h>

#include <array>
#include <memory>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkTranslucentPass;

class SHADELAB_FILTERS_EXPORT vtkShadelabPeelingPass : public vtkOpenGLRenderPass
{
public:
  static vtkShadelabPeelingPass* New();
  vtkTypeMacro(vtkShadelabPeelingPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /** The most peels a picture takes; 0 (the default): as many as its layers. */
  void SetMaximumNumberOfPeels(int peels) { this->MaximumNumberOfPeels = peels; }
  /** The peels the last render took, the last one (which drew nothing) included. */
  int GetNumberOfPeels() const { return this->NumberOfPeels; }

  /** The peel's test of each fragment against the opaque depth and the last peel's. */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  /** Its uniforms: the depth textures' units and whether a peel came before. */
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao) override;

protected:
  vtkShadelabPeelingPass();
  ~vtkShadelabPeelingPass() override;

private:
  vtkShadelabPeelingPass(const vtkShadelabPeelingPass&) = delete;
  void operator=(const vtkShadelabPeelingPass&) = delete;

  void ReleaseTextures();
  // The textures and framebuffer for width x height.
  void PrepareTargets(vtkOpenGLRenderWindow* window, int width, int height);
  // Draws peel number this->NumberOfPeels; whether it drew a fragment.
  bool Peel(const vtkRenderState* s);
  // Puts the last peel under the accumulator.
  void AccumulatePeel(vtkOpenGLRenderWindow* window);
  // Puts the accumulator over the state's framebuffer.
  void CompositeOverOpaque(vtkOpenGLRenderWindow* window);
  // Draws `texture` over the bound target in a full-screen quad whose
  // fragment stage ends with `output` (its texel is f), blended by these
  // factors, colour and alpha alike.
  void BlendTexture(vtkOpenGLRenderWindow* window, std::unique_ptr<vtkOpenGLQuadHelper>& quad,
    const char* output, vtkTextureObject* texture, unsigned int source, unsigned int destination);

  vtkTranslucentPass* TranslucentPass;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  vtkTextureObject* PeelColor = nullptr;
  vtkTextureObject* Accumulated = nullptr;
  std::array<vtkTextureObject*, 2> PeelDepths{}; // this peel's and the last one's, in turn
  vtkTextureObject* CopiedDepth = nullptr;       // a window's opaque depth
  vtkTextureObject* OpaqueDepth = nullptr;       // the state's framebuffer's, or CopiedDepth
  std::unique_ptr<vtkOpenGLQuadHelper> AccumulateQuad;
  std::unique_ptr<vtkOpenGLQuadHelper> CompositeQuad;
  unsigned int Query = 0;
  int Width = 0;
  int Height = 0;
  int MaximumNumberOfPeels = 0;
  int NumberOfPeels = 0;
};

#endif
