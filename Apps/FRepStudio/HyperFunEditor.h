// The HyperFun editor: a plain-text editor with line numbers, syntax colours and the errors of
// the last analysis underlined where the parser put them (file:line:col).
#pragma once

#include <QPlainTextEdit>
#include <vector>

namespace frepstudio
{

class HyperFunHighlighter;

/// A position in the text as the engine reports it: 1-based line, 1-based byte column.
struct TextLocation
{
  int line = 0;
  int column = 0;
};

class HyperFunEditor : public QPlainTextEdit
{
  Q_OBJECT
public:
  explicit HyperFunEditor(QWidget* parent = nullptr);

  /// Underlines the token at every location (replaces the previous ones).
  void setErrorLocations(const std::vector<TextLocation>& locations);
  /// How many error underlines are shown (for tests).
  int errorUnderlineCount() const { return static_cast<int>(error_selections_.size()); }
  /// Moves the cursor to a 1-based line and byte column, and shows it.
  void goToLocation(TextLocation location);
  /// The cursor's position as line and byte column (what diagnostics use).
  TextLocation cursorLocation() const;

  /// Width of the line-number gutter (used by the gutter widget).
  int lineNumberAreaWidth() const;
  void paintLineNumbers(QPaintEvent* event);

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  QTextCursor cursorAt(TextLocation location) const;
  void updateLineNumberArea(const QRect& rect, int dy);
  void refreshSelections();

  QWidget* line_numbers_ = nullptr;
  HyperFunHighlighter* highlighter_ = nullptr;
  QList<QTextEdit::ExtraSelection> error_selections_;
};

} // namespace frepstudio
