#pragma once
// Where FRepStudio finds the example models and mappings: <bin>/../share/frepkit/examples,
// relative to the running executable, in an installation (<prefix>/bin/FRepStudio) and in the
// build tree alike (build/share/frepkit/examples is a link to the source tree's Examples/).
// No path of the build machine is compiled in.
#include <QString>

namespace frepstudio
{
QString examplesDirectory();
}
