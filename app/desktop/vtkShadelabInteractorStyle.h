/**
 * @class   vtkShadelabInteractorStyle
 * @brief   the inspector's mouse and keys
 *
 * VTK's trackball camera for the mouse; every key goes to the handler
 * instead of VTK's own bindings (3 for stereo, e and q for exit, w and s
 * for wireframe and surface, ...), which the inspector's keys replace.
 */
#ifndef vtkShadelabInteractorStyle_h
#define vtkShadelabInteractorStyle_h

#include <vtkInteractorStyleTrackballCamera.h>

#include <functional>
#include <string>

class vtkShadelabInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkShadelabInteractorStyle* New();
  vtkTypeMacro(vtkShadelabInteractorStyle, vtkInteractorStyleTrackballCamera);

  /** Called with the key's character (or its X key name when it has none, e.g. "Escape"). */
  void SetKeyHandler(std::function<void(const std::string&)> handler)
  {
    this->KeyHandler = std::move(handler);
  }

  void OnChar() override;
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

protected:
  vtkShadelabInteractorStyle() = default;
  ~vtkShadelabInteractorStyle() override = default;

private:
  vtkShadelabInteractorStyle(const vtkShadelabInteractorStyle&) = delete;
  void operator=(const vtkShadelabInteractorStyle&) = delete;

  std::function<void(const std::string&)> KeyHandler;
};

#endif
