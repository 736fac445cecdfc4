#include "desktop/light_list_edit.h"

#include "desktop/color_edit.h"
#include "desktop/triple_edit.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QListWidget>
#include <QPushButton>
#include <QSignalBlocker>

namespace shadelab
{
namespace
{
QDoubleSpinBox* Number(const char* name, double lowest, double highest, QWidget* parent)
{
  auto* number = new QDoubleSpinBox(parent);
  number->setObjectName(name); // for the tests (findChild)
  number->setRange(lowest, highest);
  number->setDecimals(3);
  number->setKeyboardTracking(false);
  return number;
}

QString Describe(const Light& light, std::size_t index)
{
  const Vec3& where = GeometryOf(light.Kind).Position ? light.Position : light.Direction;
  return QString("%1 %2 (%3, %4, %5)")
    .arg(index + 1)
    .arg(ToString(light.Kind))
    .arg(where[0], 0, 'g', 3)
    .arg(where[1], 0, 'g', 3)
    .arg(where[2], 0, 'g', 3);
}
}

LightListEdit::LightListEdit(Inspector& inspector, QWidget* parent)
  : QWidget(parent)
  , Engine(inspector)
  , List(new QListWidget(this))
  , Position(new TripleEdit("light position", { "x", "y", "z" }, -1e6, 1e6, this))
  , Direction(new TripleEdit("light direction", { "x", "y", "z" }, -1e6, 1e6, this))
  , Color(new ColorEdit("light color", this))
  , Cone(Number("cone angle", 0.001, 90, this))
  , Exponent(Number("exponent", 0, 1000, this))
{
  auto* form = new QFormLayout(this);
  form->setContentsMargins(0, 0, 0, 0);
  this->List->setObjectName("light list");
  this->List->setMaximumHeight(90);
  form->addRow(this->List);
  auto* buttons = new QGridLayout();
  form->addRow(buttons);
  for (const LightKind kind : { LightKind::Point, LightKind::Directional, LightKind::Spot })
  {
    auto* add = new QPushButton(QString("Add ") + ToString(kind), this);
    add->setObjectName(QString("add ") + ToString(kind));
    buttons->addWidget(add, buttons->count() / 2, buttons->count() % 2);
    QObject::connect(add, &QPushButton::clicked, this,
      [this, kind]
      {
        this->Engine.Edit(
          [this, kind](ViewState& s)
          {
            s.Scene.Lights.push_back(this->Engine.LightAtCamera(kind));
            s.Lights = LightMode::Given;
            this->Selected = static_cast<int>(s.Scene.Lights.size()) - 1;
          });
      });
  }
  auto* remove = new QPushButton("Remove", this);
  remove->setObjectName("remove light");
  buttons->addWidget(remove, buttons->count() / 2, buttons->count() % 2);
  QObject::connect(remove, &QPushButton::clicked, this,
    [this]
    {
      if (this->Selected < 0)
      {
        return;
      }
      this->Engine.Edit(
        [this](ViewState& s)
        {
          s.Scene.Lights.erase(s.Scene.Lights.begin() + this->Selected);
          this->Selected = std::min(this->Selected, static_cast<int>(s.Scene.Lights.size()) - 1);
          // An empty list: the lecture's light at the camera again.
          s.Lights = s.Scene.Lights.empty() ? LightMode::PointAtCamera : LightMode::Given;
        });
    });
  QObject::connect(this->List, &QListWidget::currentRowChanged, this,
    [this](int row)
    {
      this->Selected = row;
      this->Show();
    });
  form->addRow("Position", this->Position);
  form->addRow("Direction", this->Direction);
  form->addRow("Colour", this->Color);
  form->addRow("Cone angle", this->Cone);
  form->addRow("Exponent", this->Exponent);
  this->Position->Edited = [this](const Vec3& p)
  { this->EditSelected([&p](Light& l) { l.Position = p; }); };
  this->Direction->Edited = [this](const Vec3& d)
  { this->EditSelected([&d](Light& l) { l.Direction = d; }); };
  this->Color->Edited = [this](const Rgb& c)
  { this->EditSelected([&c](Light& l) { l.Color = c; }); };
  QObject::connect(this->Cone, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double cone) { this->EditSelected([cone](Light& l) { l.HalfAngleDeg = cone; }); });
  QObject::connect(this->Exponent, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double e) { this->EditSelected([e](Light& l) { l.Exponent = e; }); });
}

void LightListEdit::EditSelected(const std::function<void(Light&)>& edit)
{
  if (this->Selected < 0)
  {
    return;
  }
  this->Engine.Edit(
    [this, &edit](ViewState& s)
    {
      edit(s.Scene.Lights[this->Selected]);
      s.Lights = LightMode::Given;
    });
}

void LightListEdit::Show()
{
  const std::vector<Light>& lights = this->Engine.GetState().Scene.Lights;
  if (this->Selected >= static_cast<int>(lights.size()))
  {
    this->Selected = static_cast<int>(lights.size()) - 1;
  }
  {
    const QSignalBlocker quiet(this->List);
    this->List->clear();
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
      this->List->addItem(Describe(lights[i], i));
    }
    this->List->setCurrentRow(this->Selected);
  }
  const bool any = this->Selected >= 0;
  const Light light = any ? lights[this->Selected] : Light{};
  this->Position->SetValue(light.Position);
  this->Direction->SetValue(light.Direction);
  this->Color->SetColor(light.Color);
  const QSignalBlocker quietCone(this->Cone);
  const QSignalBlocker quietExponent(this->Exponent);
  this->Cone->setValue(light.HalfAngleDeg);
  this->Exponent->setValue(light.Exponent);
  const LightGeometry g = GeometryOf(light.Kind);
  this->Position->setEnabled(any && g.Position);
  this->Direction->setEnabled(any && g.Direction);
  this->Color->setEnabled(any);
  this->Cone->setEnabled(any && g.Cone);
  this->Exponent->setEnabled(any && g.Cone);
  this->Engine.ShowLightHandle(this->Selected);
}
}
