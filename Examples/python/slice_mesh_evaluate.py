"""FRepKit from Python: a 5-D HyperFun model -> a 3-D cross-section -> a watertight mesh, and F
of the cross-section at many points through numpy. Run with Debian's python3 or pvpython, the
package frepkit on PYTHONPATH (build/lib/python3/dist-packages in the build tree):

  PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \
      Examples/python/slice_mesh_evaluate.py Examples/homotopy5d.hf slice.vtp

(ctest -R Python.Example runs it.)"""

import sys

import numpy

import frepkit
from frepkit import vtkHyperFunSource, vtkFRepSlice, vtkFRepPolygonizer, vtkFRepEvaluator
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkFiltersCore import vtkFeatureEdges
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
from vtkmodules.util import numpy_support

model = sys.argv[1] if len(sys.argv) > 1 else "Examples/homotopy5d.hf"
output = sys.argv[2] if len(sys.argv) > 2 else "slice.vtp"

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

# The same with the VTK class and arrays directly (what frepkit.evaluate does).
evaluator = vtkFRepEvaluator()
evaluator.SetObject(section)
values = vtkDoubleArray()
evaluator.Evaluate(numpy_support.numpy_to_vtk(points, deep=1), values)
same = numpy.array_equal(numpy_support.vtk_to_numpy(values), f)
print("vtkFRepEvaluator gives the same values: %s" % ("bit-equal" if same else "DIFFERENT"))
sys.exit(0 if open_edges == 0 and same else 1)
