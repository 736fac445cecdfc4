/**
 * @class   vtkShadelabOSMesaRenderWindow
 * @brief   headless render window over an OSMesa (llvmpipe) core-profile context
 *
 * Debian's VTK 9.1 is built for X11/GLX without its own OSMesa window
 * (VTK_OPENGL_HAS_OSMESA is off), so this class drives an OSMesa context
 * through vtkGenericOpenGLRenderWindow, the way vtkOSOpenGLRenderWindow
 * would: RGBA, 24-bit depth, core profile 3.2. It needs the GLX answers of
 * glx_shim.cxx in the same executable and libOSMesa ahead of libOpenGL/libGL
 * in symbol lookup; CMake's shadelab_link_osmesa() arranges both.
 *
 * The context is made in Initialize(); a failure is reported through
 * vtkErrorMacro and leaves GetContextReady() false.
 */
#ifndef vtkShadelabOSMesaRenderWindow_h
#define vtkShadelabOSMesaRenderWindow_h

#include <vtkGenericOpenGLRenderWindow.h>

#include <array>

class vtkShadelabOSMesaRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkShadelabOSMesaRenderWindow* New();
  vtkTypeMacro(vtkShadelabOSMesaRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Creates the OSMesa context and initialises VTK's OpenGL state in it. */
  void Initialize() override;
  void Finalize() override;

  /**
   * As VTK's Start, but with its render, display and resolve framebuffers
   * at one pixel when FramebuffersUnused is on.
   */
  void Start() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  vtkTypeBool IsDirect() override { return 1; }
  int SupportsOpenGL() override { return this->ContextReady ? 1 : 0; }
  void Frame() override {}

  vtkGetMacro(ContextReady, bool);

  /**
   * On when every render draws into a framebuffer of its own (the float
   * capture pass) and nothing reads the window's: then VTK's render,
   * display and resolve framebuffers are kept at one pixel instead of the
   * window's size (56 MB at 1080p, which llvmpipe would zero). Off by
   * default: vtkWindowToImageFilter and GetPixelData read them.
   */
  vtkSetMacro(FramebuffersUnused, bool);
  vtkGetMacro(FramebuffersUnused, bool);

  /**
   * Sets LP_NUM_THREADS (llvmpipe's rasteriser threads) to the number of
   * processors this process may run on, unless the user has set it. Mesa's
   * own default counts every online processor, which oversubscribes a
   * container or a job limited by CPU affinity. Call before the first context.
   */
  static void ChooseRasterizerThreads();

protected:
  vtkShadelabOSMesaRenderWindow();
  ~vtkShadelabOSMesaRenderWindow() override;

private:
  vtkShadelabOSMesaRenderWindow(const vtkShadelabOSMesaRenderWindow&) = delete;
  void operator=(const vtkShadelabOSMesaRenderWindow&) = delete;

  bool BindBuffer();

  void* Context = nullptr; // OSMesaContext, kept opaque to keep osmesa.h out
  // OSMesa's default framebuffer, one pixel: VTK draws into framebuffer
  // objects of its own and reads those; Frame, which would copy them here,
  // does nothing.
  std::array<unsigned char, 4> Buffer{};
  bool ContextReady = false;
  bool FramebuffersUnused = false;
};

#endif
