"""The Homotopic Fun spreadsheet in ParaView: the 5-D object Meta5D (Examples/homotopic/
meta5d.hf; Cat, Robot, NiHon and Rob_let blended by x4 and x5) mapped by
Examples/paraview/meta5d-spreadsheet.json onto a 5 x 5 spreadsheet of 3-D cross-sections
(x4 along the columns, x5 down the rows, both 0, 0.25, .. 1), laid out on a grid with labels by
Spreadsheet Layout. Prints the cells and, with --output, saves spreadsheet.png.

  pvpython Examples/paraview/homotopic_spreadsheet.py [--output DIR] [--resolution 64]"""

import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from frepkit_example import arguments, example_file
from paraview.simple import *  # noqa: F401,F403

args = arguments(__doc__, resolution=64)
LoadPlugin(args.plugin, remote=False, ns=globals())

reader = HyperFunReader(FileName=example_file("homotopic", "meta5d.hf"), GenerateGeometry=0)
reader.CoordinateRanges = [-10, 10, -10, 10, -10, 10, 0, 1, 0, 1]
mapper = MultimediaMapper(Input=reader, Resolution=args.resolution,
                          MappingFileName=example_file("paraview", "meta5d-spreadsheet.json"))
layout = SpreadsheetLayout(Input=mapper, Spacing=0.1)
layout.UpdatePipeline()
cells = mapper.GetDataInformation().DataInformation.GetNumberOfDataSets()
print("%d spreadsheet cells, %d triangles laid out" % (cells, layout.GetDataInformation().GetNumberOfCells()))

if args.output:
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [1200, 1200]
    view.OrientationAxesVisibility = 0
    shown = Show(layout, view)
    ColorBy(shown, ("POINTS", "Colors"))
    shown.MapScalars = 0  # the mapping's own RGB colours
    view.CameraParallelProjection = 1
    b = layout.GetDataInformation().GetBounds()
    centre = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1] - 200.0, centre[2]]  # from -y, head-on
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(False)
    Render(view)
    SaveScreenshot(args.output + "/spreadsheet.png", view)
