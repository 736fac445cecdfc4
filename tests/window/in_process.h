// What the in-process window tests share: the inspector's window on the
// teapot, Qt's application made as RunView makes it, and reading and typing
// into its widgets with QTest.
#ifndef shadelab_window_in_process_h
#define shadelab_window_in_process_h

#include "commands/view_command.h"

#include <QApplication>

#include <memory>
#include <set>
#include <string>
#include <vector>

class QAbstractSpinBox;
class QPlainTextEdit;
class QString;

namespace shadelab_test
{
/** The inspector's window on the teapot at 240x180, under rule. */
shadelab::ViewOptions SpotView(shadelab::Shading rule);

/** Qt's application, made as RunView makes it (the widget's format first). */
std::unique_ptr<QApplication> MakeApplication();

/** The lines (0-based) of source that hold any of codes. */
std::set<int> LinesWith(const std::string& source, const std::vector<std::string>& codes);

/** The lines (0-based) that edit shows highlighted. */
std::set<int> Highlighted(const QPlainTextEdit* edit);

/** Types text into box, as a user does, and presses Return. */
void Type(QAbstractSpinBox* box, const QString& text);
}

#endif
