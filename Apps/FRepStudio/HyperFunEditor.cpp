#include "HyperFunEditor.h"

#include "HyperFunHighlighter.h"

#include <QFontDatabase>
#include <QPainter>
#include <QTextBlock>

namespace frepstudio
{

namespace
{

/// The gutter: paints through the editor, which knows the block geometry.
class LineNumberArea : public QWidget
{
public:
  explicit LineNumberArea(HyperFunEditor* editor)
    : QWidget(editor)
    , editor_(editor)
  {
  }
  QSize sizeHint() const override { return { editor_->lineNumberAreaWidth(), 0 }; }

protected:
  void paintEvent(QPaintEvent* event) override { editor_->paintLineNumbers(event); }

private:
  HyperFunEditor* editor_;
};

/// Diagnostics count bytes of UTF-8; the editor counts UTF-16 code units.
int byteColumnToIndex(const QString& line, int byte_column)
{
  const QByteArray bytes = line.toUtf8();
  const int bytes_before = std::clamp(byte_column - 1, 0, static_cast<int>(bytes.size()));
  return QString::fromUtf8(bytes.left(bytes_before)).size();
}

} // namespace

HyperFunEditor::HyperFunEditor(QWidget* parent)
  : QPlainTextEdit(parent)
{
  setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  setLineWrapMode(QPlainTextEdit::NoWrap);
  setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * 4);
  highlighter_ = new HyperFunHighlighter(document());
  line_numbers_ = new LineNumberArea(this);
  connect(this, &QPlainTextEdit::blockCountChanged, this,
    [this] { setViewportMargins(lineNumberAreaWidth(), 0, 0, 0); });
  connect(this, &QPlainTextEdit::updateRequest, this, &HyperFunEditor::updateLineNumberArea);
  setViewportMargins(lineNumberAreaWidth(), 0, 0, 0);
}

int HyperFunEditor::lineNumberAreaWidth() const
{
  int digits = 1;
  for (int max = std::max(1, blockCount()); max >= 10; max /= 10)
    ++digits;
  return 8 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(3, digits);
}

void HyperFunEditor::updateLineNumberArea(const QRect& rect, int dy)
{
  if (dy != 0)
    line_numbers_->scroll(0, dy);
  else
    line_numbers_->update(0, rect.y(), line_numbers_->width(), rect.height());
}

void HyperFunEditor::resizeEvent(QResizeEvent* event)
{
  QPlainTextEdit::resizeEvent(event);
  const QRect area = contentsRect();
  line_numbers_->setGeometry(QRect(area.left(), area.top(), lineNumberAreaWidth(), area.height()));
}

void HyperFunEditor::paintLineNumbers(QPaintEvent* event)
{
  QPainter painter(line_numbers_);
  painter.fillRect(event->rect(), QColor(0xee, 0xee, 0xee));
  QTextBlock block = firstVisibleBlock();
  int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
  int bottom = top + qRound(blockBoundingRect(block).height());
  // Lines with an error get a red number, so they are found when scrolling.
  QSet<int> error_lines;
  for (const auto& selection : error_selections_)
    error_lines.insert(selection.cursor.blockNumber());
  while (block.isValid() && top <= event->rect().bottom())
  {
    if (block.isVisible() && bottom >= event->rect().top())
    {
      const int number = block.blockNumber();
      painter.setPen(error_lines.contains(number) ? QColor(0xc0, 0, 0) : QColor(0x80, 0x80, 0x80));
      painter.drawText(0, top, line_numbers_->width() - 4, fontMetrics().height(), Qt::AlignRight,
        QString::number(number + 1));
    }
    block = block.next();
    top = bottom;
    bottom = top + qRound(blockBoundingRect(block).height());
  }
}

QTextCursor HyperFunEditor::cursorAt(TextLocation location) const
{
  QTextBlock block = document()->findBlockByNumber(std::max(0, location.line - 1));
  if (!block.isValid())
    block = document()->lastBlock();
  QTextCursor cursor(block);
  const int index = byteColumnToIndex(block.text(), location.column);
  cursor.setPosition(block.position() + std::min(index, block.length() - 1));
  return cursor;
}

void HyperFunEditor::setErrorLocations(const std::vector<TextLocation>& locations)
{
  error_selections_.clear();
  for (const TextLocation& location : locations)
  {
    if (location.line <= 0)
      continue;
    QTextEdit::ExtraSelection selection;
    selection.cursor = cursorAt(location);
    // Underline the word at the error; at the end of a line (a missing ';', say) the character
    // before, so there is always something to see.
    selection.cursor.movePosition(QTextCursor::EndOfWord, QTextCursor::KeepAnchor);
    if (!selection.cursor.hasSelection())
    {
      selection.cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor);
      if (!selection.cursor.hasSelection())
        selection.cursor.movePosition(QTextCursor::Left, QTextCursor::KeepAnchor);
    }
    selection.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
    selection.format.setUnderlineColor(Qt::red);
    selection.format.setBackground(QColor(255, 0, 0, 40));
    error_selections_.append(selection);
  }
  refreshSelections();
  line_numbers_->update();
}

void HyperFunEditor::refreshSelections()
{
  setExtraSelections(error_selections_);
}

void HyperFunEditor::goToLocation(TextLocation location)
{
  setTextCursor(cursorAt(location));
  centerCursor();
  setFocus();
}

TextLocation HyperFunEditor::cursorLocation() const
{
  const QTextCursor cursor = textCursor();
  const QString before = cursor.block().text().left(cursor.positionInBlock());
  return { cursor.blockNumber() + 1, static_cast<int>(before.toUtf8().size()) + 1 };
}

} // namespace frepstudio
