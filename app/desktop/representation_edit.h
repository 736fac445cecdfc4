// What is drawn, in the control panel: the surface, the wireframe or the
// points, and beside it the lines' width or the points' size in pixels,
// enabled for the representation that uses it.
#ifndef shadelab_representation_edit_h
#define shadelab_representation_edit_h

#include "shadelabRepresentation.h"

#include <QWidget>

#include <functional>

class QComboBox;
class QSpinBox;

namespace shadelab
{
class RepresentationEdit : public QWidget
{
public:
  explicit RepresentationEdit(QWidget* parent = nullptr);

  /** Shows these without telling Edited. */
  void Set(Representation drawn, int lineWidth, int pointSize);

  /** A representation chosen, or a width or size typed. */
  std::function<void(Representation drawn, int lineWidth, int pointSize)> Edited;

private:
  void Changed();

  QComboBox* Drawn;
  QSpinBox* Pixels; // the line width or the point size, as Drawn says
  Representation Shown = Representation::Surface;
  int LineWidth = 1, PointSize = 1;
};
}

#endif
