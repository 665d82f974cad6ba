"""Run by the ParaView GUI (paraview --script=gui_autoload.py --exit, under Xvfb): writes
"FRepKit loaded" and the plug-in's file, or "FRepKit not loaded", to $FREPKIT_RESULT. Checks
that the GUI auto-loaded the plug-in from ParaView's own plug-in folder (paraview.conf ->
frepkit.plugins.xml, auto_load="1")."""

import os

from paraview import servermanager

tracker = servermanager.vtkPVPluginTracker.GetInstance()
result = "FRepKit not loaded"
for i in range(tracker.GetNumberOfPlugins()):
    if tracker.GetPluginName(i) == "FRepKit" and tracker.GetPluginLoaded(i):
        result = "FRepKit loaded from %s" % tracker.GetPluginFileName(i)
with open(os.environ["FREPKIT_RESULT"], "w") as out:
    out.write(result + "\n")
