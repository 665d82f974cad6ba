"""FRepKit from Python: a 5-D HyperFun model -> a 3-D cross-section -> a watertight mesh, and F
of the cross-section at many points through numpy, checked against two other routes (the C++
point evaluator one point per call, and the frepkit program's eval). Run with Debian's python3
or pvpython, the package frepkit on PYTHONPATH (build/lib/python3/dist-packages in the build
tree):

  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
      Examples/python/slice_mesh_evaluate.py Examples/homotopy5d.hf slice.vtp build/bin/frepkit

The third argument (the frepkit program) is optional: without it, frepkit on PATH, else that
check is left out. (ctest -R Python.Example runs it with all three.)"""

import shutil
import subprocess
import sys

import numpy

import frepkit
from frepkit import vtkHyperFunSource, vtkFRepSlice, vtkFRepPolygonizer, vtkFRepImplicitFunction
from vtkmodules.vtkFiltersCore import vtkFeatureEdges
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

model = sys.argv[1] if len(sys.argv) > 1 else "Examples/homotopy5d.hf"
output = sys.argv[2] if len(sys.argv) > 2 else "slice.vtp"
frepkit_program = sys.argv[3] if len(sys.argv) > 3 else shutil.which("frepkit")

# The VTK pipeline, as in C++ (Examples/cpp/slice_and_mesh_pipeline.cxx).
reader = vtkHyperFunSource()                  # .hf file -> n-D vtkFRepObject
reader.SetFileName(model)
for i in range(3):
    reader.SetCoordinateRange(i, -4, 4)       # x1..x3: the box to mesh
slice_ = vtkFRepSlice()                       # fix x4, x5 -> a 3-D object, a smaller tape
slice_.SetInputConnection(reader.GetOutputPort())
slice_.SetFixedValueByName("x4", 0.5)
slice_.SetFixedValueByName("x5", 0.25)
mesher = vtkFRepPolygonizer()                 # F = 0: watertight, outward, all cores
mesher.SetInputConnection(slice_.GetOutputPort())
mesher.SetSampleDimensions(96, 96, 96)
writer = vtkXMLPolyDataWriter()
writer.SetInputConnection(mesher.GetOutputPort())
writer.SetFileName(output)
frepkit.update(writer)                        # Update(), raising frepkit.FRepError on errors

mesh = mesher.GetOutput()
edges = vtkFeatureEdges()
edges.SetInputData(mesh)
edges.BoundaryEdgesOn()
edges.NonManifoldEdgesOn()
edges.FeatureEdgesOff()
edges.ManifoldEdgesOff()
edges.Update()
open_edges = edges.GetOutput().GetNumberOfCells()
print("x4 = 0.5, x5 = 0.25: %d triangles, %s (%d open edges), written to %s"
      % (mesh.GetNumberOfCells(), "watertight" if open_edges == 0 else "NOT watertight",
         open_edges, output))

# F at many points: numpy (N, 3) in, numpy (N,) out, the engine's batch evaluator.
section = slice_.GetOutput()
points = numpy.random.default_rng(1).uniform(-4, 4, size=(100000, 3))
points[0] = 0
f = frepkit.evaluate(section, points)
print("F at the origin %.17g; %d of %d random points inside" % (f[0], (f > 0).sum(), len(f)))



def same_bits(a, b):
    return a.shape == b.shape and numpy.array_equal(a.view(numpy.uint64), b.view(numpy.uint64))


# frepkit.evaluate runs the engine's batch evaluator (SIMD blocks, compiled kernels). Check its
# first 2000 values against routes that do not go through it: the C++ point evaluator, one point
# per call (vtkFRepImplicitFunction, which returns -F), and `frepkit eval` in another process on
# the 5-D model itself, with x4 = 0.5, x5 = 0.25 appended to every point.
n = 2000
implicit = vtkFRepImplicitFunction()
implicit.SetFRepObject(section)
by_point = numpy.array([-implicit.EvaluateFunction(*p) for p in points[:n]])
same = same_bits(by_point, f[:n])
print("point evaluator (vtkFRepImplicitFunction), %d points: %s"
      % (n, "bit-equal" if same else "DIFFERENT"))
if frepkit_program:
    full = numpy.hstack([points[:n], numpy.tile([0.5, 0.25], (n, 1))])
    text = "\n".join(" ".join("%.17g" % v for v in row) for row in full) + "\n"
    done = subprocess.run([frepkit_program, "eval", model], input=text, capture_output=True,
                          text=True)
    values = numpy.array([float(v) for v in done.stdout.split()]) if done.returncode == 0 else None
    same_eval = values is not None and same_bits(values, f[:n])
    print("frepkit eval (the 5-D model), %d points: %s"
          % (n, "bit-equal" if same_eval else "DIFFERENT (exit %d)" % done.returncode))
    same = same and same_eval
sys.exit(0 if open_edges == 0 and same else 1)
