"""One render of the plug-in's pipeline compared with a baseline image: the 4-D model
Examples/mapping/morph4d.hf cut at x4 = 0.85 by FRep Slice, meshed by FRep Polygonizer, shown in
a render view (SaveScreenshot), next to the reader's default mesh. Run under xvfb-run -a
(the packaged ParaView renders through X only). With --write-baseline the image becomes the
baseline (the test then fails, so that a new baseline is never taken silently)."""

import os
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import Checker, arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

plugin, source_dir, rest = arguments()
LoadPlugin(plugin, remote=False, ns=globals())
t = Checker("TestPluginRender")
baseline = os.path.join(source_dir, "ParaViewPlugin", "Testing", "Data", "Baseline",
                        "TestPluginRender.png")

reader = HyperFunReader(FileName=os.path.join(source_dir, "Examples", "mapping", "morph4d.hf"))
reader.CoordinateRanges = [-2.4, 2.4, -2.4, 2.4, -2.4, 2.4, 0.0, 1.0]
reader.GeometryResolution = 48
fslice = FRepSlice(Input=reader)
fslice.X4 = 0.85  # the default mesh (left) is x4 = 0.5, the midpoint
poly = FRepPolygonizer(Input=fslice, SampleDimensions=[64, 64, 64])
moved = Transform(Input=poly)
moved.Transform.Translate = [5.5, 0.0, 0.0]

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [480, 300]
view.OrientationAxesVisibility = 0
view.Background = [1.0, 1.0, 1.0]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
default_mesh = Show(OutputPort(reader, 1), view)
default_mesh.DiffuseColor = [0.55, 0.6, 0.75]
default_mesh.AmbientColor = [0.55, 0.6, 0.75]
default_mesh.ColorArrayName = ["POINTS", ""]
section = Show(moved, view)
section.DiffuseColor = [0.85, 0.62, 0.38]
section.AmbientColor = [0.85, 0.62, 0.38]
section.ColorArrayName = ["POINTS", ""]
view.CameraPosition = [2.75, -11.0, 5.5]
view.CameraFocalPoint = [2.75, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelProjection = 0
Render(view)

t.check(poly.GetDataInformation().GetNumberOfCells() > 1000, "the section is meshed")
t.check(reader.GetDataInformation(1).GetNumberOfCells() > 1000, "the default mesh is there")

image = os.path.join(tempfile.mkdtemp(prefix="frepkit-render-"), "TestPluginRender.png")
SaveScreenshot(image, view, ImageResolution=[480, 300])
t.check(os.path.exists(image), "screenshot written")

if "--write-baseline" in rest or not os.path.exists(baseline):
    import shutil
    os.makedirs(os.path.dirname(baseline), exist_ok=True)
    shutil.copyfile(image, baseline)
    t.check(False, "baseline written to %s: check it and run again" % baseline)
else:
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference
    readers = []
    for name in (image, baseline):
        r = vtkPNGReader()
        r.SetFileName(name)
        r.Update()
        readers.append(r)
    same_size = (readers[0].GetOutput().GetDimensions() == readers[1].GetOutput().GetDimensions())
    t.check(same_size, "image size %s, baseline %s" % (readers[0].GetOutput().GetDimensions(),
                                                       readers[1].GetOutput().GetDimensions()))
    if same_size:
        diff = vtkImageDifference()
        diff.SetInputConnection(readers[0].GetOutputPort())
        diff.SetImageConnection(readers[1].GetOutputPort())
        diff.Update()
        error = diff.GetThresholdedError()
        sys.__stderr__.write("image difference (thresholded): %g\n" % error)
        t.check(error <= 0.15, "image differs from the baseline: thresholded error %g > 0.15 "
                "(image kept at %s)" % (error, image))
    # A picture that would pass for anything is no test: an empty view must differ.
    Hide(moved, view)
    Hide(OutputPort(reader, 1), view)
    empty = image.replace(".png", "-empty.png")
    SaveScreenshot(empty, view, ImageResolution=[480, 300])
    r = vtkPNGReader()
    r.SetFileName(empty)
    diff = vtkImageDifference()
    diff.SetInputConnection(r.GetOutputPort())
    diff.SetImageConnection(readers[1].GetOutputPort())
    diff.Update()
    t.check(diff.GetThresholdedError() > 1.0, "an empty view differs from the baseline (%g)"
            % diff.GetThresholdedError())

# Exit only on failure: sys.exit() in pvpython with a render window open ends in an X error
# (GLXBadContext) and status 1 even after a success; the normal end finalises cleanly.
if t.report():
    sys.exit(1)
