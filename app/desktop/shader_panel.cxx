#include "desktop/shader_panel.h"

#include "desktop/code_view.h"
#include "shadelabShaderSource.h"

#include <QButtonGroup>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QListWidget>
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
// What the generator marks (TermMarker): the equation's terms, in Terms'
// order after All, then the effects a scene may add, each with the colour
// of its lines and the formula its button names.
struct Mark
{
  const char* Name;
  QColor Colour; // light backgrounds, far enough apart to tell and light enough to read on
  const char* Formula;
  bool Effect; // compiled in only where a scene uses it: its button shows only then
  // An effect a scene has instead of the one before (a bump map, or a
  // normal map): its button takes that one's place where its lines are.
  bool Instead = false;
};

const std::array<Mark, ShaderPanel::MarkCount>& Marks()
{
  static const std::array<Mark, ShaderPanel::MarkCount> marks{ {
    { "ambient", QColor(0xc8, 0xdc, 0xff), "ka*Ia", false },
    { "diffuse", QColor(0xc8, 0xf0, 0xbe), "kd*Il*N.L", false },
    { "specular", QColor(0xff, 0xdc, 0xb4), "ks*Il*base^ns", false },
    { "attenuation", QColor(0xf0, 0xd2, 0xf0), "Il/(c0+c1*d+c2*d^2)", true },
    { "fog", QColor(0xdc, 0xdc, 0xdc), "f*C+(1-f)*fog", true },
    { "translucency", QColor(0xff, 0xf5, 0xb4), "a*I+(1-a)*behind", true },
    { "shadow", QColor(0xd2, 0xe6, 0xe6), "d <= map + bias", true },
    { "environment", QColor(0xe6, 0xf0, 0xc8), "ks*E(R)", true },
    { "normal map", QColor(0xf0, 0xe0, 0xd0), "N'=T x+B y+N z", true },
    { "bump map", QColor(0xe6, 0xd8, 0xf0), "N'=N-k(T hs+B ht)", true, true },
  } };
  return marks;
}

// The marks that line's marker names, numbered as the buttons are (1 is
// Marks()'s first; ShaderPanel::AllMarks is 0); none without a
// marker, or where a name is not a mark's (a comment that merely starts like
// a marker).
std::vector<std::size_t> MarksOf(const QString& line)
{
  const int at = line.lastIndexOf(TermMarker);
  if (at < 0)
  {
    return {};
  }
  std::vector<std::size_t> marks;
  for (const QString& name : line.mid(at + static_cast<int>(std::strlen(TermMarker))).split(','))
  {
    const auto& all = Marks();
    const auto mark = std::find_if(
      all.begin(), all.end(), [&name](const Mark& m) { return name.trimmed() == m.Name; });
    if (mark == all.end())
    {
      return {};
    }
    marks.push_back(static_cast<std::size_t>(mark - all.begin()) + 1);
  }
  return marks;
}

// The background of a line with `marks` when mark `shown` is highlighted
// (ShaderPanel::AllMarks: every one); none (invalid) when the line is not
// one of them. A line that adds up several terms mixes their colours.
QColor Background(const std::vector<std::size_t>& marks, std::size_t shown)
{
  if (shown != ShaderPanel::AllMarks)
  {
    return std::count(marks.begin(), marks.end(), shown) ? Marks()[shown - 1].Colour : QColor();
  }
  if (marks.empty())
  {
    return QColor();
  }
  int red = 0, green = 0, blue = 0;
  for (std::size_t mark : marks)
  {
    const QColor c = Marks()[mark - 1].Colour;
    red += c.red();
    green += c.green();
    blue += c.blue();
  }
  const int n = static_cast<int>(marks.size());
  return QColor(red / n, green / n, blue / n);
}

// The button that highlights every mark's lines.
QPushButton* AllMarksButton(QWidget* parent)
{
  auto* button = new QPushButton("all terms", parent);
  button->setObjectName("highlight " + QString(ToString(Terms::All)));
  button->setToolTip("Highlight the lines of every term");
  return button;
}

// A line the driver refused: red, over any term's colour.
const QColor ErrorColour(0xff, 0xa8, 0xa8);

// The stage's tab a driver's error is in (a link error: none).
int StageOf(const StageErrorLine& error)
{
  return error.Where == StageError::Stage::Vertex ? 0
    : error.Where == StageError::Stage::Fragment  ? 1
                                                  : -1;
}

QString Describe(const StageErrorLine& error)
{
  const int stage = StageOf(error);
  const QString where = stage < 0 ? "link" : stage == 0 ? "vertex" : "fragment";
  return where + (error.Line ? ", line " + QString::number(error.Line) : QString()) + ": " +
    QString::fromStdString(error.Message);
}

QPushButton* MarkButton(const Mark& mark, QWidget* parent)
{
  const QString name = mark.Name;
  auto* button = new QPushButton(name + "  " + mark.Formula, parent);
  button->setObjectName("highlight " + name);
  button->setToolTip("Highlight the lines that compute the " + name + (mark.Effect ? "" : " term") +
    " only, and go to the first");
  button->setStyleSheet("QPushButton { background-color: " + mark.Colour.name() +
    "; padding: 3px 6px; } QPushButton:checked { border: 2px solid #404040; }");
  return button;
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
  // The terms' buttons in a row, the effects' below, greyed where the
  // program has no lines of theirs: the panel keeps its size, and with it
  // the window and the view. The effects go EffectColumns to a row, so that
  // the panel is no wider than the terms' row (a small screen's window
  // keeps the view's aspect).
  constexpr int EffectColumns = 3;
  auto* legend = new QHBoxLayout;
  auto* effects = new QGridLayout;
  auto* group = new QButtonGroup(this);
  int effect = 0;
  for (std::size_t i = 0; i < this->Buttons.size(); ++i)
  {
    QPushButton* button = i == AllMarks ? AllMarksButton(this) : MarkButton(Marks()[i - 1], this);
    button->setCheckable(true);
    // An effect's button once a program has its lines (Show).
    button->setEnabled(i == AllMarks || !Marks()[i - 1].Effect);
    group->addButton(button);
    if (i != AllMarks && Marks()[i - 1].Effect)
    {
      // One in its place: the cell of the effect before, shown instead
      // (Show), as wide as it, so that the panel keeps its size.
      const bool instead = Marks()[i - 1].Instead;
      const int cell = instead ? effect - 1 : effect++;
      effects->addWidget(button, cell / EffectColumns, cell % EffectColumns);
      button->setVisible(!instead);
      if (instead)
      {
        const int wide =
          std::max(button->sizeHint().width(), this->Buttons[i - 1]->sizeHint().width());
        button->setMinimumWidth(wide);
        this->Buttons[i - 1]->setMinimumWidth(wide);
      }
    }
    else
    {
      legend->addWidget(button);
    }
    this->Buttons[i] = button;
    QObject::connect(button, &QPushButton::clicked, this, [this, i] { this->HighlightMark(i); });
  }
  this->Buttons[AllMarks]->setChecked(true);
  auto* column = new QVBoxLayout(this);
  column->addLayout(legend);
  effects->setColumnStretch(EffectColumns, 1);
  column->addLayout(effects);
  column->addWidget(this->Tabs);

  // The hands-on's editing: apply, revert, save, and the driver's errors.
  auto* edits = new QHBoxLayout;
  const auto button = [this, edits](const QString& text, const char* name, const QString& tip,
                        const std::function<void()>& act)
  {
    auto* b = new QPushButton(text, this);
    b->setObjectName(name);
    b->setToolTip(tip);
    edits->addWidget(b);
    QObject::connect(b, &QPushButton::clicked, this, act);
  };
  button("Apply", "apply stages",
    "Draw the edited stages (Ctrl+Return); where the driver refuses them, the program that drew "
    "before keeps drawing",
    [this] { this->Apply(); });
  button("Revert", "revert stages", "The generated stages again",
    [this]
    {
      this->ShowErrors({});
      for (QPlainTextEdit* edit : this->Stages)
      {
        edit->document()->setModified(false);
      }
      if (this->Revert)
      {
        this->Revert();
      }
    });
  button("Save", "save stages",
    "Write the stages of one's own to their files (new ones: shadelab-MESH-001.vert, .frag "
    "in the current folder); Copy command and Save scene name them",
    [this]
    {
      if (this->Save)
      {
        this->Save();
      }
    });
  edits->addStretch();
  column->addLayout(edits);
  // Ctrl+Return where the edit is typed: a shortcut would wait for the
  // window to be the active one, which a window without a manager never is.
  for (QPlainTextEdit* edit : this->Stages)
  {
    edit->installEventFilter(this);
  }
  this->ErrorList = new QListWidget(this);
  this->ErrorList->setObjectName("stage errors");
  // Always there and of one height: errors coming and going never resize
  // the window, and with it the 3D view.
  this->ErrorList->setFixedHeight(3 * this->ErrorList->fontMetrics().height());
  this->ErrorList->setToolTip("The driver's errors of the last Apply; click one to go to its line");
  QObject::connect(this->ErrorList, &QListWidget::currentRowChanged, this,
    [this](int row) { this->GoToError(row); });
  column->addWidget(this->ErrorList);
}

void ShaderPanel::Show(const ShaderSources& sources)
{
  const bool same =
    sources.Vertex == this->Sources.Vertex && sources.Fragment == this->Sources.Fragment;
  this->Sources = sources;
  // The user's edit is kept until applied or reverted; text that is
  // already shown is not set again (the cursor and the scroll stay).
  bool set = false;
  for (std::size_t i = 0; i < this->Stages.size(); ++i)
  {
    const QString text = QString::fromStdString(i == 0 ? sources.Vertex : sources.Fragment);
    if (!this->Stages[i]->document()->isModified() && this->Stages[i]->toPlainText() != text)
    {
      this->Stages[i]->setPlainText(text);
      set = true;
    }
  }
  if (same && !set)
  {
    return;
  }
  // An effect's button enabled only where the program has its lines.
  for (std::size_t i = 0; i < Marks().size(); ++i)
  {
    if (Marks()[i].Effect)
    {
      const std::string marker = std::string(TermMarker) + Marks()[i].Name;
      const bool used = sources.Vertex.find(marker) != std::string::npos ||
        sources.Fragment.find(marker) != std::string::npos;
      this->Buttons[i + 1]->setEnabled(used);
      if (Marks()[i].Instead)
      {
        this->Buttons[i + 1]->setVisible(used);
        this->Buttons[i]->setVisible(!used);
      }
      if (!used && this->Shown == i + 1)
      {
        this->HighlightMark(AllMarks);
      }
    }
  }
  this->Highlight();
}

bool ShaderPanel::eventFilter(QObject* watched, QEvent* event)
{
  if (event->type() == QEvent::KeyPress)
  {
    const auto* key = static_cast<QKeyEvent*>(event);
    if ((key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) &&
      (key->modifiers() & Qt::ControlModifier))
    {
      this->Apply();
      return true;
    }
  }
  return QWidget::eventFilter(watched, event);
}

void ShaderPanel::Apply()
{
  OwnStages edits;
  for (std::size_t i = 0; i < this->Stages.size(); ++i)
  {
    if (this->Stages[i]->document()->isModified())
    {
      (i == 0 ? edits.Vertex : edits.Fragment) = this->Stages[i]->toPlainText().toStdString();
    }
  }
  if (edits.Empty() || !this->ApplyEdits)
  {
    return;
  }
  const std::vector<StageErrorLine> errors = this->ApplyEdits(edits);
  if (errors.empty())
  {
    for (QPlainTextEdit* edit : this->Stages)
    {
      edit->document()->setModified(false);
    }
    this->Show(this->Sources); // what runs now: the edit, with what the render passes add
  }
  this->ShowErrors(errors);
}

void ShaderPanel::ShowErrors(const std::vector<StageErrorLine>& errors)
{
  this->Errors = errors;
  this->ErrorList->clear();
  for (const StageErrorLine& error : errors)
  {
    this->ErrorList->addItem(Describe(error));
  }
  this->Highlight();
  if (!errors.empty())
  {
    this->ErrorList->setCurrentRow(0); // the first error's line shown
  }
}

void ShaderPanel::GoToError(int row)
{
  if (row < 0 || row >= static_cast<int>(this->Errors.size()))
  {
    return;
  }
  const StageErrorLine& error = this->Errors[row];
  const int stage = StageOf(error);
  if (stage < 0 || error.Line < 1)
  {
    return;
  }
  QPlainTextEdit* edit = this->Stages[stage];
  const QTextBlock block = edit->document()->findBlockByNumber(error.Line - 1);
  if (block.isValid())
  {
    this->Tabs->setCurrentWidget(edit);
    edit->setTextCursor(QTextCursor(block));
    edit->centerCursor();
  }
}

void ShaderPanel::HighlightTerm(Terms term)
{
  this->HighlightMark(static_cast<std::size_t>(term)); // Terms' order is the buttons'
}

void ShaderPanel::HighlightMark(std::size_t mark)
{
  this->Shown = mark;
  this->Buttons[mark]->setChecked(true);
  this->Highlight();
}

// Colours the marked lines of both stages and the refused ones, and shows
// the first highlighted line of the first stage that has one (the stage
// that lights).
void ShaderPanel::Highlight()
{
  bool shown = false;
  for (std::size_t stage = 0; stage < this->Stages.size(); ++stage)
  {
    QPlainTextEdit* edit = this->Stages[stage];
    QList<QTextEdit::ExtraSelection> lines;
    for (QTextBlock block = edit->document()->begin(); block.isValid(); block = block.next())
    {
      const bool refused = std::any_of(this->Errors.begin(), this->Errors.end(),
        [&](const StageErrorLine& e)
        { return StageOf(e) == static_cast<int>(stage) && e.Line == block.blockNumber() + 1; });
      const QColor background =
        refused ? ErrorColour : Background(MarksOf(block.text()), this->Shown);
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
