#include "MappingEditor.h"

#include "DurableSave.h"

#include "ExamplesDirectory.h"

#include <QComboBox>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <array>

namespace frepstudio
{

namespace
{
using Type = frep::mapping::Channel::Type;
constexpr std::array kTypes{ Type::World, Type::Dynamic, Type::Spreadsheet, Type::Fixed,
  Type::Colour, Type::Transparency, Type::Transformation, Type::Audio, Type::Projected };
constexpr int kCoordinateColumn = 0, kTypeColumn = 1, kLoColumn = 2, kHiColumn = 3;
}

QString MappingEditor::typeName(Type type)
{
  switch (type)
  {
    case Type::World: return "world";
    case Type::Dynamic: return "dynamic";
    case Type::Spreadsheet: return "spreadsheet";
    case Type::Fixed: return "fixed";
    case Type::Colour: return "colour";
    case Type::Transparency: return "transparency";
    case Type::Transformation: return "transformation";
    case Type::Audio: return "audio";
    case Type::Projected: return "projected";
  }
  return {};
}

MappingEditor::MappingEditor(QWidget* parent)
  : QWidget(parent)
{
  auto* layout = new QVBoxLayout(this);
  auto* buttons = new QHBoxLayout;
  auto* open = new QPushButton(tr("Open..."), this);
  auto* save = new QPushButton(tr("Save As..."), this);
  auto* add = new QPushButton(tr("Add channel..."), this);
  auto* remove = new QPushButton(tr("Remove channel"), this);
  for (QPushButton* button : { open, save, add, remove })
    buttons->addWidget(button);
  buttons->addStretch(1);
  layout->addLayout(buttons);

  table_ = new QTableWidget(0, 4, this);
  table_->setObjectName("mappingTable");
  table_->setHorizontalHeaderLabels({ tr("Coordinate"), tr("Type"), tr("Range from"),
    tr("Range to") });
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  layout->addWidget(table_, 1);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  layout->addWidget(status_);

  connect(open, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open mapping"),
      examplesDirectory(), tr("Mapping (*.json)"));
    if (!path.isEmpty())
      loadFile(path);
  });
  connect(save, &QPushButton::clicked, this, [this] {
    const QString path =
      QFileDialog::getSaveFileName(this, tr("Save mapping"), {}, tr("Mapping (*.json)"));
    if (!path.isEmpty())
      saveFile(path);
  });
  connect(add, &QPushButton::clicked, this, &MappingEditor::addChannel);
  connect(remove, &QPushButton::clicked, this, &MappingEditor::removeChannel);
  // Ranges are edited in place; an empty cell means "the model's default interval".
  connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    frep::mapping::Channel* channel = channelAt(item->row());
    if (!channel || (item->column() != kLoColumn && item->column() != kHiColumn))
      return;
    const QString lo_text = table_->item(item->row(), kLoColumn)->text().trimmed();
    const QString hi_text = table_->item(item->row(), kHiColumn)->text().trimmed();
    bool lo_ok = false, hi_ok = false;
    const double lo = lo_text.toDouble(&lo_ok), hi = hi_text.toDouble(&hi_ok);
    if (lo_text.isEmpty() && hi_text.isEmpty())
      channel->range.reset();
    else if (lo_ok && hi_ok)
      channel->range = frep::mapping::Interval{ lo, hi };
    else
      return; // half typed: wait for both numbers
    emit specChanged();
  });
  setSpec({});
}

frep::mapping::Channel* MappingEditor::channelAt(int row)
{
  int index = 0;
  for (auto& coordinate : spec_.coordinates)
    for (auto& channel : coordinate.channels)
      if (index++ == row)
        return &channel;
  return nullptr;
}

void MappingEditor::setSpec(const frep::mapping::Spec& spec)
{
  spec_ = spec;
  rebuildTable();
  emit specChanged();
}

void MappingEditor::rebuildTable()
{
  QSignalBlocker block(table_);
  table_->setRowCount(0);
  int row = 0;
  for (const auto& coordinate : spec_.coordinates)
    for (const auto& channel : coordinate.channels)
    {
      table_->insertRow(row);
      auto* name = new QTableWidgetItem(QString::fromStdString(coordinate.name));
      name->setFlags(name->flags() & ~Qt::ItemIsEditable);
      table_->setItem(row, kCoordinateColumn, name);
      auto* type = new QComboBox(table_);
      for (Type t : kTypes)
        type->addItem(typeName(t), static_cast<int>(t));
      type->setCurrentIndex(type->findData(static_cast<int>(channel.type)));
      connect(type, qOverload<int>(&QComboBox::currentIndexChanged), this, [this, row, type] {
        if (frep::mapping::Channel* c = channelAt(row))
        {
          c->type = static_cast<Type>(type->currentData().toInt());
          emit specChanged();
        }
      });
      table_->setCellWidget(row, kTypeColumn, type);
      table_->setItem(row, kLoColumn, new QTableWidgetItem(
        channel.range ? QString::number(channel.range->lo) : QString()));
      table_->setItem(row, kHiColumn, new QTableWidgetItem(
        channel.range ? QString::number(channel.range->hi) : QString()));
      ++row;
    }
  status_->setText(errors_.isEmpty() ? tr("%n channel(s)", nullptr, row) : errors_.join('\n'));
}

void MappingEditor::addChannel()
{
  bool ok = false;
  const QString name = QInputDialog::getText(this, tr("Add channel"),
    tr("Coordinate (x1, x2, ...):"), QLineEdit::Normal, "x4", &ok).trimmed().toLower();
  if (!ok || name.isEmpty())
    return;
  auto found = std::find_if(spec_.coordinates.begin(), spec_.coordinates.end(),
    [&](const auto& c) { return c.name == name.toStdString(); });
  if (found == spec_.coordinates.end())
    found = spec_.coordinates.insert(spec_.coordinates.end(), { name.toStdString(), {} });
  found->channels.push_back({});
  rebuildTable();
  emit specChanged();
}

void MappingEditor::removeChannel()
{
  int index = 0;
  const int row = table_->currentRow();
  for (auto c = spec_.coordinates.begin(); c != spec_.coordinates.end(); ++c)
    for (auto channel = c->channels.begin(); channel != c->channels.end(); ++channel)
      if (index++ == row)
      {
        c->channels.erase(channel);
        if (c->channels.empty())
          spec_.coordinates.erase(c);
        rebuildTable();
        emit specChanged();
        return;
      }
}

bool MappingEditor::loadFile(const QString& path)
{
  QFile in(path);
  errors_.clear();
  if (!in.open(QIODevice::ReadOnly))
  {
    errors_ << tr("%1: %2").arg(path, in.errorString());
    rebuildTable();
    return false;
  }
  const frep::mapping::LoadResult loaded = frep::mapping::load_mapping(in.readAll().toStdString());
  for (const auto& error : loaded.errors)
    errors_ << QString::fromStdString(error.place + ": " + error.message);
  if (!loaded.ok())
  {
    rebuildTable();
    return false;
  }
  setSpec(loaded.spec);
  return true;
}

bool MappingEditor::saveFile(const QString& path)
{
  const QByteArray text = QByteArray::fromStdString(frep::mapping::save_mapping(spec_));
  if (const QString problem = saveDurably(path, text); !problem.isEmpty())
  {
    status_->setText(tr("Cannot save %1: %2").arg(path, problem));
    return false;
  }
  status_->setText(tr("Saved %1").arg(path));
  return true;
}

} // namespace frepstudio
