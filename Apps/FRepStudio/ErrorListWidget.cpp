#include "ErrorListWidget.h"

namespace frepstudio
{

namespace
{
constexpr int kLineRole = Qt::UserRole;
constexpr int kColumnRole = Qt::UserRole + 1;
constexpr int kLocatedRole = Qt::UserRole + 2; // false for the warning: no place to go to
}

ErrorListWidget::ErrorListWidget(QWidget* parent)
  : QListWidget(parent)
{
  // A click is enough: the list is short and a row is only ever a place to go to.
  auto go = [this](QListWidgetItem* item)
  {
    if (!item->data(kLocatedRole).toBool())
      return;
    emit locationActivated({ item->data(kLineRole).toInt(), item->data(kColumnRole).toInt() });
  };
  connect(this, &QListWidget::itemClicked, this, go);
  connect(this, &QListWidget::itemActivated, this, go);
}

void ErrorListWidget::setDiagnostics(const std::vector<frep::Diagnostic>& diagnostics)
{
  diagnostics_ = diagnostics;
  rebuild();
}

void ErrorListWidget::setWarning(const QString& warning)
{
  if (warning == warning_)
    return;
  warning_ = warning;
  rebuild();
}

void ErrorListWidget::rebuild()
{
  clear();
  for (const frep::Diagnostic& diagnostic : diagnostics_)
  {
    auto* item = new QListWidgetItem(QString::fromStdString(diagnostic.format()), this);
    item->setData(kLineRole, diagnostic.location.line);
    item->setData(kColumnRole, diagnostic.location.column);
    item->setData(kLocatedRole, true);
    item->setForeground(QColor(0xa0, 0, 0));
  }
  if (!warning_.isEmpty())
  {
    auto* item = new QListWidgetItem(warning_, this);
    item->setData(kLocatedRole, false);
    item->setForeground(QColor(0x8a, 0x5a, 0));
    item->setToolTip(warning_);
  }
}

QStringList ErrorListWidget::messages() const
{
  QStringList rows;
  for (int i = 0; i < count(); ++i)
    rows << item(i)->text();
  return rows;
}

} // namespace frepstudio
