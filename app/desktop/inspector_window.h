// shadelab-view's Qt window: the inspector's 3D view (VTK's
// QVTKOpenGLNativeWidget showing the Inspector's render window) with the
// control panel in a dock beside it, the running shader's panel and the
// probe's readout in docks tabbed with it, and the profile's chart. Every key of the key table
// (desktop/view_keys.h) works wherever the focus is, but in a field being
// typed into.
#ifndef shadelab_inspector_window_h
#define shadelab_inspector_window_h

#include "desktop/inspector.h"

#include <QMainWindow>
#include <QPixmap>
#include <QTemporaryDir>

#include <string>
#include <vector>

class QDockWidget;
class QLabel;
class QProcess;
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

  /**
   * Shows the window with its 3D view `size` pixels, on the screen it opens
   * on (the view shrunk in the same shape where the whole window would not
   * fit, unless sizeGiven: then kept, with a warning), and starts the
   * inspector in it; whether the window is still open (a quit key may have
   * come first).
   */
  bool Open(const ImageSize& size, bool sizeGiven = false);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void FitScreen(const QSize& view, bool sizeGiven);
  void RunProfile(Pixel from, Pixel to);
  void FitProfileChart();

  Inspector& Engine;
  QVTKOpenGLNativeWidget* View;
  ControlPanel* Panel;
  ShaderPanel* Shaders;
  ProbePanel* Readout;
  QDockWidget* Controls = nullptr; // the controls' dock, in front at start
  QDockWidget* ProfileDock = nullptr;
  QLabel* ProfileChart = nullptr; // the chart; its tooltip the command that made it
  QPixmap ProfilePicture;         // the chart as written
  QProcess* Profiler = nullptr;   // `shadelab profile`, while it runs
  QTemporaryDir ProfileFolder;    // where it writes the chart
  bool Started = false;
  std::vector<std::string> EarlyKeys; // pressed before the inspector started
};
}

#endif
