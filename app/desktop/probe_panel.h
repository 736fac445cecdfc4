// The probe's dock: the probed pixel explained as `shadelab probe` writes
// it (probe/probe_text.h) in a read-only monospace text, the colours of the
// arrows drawn in the 3D view, and a button that clears the probe.
#ifndef shadelab_probe_panel_h
#define shadelab_probe_panel_h

#include "desktop/inspector.h"

#include <QWidget>

class QPlainTextEdit;

namespace shadelab
{
class ProbePanel : public QWidget
{
public:
  explicit ProbePanel(Inspector& inspector, QWidget* parent = nullptr);

  /** The readout as the inspector's probe is now. */
  void Show();

private:
  Inspector& Engine;
  QPlainTextEdit* Readout;
};
}

#endif
