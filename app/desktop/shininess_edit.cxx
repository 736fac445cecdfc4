#include "desktop/shininess_edit.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace
{
// The slider's steps: 0 is ns 0, then 10^-1 to 10^4 in equal ratios.
constexpr int Steps = 1000;
constexpr double LowestExponent = -1, HighestExponent = 4;

double ShininessAt(int step)
{
  return step == 0
    ? 0
    : std::pow(10, LowestExponent + (HighestExponent - LowestExponent) * step / Steps);
}

int StepOf(double ns)
{
  if (ns <= 0)
  {
    return 0;
  }
  const double at = (std::log10(ns) - LowestExponent) / (HighestExponent - LowestExponent);
  return std::clamp(static_cast<int>(std::lround(at * Steps)), 1, Steps);
}
}

ShininessEdit::ShininessEdit(QWidget* parent)
  : QWidget(parent)
  , Slider(new QSlider(Qt::Horizontal, this))
  , Number(new QDoubleSpinBox(this))
{
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  this->Slider->setRange(0, Steps);
  this->Slider->setToolTip("ns on a logarithmic scale, 0.1 to 10000");
  this->Number->setRange(0, std::pow(10, HighestExponent));
  this->Number->setDecimals(3);
  this->Number->setKeyboardTracking(false);
  this->Number->setToolTip("ns");
  this->Number->setObjectName("ns number");
  row->addWidget(this->Slider, 1);
  row->addWidget(this->Number);
  QObject::connect(this->Slider, &QSlider::valueChanged, this,
    [this](int step)
    {
      const double ns = ShininessAt(step);
      const QSignalBlocker quiet(this->Number);
      this->Number->setValue(ns);
      if (this->Edited)
      {
        this->Edited(ns);
      }
    });
  QObject::connect(this->Number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double ns)
    {
      const QSignalBlocker quiet(this->Slider);
      this->Slider->setValue(StepOf(ns));
      if (this->Edited)
      {
        this->Edited(ns);
      }
    });
}

void ShininessEdit::SetShininess(double ns)
{
  const QSignalBlocker quietSlider(this->Slider);
  const QSignalBlocker quietNumber(this->Number);
  this->Slider->setValue(StepOf(ns));
  this->Number->setValue(ns);
}
}
