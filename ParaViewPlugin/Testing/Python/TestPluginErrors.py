"""Bad input on the GUI's paths: a .hf file with a syntax error opened with the HyperFun Reader
gives an error message naming file:line:col in the output window (VTK's output window, which
ParaView's Output Messages window shows in red), empty outputs and no crash downstream; after the
file is fixed, File > Reload Files (ReloadFiles) makes the same pipeline work again. The same for
a bad mapping file and for the text source. pvpython, no rendering."""

import os
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import CapturedMessages, Checker, arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

plugin, source_dir, _ = arguments()
LoadPlugin(plugin, remote=False, ns=globals())
t = Checker("TestPluginErrors")
messages = CapturedMessages()

directory = tempfile.mkdtemp(prefix="frepkit-plugin-")
path = os.path.join(directory, "broken.hf")
good = ("my_model(x[4], a[1])\n{\n"
        "  my_model = 4 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2;\n}\n")
# Line 3, column 15: an operator where an operand is expected.
bad = ("my_model(x[4], a[1])\n{\n"
       "  my_model = 4 - * x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2;\n}\n")
with open(path, "w") as f:
    f.write(bad)

reader = OpenDataFile(path)
t.check(reader is not None and reader.GetXMLName() == "HyperFunReader",
        "OpenDataFile picks the HyperFun Reader for .hf")
fslice = FRepSlice(Input=reader)
poly = FRepPolygonizer(Input=fslice, SampleDimensions=[32, 32, 32])
poly.UpdatePipeline()
text = messages.text()
sys.__stderr__.write("captured:\n" + text + "\n")
t.check("ERROR" in text or "Error" in text, "an error was reported")
t.check(("%s:3:18:" % path) in text, "the message names %s:3:18 (the '*')" % path)
t.check("error:" in text, "file:line:col: error: message format")
t.check(poly.GetDataInformation().GetNumberOfCells() == 0, "empty mesh downstream")
t.check(reader.GetDataInformation(1).GetNumberOfCells() == 0, "empty default mesh")
t.check(text.count("%s:3:" % path) == 1, "reported once, not cascaded downstream")

# Fix the file; Reload Files (the GUI's File > Reload Files) and the pipeline works again.
with open(path, "w") as f:
    f.write(good)
messages.clear()
ReloadFiles(reader)
poly.UpdatePipeline()
t.check(messages.text().count("ERROR") == 0, "no error after the fix: %r" % messages.text())
t.check(poly.GetDataInformation().GetNumberOfCells() > 100, "the slice is meshed again")
b = poly.GetDataInformation().GetBounds()
t.check(abs(b[1] - 2.0) < 0.3, "the ball of radius 2 (x4 = 0): %s" % (b,))
t.check(reader.GetDataInformation(1).GetNumberOfCells() > 100, "default mesh back")

# Broken again and the Reload button (the reader's own Reload property).
with open(path, "w") as f:
    f.write(bad)
messages.clear()
reader.Reload()
poly.UpdatePipeline()
t.check(("%s:3:" % path) in messages.text(), "Reload re-reads: the error again")
with open(path, "w") as f:
    f.write(good)
reader.Reload()
poly.UpdatePipeline()
t.check(poly.GetDataInformation().GetNumberOfCells() > 100, "and works after the fix")

# The text source: <string>:line:col.
messages.clear()
src = HyperFunSource(ModelText="my_model(x[3], a[1])\n{\n  my_model = 1 +;\n}\n")
src.UpdatePipeline()
t.check("<string>:3:" in messages.text(), "text source names <string>:3:col: %r" % messages.text())
src.ModelText = "my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }"
src.UpdatePipeline()
t.check(src.GetDataInformation(1).GetNumberOfCells() > 100, "text source works after the fix")

# An unknown object: the error lists the objects.
messages.clear()
src.ObjectName = "nosuch"
src.UpdatePipeline()
t.check("nosuch" in messages.text() and "my_model" in messages.text(),
        "unknown object: the objects are listed")
src.ObjectName = "my_model"

# A bad mapping file: its place in the JSON is named; fixed, the mapper works.
mapping = os.path.join(directory, "bad.json")
with open(mapping, "w") as f:
    f.write('{ "coordinates": { "x1": [{ "type": "world", "axis": "x", "range": [1, -1] }] } }')
messages.clear()
mapper = MultimediaMapper(Input=reader, MappingFileName=mapping)
mapper.UpdatePipeline()
t.check("coordinates.x1[0]" in messages.text(), "mapping error names its place: %r" % messages.text())
t.check(mapper.GetDataInformation().GetNumberOfCells() == 0, "empty mapper output")
with open(mapping, "w") as f:
    f.write(open(os.path.join(source_dir, "Examples", "mapping", "spreadsheet-1d.json")).read())
mapper.Resolution = 24  # a new request: the mapper reads the (fixed) file again
mapper.UpdatePipeline()
t.check(mapper.GetDataInformation().GetNumberOfCells() > 100, "mapper works after the fix")

messages.restore()
# Exit only on failure: sys.exit() in pvpython with a render window open ends in an X error
# (GLXBadContext) and status 1 even after a success; the normal end finalises cleanly.
if t.report():
    sys.exit(1)
