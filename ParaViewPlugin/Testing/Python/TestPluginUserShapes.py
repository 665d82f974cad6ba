"""Issue 17 in ParaView. The HyperFun Reader's UserLibraries property: a .hf model that calls the
example user library's ring(x, R, r) (Examples/user-library) reads and meshes once the library is
listed; a library that does not exist is an error naming it, with empty outputs and no crash.
Mesh To FRep and Volume To FRep: a closed sphere and a sampled volume as FRep objects meshed by
FRep Polygonizer; an open plane refused naming its open edges. Implicit Function To FRep: ParaView's
Sphere implicit function (radius 2, moved) meshed, and its Box (moved and sized: its Transform). pvpython, no rendering."""

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

# Implicit Function To FRep: ParaView's own implicit-function proxies as FRep objects.
messages.clear()
ball = ImplicitFunctionToFRep(ImplicitFunction="Sphere", FunctionName="ball",
                              Bounds=[-4, 4, -4, 4, -4, 4])
ball.ImplicitFunction.Center = [1.0, 0.0, 0.0]
ball.ImplicitFunction.Radius = 2.0
bpoly = FRepPolygonizer(Input=ball, SampleDimensions=[48, 48, 48])
bpoly.UpdatePipeline()
t.check(messages.text().count("ERROR") == 0, "no error from Implicit Function To FRep: %r"
        % messages.text())
b = bpoly.GetDataInformation().GetBounds()
t.check(bpoly.GetDataInformation().GetNumberOfCells() > 100 and abs(b[0] + 1.0) < 0.1
        and abs(b[1] - 3.0) < 0.1 and abs(b[3] - 2.0) < 0.1,
        "the sphere of radius 2 at (1, 0, 0) meshed: %s" % (b,))
box = ImplicitFunctionToFRep(ImplicitFunction="Box", Bounds=[-2, 2, -2, 2, -2, 2])
box.ImplicitFunction.Position = [0.5, 0.25, 0.0]
box.ImplicitFunction.Length = [1.0, 1.5, 0.5]
xpoly = FRepPolygonizer(Input=box, SampleDimensions=[41, 41, 41])
xpoly.UpdatePipeline()
b = xpoly.GetDataInformation().GetBounds()
want = [0.5, 1.5, 0.25, 1.75, 0.0, 0.5]
t.check(xpoly.GetDataInformation().GetNumberOfCells() > 10 and all(abs(v - w) < 0.06
        for v, w in zip(b, want)), "the box [0.5, 1.5] x [0.25, 1.75] x [0, 0.5] meshed: %s" % (b,))

if t.report():
    sys.exit(1)
