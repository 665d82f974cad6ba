#include "DurableSave.h"

#include "Media/durable_file.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QImageWriter>

#include <functional>

namespace frepstudio
{
namespace
{

// The temporary lies in the target's directory (the rename must not cross file systems) and is
// named as frepkit's (NAME.tmp-PID).
QString temporaryFor(const QString& path)
{
  return path + QStringLiteral(".tmp-%1").arg(QCoreApplication::applicationPid());
}

QString putInPlace(const QString& path, const std::function<QString(const QString&)>& write)
{
  const QString temporary = temporaryFor(path);
  if (QString problem = write(temporary); !problem.isEmpty())
  {
    QFile::remove(temporary);
    return problem;
  }
  const std::string problem = frep::media::durable_rename(
    QFile::encodeName(temporary).toStdString(), QFile::encodeName(path).toStdString());
  if (!problem.empty())
  {
    QFile::remove(temporary);
    return QString::fromStdString(problem);
  }
  return {};
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
