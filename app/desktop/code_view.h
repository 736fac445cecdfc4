// A monospace editor of source code with its line numbers in a
// margin (numbered from 1, as the compiler's messages and the dumped
// files' lines are). Qt's own "Code Editor" example, without moc.
#ifndef shadelab_code_view_h
#define shadelab_code_view_h

#include <QPlainTextEdit>

namespace shadelab
{
class CodeView : public QPlainTextEdit
{
public:
  explicit CodeView(QWidget* parent = nullptr);

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  friend class LineNumbers;

  int NumbersWidth() const;
  void PaintNumbers(QPaintEvent* event);

  QWidget* Numbers;
};
}

#endif
