#include "UserInputs.h"

#include <QFileInfo>

namespace frepstudio
{

UserInputs absoluteUserInputs(const UserInputs& inputs)
{
  UserInputs out = inputs;
  out.libraries.clear();
  out.shapes.clear();
  for (const QString& path : inputs.libraries)
    out.libraries << QFileInfo(path).absoluteFilePath();
  for (const QString& spec : inputs.shapes)
  {
    // name=FILE[:ISO]: only FILE is made absolute; a volume's ":ISO" stays a suffix of it.
    const int equals = spec.indexOf('=');
    out.shapes << (equals <= 0 ? spec
                               : spec.left(equals + 1) +
                     QFileInfo(spec.mid(equals + 1)).absoluteFilePath());
  }
  return out;
}

} // namespace frepstudio
