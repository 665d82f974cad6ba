"""A 4-D model cut by a slider: Examples/mapping/morph4d.hf (a ball that becomes a torus as x4
runs from 0 to 1) opened with the HyperFun Reader, FRep Slice moving x4 through 0, 0.25, .. 1,
FRep Polygonizer meshing each 3-D cross-section. Prints the triangles and bounds of each and,
with --output, saves one picture per value (x4_0.00.png, ...), next to the reader's default
mesh (x4 at its interval's midpoint).

  pvpython Examples/paraview/slice_4d.py [--output DIR]"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from frepkit_example import arguments, example_file
from paraview.simple import *  # noqa: F401,F403

args = arguments(__doc__)
LoadPlugin(args.plugin, remote=False, ns=globals())

reader = HyperFunReader(FileName=example_file("mapping", "morph4d.hf"))
# Intervals: x1..x3 the box, x4 the homotopy parameter (the slider's range).
reader.CoordinateRanges = [-2.4, 2.4, -2.4, 2.4, -2.4, 2.4, 0.0, 1.0]
cut = FRepSlice(Input=reader)
mesh = FRepPolygonizer(Input=cut, SampleDimensions=[args.resolution] * 3)

if args.output:
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [800, 500]
    view.OrientationAxesVisibility = 0
    shown = Show(mesh, view)
    shown.DiffuseColor = [0.85, 0.62, 0.38]
    shown.ColorArrayName = ["POINTS", ""]
    view.CameraPosition = [0.0, -9.0, 5.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]

print("the X4 slider spans %s" % list(cut.GetProperty("X4Range")))
for x4 in (0.0, 0.25, 0.5, 0.75, 1.0):
    cut.X4 = x4
    mesh.UpdatePipeline()
    info = mesh.GetDataInformation()
    print("x4 = %.2f: %6d triangles, bounds %s" % (x4, info.GetNumberOfCells(),
          ", ".join("%.2f" % b for b in info.GetBounds())))
    if args.output:
        Render(view)
        SaveScreenshot("%s/x4_%.2f.png" % (args.output, x4), view)
