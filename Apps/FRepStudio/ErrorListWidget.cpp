#include "ErrorListWidget.h"

namespace frepstudio
{

namespace
{
constexpr int kLineRole = Qt::UserRole;
constexpr int kColumnRole = Qt::UserRole + 1;
}

ErrorListWidget::ErrorListWidget(QWidget* parent)
  : QListWidget(parent)
{
  // A click is enough: the list is short and a row is only ever a place to go to.
  auto go = [this](QListWidgetItem* item) {
    emit locationActivated({ item->data(kLineRole).toInt(), item->data(kColumnRole).toInt() });
  };
  connect(this, &QListWidget::itemClicked, this, go);
  connect(this, &QListWidget::itemActivated, this, go);
}

void ErrorListWidget::setDiagnostics(const std::vector<frep::Diagnostic>& diagnostics)
{
  clear();
  for (const frep::Diagnostic& diagnostic : diagnostics)
  {
    auto* item = new QListWidgetItem(QString::fromStdString(diagnostic.format()), this);
    item->setData(kLineRole, diagnostic.location.line);
    item->setData(kColumnRole, diagnostic.location.column);
    item->setForeground(QColor(0xa0, 0, 0));
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
