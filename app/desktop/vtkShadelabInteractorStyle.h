/**
 * @class   vtkShadelabInteractorStyle
 * @brief   the inspector's mouse and keys
 *
 * VTK's trackball camera for the mouse, and none of VTK's own key
 * bindings (3 for stereo, e and q for exit, w and s for wireframe and
 * surface, ...): the inspector's keys replace them, and come through the
 * Qt window (desktop/inspector_window.h), which sees every key first.
 */
#ifndef vtkShadelabInteractorStyle_h
#define vtkShadelabInteractorStyle_h

#include <vtkInteractorStyleTrackballCamera.h>

class vtkShadelabInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkShadelabInteractorStyle* New();
  vtkTypeMacro(vtkShadelabInteractorStyle, vtkInteractorStyleTrackballCamera);

  void OnChar() override {}
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

protected:
  vtkShadelabInteractorStyle() = default;
  ~vtkShadelabInteractorStyle() override = default;

private:
  vtkShadelabInteractorStyle(const vtkShadelabInteractorStyle&) = delete;
  void operator=(const vtkShadelabInteractorStyle&) = delete;
};

#endif
