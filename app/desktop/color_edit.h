// A colour of the lecture's model (ka, kd, ks, Ia, a light's) in the
// control panel: a swatch that opens Qt's colour dialog, and the three
// numbers beside it for exact values.
#ifndef shadelab_color_edit_h
#define shadelab_color_edit_h

#include "shadelabIllumination.h"

#include <QWidget>

#include <functional>

class QPushButton;

namespace shadelab
{
class TripleEdit;

class ColorEdit : public QWidget
{
public:
  explicit ColorEdit(const QString& name, QWidget* parent = nullptr);

  /** Shows `color` without telling Edited. */
  void SetColor(const Rgb& color);

  std::function<void(const Rgb&)> Edited; // a number typed or a colour picked

private:
  void PickColor();
  void PaintSwatch();

  QString Name;
  QPushButton* Swatch;
  TripleEdit* Numbers;
};
}

#endif
