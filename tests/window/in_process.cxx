#include "in_process.h"

#include "cli_test_support.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QAbstractSpinBox>
#include <QPlainTextEdit>
#include <QSurfaceFormat>
#include <QTest>

#include <sstream>

using namespace shadelab;

namespace shadelab_test
{
ViewOptions SpotView(Shading rule)
{
  ViewOptions options;
  options.Scene.Mesh = TestMesh("teapot.obj").string();
  options.Scene.Size = { 240, 180 };
  options.Scene.CameraPosition = Vec3{ 5, 5, 9 };
  options.Scene.ShadingRule = rule;
  return options;
}

std::unique_ptr<QApplication> MakeApplication()
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  static int argc = 1;
  static char name[] = "shadelab-view-test";
  static char* argv[] = { name, nullptr };
  return std::make_unique<QApplication>(argc, argv);
}

std::set<int> LinesWith(const std::string& source, const std::vector<std::string>& codes)
{
  std::set<int> lines;
  std::istringstream in(source);
  std::string line;
  for (int n = 0; std::getline(in, line); ++n)
  {
    for (const std::string& code : codes)
    {
      if (line.find(code) != std::string::npos)
      {
        lines.insert(n);
      }
    }
  }
  return lines;
}

std::set<int> Highlighted(const QPlainTextEdit* edit)
{
  std::set<int> lines;
  for (const QTextEdit::ExtraSelection& selection : edit->extraSelections())
  {
    lines.insert(selection.cursor.blockNumber());
  }
  return lines;
}

void Type(QAbstractSpinBox* box, const QString& text)
{
  box->setFocus();
  box->selectAll();
  QTest::keyClicks(box, text);
  QTest::keyClick(box, Qt::Key_Return);
}
}
