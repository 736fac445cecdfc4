// The probe's dock: the probed pixel explained as `shadelab probe` writes
// it (probe/probe_text.h) in a read-only monospace text, the colours of the
// arrows drawn in the 3D view, and a button that clears the probe. Putting
// the cursor on a term's line (ka*Ia, kd*Il*(N.L), ks*Il*(base)^ns) picks
// that term, for the shader panel to highlight the lines that compute it.
#ifndef shadelab_probe_panel_h
#define shadelab_probe_panel_h

#include "desktop/inspector.h"

#include <QWidget>

#include <functional>

class QPlainTextEdit;

namespace shadelab
{
class ProbePanel : public QWidget
{
public:
  explicit ProbePanel(Inspector& inspector, QWidget* parent = nullptr);

  /** The readout as the inspector's probe is now. */
  void Show();

  /** Called with the term whose line the user puts the cursor on. */
  std::function<void(Terms)> TermPicked;

private:
  Inspector& Engine;
  QPlainTextEdit* Readout;
};
}

#endif
