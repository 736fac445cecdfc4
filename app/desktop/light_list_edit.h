// The light list in the control panel: LightMode::Given's lights, added
// (point, directional, spot: where the camera is, along the view) and
// removed, the selected one's position, direction, colour, cone angle and
// exponent edited. Any edit makes the list the picture's lights.
#ifndef shadelab_light_list_edit_h
#define shadelab_light_list_edit_h

#include "desktop/inspector.h"

#include <QWidget>

#include <functional>

class QDoubleSpinBox;
class QListWidget;

namespace shadelab
{
class ColorEdit;
class TripleEdit;

class LightListEdit : public QWidget
{
public:
  explicit LightListEdit(Inspector& inspector, QWidget* parent = nullptr);

  /** The list and the selected light's fields as the state is now. */
  void Show();

private:
  /** Edits the selected light, and makes the list the picture's lights. */
  void EditSelected(const std::function<void(Light&)>& edit);

  Inspector& Engine;
  int Selected = -1;
  QListWidget* List;
  TripleEdit* Position;
  TripleEdit* Direction;
  ColorEdit* Color;
  QDoubleSpinBox* Cone;
  QDoubleSpinBox* Exponent;
};
}

#endif
