"""Writes Examples/paraview/morph4d-slice.pvsm, the ParaView state of the 4-D slice example:
HyperFun Reader (morph4d.hf, x4 in [0, 1]) -> FRep Slice (X4 = 0.75) -> FRep Polygonizer,
shown with the reader's default mesh. Load it in the GUI (File > Load State, after loading the
plug-in; choose "Search files under specified directory" = Examples/mapping) or with
  LoadPlugin(...); LoadState("morph4d-slice.pvsm", data_directory="Examples/mapping")
  pvpython Examples/paraview/make_state.py [--output DIR]"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import os

from frepkit_example import HERE, arguments, example_file
from paraview.simple import *  # noqa: F401,F403

args = arguments(__doc__)
LoadPlugin(args.plugin, remote=False, ns=globals())
reader = HyperFunReader(registrationName="morph4d.hf", FileName=example_file("mapping", "morph4d.hf"))
reader.CoordinateRanges = [-2.4, 2.4, -2.4, 2.4, -2.4, 2.4, 0.0, 1.0]
cut = FRepSlice(registrationName="FRepSlice1", Input=reader)
cut.X4 = 0.75
mesh = FRepPolygonizer(registrationName="FRepPolygonizer1", Input=cut, SampleDimensions=[96] * 3)
view = GetActiveViewOrCreate("RenderView")
shown = Show(mesh, view)
shown.DiffuseColor = [0.85, 0.62, 0.38]
shown.ColorArrayName = ["POINTS", ""]
view.CameraPosition = [0.0, -8.5, 5.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
state = os.path.join(args.output or HERE, "morph4d-slice.pvsm")
SaveState(state)
# A state names its files by absolute path; the committed one must not name this machine's
# checkout (it is installed, and LoadState's data_directory relocates by file name anyway).
source_root = os.path.dirname(os.path.dirname(os.path.abspath(HERE)))
with open(state, encoding="utf-8") as handle:
    text = handle.read()
with open(state, "w", encoding="utf-8") as handle:
    handle.write(text.replace(source_root + os.sep, "/frepkit-source/"))
print("state written to %s" % state)
