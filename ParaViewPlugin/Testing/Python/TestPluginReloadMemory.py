"""ParaView's session memory stays flat while a .hf file is edited and reloaded (issue 18, item
6): a pipeline reader -> FRepSlice -> FRepPolygonizer is updated after each of 100 changes of
the file (the ball's radius and an extra term, as an editing user would) and File > Reload Files.
The resident set size after the 100th reload may exceed the one after the 20th (the warm-up:
caches, the allocator's pools) by at most LIMIT_MB. Every reload must also mesh the new ball
(its bounds follow the radius), so the check cannot pass on a pipeline that stopped updating.
pvpython, no rendering."""

import os
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import Checker, arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

RELOADS = 100
WARM_UP = 20
LIMIT_MB = 4.0  # measured +0.1 MB; a kept 48^3 mesh per reload (~65 KB) gives +5.2 MB


def resident_mb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024.0
    return float("nan")


plugin, source_dir, _ = arguments()
LoadPlugin(plugin, remote=False, ns=globals())
t = Checker("TestPluginReloadMemory")
directory = tempfile.mkdtemp(prefix="frepkit-reload-")
path = os.path.join(directory, "edited.hf")


def write_model(i):
    radius = 1.5 + 0.01 * (i % 50)
    with open(path, "w") as f:
        f.write("my_model(x[4], a[1])\n{\n  -- edit %d\n"
                "  my_model = %.3f^2 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2 + 0 * %d;\n}\n"
                % (i, radius, i))
    return radius


write_model(0)
reader = OpenDataFile(path)
fslice = FRepSlice(Input=reader)
poly = FRepPolygonizer(Input=fslice, SampleDimensions=[48, 48, 48])
poly.UpdatePipeline()
samples = {}
wrong = 0
for i in range(1, RELOADS + 1):
    radius = write_model(i)
    ReloadFiles(reader)
    poly.UpdatePipeline()
    bounds = poly.GetDataInformation().GetBounds()
    if abs(bounds[1] - radius) > 0.1:
        wrong += 1
    if i in (WARM_UP, RELOADS):
        samples[i] = resident_mb()
t.check(wrong == 0, "every reload meshes the edited ball (%d did not)" % wrong)
growth = samples[RELOADS] - samples[WARM_UP]
sys.__stderr__.write("resident set: %.1f MB after %d reloads, %.1f MB after %d: %+.1f MB\n"
                     % (samples[WARM_UP], WARM_UP, samples[RELOADS], RELOADS, growth))
t.check(growth <= LIMIT_MB, "memory flat over %d reloads: %+.1f MB (limit %.0f MB)"
        % (RELOADS - WARM_UP, growth, LIMIT_MB))
os.remove(path)
os.rmdir(directory)
sys.exit(t.report())
