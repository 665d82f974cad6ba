// The error list: one row per diagnostic, "file:line:col: error: message"; activating a row
// asks for the cursor to go there.
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
  /// The row texts (for tests and the status bar).
  QStringList messages() const;

signals:
  void locationActivated(frepstudio::TextLocation location);
};

} // namespace frepstudio
