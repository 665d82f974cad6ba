// The mapping editor: the channels of a multimedia mapping (Documentation/mapping-file.md), one
// row per channel: its coordinate, type (world, dynamic, spreadsheet, fixed, colour,
// transparency, transformation, audio, projected) and range. Files are read and written by the Mapping
// module's own load_mapping / save_mapping, so they are the same JSON files as `frepkit map`'s,
// and every field the editor does not show is kept as it was read.
#pragma once

#include "Mapping/mapping_json.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace frepstudio
{

class MappingEditor : public QWidget
{
  Q_OBJECT
public:
  explicit MappingEditor(QWidget* parent = nullptr);

  /// Reads a mapping file; false (and the errors listed, each with its JSON place) when it
  /// cannot be read or is not a valid mapping.
  bool loadFile(const QString& path);
  /// Writes the mapping (temporary file, then rename); false on error.
  bool saveFile(const QString& path);
  /// Replaces the mapping.
  void setSpec(const frep::mapping::Spec& spec);
  const frep::mapping::Spec& spec() const { return spec_; }
  /// The messages of the last load ("place: message").
  QStringList errors() const { return errors_; }
  QTableWidget* table() const { return table_; }

  /// The type's name as the JSON file spells it ("world", "spreadsheet", ...).
  static QString typeName(frep::mapping::Channel::Type type);

signals:
  void specChanged();

private:
  void rebuildTable();
  void addChannel();
  void removeChannel();
  /// The channel of table row `row`.
  frep::mapping::Channel* channelAt(int row);

  frep::mapping::Spec spec_;
  QStringList errors_;
  QTableWidget* table_ = nullptr;
  QLabel* status_ = nullptr;
};

} // namespace frepstudio
