#include "desktop/representation_edit.h"

#include "core/options.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace shadelab
{
RepresentationEdit::RepresentationEdit(QWidget* parent)
  : QWidget(parent)
  , Drawn(new QComboBox(this))
  , Pixels(new QSpinBox(this))
{
  this->Drawn->setObjectName("representation"); // for the tests (findChild)
  this->Pixels->setObjectName("representation pixels");
  for (const std::string& name : Names<Representation>())
  {
    this->Drawn->addItem(QString::fromStdString(name));
  }
  this->Pixels->setSuffix(" px");
  this->Pixels->setKeyboardTracking(false);
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(this->Drawn, 1);
  row->addWidget(this->Pixels);
  QObject::connect(
    this->Drawn, QOverload<int>::of(&QComboBox::activated), this, [this] { this->Changed(); });
  QObject::connect(
    this->Pixels, QOverload<int>::of(&QSpinBox::valueChanged), this, [this] { this->Changed(); });
  this->Set(Representation::Surface, 1, 1);
}

void RepresentationEdit::Set(Representation drawn, int lineWidth, int pointSize)
{
  this->Shown = drawn;
  this->LineWidth = lineWidth;
  this->PointSize = pointSize;
  const QSignalBlocker quiet[] = { QSignalBlocker(this->Drawn), QSignalBlocker(this->Pixels) };
  this->Drawn->setCurrentIndex(static_cast<int>(drawn));
  const bool points = drawn == Representation::Points;
  this->Pixels->setRange(1, points ? MaxPointSize : MaxLineWidth);
  this->Pixels->setValue(points ? pointSize : lineWidth);
  this->Pixels->setEnabled(drawn != Representation::Surface);
  this->Pixels->setToolTip(points ? "the points' size" : "the lines' width");
}

void RepresentationEdit::Changed()
{
  const auto drawn = static_cast<Representation>(this->Drawn->currentIndex());
  // The number is that of the representation shown when it was typed.
  if (this->Shown == Representation::Points)
  {
    this->PointSize = this->Pixels->value();
  }
  else if (this->Shown == Representation::Wireframe)
  {
    this->LineWidth = this->Pixels->value();
  }
  this->Set(drawn, this->LineWidth, this->PointSize);
  if (this->Edited)
  {
    this->Edited(drawn, this->LineWidth, this->PointSize);
  }
}
}
