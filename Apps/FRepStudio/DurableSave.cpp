#include "DurableSave.h"

#include "Durable/pending_file.h"

#include <QFile>
#include <QFileInfo>
#include <QImageWriter>

#include <functional>

namespace frepstudio
{
namespace
{

// The one temporary of the project (frep::durable::PendingFile: TARGET.tmp-PID-N beside the
// target, removed unless put in place), written by `write`, then put in place durably.
QString putInPlace(const QString& path, const std::function<QString(const QString&)>& write)
{
  frep::durable::PendingFile pending(QFile::encodeName(path).toStdString());
  if (!pending.error().empty())
    return QString::fromStdString(pending.error());
  if (QString problem = write(QFile::decodeName(pending.temporary().c_str())); !problem.isEmpty())
    return problem;
  return QString::fromStdString(pending.commit());
}

} // namespace

QString saveDurably(const QString& path, const QByteArray& bytes)
{
  return putInPlace(path,
    [&bytes](const QString& temporary) -> QString
    {
      QFile file(temporary);
      if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return file.errorString();
      if (file.write(bytes) != bytes.size() || !file.flush())
        return file.errorString();
      file.close();
      return file.error() == QFileDevice::NoError ? QString() : file.errorString();
    });
}

QString saveImageDurably(const QString& path, const QImage& image)
{
  return putInPlace(path,
    [&](const QString& temporary) -> QString
    {
      // The temporary's name has no image suffix: the format comes from the target's.
      QImageWriter writer(temporary, QFileInfo(path).suffix().toLower().toLatin1());
      return writer.write(image) ? QString() : writer.errorString();
    });
}

} // namespace frepstudio
