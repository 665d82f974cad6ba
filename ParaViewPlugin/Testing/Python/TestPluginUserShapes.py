"""Issue 17 in ParaView. The HyperFun Reader's UserLibraries property: a .hf model that calls the
example user library's ring(x, R, r) (Examples/user-library) reads and meshes once the library is
listed; a library that does not exist is an error naming it, with empty outputs and no crash.
Mesh To FRep and Volume To FRep: a closed sphere and a sampled volume as FRep objects meshed by
FRep Polygonizer; an open plane refused naming its open edges. pvpython, no rendering."""

import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import CapturedMessages, Checker, arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403

plugin, source_dir, rest = arguments()
library = rest[0]
LoadPlugin(plugin, remote=False, ns=globals())
t = Checker("TestPluginUserShapes")
messages = CapturedMessages()

model = os.path.join(source_dir, "Examples", "user-library", "ring.hf")
# The library first: a reader given its file at once parses it before the library is listed.
reader = HyperFunReader(UserLibraries=[library])
messages.clear()
reader.FileName = model
reader.UpdatePipeline()
t.check(messages.text().count("ERROR") == 0, "no error with the library: %r" % messages.text())
cells = reader.GetDataInformation(1).GetNumberOfCells()
t.check(cells > 100, "the ring and ball are meshed (%d cells)" % cells)
b = reader.GetDataInformation(1).GetBounds()
t.check(abs(b[1] - 3.3) < 0.35, "x extends to R + r = 3.3: %s" % (b,))

messages.clear()
missing = HyperFunReader(UserLibraries=["/nonexistent/libshapes.so"])
messages.clear()
missing.FileName = model
missing.UpdatePipeline()
text = messages.text()
t.check("user library /nonexistent/libshapes.so: no such file" in text,
        "the missing library is named: %r" % text)
t.check(missing.GetDataInformation(1).GetNumberOfCells() == 0, "empty output")
# Mesh To FRep and Volume To FRep: a ParaView sphere (closed) and a sampled volume as 3-D FRep
# objects, meshed by FRep Polygonizer; an open plane is refused naming its open edges.
messages.clear()
sphere = Sphere(Radius=2.0, ThetaResolution=32, PhiResolution=32)
mesh = MeshToFRep(Input=sphere, FunctionName="ball")
poly = FRepPolygonizer(Input=mesh, SampleDimensions=[40, 40, 40])
poly.UpdatePipeline()
t.check(messages.text().count("ERROR") == 0, "no error from Mesh To FRep: %r" % messages.text())
b = poly.GetDataInformation().GetBounds()
t.check(poly.GetDataInformation().GetNumberOfCells() > 100 and abs(b[1] - 2.0) < 0.15,
        "the sphere of radius 2 meshed again: %s" % (b,))
plane = Plane(XResolution=2, YResolution=2)
openmesh = MeshToFRep(Input=plane)
messages.clear()
openmesh.UpdatePipeline()
t.check("8 open edges" in messages.text(), "the open plane is refused: %r" % messages.text())
wavelet = Wavelet()
volume = VolumeToFRep(Input=wavelet, IsoValue=200.0)
vpoly = FRepPolygonizer(Input=volume, SampleDimensions=[32, 32, 32])
messages.clear()
vpoly.UpdatePipeline()
t.check(messages.text().count("ERROR") == 0, "no error from Volume To FRep: %r" % messages.text())
t.check(vpoly.GetDataInformation().GetNumberOfCells() > 100, "the wavelet's 200 surface meshed")

if t.report():
    sys.exit(1)
