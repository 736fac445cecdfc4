// Three numbers edited together in the control panel: a colour's R, G, B
// (color_edit.h), a light's position or direction. Six decimals, as the
// lecture's table has.
#ifndef shadelab_triple_edit_h
#define shadelab_triple_edit_h

#include "shadelabIllumination.h"

#include <QWidget>

#include <array>
#include <functional>

class QDoubleSpinBox;

namespace shadelab
{
class TripleEdit : public QWidget
{
public:
  /** Each number in [lowest, highest]; named `name` + " x" or the given suffixes. */
  TripleEdit(const QString& name, const std::array<const char*, 3>& parts, double lowest,
    double highest, QWidget* parent = nullptr);

  /** Shows `value` without telling Edited. */
  void SetValue(const Vec3& value);
  Vec3 Value() const;

  std::function<void(const Vec3&)> Edited; // a number typed

private:
  std::array<QDoubleSpinBox*, 3> Numbers;
};
}

#endif
