#include "desktop/color_edit.h"

#include "desktop/triple_edit.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QPushButton>

#include <algorithm>

namespace shadelab
{
namespace
{
// The colour shown for c: coefficients above 1 are allowed, as on the command line.
QColor Shown(const Rgb& c)
{
  return QColor::fromRgbF(std::min(c[0], 1.0), std::min(c[1], 1.0), std::min(c[2], 1.0));
}
}

ColorEdit::ColorEdit(const QString& name, QWidget* parent)
  : QWidget(parent)
  , Name(name)
  , Swatch(new QPushButton(this))
  , Numbers(new TripleEdit(name, { "red", "green", "blue" }, 0, 10, this))
{
  this->setObjectName(name);
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  this->Swatch->setFixedWidth(28);
  this->Swatch->setToolTip("Pick " + name + " with a colour dialog");
  row->addWidget(this->Swatch);
  row->addWidget(this->Numbers);
  QObject::connect(this->Swatch, &QPushButton::clicked, this, [this] { this->PickColor(); });
  this->Numbers->Edited = [this](const Rgb& color)
  {
    this->PaintSwatch();
    if (this->Edited)
    {
      this->Edited(color);
    }
  };
}

void ColorEdit::SetColor(const Rgb& color)
{
  this->Numbers->SetValue(color);
  this->PaintSwatch();
}

void ColorEdit::PaintSwatch()
{
  this->Swatch->setStyleSheet("background-color: " + Shown(this->Numbers->Value()).name());
}

void ColorEdit::PickColor()
{
  const QColor picked = QColorDialog::getColor(Shown(this->Numbers->Value()), this, this->Name);
  if (!picked.isValid())
  {
    return; // cancelled
  }
  this->SetColor({ picked.redF(), picked.greenF(), picked.blueF() });
  if (this->Edited)
  {
    this->Edited(this->Numbers->Value());
  }
}
}
