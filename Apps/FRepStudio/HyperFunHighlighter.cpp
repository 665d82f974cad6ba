#include "HyperFunHighlighter.h"

namespace frepstudio
{

HyperFunHighlighter::HyperFunHighlighter(QTextDocument* document)
  : QSyntaxHighlighter(document)
{
  const auto option = QRegularExpression::CaseInsensitiveOption;
  QTextCharFormat keyword;
  keyword.setForeground(QColor(0x00, 0x3f, 0xa8));
  keyword.setFontWeight(QFont::Bold);
  rules_.push_back({ QRegularExpression(
    R"(\b(array|if|then|else|endif|while|loop|endloop|and|or|not|xor)\b)", option), keyword });

  QTextCharFormat arrays;
  arrays.setForeground(QColor(0x8a, 0x2b, 0xa0));
  rules_.push_back({ QRegularExpression(R"(\b[xas](?=\s*\[))", option), arrays });

  // Library names: hfSphere, hfA_..., and the builtins the original knows without the prefix.
  QTextCharFormat library;
  library.setForeground(QColor(0x00, 0x80, 0x80));
  rules_.push_back({ QRegularExpression(R"(\bhf[A-Za-z0-9_]*\b)", option), library });
  rules_.push_back({ QRegularExpression(
    R"(\b(sqrt|exp|log|logd|sin|cos|tan|asin|acos|atan|sinh|cosh|tanh|abs|sign|max|min|mod|atan2)\b(?=\s*\())",
    option), library });

  QTextCharFormat number;
  number.setForeground(QColor(0xb0, 0x50, 0x00));
  rules_.push_back({ QRegularExpression(R"((?<![A-Za-z_0-9])(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)"),
    number });

  comment_ = QRegularExpression("--.*$");
  comment_format_.setForeground(QColor(0x70, 0x70, 0x70));
  comment_format_.setFontItalic(true);
}

void HyperFunHighlighter::highlightBlock(const QString& text)
{
  for (const Rule& rule : rules_)
  {
    auto matches = rule.pattern.globalMatch(text);
    while (matches.hasNext())
    {
      const auto match = matches.next();
      setFormat(static_cast<int>(match.capturedStart()), static_cast<int>(match.capturedLength()),
        rule.format);
    }
  }
  // Last: a comment wins over whatever the rules found inside it. HyperFun comments run to the
  // end of the line, so no state carries to the next block.
  const auto comment = comment_.match(text);
  if (comment.hasMatch())
    setFormat(static_cast<int>(comment.capturedStart()), static_cast<int>(comment.capturedLength()),
      comment_format_);
}

} // namespace frepstudio
