// The inspector's control panel (the dock beside the 3D view): every
// setting of ViewState as a widget. A control changes the state through
// Inspector::SetState; Show puts the state, however it changed (a key, a
// control), back into the widgets, so that keys and controls agree.
#ifndef shadelab_control_panel_h
#define shadelab_control_panel_h

#include "desktop/inspector.h"

#include <QWidget>

#include <array>
#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace shadelab
{
class ColorEdit;
class FogEdit;
class TripleEdit;
class LightListEdit;
class RepresentationEdit;
class SliderEdit;

class ControlPanel : public QWidget
{
public:
  explicit ControlPanel(Inspector& inspector, QWidget* parent = nullptr);

  /** The widgets as the inspector's state is now. */
  void Show();

private:
  QCheckBox* Toggle(const QString& text, bool ViewState::*setting);

  Inspector& Engine;
  QComboBox* Rule;
  QComboBox* Model;
  QComboBox* Form; // the specular term's, SpecularForm's order
  RepresentationEdit* Drawn;
  QComboBox* MaterialRow;
  std::array<ColorEdit*, 3> Coefficients; // ka, kd, ks
  SliderEdit* Ns;
  SliderEdit* Opacity; // a
  QSpinBox* Peels;     // --peels: 0, every layer
  ColorEdit* AmbientLight;
  TripleEdit* Attenuation; // the scene's C0, C1, C2
  QCheckBox* Shadows;      // --shadows
  QSpinBox* ShadowMapSize;
  FogEdit* Fogging;
  QComboBox* LightChoice;
  QComboBox* NormalsChoice;
  QDoubleSpinBox* FeatureAngle;
  LightListEdit* Lights;
  std::vector<std::pair<QCheckBox*, bool ViewState::*>> Toggles;
};
}

#endif
