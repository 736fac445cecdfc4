#include "desktop/probe_panel.h"

#include "probe/probe_text.h"

#include <QColor>
#include <QFontDatabase>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QVBoxLayout>

namespace shadelab
{
namespace
{
// "■ name" in the arrow's colour, for the legend.
QString Swatch(char vector, const QString& name)
{
  const Rgb c = ProbeArrowColor(vector);
  const QColor color = QColor::fromRgbF(c[0], c[1], c[2]);
  return "<span style=\"color:" + color.name() + "\">&#9632;</span> " + name;
}

const char* const Hint = "Ctrl+click the mesh to explain a pixel (in the single view).";
}

ProbePanel::ProbePanel(Inspector& inspector, QWidget* parent)
  : QWidget(parent)
  , Engine(inspector)
  , Readout(new QPlainTextEdit(this))
{
  this->Readout->setObjectName("probe readout");
  this->Readout->setReadOnly(true);
  this->Readout->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  this->Readout->setLineWrapMode(QPlainTextEdit::NoWrap); // the lines are columns
  this->Readout->setMinimumWidth(this->Readout->fontMetrics().averageCharWidth() * 48);
  auto* legend = new QLabel(Swatch('N', "N") + "&nbsp;&nbsp;" + Swatch('L', "L (each light)") +
      "&nbsp;&nbsp;" + Swatch('H', "H (Blinn-Phong) or R (Phong)"),
    this);
  legend->setWordWrap(true);
  auto* clear = new QPushButton("Clear probe", this);
  clear->setObjectName("clear probe");
  QObject::connect(this->Readout, &QPlainTextEdit::cursorPositionChanged, this,
    [this]
    {
      const std::optional<Terms> term =
        ProbeTextTerm(this->Readout->textCursor().block().text().toStdString());
      if (term && this->TermPicked)
      {
        this->TermPicked(*term);
      }
    });
  QObject::connect(clear, &QPushButton::clicked, this, [this] { this->Engine.ClearProbe(); });
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(legend);
  layout->addWidget(this->Readout);
  layout->addWidget(clear);
  this->Show();
}

void ProbePanel::Show()
{
  const std::optional<PixelProbe>& probe = this->Engine.GetProbe();
  this->Readout->setPlainText(QString::fromStdString(probe ? ProbeText(*probe) : Hint));
}
}
