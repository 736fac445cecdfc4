#include "desktop/shader_panel.h"

#include "desktop/code_view.h"
#include "shadelabShaderSource.h"

#include <QButtonGroup>
#include <QHBoxLayout>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QTextBlock>
#include <QVBoxLayout>

#include <algorithm>
#include <cstring>
#include <vector>

namespace shadelab
{
namespace
{
constexpr std::array<Terms, 3> MarkedTerms{ Terms::Ambient, Terms::Diffuse, Terms::Specular };

// Light backgrounds, far enough apart to tell and light enough to read on.
QColor Colour(Terms term)
{
  switch (term)
  {
    case Terms::Ambient:
      return QColor(0xc8, 0xdc, 0xff);
    case Terms::Diffuse:
      return QColor(0xc8, 0xf0, 0xbe);
    case Terms::Specular:
      return QColor(0xff, 0xdc, 0xb4);
    case Terms::All:
      break;
  }
  return QColor(Qt::white);
}

// The equation's part that each term's button names.
QString Formula(Terms term)
{
  switch (term)
  {
    case Terms::Ambient:
      return "ka*Ia";
    case Terms::Diffuse:
      return "kd*Il*N.L";
    case Terms::Specular:
      return "ks*Il*base^ns";
    case Terms::All:
      break;
  }
  return "";
}

// The terms that line's marker names; none without a marker, or where a
// name is not a term's (a comment that merely starts like a marker).
std::vector<Terms> TermsOf(const QString& line)
{
  const int at = line.lastIndexOf(TermMarker);
  if (at < 0)
  {
    return {};
  }
  std::vector<Terms> terms;
  for (const QString& name : line.mid(at + static_cast<int>(std::strlen(TermMarker))).split(','))
  {
    const auto term = std::find_if(MarkedTerms.begin(), MarkedTerms.end(),
      [&name](Terms t) { return name.trimmed() == ToString(t); });
    if (term == MarkedTerms.end())
    {
      return {};
    }
    terms.push_back(*term);
  }
  return terms;
}

// The background of a line with `terms` when `shown` is highlighted; none
// (invalid) when the line is not one of them. A line that adds up several
// terms mixes their colours.
QColor Background(const std::vector<Terms>& terms, Terms shown)
{
  if (shown != Terms::All)
  {
    return std::count(terms.begin(), terms.end(), shown) ? Colour(shown) : QColor();
  }
  if (terms.empty())
  {
    return QColor();
  }
  int red = 0, green = 0, blue = 0;
  for (Terms term : terms)
  {
    const QColor c = Colour(term);
    red += c.red();
    green += c.green();
    blue += c.blue();
  }
  const int n = static_cast<int>(terms.size());
  return QColor(red / n, green / n, blue / n);
}
}

ShaderPanel::ShaderPanel(QWidget* parent)
  : QWidget(parent)
  , Tabs(new QTabWidget(this))
{
  for (std::size_t i = 0; i < this->Stages.size(); ++i)
  {
    auto* edit = new CodeView(this);
    edit->setObjectName(i == 0 ? "vertex source" : "fragment source");
    this->Stages[i] = edit;
    this->Tabs->addTab(edit, i == 0 ? "Vertex" : "Fragment");
  }
  auto* legend = new QHBoxLayout;
  auto* group = new QButtonGroup(this);
  for (Terms term : { Terms::All, Terms::Ambient, Terms::Diffuse, Terms::Specular })
  {
    const QString name = ToString(term);
    auto* button = new QPushButton(
      term == Terms::All ? QString("all terms") : name + "  " + Formula(term), this);
    button->setObjectName("highlight " + name);
    button->setCheckable(true);
    button->setToolTip(term == Terms::All
        ? "Highlight the lines of every term"
        : "Highlight the lines that compute the " + name + " term only, and go to the first");
    if (term != Terms::All)
    {
      button->setStyleSheet("QPushButton { background-color: " + Colour(term).name() +
        "; padding: 3px 6px; } QPushButton:checked { border: 2px solid #404040; }");
    }
    group->addButton(button);
    legend->addWidget(button);
    this->Buttons[static_cast<std::size_t>(term)] = button;
    QObject::connect(
      button, &QPushButton::clicked, this, [this, term] { this->HighlightTerm(term); });
  }
  this->Buttons[static_cast<std::size_t>(Terms::All)]->setChecked(true);
  auto* column = new QVBoxLayout(this);
  column->addLayout(legend);
  column->addWidget(this->Tabs);
}

void ShaderPanel::Show(const ShaderSources& sources)
{
  if (sources.Vertex == this->Sources.Vertex && sources.Fragment == this->Sources.Fragment)
  {
    return;
  }
  this->Sources = sources;
  this->Stages[0]->setPlainText(QString::fromStdString(sources.Vertex));
  this->Stages[1]->setPlainText(QString::fromStdString(sources.Fragment));
  this->Highlight();
}

void ShaderPanel::HighlightTerm(Terms term)
{
  this->Shown = term;
  this->Buttons[static_cast<std::size_t>(term)]->setChecked(true);
  this->Highlight();
}

// Colours the marked lines of both stages, and shows the first highlighted
// line of the first stage that has one (the stage that lights).
void ShaderPanel::Highlight()
{
  bool shown = false;
  for (QPlainTextEdit* edit : this->Stages)
  {
    QList<QTextEdit::ExtraSelection> lines;
    for (QTextBlock block = edit->document()->begin(); block.isValid(); block = block.next())
    {
      const QColor background = Background(TermsOf(block.text()), this->Shown);
      if (!background.isValid())
      {
        continue;
      }
      QTextEdit::ExtraSelection line;
      line.cursor = QTextCursor(block);
      line.format.setBackground(background);
      line.format.setProperty(QTextFormat::FullWidthSelection, true);
      lines.append(line);
    }
    edit->setExtraSelections(lines);
    if (!shown && !lines.isEmpty())
    {
      shown = true;
      this->Tabs->setCurrentWidget(edit);
      edit->setTextCursor(lines.front().cursor);
      edit->centerCursor();
    }
  }
}
}
