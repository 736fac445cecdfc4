#include "desktop/color_edit.h"

#include <QColorDialog>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSignalBlocker>

#include <algorithm>

namespace shadelab
{
ColorEdit::ColorEdit(const QString& name, QWidget* parent)
  : QWidget(parent)
  , Name(name)
  , Swatch(new QPushButton(this))
{
  this->setObjectName(name);
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  this->Swatch->setFixedWidth(28);
  this->Swatch->setToolTip("Pick " + name + " with a colour dialog");
  row->addWidget(this->Swatch);
  QObject::connect(this->Swatch, &QPushButton::clicked, this, [this] { this->PickColor(); });
  for (QDoubleSpinBox*& number : this->Numbers)
  {
    number = new QDoubleSpinBox(this);
    number->setDecimals(6);  // as the lecture's table
    number->setRange(0, 10); // coefficients above 1 are allowed, as on the command line
    number->setSingleStep(0.05);
    number->setKeyboardTracking(false); // a value once typed whole, not at each digit
    row->addWidget(number);
    QObject::connect(number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
      [this]
      {
        this->PaintSwatch();
        if (this->Edited)
        {
          this->Edited(this->Color());
        }
      });
  }
  const char* channels[] = { " red", " green", " blue" };
  for (int c = 0; c < 3; ++c)
  {
    this->Numbers[c]->setObjectName(name + channels[c]);
    this->Numbers[c]->setToolTip(name + channels[c]);
  }
}

void ColorEdit::SetColor(const Rgb& color)
{
  for (int c = 0; c < 3; ++c)
  {
    const QSignalBlocker quiet(this->Numbers[c]);
    this->Numbers[c]->setValue(color[c]);
  }
  this->PaintSwatch();
}

Rgb ColorEdit::Color() const
{
  return { this->Numbers[0]->value(), this->Numbers[1]->value(), this->Numbers[2]->value() };
}

void ColorEdit::PaintSwatch()
{
  const Rgb c = this->Color();
  const QColor shown =
    QColor::fromRgbF(std::min(c[0], 1.0), std::min(c[1], 1.0), std::min(c[2], 1.0));
  this->Swatch->setStyleSheet("background-color: " + shown.name());
}

void ColorEdit::PickColor()
{
  const Rgb c = this->Color();
  const QColor picked = QColorDialog::getColor(
    QColor::fromRgbF(std::min(c[0], 1.0), std::min(c[1], 1.0), std::min(c[2], 1.0)), this,
    this->Name);
  if (!picked.isValid())
  {
    return; // cancelled
  }
  this->SetColor({ picked.redF(), picked.greenF(), picked.blueF() });
  if (this->Edited)
  {
    this->Edited(this->Color());
  }
}
}
