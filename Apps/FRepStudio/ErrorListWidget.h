// The error list: one row per diagnostic, "file:line:col: error: message"; activating a row
// asks for the cursor to go there. After them, at most one warning about the model that is not an
// error (the section is still drawn), "file: warning: message": e.g. a solid that cannot be
// bounded and keeps hfp's box (CoordinateRanges::note).
#pragma once

#include "HyperFunEditor.h"

#include "Language/diagnostic.h"

#include <QListWidget>
#include <vector>

namespace frepstudio
{

class ErrorListWidget : public QListWidget
{
  Q_OBJECT
public:
  explicit ErrorListWidget(QWidget* parent = nullptr);

  void setDiagnostics(const std::vector<frep::Diagnostic>& diagnostics);
  /// Shows `warning` (one row, already "file: warning: ..."; empty: none) after the diagnostics,
  /// until the next setWarning.
  void setWarning(const QString& warning);
  /// The row texts (for tests and the status bar).
  QStringList messages() const;
  /// The diagnostics' rows (without the warning).
  int errorCount() const { return static_cast<int>(diagnostics_.size()); }
  const QString& warning() const { return warning_; }

signals:
  void locationActivated(frepstudio::TextLocation location);

private:
  void rebuild();

  std::vector<frep::Diagnostic> diagnostics_;
  QString warning_;
};

} // namespace frepstudio
