// The shininess ns in the control panel: a slider on a logarithmic scale
// (0, then 0.1 to 10^4, as the highlight's width changes by ratios) and the
// number beside it for a typed value.
#ifndef shadelab_shininess_edit_h
#define shadelab_shininess_edit_h

#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QSlider;

namespace shadelab
{
class ShininessEdit : public QWidget
{
public:
  explicit ShininessEdit(QWidget* parent = nullptr);

  /** Shows `ns` without telling Edited. */
  void SetShininess(double ns);

  std::function<void(double)> Edited;

private:
  QSlider* Slider;
  QDoubleSpinBox* Number;
};
}

#endif
