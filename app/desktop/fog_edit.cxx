#include "desktop/fog_edit.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>

namespace shadelab
{
namespace
{
QDoubleSpinBox* Number(const QString& name, double lowest, QWidget* parent)
{
  auto* number = new QDoubleSpinBox(parent);
  number->setObjectName(name); // for the tests (findChild)
  number->setToolTip(name);
  number->setDecimals(6);
  number->setRange(lowest, 1e9);
  number->setSingleStep(0.1);
  number->setKeyboardTracking(false); // a value once typed whole, not at each digit
  return number;
}
}

FogEdit::FogEdit(QWidget* parent)
  : QWidget(parent)
  , Mode(new QComboBox(this))
  , Start(Number("fog start", -1e9, this))
  , End(Number("fog end", -1e9, this))
  , Density(Number("fog density", 0, this))
{
  this->Mode->setObjectName("fog");
  for (const std::string& name : Names<FogMode>())
  {
    this->Mode->addItem(QString::fromStdString(name));
  }
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  form->addRow("Fog", this->Mode);
  form->addRow("Start", this->Start);
  form->addRow("End", this->End);
  form->addRow("Density", this->Density);
  QObject::connect(
    this->Mode, QOverload<int>::of(&QComboBox::activated), this, [this] { this->Changed(); });
  for (QDoubleSpinBox* number : { this->Start, this->End, this->Density })
  {
    QObject::connect(number, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
      [this] { this->Changed(); });
  }
  this->SetFog(Fog{});
}

void FogEdit::SetFog(const Fog& fog)
{
  this->Shown = fog;
  const QSignalBlocker quiet[] = { QSignalBlocker(this->Mode), QSignalBlocker(this->Start),
    QSignalBlocker(this->End), QSignalBlocker(this->Density) };
  this->Mode->setCurrentIndex(static_cast<int>(fog.Mode));
  this->Start->setValue(fog.Start);
  this->End->setValue(fog.End);
  this->Density->setValue(fog.Density);
  this->Enable();
}

void FogEdit::Enable()
{
  const auto mode = static_cast<FogMode>(this->Mode->currentIndex());
  this->Start->setEnabled(mode == FogMode::Linear);
  this->End->setEnabled(mode == FogMode::Linear);
  this->Density->setEnabled(mode == FogMode::Exp || mode == FogMode::Exp2);
}

void FogEdit::Changed()
{
  Fog fog = this->Shown;
  fog.Mode = static_cast<FogMode>(this->Mode->currentIndex());
  fog.Start = this->Start->value();
  fog.End = this->End->value();
  fog.Density = this->Density->value();
  if (fog.Mode == FogMode::Linear && !(fog.End > fog.Start))
  {
    this->SetFog(this->Shown); // as --fog refuses it
    return;
  }
  this->Shown = fog;
  this->Enable();
  if (this->Edited)
  {
    this->Edited(fog);
  }
}
}
