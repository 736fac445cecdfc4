/**
 * @class   vtkShadelabCapturePass
 * @brief   renders its delegate into its own target and reads it back: floats, or 8-bit
 *
 * VTK 9.1's window framebuffers are 8-bit, which would clamp and quantise
 * intensities before an EXR or float TIFF could see them. This pass renders
 * the delegate (normally vtkRenderStepsPass) into an RGBA32F framebuffer
 * object and keeps the pixels, unclamped, for the image writer.
 *
 * A picture bound for an 8-bit file needs only round(255*clamp(I)), the
 * contract's quantisation (image_pixels.h, Quantised). With SetEightBit the
 * pass renders into an RGBA8 target instead, a quarter of the memory to
 * clear, write and read back, and keeps every byte what quantising the
 * floats would give: it appends to each mapper's fragment shader a step
 * that decides k = round(255*clamp(I)) exactly (a comparison with the
 * least float at or above each half step, not a float multiply) and writes
 * k/255, which the target stores as k, and it clears to the background
 * quantised the same way. Blending in 8 bits would not be the floats'
 * blend quantised, so every prop must be opaque (an error otherwise).
 * Rows are bottom-up, as OpenGL reads them.
 */
#ifndef vtkShadelabCapturePass_h
#define vtkShadelabCapturePass_h

#include <vtkOpenGLRenderPass.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;

class vtkShadelabCapturePass : public vtkOpenGLRenderPass
{
public:
  static vtkShadelabCapturePass* New();
  vtkTypeMacro(vtkShadelabCapturePass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);

  /** The next renders' target: 8-bit, quantised exactly (above), or floats (the default). */
  void SetEightBit(bool eightBit) { this->EightBit = eightBit; }

  /**
   * RGBA floats of the last float render, width*height*4, bottom row
   * first, handed over rather than copied (33 MB a 1080p frame): the pass
   * keeps none.
   */
  std::vector<float> TakePixels() { return std::move(this->Pixels); }
  /** The same of the last 8-bit render: RGBA bytes. */
  std::vector<std::uint8_t> TakePixels8() { return std::move(this->Pixels8); }
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /** The 8-bit step: declares its function and calls it last in main. */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  /** Its uniforms: the half steps. */
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao) override;

  /**
   * The least float v with Quantised(v, 255) >= j, for j = 1..255 (index
   * j - 1): where round(255*clamp(v)) steps up, as the shader step compares.
   */
  static const std::array<float, 255>& HalfSteps();

protected:
  vtkShadelabCapturePass() = default;
  ~vtkShadelabCapturePass() override;

private:
  vtkShadelabCapturePass(const vtkShadelabCapturePass&) = delete;
  void operator=(const vtkShadelabCapturePass&) = delete;

  // The target for width x height in the current format; false (reported) if it cannot be made.
  bool PrepareTarget(vtkOpenGLRenderWindow* window, int width, int height);
  // The 8-bit render's preconditions: every prop opaque, a plain background.
  bool CheckEightBitScene(const vtkRenderState* s);

  vtkRenderPass* DelegatePass = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  bool EightBit = false;
  bool TargetEightBit = false; // the format of Framebuffer's colour texture
  std::vector<float> Pixels;
  std::vector<std::uint8_t> Pixels8;
  int Width = 0;
  int Height = 0;
};

#endif
