#include "desktop/code_view.h"

#include <QFontDatabase>
#include <QPainter>
#include <QTextBlock>

#include <algorithm>

namespace shadelab
{
// The margin: CodeView paints it (QPlainTextEdit's block geometry is protected).
class LineNumbers : public QWidget
{
public:
  explicit LineNumbers(CodeView* view)
    : QWidget(view)
    , View(view)
  {
  }

protected:
  void paintEvent(QPaintEvent* event) override { this->View->PaintNumbers(event); }

private:
  CodeView* View;
};

CodeView::CodeView(QWidget* parent)
  : QPlainTextEdit(parent)
  , Numbers(new LineNumbers(this))
{
  this->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  this->setLineWrapMode(QPlainTextEdit::NoWrap);
  const auto fit = [this] { this->setViewportMargins(this->NumbersWidth(), 0, 0, 0); };
  QObject::connect(this, &QPlainTextEdit::blockCountChanged, this, fit);
  QObject::connect(this, &QPlainTextEdit::updateRequest, this,
    [this](const QRect& rect, int dy)
    {
      if (dy)
      {
        this->Numbers->scroll(0, dy);
      }
      else
      {
        this->Numbers->update(0, rect.y(), this->Numbers->width(), rect.height());
      }
    });
  fit();
}

int CodeView::NumbersWidth() const
{
  const int digits = QString::number(std::max(1, this->blockCount())).size();
  return 8 + this->fontMetrics().horizontalAdvance(QLatin1Char('9')) * digits;
}

void CodeView::resizeEvent(QResizeEvent* event)
{
  QPlainTextEdit::resizeEvent(event);
  const QRect r = this->contentsRect();
  this->Numbers->setGeometry(r.left(), r.top(), this->NumbersWidth(), r.height());
}

void CodeView::PaintNumbers(QPaintEvent* event)
{
  QPainter painter(this->Numbers);
  painter.fillRect(event->rect(), this->palette().window());
  painter.setPen(this->palette().color(QPalette::Disabled, QPalette::Text));
  QTextBlock block = this->firstVisibleBlock();
  int top = qRound(this->blockBoundingGeometry(block).translated(this->contentOffset()).top());
  const int lineHeight = this->fontMetrics().height();
  while (block.isValid() && top <= event->rect().bottom())
  {
    const int bottom = top + qRound(this->blockBoundingRect(block).height());
    if (block.isVisible() && bottom >= event->rect().top())
    {
      painter.drawText(0, top, this->Numbers->width() - 4, lineHeight, Qt::AlignRight,
        QString::number(block.blockNumber() + 1));
    }
    block = block.next();
    top = bottom;
  }
}
}
