// The fog in the control panel: its mode (none, linear, exp, exp2) and its
// numbers, START and END for linear, DENSITY for exp and exp2, each enabled
// only for the mode that uses it. The colour stays the scene's (--fog's
// :R,G,B, or the background's).
#ifndef shadelab_fog_edit_h
#define shadelab_fog_edit_h

#include "shadelabFog.h"

#include <QWidget>

#include <functional>

class QComboBox;
class QDoubleSpinBox;

namespace shadelab
{
class FogEdit : public QWidget
{
public:
  explicit FogEdit(QWidget* parent = nullptr);

  /** Shows `fog` without telling Edited. */
  void SetFog(const Fog& fog);

  /** A fog chosen or typed; linear's END not beyond START is not told (the numbers go back). */
  std::function<void(const Fog&)> Edited;

private:
  void Changed();
  void Enable();

  QComboBox* Mode;
  QDoubleSpinBox* Start;
  QDoubleSpinBox* End;
  QDoubleSpinBox* Density;
  Fog Shown;
};
}

#endif
