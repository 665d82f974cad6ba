// Syntax colours for HyperFun: keywords (case-insensitive, as the language), the x/a/s arrays,
// hf* library names, numbers and `--` comments.
#pragma once

#include <QRegularExpression>
#include <QSyntaxHighlighter>
#include <QTextCharFormat>
#include <vector>

namespace frepstudio
{

class HyperFunHighlighter : public QSyntaxHighlighter
{
  Q_OBJECT
public:
  explicit HyperFunHighlighter(QTextDocument* document);

protected:
  void highlightBlock(const QString& text) override;

private:
  struct Rule
  {
    QRegularExpression pattern;
    QTextCharFormat format;
  };
  std::vector<Rule> rules_;
  QRegularExpression comment_;
  QTextCharFormat comment_format_;
};

} // namespace frepstudio
