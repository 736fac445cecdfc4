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
class vtkShadelabPeelingPass;

namespace shadelab
{
struct EnvironmentMap;

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
   * Renders one frame and returns it; with `behind`, each sample laid over
   * the environment along its own ray before the samples are averaged
   * (OverEnvironment: --background environment). VTK's first error during
   * the frame (a shader that does not compile, say) is then GetError(),
   * else ""; its warnings are reported.
   */
  FloatImage Render(const EnvironmentMap* behind = nullptr);
  const std::string& GetError() const { return this->Error; }

  /**
   * Renders one frame for an 8-bit file (RGB, or RGBA with alpha): byte for
   * byte Quantise(Render()), at a quarter of the target's memory
   * (vtkShadelabCapturePass::SetEightBit), for a scene of opaque actors.
   * With samples > 1 or translucent props, Render's picture quantised.
   * Errors as Render.
   */
  Image8 RenderEightBit(bool alpha);

  /** --peels: the most peels of translucent surfaces; 0, as many as they have layers. */
  void SetMaximumNumberOfPeels(int peels);

private:
  bool Translucent() const; // a visible prop is drawn in the translucent step
  void RenderFrame(bool eightBit);

  vtkSmartPointer<vtkShadelabOSMesaRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkShadelabCapturePass> Capture;
  vtkSmartPointer<vtkShadelabPeelingPass> Peeling; // the translucent step
  std::string Error;
  int Samples = 1;
};
}

#endif
