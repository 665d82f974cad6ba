"""Startup script for ParaView's GUI (paraview --script=...): loads the FRepKit plug-in (path in
$FREPKIT_PARAVIEW_PLUGIN), opens the 4-D model morph4d.hf, cuts it at x4 = 0.75 with FRep Slice,
meshes it and selects the slice so that the Properties panel shows its X4 slider. Used by
ParaViewPlugin/Testing/gui_screenshot.sh for Documentation/paraview-plugin-gui.png."""

import os
from paraview.simple import *  # noqa: F401,F403

LoadPlugin(os.environ["FREPKIT_PARAVIEW_PLUGIN"], remote=False, ns=globals())
source_dir = os.environ["FREPKIT_SOURCE_DIR"]
reader = HyperFunReader(registrationName="morph4d.hf",
                        FileName=os.path.join(source_dir, "Examples", "mapping", "morph4d.hf"))
reader.CoordinateRanges = [-2.4, 2.4, -2.4, 2.4, -2.4, 2.4, 0.0, 1.0]
cut = FRepSlice(registrationName="FRepSlice1", Input=reader)
cut.X4 = 0.75
mesh = FRepPolygonizer(registrationName="FRepPolygonizer1", Input=cut,
                       SampleDimensions=[96, 96, 96])
view = GetActiveViewOrCreate("RenderView")
shown = Show(mesh, view)
shown.DiffuseColor = [0.85, 0.62, 0.38]
shown.ColorArrayName = ["POINTS", ""]
default_mesh = Show(OutputPort(reader, 1), view)
default_mesh.Opacity = 0.25
view.CameraPosition = [0.0, -8.5, 5.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
SetActiveSource(cut)
Render(view)
