/**
 * @class   vtkShadelabFloatCapturePass
 * @brief   renders its delegate into a 32-bit float target and reads it back
 *
 * VTK 9.1's window framebuffers are 8-bit, which would clamp and quantise
 * intensities before an EXR or float TIFF could see them. This pass renders
 * the delegate (normally vtkRenderStepsPass) into an RGBA32F framebuffer
 * object and keeps the pixels, unclamped, for the image writer. 8-bit images
 * are quantised from the same floats on the CPU, so every format sees one
 * render. Rows are bottom-up, as OpenGL reads them.
 */
#ifndef vtkShadelabFloatCapturePass_h
#define vtkShadelabFloatCapturePass_h

#include <vtkRenderPass.h>

#include <utility>
#include <vector>

class vtkOpenGLFramebufferObject;

class vtkShadelabFloatCapturePass : public vtkRenderPass
{
public:
  static vtkShadelabFloatCapturePass* New();
  vtkTypeMacro(vtkShadelabFloatCapturePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);

  /**
   * RGBA floats of the last render, width*height*4, bottom row first, handed
   * over rather than copied (33 MB a 1080p frame): the pass keeps none.
   */
  std::vector<float> TakePixels() { return std::move(this->Pixels); }
  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

protected:
  vtkShadelabFloatCapturePass() = default;
  ~vtkShadelabFloatCapturePass() override;

private:
  vtkShadelabFloatCapturePass(const vtkShadelabFloatCapturePass&) = delete;
  void operator=(const vtkShadelabFloatCapturePass&) = delete;

  vtkRenderPass* DelegatePass = nullptr;
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  std::vector<float> Pixels;
  int Width = 0;
  int Height = 0;
};

#endif
