#include "desktop/slider_edit.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace shadelab
{
SliderEdit::Scale SliderEdit::Shininess()
{
  constexpr double lowest = -1, highest = 4; // exponents of 10
  return { std::pow(10, highest),
    [](int step)
    { return step == 0 ? 0 : std::pow(10, lowest + (highest - lowest) * step / Steps); },
    [](double ns)
    {
      if (ns <= 0)
      {
        return 0;
      }
      const double at = (std::log10(ns) - lowest) / (highest - lowest);
      return std::clamp(static_cast<int>(std::lround(at * Steps)), 1, Steps);
    },
    "ns on a logarithmic scale, 0.1 to 10000", "ns" };
}

SliderEdit::Scale SliderEdit::Opacity()
{
  return { 1, [](int step) { return static_cast<double>(step) / Steps; },
    [](double a) { return std::clamp(static_cast<int>(std::lround(a * Steps)), 0, Steps); },
    "a: 1 opaque, 0 unseen", "a" };
}

SliderEdit::SliderEdit(const Scale& scale, QWidget* parent)
  : QWidget(parent)
  , Along(scale)
  , Slider(new QSlider(Qt::Horizontal, this))
  , Number(new QDoubleSpinBox(this))
{
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  this->Slider->setRange(0, Steps);
  this->Slider->setToolTip(scale.SliderTip);
  this->Number->setRange(0, scale.Max);
  this->Number->setDecimals(3);
  this->Number->setKeyboardTracking(false);
  this->Number->setToolTip(scale.Name);
  this->Number->setObjectName(QString(scale.Name) + " number");
  row->addWidget(this->Slider, 1);
  row->addWidget(this->Number);
  QObject::connect(this->Slider, &QSlider::valueChanged, this,
    [this](int step)
    {
      const double value = this->Along.ValueAt(step);
      const QSignalBlocker quiet(this->Number);
      this->Number->setValue(value);
      if (this->Edited)
      {
        this->Edited(value);
      }
    });
  QObject::connect(this->Number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double value)
    {
      const QSignalBlocker quiet(this->Slider);
      this->Slider->setValue(this->Along.StepAt(value));
      if (this->Edited)
      {
        this->Edited(value);
      }
    });
}

void SliderEdit::SetValue(double value)
{
  const QSignalBlocker quietSlider(this->Slider);
  const QSignalBlocker quietNumber(this->Number);
  this->Slider->setValue(this->Along.StepAt(value));
  this->Number->setValue(value);
}
}
