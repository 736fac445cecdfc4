// shadelab-view's Qt window: the inspector's 3D view (VTK's
// QVTKOpenGLNativeWidget showing the Inspector's render window) with the
// control panel in a dock beside it, the running shader's panel in a dock
// tabbed with it, and the probe's readout in a dock beside them. Every key of the key table
// (desktop/view_keys.h) works wherever the focus is, but in a field being
// typed into.
#ifndef shadelab_inspector_window_h
#define shadelab_inspector_window_h

#include "desktop/inspector.h"

#include <QMainWindow>

#include <string>
#include <vector>

class QVTKOpenGLNativeWidget;

namespace shadelab
{
class ControlPanel;
class ShaderPanel;
class ProbePanel;

class InspectorWindow : public QMainWindow
{
public:
  explicit InspectorWindow(Inspector& inspector);

  /** Shows the window with its 3D view `size` pixels, and starts the
   * inspector in it; whether the window is still open (a quit key may
   * have come first). */
  bool Open(const ImageSize& size);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  Inspector& Engine;
  QVTKOpenGLNativeWidget* View;
  ControlPanel* Panel;
  ShaderPanel* Shaders;
  ProbePanel* Readout;
  bool Started = false;
  std::vector<std::string> EarlyKeys; // pressed before the inspector started
};
}

#endif
