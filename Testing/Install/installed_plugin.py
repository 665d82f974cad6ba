"""Loads an installed FRepKit ParaView plug-in the way a user does and runs a pipeline with it:
HyperFunReader (a 5-D model) -> FRepSlice -> FRepPolygonizer, a triangle count. No display.
  pvpython installed_plugin.py MODE MODEL.hf
MODE says how the plug-in is found:
  search-path  already loaded by ParaView at start-up from PV_PLUGIN_PATH=<prefix>/lib/paraview-5.11/plugins/FRepKit
  config       auto-loaded at start-up from PV_PLUGIN_CONFIG_FILE=<...>/frepkit.plugins.xml (auto_load="1")
  name         LoadDistributedPlugin("FRepKit"): by name from ParaView's own plug-in folder
               (/usr/lib/x86_64-linux-gnu/paraview-5.11/plugins/FRepKit, where the .deb puts it)"""

import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

mode, model = sys.argv[1], sys.argv[2]
manager = servermanager.vtkSMProxyManager.GetProxyManager()
tracker = servermanager.vtkPVPluginTracker.GetInstance()


def loaded_plugin():
    for i in range(tracker.GetNumberOfPlugins()):
        if tracker.GetPluginName(i) == "FRepKit" and tracker.GetPluginLoaded(i):
            return tracker.GetPluginFileName(i)
    return None


if mode == "name":
    LoadDistributedPlugin("FRepKit", remote=False, ns=globals())
elif loaded_plugin() is None:
    print("FAILED: FRepKit was not loaded at start-up (mode %s)" % mode)
    sys.exit(1)
else:
    # Loaded before paraview.simple made its functions: make them for the plug-in's proxies.
    from paraview import simple
    simple._add_functions(globals())
print("plug-in loaded from %s" % loaded_plugin())

source = HyperFunReader(FileName=model)  # noqa: F405
source.CoordinateRanges = [-4, 4, -4, 4, -4, 4, 0, 1, 0, 1]
fslice = FRepSlice(Input=source)  # noqa: F405
fslice.X4 = 0.5
fslice.X5 = 0.25
poly = FRepPolygonizer(Input=fslice, SampleDimensions=[48, 48, 48])  # noqa: F405
poly.UpdatePipeline()
triangles = poly.GetDataInformation().GetNumberOfCells()
print("FRepPolygonizer: %d triangles" % triangles)
sys.exit(0 if triangles > 0 else 1)
