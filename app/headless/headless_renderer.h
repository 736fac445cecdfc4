// The headless backend as the commands use it: an OSMesa render window with
// one renderer whose frames are captured as unclamped floats.
#ifndef shadelab_headless_renderer_h
#define shadelab_headless_renderer_h

#include "image/image_pixels.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkRenderer;
class vtkShadelabCapturePass;
class vtkShadelabOSMesaRenderWindow;

namespace shadelab
{
class HeadlessRenderer
{
public:
  HeadlessRenderer();
  ~HeadlessRenderer();

  /**
   * Creates the OpenGL context for width x height pictures, each pixel
   * `samples` x `samples` rendered samples (--ssaa); an error text or "".
   */
  std::string Start(int width, int height, int samples = 1);

  /** The renderer to fill with the scene. */
  vtkRenderer* GetRenderer() const { return this->Renderer; }

  /**
   * Renders one frame and returns it. VTK's first error during the frame (a
   * shader that does not compile, say) is then GetError(), else "";
   * its warnings are reported.
   */
  FloatImage Render();
  const std::string& GetError() const { return this->Error; }

  /**
   * Renders one frame for an 8-bit file (RGB, or RGBA with alpha): byte for
   * byte Quantise(Render()), at a quarter of the target's memory
   * (vtkShadelabCapturePass::SetEightBit), for a scene of opaque actors.
   * With samples > 1, Render's average quantised. Errors as Render.
   */
  Image8 RenderEightBit(bool alpha);

private:
  void RenderFrame(bool eightBit);

  vtkSmartPointer<vtkShadelabOSMesaRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkShadelabCapturePass> Capture;
  std::string Error;
  int Samples = 1;
};
}

#endif
