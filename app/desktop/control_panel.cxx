#include "desktop/control_panel.h"

#include "desktop/color_edit.h"
#include "desktop/fog_edit.h"
#include "desktop/light_list_edit.h"
#include "desktop/representation_edit.h"
#include "desktop/slider_edit.h"
#include "desktop/triple_edit.h"
#include "shadelabVec3.h"
#include "vtkShadelabMeshNormals.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>

namespace shadelab
{
namespace
{
const std::vector<std::string> Weightings = Names<vtkShadelabMeshNormals::Weightings>();

// The choices' names in their enum's order (an item's index is its value),
// the first `count` of them.
template <typename Enum>
QComboBox* NamesBox(QWidget* parent, std::size_t count = NameTable<Enum>::Entries.size())
{
  auto* box = new QComboBox(parent);
  const std::vector<std::string> names = Names<Enum>();
  for (std::size_t i = 0; i < count; ++i)
  {
    box->addItem(QString::fromStdString(names[i]));
  }
  return box;
}

bool CustomMaterial(const SceneOptions& s)
{
  return s.Ka || s.Kd || s.Ks || s.Ns;
}
}

ControlPanel::ControlPanel(Inspector& inspector, QWidget* parent)
  : QWidget(parent)
  , Engine(inspector)
  , Rule(NamesBox<Shading>(this, static_cast<std::size_t>(Shading::Raytrace))) // the raster's
  , Model(new QComboBox(this))
  , Form(new QComboBox(this))
  , Drawn(new RepresentationEdit(this))
  , MaterialRow(new QComboBox(this))
  , Ns(new SliderEdit(SliderEdit::Shininess(), this))
  , Opacity(new SliderEdit(SliderEdit::Opacity(), this))
  , Peels(new QSpinBox(this))
  , AmbientLight(new ColorEdit("Ia", this))
  , Attenuation(new TripleEdit("attenuation", { "c0", "c1", "c2" }, 0, 1e6, this))
  , Shadows(new QCheckBox("every light casts", this))
  , ShadowMapSize(new QSpinBox(this))
  , Fogging(new FogEdit(this))
  , LightChoice(new QComboBox(this))
  , NormalsChoice(new QComboBox(this))
  , FeatureAngle(new QDoubleSpinBox(this))
  , Lights(new LightListEdit(inspector, this))
{
  // Named for the tests (findChild).
  this->Rule->setObjectName("rule");
  this->Model->setObjectName("reflection");
  this->Form->setObjectName("specular form");
  this->MaterialRow->setObjectName("material");
  this->Ns->setObjectName("ns");
  this->Opacity->setObjectName("a");
  this->Peels->setObjectName("peels");
  this->Shadows->setObjectName("shadows");
  this->ShadowMapSize->setObjectName("shadow map size");
  this->LightChoice->setObjectName("lights");
  this->NormalsChoice->setObjectName("normals");
  this->FeatureAngle->setObjectName("feature angle");
  auto* column = new QVBoxLayout(this);
  const auto group = [this, column](const QString& title)
  {
    auto* box = new QGroupBox(title, this);
    auto* form = new QFormLayout(box);
    column->addWidget(box);
    return form;
  };

  QFormLayout* shading = group("Shading");
  shading->addRow("Rule", this->Rule);
  this->Model->addItems({ "Blinn-Phong", "Phong" }); // Reflection's order
  shading->addRow("Reflection", this->Model);
  this->Form->addItems({ "stable", "literal (the slide's pow)" }); // SpecularForm's order
  this->Form->setToolTip("How the shaders write the specular term: stable up to ns = 1e6, or "
                         "pow(max(N.H, 0), ns) as the lecture writes it (see the Shader dock)");
  shading->addRow("Specular form", this->Form);
  shading->addRow("Drawn", this->Drawn);
  this->Drawn->setToolTip("The surface, or its edges or points lit by the same rule");
  this->Drawn->Edited = [this](Representation drawn, int lineWidth, int pointSize)
  {
    this->Engine.Edit(
      [=](ViewState& s)
      {
        s.Scene.Drawn = drawn;
        s.Scene.LineWidth = lineWidth;
        s.Scene.PointSize = pointSize;
      });
  };
  QObject::connect(this->Rule, QOverload<int>::of(&QComboBox::activated), this,
    [this](int rule) {
      this->Engine.Edit([rule](ViewState& s) { s.Scene.ShadingRule = static_cast<Shading>(rule); });
    });
  QObject::connect(this->Model, QOverload<int>::of(&QComboBox::activated), this,
    [this](int model)
    {
      this->Engine.Edit(
        [model](ViewState& s) { s.Scene.ReflectionModel = static_cast<Reflection>(model); });
    });
  QObject::connect(this->Form, QOverload<int>::of(&QComboBox::activated), this,
    [this](int form) {
      this->Engine.Edit([form](ViewState& s) { s.Scene.Form = static_cast<SpecularForm>(form); });
    });

  QFormLayout* material = group("Material");
  for (const Material& m : LectureMaterials())
  {
    this->MaterialRow->addItem(QString::fromStdString(m.Name));
  }
  this->MaterialRow->addItem("custom");
  material->addRow("Table row", this->MaterialRow);
  QObject::connect(this->MaterialRow, QOverload<int>::of(&QComboBox::activated), this,
    [this](int row)
    {
      this->Engine.Edit(
        [row](ViewState& state)
        {
          SceneOptions& s = state.Scene;
          const auto& table = LectureMaterials();
          if (row < static_cast<int>(table.size()))
          {
            s.MaterialName = table[row].Name;
            s.MaterialGiven = true; // every part's material, as --material replaces it
            s.Ka.reset();
            s.Kd.reset();
            s.Ks.reset();
            s.Ns.reset();
            return;
          }
          // custom: the coefficients as they are, from now on the user's
          const Material m = s.EffectiveMaterial();
          s.Ka = m.Ka;
          s.Kd = m.Kd;
          s.Ks = m.Ks;
          s.Ns = m.Ns;
        });
    });
  const char* names[] = { "ka", "kd", "ks" };
  for (int i = 0; i < 3; ++i)
  {
    this->Coefficients[i] = new ColorEdit(names[i], this);
    material->addRow(names[i], this->Coefficients[i]);
    this->Coefficients[i]->Edited = [this, i](const Rgb& color)
    {
      this->Engine.Edit(
        [i, &color](ViewState& s)
        {
          std::optional<Rgb>* k[] = { &s.Scene.Ka, &s.Scene.Kd, &s.Scene.Ks };
          *k[i] = color;
        });
    };
  }
  material->addRow("ns", this->Ns);
  this->Ns->Edited = [this](double ns)
  { this->Engine.Edit([ns](ViewState& s) { s.Scene.Ns = ns; }); };
  // --translucency: every part's a.
  material->addRow("a", this->Opacity);
  this->Opacity->Edited = [this](double a)
  { this->Engine.Edit([a](ViewState& s) { s.Scene.Translucency = a; }); };
  // --peels: the nearest layers kept, to see what a limit loses and saves.
  this->Peels->setRange(0, MaxPeels);
  this->Peels->setSpecialValueText("every layer");
  this->Peels->setKeyboardTracking(false);
  this->Peels->setToolTip("the nearest translucent layers drawn at each pixel");
  material->addRow("peels", this->Peels);
  QObject::connect(this->Peels, QOverload<int>::of(&QSpinBox::valueChanged), this,
    [this](int peels) { this->Engine.Edit([peels](ViewState& s) { s.Scene.Peels = peels; }); });

  QFormLayout* light = group("Light");
  light->addRow("Ia", this->AmbientLight);
  this->AmbientLight->Edited = [this](const Rgb& ia)
  { this->Engine.Edit([&ia](ViewState& s) { s.Scene.Ambient = ia; }); };
  for (int mode = 0; mode <= static_cast<int>(LightMode::Spot); ++mode)
  {
    this->LightChoice->addItem(Describe(static_cast<LightMode>(mode)));
  }
  light->addRow("Lights", this->LightChoice);
  QObject::connect(this->LightChoice, QOverload<int>::of(&QComboBox::activated), this,
    [this](int mode)
    { this->Engine.Edit([mode](ViewState& s) { s.Lights = static_cast<LightMode>(mode); }); });
  light->addRow(this->Lights);
  light->addRow("Attenuation", this->Attenuation);
  this->Attenuation->setToolTip(
    "Point and spot lights: Il / (c0 + c1*d + c2*d^2), d the distance from the light; 1, 0, 0 "
    "is none");
  this->Attenuation->Edited = [this](const Vec3& c)
  {
    if (c == Vec3{ 0, 0, 0 })
    {
      // No light is infinitely bright: the numbers go back to the scene's.
      this->Attenuation->SetValue(this->Engine.GetState().Scene.Attenuation);
      return;
    }
    this->Engine.Edit([&c](ViewState& s) { s.Scene.Attenuation = c; });
  };
  // --shadows and --shadow-map-size: a light's own choice (a scene file's)
  // stays as it is.
  light->addRow("Shadows", this->Shadows);
  this->Shadows->setToolTip("Hard shadows from shadow maps, tested where the rule lights");
  QObject::connect(this->Shadows, &QCheckBox::toggled, this,
    [this](bool on) { this->Engine.Edit([on](ViewState& s) { s.Scene.Shadows = on; }); });
  this->ShadowMapSize->setRange(1, MaxShadowMapSize);
  this->ShadowMapSize->setKeyboardTracking(false);
  this->ShadowMapSize->setSuffix(" texels");
  this->ShadowMapSize->setToolTip("Each shadow map's side (a cube map's face)");
  light->addRow("Shadow map", this->ShadowMapSize);
  QObject::connect(this->ShadowMapSize, QOverload<int>::of(&QSpinBox::valueChanged), this,
    [this](int size)
    { this->Engine.Edit([size](ViewState& s) { s.Scene.ShadowMapSize = size; }); });

  group("Atmosphere")->addRow(this->Fogging);
  this->Fogging->Edited = [this](Fog fog)
  {
    // Fog switched on with no numbers yet: ones that show on the mesh,
    // from the camera's distance to what it looks at (world units).
    if (this->Engine.GetState().Scene.Fogging.Mode == FogMode::None && fog.Start == Fog{}.Start &&
      fog.End == Fog{}.End && fog.Density == Fog{}.Density)
    {
      const SceneOptions shown = this->Engine.ShownScene();
      const double distance = shown.CameraPosition && shown.CameraFocalPoint
        ? length(*shown.CameraPosition - *shown.CameraFocalPoint)
        : 1;
      fog.Start = 0.5 * distance;
      fog.End = 1.5 * distance;
      fog.Density = 1 / distance;
      this->Fogging->SetFog(fog);
    }
    this->Engine.Edit([&fog](ViewState& s) { s.Scene.Fogging = fog; });
  };

  QFormLayout* terms = group("Terms");
  terms->addRow(this->Toggle("ambient  ka Ia", &ViewState::Ambient));
  terms->addRow(this->Toggle("diffuse  kd Il (N.L)", &ViewState::Diffuse));
  terms->addRow(this->Toggle("specular  ks Il (base)^ns", &ViewState::Specular));
  if (!inspector.GetState().Scene.Environment.empty())
  {
    terms->addRow(this->Toggle("environment  ks E(R)", &ViewState::Reflected));
  }
  if (const auto& map = inspector.GetState().Scene.Relief())
  {
    // The map on or off, and its scale (the x and y of a normal map's
    // directions, a bump map's height).
    const bool bump = inspector.GetState().Scene.BumpMap.has_value();
    const QString name = bump ? "bump map" : "normal map";
    auto* scale = new QDoubleSpinBox(this);
    scale->setObjectName(name + " scale");
    scale->setRange(-10, 10);
    scale->setSingleStep(0.1);
    scale->setDecimals(2);
    scale->setKeyboardTracking(false);
    scale->setValue(map->Scale);
    scale->setToolTip(bump ? "--bump-map's SCALE: the height of white above black, in texels"
                           : "--normal-map's SCALE: its directions' x and y times it");
    terms->addRow(this->Toggle(name + "  N'", &ViewState::Relief), scale);
    QObject::connect(scale, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
      [this](double value)
      {
        this->Engine.Edit(
          [value](ViewState& s)
          {
            if (auto& relief = s.Scene.Relief())
            {
              relief->Scale = value;
            }
          });
      });
  }
  else if (inspector.GetState().Scene.MapsNormals(inspector.HasFileNormalMaps()))
  {
    // The file's maps on or off (each part's scale is its own).
    terms->addRow(this->Toggle("normal map  N'", &ViewState::Relief));
  }

  QFormLayout* normals = group("Normals");
  if (inspector.HasFileNormals())
  {
    this->NormalsChoice->addItem("the file's");
  }
  for (const std::string& weighting : Weightings)
  {
    this->NormalsChoice->addItem(QString::fromStdString(weighting) + " weighting");
  }
  normals->addRow("Normals", this->NormalsChoice);
  QObject::connect(this->NormalsChoice, QOverload<int>::of(&QComboBox::activated), this,
    [this](int item)
    {
      const int weighting = item - (this->Engine.HasFileNormals() ? 1 : 0);
      this->Engine.Edit(
        [weighting](ViewState& s)
        {
          if (weighting < 0)
          {
            s.Scene.Normals = NormalsMode::Auto;
            return;
          }
          s.Scene.Normals = NormalsMode::Compute;
          s.Scene.Computed.Weighting = Weightings[weighting];
        });
    });
  // Its lowest value is "none": no splitting at sharp edges.
  this->FeatureAngle->setRange(-1, 180);
  this->FeatureAngle->setDecimals(1);
  this->FeatureAngle->setSpecialValueText("none");
  this->FeatureAngle->setKeyboardTracking(false);
  normals->addRow("Feature angle", this->FeatureAngle);
  QObject::connect(this->FeatureAngle, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
    [this](double angle)
    {
      this->Engine.Edit(
        [angle](ViewState& s) {
          s.Scene.Computed.FeatureAngle = angle < 0 ? std::nullopt : std::optional<double>(angle);
        });
    });

  QFormLayout* show = group("Show");
  show->addRow(this->Toggle("edges", &ViewState::Edges));
  show->addRow(this->Toggle("normal glyphs", &ViewState::Glyphs));
  show->addRow(this->Toggle("comparison layout", &ViewState::Compare));
  show->addRow(this->Toggle("key help", &ViewState::Help));

  auto* buttons = new QGridLayout();
  column->addLayout(buttons);
  const auto button = [this, buttons](const QString& text, ViewAction action)
  {
    auto* b = new QPushButton(text, this);
    buttons->addWidget(b, buttons->count() / 2, buttons->count() % 2);
    QObject::connect(b, &QPushButton::clicked, this, [this, action] { this->Engine.Do(action); });
  };
  button("Reset camera", ViewAction::ResetCamera);
  button("Screenshot", ViewAction::Screenshot);
  button("Copy command", ViewAction::CopyCommand);
  auto* save = new QPushButton("Save scene...", this);
  buttons->addWidget(save, buttons->count() / 2, buttons->count() % 2);
  QObject::connect(save, &QPushButton::clicked, this,
    [this]
    {
      const QString path =
        QFileDialog::getSaveFileName(this, "Save scene", "scene.json", "Scene files (*.json)");
      if (!path.isEmpty())
      {
        this->Engine.SaveScene(path.toStdString());
      }
    });
  column->addStretch(1);
  this->Show();
}

QCheckBox* ControlPanel::Toggle(const QString& text, bool ViewState::*setting)
{
  auto* box = new QCheckBox(text, this);
  this->Toggles.emplace_back(box, setting);
  QObject::connect(box, &QCheckBox::toggled, this,
    [this, setting](bool on)
    { this->Engine.Edit([setting, on](ViewState& s) { s.*setting = on; }); });
  return box;
}

void ControlPanel::Show()
{
  const ViewState& state = this->Engine.GetState();
  const SceneOptions& s = state.Scene;
  const Material m = s.EffectiveMaterial();
  const QSignalBlocker quiet[] = { QSignalBlocker(this->Rule), QSignalBlocker(this->Model),
    QSignalBlocker(this->Form), QSignalBlocker(this->MaterialRow),
    QSignalBlocker(this->LightChoice), QSignalBlocker(this->NormalsChoice),
    QSignalBlocker(this->FeatureAngle), QSignalBlocker(this->Peels), QSignalBlocker(this->Shadows),
    QSignalBlocker(this->ShadowMapSize) };
  this->Rule->setCurrentIndex(static_cast<int>(s.ShadingRule));
  this->Model->setCurrentIndex(static_cast<int>(s.ReflectionModel));
  this->Form->setCurrentIndex(static_cast<int>(s.Form));
  this->Drawn->Set(s.Drawn, s.LineWidth, s.PointSize);
  const auto& table = LectureMaterials();
  const auto row = std::find_if(
    table.begin(), table.end(), [&s](const Material& t) { return t.Name == s.MaterialName; });
  this->MaterialRow->setCurrentIndex(CustomMaterial(s) || row == table.end()
      ? static_cast<int>(table.size())
      : static_cast<int>(row - table.begin()));
  this->Coefficients[0]->SetColor(m.Ka);
  this->Coefficients[1]->SetColor(m.Kd);
  this->Coefficients[2]->SetColor(m.Ks);
  this->Ns->SetValue(m.Ns);
  this->Opacity->SetValue(m.Translucency);
  this->Peels->setValue(s.Peels);
  this->AmbientLight->SetColor(s.Ambient);
  this->Attenuation->SetValue(s.Attenuation);
  this->Shadows->setChecked(s.Shadows);
  this->ShadowMapSize->setValue(s.ShadowMapSize);
  this->Fogging->SetFog(s.Fogging);
  this->LightChoice->setCurrentIndex(static_cast<int>(state.Lights));
  const bool fromFile = s.Normals != NormalsMode::Compute && this->Engine.HasFileNormals();
  const auto weighting = std::find(Weightings.begin(), Weightings.end(), s.Computed.Weighting);
  this->NormalsChoice->setCurrentIndex(fromFile
      ? 0
      : static_cast<int>(weighting - Weightings.begin()) + (this->Engine.HasFileNormals() ? 1 : 0));
  this->FeatureAngle->setValue(s.Computed.FeatureAngle.value_or(-1));
  this->Lights->Show();
  for (auto& [box, setting] : this->Toggles)
  {
    const QSignalBlocker quietBox(box);
    box->setChecked(state.*setting);
  }
}
}
