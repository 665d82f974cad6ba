#include "ExamplesDirectory.h"

#include <QCoreApplication>
#include <QDir>

namespace frepstudio
{
QString examplesDirectory()
{
  return QDir::cleanPath(
    QCoreApplication::applicationDirPath() + QStringLiteral("/../share/frepkit/examples"));
}
}
