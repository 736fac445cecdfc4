// A number in the control panel: a slider along its scale (ns's
// logarithmic, a's linear) and the number beside it for a typed value.
#ifndef shadelab_slider_edit_h
#define shadelab_slider_edit_h

#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QSlider;

namespace shadelab
{
class SliderEdit : public QWidget
{
public:
  /** Where the slider's steps 0..Steps put the number, and the other way. */
  struct Scale
  {
    double Max;
    std::function<double(int)> ValueAt;
    std::function<int(double)> StepAt;
    const char* SliderTip;
    const char* Name; // the number's tool tip, and "NAME number" its object name
  };
  static constexpr int Steps = 1000;
  /** ns: 0, then 0.1 to 10^4 in equal ratios, as the highlight's width changes by ratios. */
  static Scale Shininess();
  /** a: 0 to 1 in equal steps. */
  static Scale Opacity();

  SliderEdit(const Scale& scale, QWidget* parent = nullptr);

  /** Shows `value` without telling Edited. */
  void SetValue(double value);

  std::function<void(double)> Edited;

private:
  Scale Along;
  QSlider* Slider;
  QDoubleSpinBox* Number;
};
}

#endif
