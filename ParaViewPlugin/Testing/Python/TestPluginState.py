"""The example state file Examples/paraview/morph4d-slice.pvsm loads with the plug-in (its
file names relocated with data_directory, as the GUI's "Search files under specified
directory" does) and rebuilds the pipeline: FRep Slice at X4 = 0.75, a meshed torus-like
section. pvpython, no rendering."""

import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import Checker, arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

plugin, source_dir, _ = arguments()
LoadPlugin(plugin, remote=False, ns=globals())
t = Checker("TestPluginState")
examples = os.path.join(source_dir, "Examples")
LoadState(os.path.join(examples, "paraview", "morph4d-slice.pvsm"),
          data_directory=os.path.join(examples, "mapping"))
reader = FindSource("morph4d.hf")
cut = FindSource("FRepSlice1")
mesh = FindSource("FRepPolygonizer1")
t.check(reader is not None and cut is not None and mesh is not None, "the three proxies")
if mesh is not None:
    t.check(os.path.samefile(reader.FileName, os.path.join(examples, "mapping", "morph4d.hf")),
            "file found under the data directory: %s" % reader.FileName)
    t.check(cut.X4 == 0.75, "X4 = %s" % cut.X4)
    mesh.UpdatePipeline()
    info = mesh.GetDataInformation()
    t.check(info.GetNumberOfCells() > 1000, "section meshed: %d" % info.GetNumberOfCells())
    b = info.GetBounds()
    t.check(abs(b[5] - 0.71) < 0.05, "x4 = 0.75 section half height ~0.71: %s" % (b,))
if t.report():
    sys.exit(1)
