#include "desktop/triple_edit.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace shadelab
{
TripleEdit::TripleEdit(const QString& name, const std::array<const char*, 3>& parts, double lowest,
  double highest, QWidget* parent)
  : QWidget(parent)
{
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < 3; ++i)
  {
    QDoubleSpinBox*& number = this->Numbers[i];
    number = new QDoubleSpinBox(this);
    number->setDecimals(6);
    number->setRange(lowest, highest);
    number->setSingleStep(0.05);
    number->setKeyboardTracking(false);           // a value once typed whole, not at each digit
    number->setObjectName(name + " " + parts[i]); // for the tests (findChild)
    number->setToolTip(name + " " + parts[i]);
    row->addWidget(number);
    QObject::connect(number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
      [this]
      {
        if (this->Edited)
        {
          this->Edited(this->Value());
        }
      });
  }
}

void TripleEdit::SetValue(const Vec3& value)
{
  for (int i = 0; i < 3; ++i)
  {
    const QSignalBlocker quiet(this->Numbers[i]);
    this->Numbers[i]->setValue(value[i]);
  }
}

Vec3 TripleEdit::Value() const
{
  return { this->Numbers[0]->value(), this->Numbers[1]->value(), this->Numbers[2]->value() };
}
}
