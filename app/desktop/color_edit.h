// A colour of the lecture's model (ka, kd, ks, Ia) in the control panel: a
// swatch that opens Qt's colour dialog, and the three numbers beside it for
// exact values (the lecture's table has six decimals).
#ifndef shadelab_color_edit_h
#define shadelab_color_edit_h

#include "shadelabIllumination.h"

#include <QWidget>

#include <array>
#include <functional>

class QDoubleSpinBox;
class QPushButton;

namespace shadelab
{
class ColorEdit : public QWidget
{
public:
  explicit ColorEdit(const QString& name, QWidget* parent = nullptr);

  /** Shows `color` without telling Edited. */
  void SetColor(const Rgb& color);

  std::function<void(const Rgb&)> Edited; // a number typed or a colour picked

private:
  void PickColor();
  Rgb Color() const;
  void PaintSwatch();

  QString Name;
  QPushButton* Swatch;
  std::array<QDoubleSpinBox*, 3> Numbers;
};
}

#endif
