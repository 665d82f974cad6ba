// FRepStudio's saves (the model, the mapping, screenshots, the export's inputs) put a file in
// place as frepkit does: written to the project's one temporary beside the target
// (frep::durable::PendingFile), then put in place by a durable rename (fsync of the file,
// rename, fsync of the directory). QSaveFile renames but does not sync the directory, so a
// crash right after "Saved" could lose the name.
#pragma once

#include <QByteArray>
#include <QImage>
#include <QString>

namespace frepstudio
{

/// Writes `bytes` to `path` durably. Empty on success, else what failed (the old file, if any,
/// is then untouched and no temporary is left).
QString saveDurably(const QString& path, const QByteArray& bytes);

/// The same for a picture, in the format of `path`'s suffix (PNG for "shot.png").
QString saveImageDurably(const QString& path, const QImage& image);

} // namespace frepstudio
