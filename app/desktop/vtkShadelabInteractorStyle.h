/**
 * @class   vtkShadelabInteractorStyle
 * @brief   the inspector's mouse and keys
 *
 * VTK's trackball camera for the mouse, and none of VTK's own key
 * bindings (3 for stereo, e and q for exit, w and s for wireframe and
 * surface, ...): the inspector's keys replace them, and come through the
 * Qt window (desktop/inspector_window.h), which sees every key first.
 * While LineDrag is set, the next left drag draws a line instead of
 * turning the camera (the profile's line).
 */
#ifndef vtkShadelabInteractorStyle_h
#define vtkShadelabInteractorStyle_h

#include <vtkInteractorStyleTrackballCamera.h>

#include <functional>

class vtkShadelabInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkShadelabInteractorStyle* New();
  vtkTypeMacro(vtkShadelabInteractorStyle, vtkInteractorStyleTrackballCamera);

  void OnChar() override {}
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

  /**
   * Called as the line is dragged, with its ends in display pixels (from
   * the bottom left) and whether the button was released; unset once it is.
   */
  std::function<void(const int from[2], const int to[2], bool released)> LineDrag;

  void OnLeftButtonDown() override;
  void OnMouseMove() override;
  void OnLeftButtonUp() override;

protected:
  vtkShadelabInteractorStyle() = default;
  ~vtkShadelabInteractorStyle() override = default;

private:
  bool DrawingLine = false;
  int LineFrom[2] = {};

  vtkShadelabInteractorStyle(const vtkShadelabInteractorStyle&) = delete;
  void operator=(const vtkShadelabInteractorStyle&) = delete;
};

#endif
