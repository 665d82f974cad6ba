"""The Python package frepkit, run by /usr/bin/python3 and by pvpython (ctest
Python.Pipeline.python3 and Python.Pipeline.pvpython):

  TestPythonPipeline.py SOURCE_DIR FREPKIT_EXECUTABLE

- the import: every class the issue names, from the package in the build tree, on ParaView's
  vtkmodules (the same vtkObject class);
- a pipeline: vtkHyperFunSource (Examples/homotopy5d.hf) -> vtkFRepSlice (x4 = 0.5,
  x5 = 0.25) -> vtkFRepPolygonizer: triangles, every edge in exactly two triangles, bounds in
  the box;
- the evaluator with numpy arrays: F of the 5-D object and of its slice, bit-equal to
  `frepkit eval` and to vtkFRepImplicitFunction (the C++ point evaluator); s[] and run-time
  errors of a model with attributes;
- bad input: wrong shapes and types give a VTK error / a Python exception, never a crash; the
  diagnostics of bad HyperFun text reach a Python observer and frepkit.FRepError with
  file:line:col.
Exits 1 on any failed check."""

import os
import subprocess
import sys
import tempfile
import warnings

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402


source_dir, frepkit_exe = sys.argv[1], sys.argv[2]
model_file = os.path.join(source_dir, "Examples", "homotopy5d.hf")

# --- the import ---------------------------------------------------------------------------
import frepkit  # noqa: E402
from frepkit import (vtkHyperFunSource, vtkFRepSlice, vtkFRepPolygonizer, vtkFRepSampler,  # noqa: E402
                     vtkFRepBoolean, vtkHyperFunReader, vtkMultimediaMapping,
                     vtkMultimediaMapper, vtkSpreadsheetLayout, vtkFRepImplicitFunction,
                     vtkFRepEvaluator, vtkFRepObject)
from vtkmodules.vtkCommonCore import vtkObject, vtkDoubleArray, vtkIntArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImplicitFunction  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkFeatureEdges  # noqa: E402
from vtkmodules.util import numpy_support  # noqa: E402

print("python", sys.version.split()[0], "frepkit from", os.path.dirname(frepkit.__file__))
for cls in (vtkHyperFunSource, vtkFRepSlice, vtkFRepPolygonizer, vtkFRepSampler, vtkFRepBoolean,
            vtkHyperFunReader, vtkMultimediaMapping, vtkMultimediaMapper, vtkSpreadsheetLayout,
            vtkFRepImplicitFunction, vtkFRepEvaluator):
    check(isinstance(cls(), vtkObject), "%s is a vtkObject of ParaView's vtkmodules" % cls.__name__)
check(issubclass(vtkFRepObject, vtkDataObject), "vtkFRepObject is a vtkDataObject")
check(issubclass(vtkFRepImplicitFunction, vtkImplicitFunction),
      "vtkFRepImplicitFunction is a vtkImplicitFunction")

# --- the pipeline -------------------------------------------------------------------------
reader = vtkHyperFunSource()
reader.SetFileName(model_file)
for i in range(3):
    reader.SetCoordinateRange(i, -4, 4)
slice_ = vtkFRepSlice()
slice_.SetInputConnection(reader.GetOutputPort())
slice_.SetFixedValueByName("x4", 0.5)
slice_.SetFixedValueByName("x5", 0.25)
mesher = vtkFRepPolygonizer()
mesher.SetInputConnection(slice_.GetOutputPort())
mesher.SetSampleDimensions(64, 64, 64)
frepkit.update(mesher)
mesh = mesher.GetOutput()
triangles = mesh.GetNumberOfCells()
print("x4 = 0.5, x5 = 0.25: %d triangles, %d points" % (triangles, mesh.GetNumberOfPoints()))
check(triangles > 1000, "the slice meshes into %d triangles" % triangles)
edges = vtkFeatureEdges()
edges.SetInputData(mesh)
edges.BoundaryEdgesOn()
edges.NonManifoldEdgesOn()
edges.FeatureEdgesOff()
edges.ManifoldEdgesOff()
edges.Update()
check(edges.GetOutput().GetNumberOfCells() == 0,
      "watertight: %d boundary or non-manifold edges" % edges.GetOutput().GetNumberOfCells())
bounds = mesh.GetBounds()
check(all(-4 - 1e-9 <= b <= 4 + 1e-9 for b in bounds), "bounds in the box: %s" % (bounds,))
sliced = slice_.GetOutput()
check(sliced.GetDimension() == 3 and sliced.GetModelDimension() == 5,
      "the slice is 3-D of a 5-D model")

# --- the evaluator with numpy -------------------------------------------------------------
rng = numpy.random.default_rng(14)
n = 2000
xyz = rng.uniform(-4, 4, size=(n, 3))
xyz[:4] = [[0, 0, 0], [3, 0, 0], [0, 3.5, 0], [1.25, -2.5, 0.75]]
full_points = numpy.hstack([xyz, numpy.tile([0.5, 0.25], (n, 1))])

with tempfile.TemporaryDirectory() as work:
    points_file = os.path.join(work, "points.txt")
    numpy.savetxt(points_file, full_points, fmt="%.17g")
    done = subprocess.run([frepkit_exe, "eval", model_file, "-p", points_file],
                          capture_output=True, text=True)
check(done.returncode == 0, "frepkit eval ran (%d): %s" % (done.returncode, done.stderr[-300:]))
expected = numpy.array([float(line) for line in done.stdout.split()])
check(expected.shape == (n,), "frepkit eval printed %d values" % expected.size)

full = reader.GetOutput()
f_full = frepkit.evaluate(full, full_points)
f_slice = frepkit.evaluate(sliced, xyz)
check(f_full.dtype == numpy.float64 and f_full.shape == (n,), "evaluate returns (N,) doubles")
check(expected.shape == (n,) and numpy.array_equal(f_full.view(numpy.uint64),
                                                    expected.view(numpy.uint64)),
      "5-D object: F bit-equal to frepkit eval at %d points" % n)
check(numpy.array_equal(f_slice.view(numpy.uint64), f_full.view(numpy.uint64)),
      "3-D slice: F bit-equal to the 5-D object at x4 = 0.5, x5 = 0.25")
inside = int((f_slice > 0).sum())
check(0 < inside < n, "%d of %d points inside" % (inside, n))

# The C++ point evaluator (vtkFRepImplicitFunction::EvaluateFunction(x, y, z) is -F).
implicit = vtkFRepImplicitFunction()
implicit.SetFRepObject(sliced)
point_values = numpy.array([-implicit.EvaluateFunction(*p) for p in xyz[:200]])
check(numpy.array_equal(point_values.view(numpy.uint64), f_slice[:200].view(numpy.uint64)),
      "F bit-equal to the C++ point evaluator (vtkFRepImplicitFunction) at 200 points")

# The VTK-array API itself, from numpy arrays: float32 input, vtkPoints, one point.
evaluator = vtkFRepEvaluator()
evaluator.SetObject(sliced)
values = vtkDoubleArray()
check(evaluator.GetDimension() == 3, "evaluator dimension 3")
as_float = numpy_support.numpy_to_vtk(xyz.astype(numpy.float32), deep=1)
check(evaluator.Evaluate(as_float, values), "Evaluate(float array)")
f32 = numpy_support.vtk_to_numpy(values)
check(numpy.array_equal(f32, frepkit.evaluate(sliced, xyz.astype(numpy.float32).astype(float))),
      "float32 points are evaluated at their double values")
pts = vtkPoints()
pts.SetData(numpy_support.numpy_to_vtk(xyz, deep=1))
check(evaluator.EvaluatePoints(pts, values), "EvaluatePoints(vtkPoints)")
check(numpy.array_equal(numpy_support.vtk_to_numpy(values), f_slice), "vtkPoints: the same F")
check(evaluator.EvaluatePoint(list(xyz[3]), 3) == f_slice[3], "EvaluatePoint")

# s[] and run-time errors.
attributed = frepkit.load(text="""
my_model(x[3], a[1], s[2])
{
  s[1] = 2 * x[1];
  s[2] = sqrt(x[2]);
  my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2;
}""")
pts2 = numpy.array([[0.5, 0.25, 0], [0.1, -1, 0], [0, 4, 0]])
f, s, ids = frepkit.evaluate(attributed, pts2, attributes=True, errors=True)
print("F", f, "s", s.tolist(), "errors", ids)
check(s.shape == (3, 2) and s[0, 0] == 1.0 and s[0, 1] == 0.5 and s[2, 1] == 2.0, "s[1], s[2]")
check(numpy.isnan(f[1]) and ids[1] > 0 and ids[0] == 0 and ids[2] == 0,
      "sqrt of a negative: NaN and an error id at that point only")
evaluator.SetObject(attributed)
message = evaluator.GetErrorMessage(int(ids[1]))
print("error", ids[1], "=", message)
check(":5:" in message and "square root" in message, "the error names line 5: %s" % message)

# --- bad input: errors, never a crash ------------------------------------------------------
evaluator.SetObject(sliced)
with frepkit.ErrorObserver(evaluator) as errors:
    ok = evaluator.Evaluate(numpy_support.numpy_to_vtk(numpy.zeros((5, 2)), deep=1), values)
check(not ok and values.GetNumberOfTuples() == 0, "2 components for a 3-D object: False")
check(any("2 components" in m and "3-D" in m for m in errors.messages),
      "... with a VTK error: %s" % errors.messages)
with frepkit.ErrorObserver(evaluator) as errors:
    ok = evaluator.Evaluate(None, values)
check(not ok and errors.messages, "None points: False and an error")
try:
    evaluator.Evaluate("not an array", values)
    check(False, "a string as points raises TypeError")
except TypeError:
    check(True, "a string as points raises TypeError")
empty = vtkFRepEvaluator()
with frepkit.ErrorObserver(empty) as errors:
    ok = empty.Evaluate(numpy_support.numpy_to_vtk(xyz, deep=1), values)
check(not ok and any("no object" in m for m in errors.messages), "no object: %s" % errors.messages)
try:
    frepkit.evaluate(sliced, numpy.zeros((4, 5)))
    check(False, "evaluate with shape (4, 5) raises FRepError")
except frepkit.FRepError as e:
    check("5 components" in str(e), "evaluate with shape (4, 5) raises FRepError: %s" % e)

bad_text = "my_model(x[3], a[1])\n{\n  my_model = 1 - x[1]^2 +;\n}\n"
bad = vtkHyperFunSource()
bad.SetModelText(bad_text)
with frepkit.ErrorObserver(bad) as errors:
    bad.Update()
print("observer saw:", errors.messages)
check(any(m.startswith("<string>:3:") and "error" in m for m in errors.messages),
      "a Python observer sees the diagnostic with file:line:col")
try:
    frepkit.load(text=bad_text)
    check(False, "load of bad text raises FRepError")
except frepkit.FRepError as e:
    check(any(m.startswith("<string>:3:") for m in e.messages), "FRepError: %s" % e)
# The error of a source reaches update() of a filter downstream.
bad_slice = vtkFRepSlice()
bad_slice.SetInputConnection(bad.GetOutputPort())
bad.Modified()
try:
    frepkit.update(bad_slice)
    check(False, "update() downstream of bad text raises FRepError")
except frepkit.FRepError as e:
    check(any("<string>:3:" in m for m in e.messages), "update() downstream: %s" % e.messages)

# One loading call everywhere (frep::load_model): a .vm tape loads by its extension, HyperFun
# library files are called like the file's own objects, and the messages are frepkit's.
vm = frepkit.load(file=os.path.join(source_dir, "Examples", "vm", "two-discs.vm"))
check(vm.GetModelDimension() == 2, ".vm file loads in Python (x[%d])" % vm.GetModelDimension())
vm_out = subprocess.run([frepkit_exe, "eval", os.path.join(source_dir, "Examples", "vm", "two-discs.vm")],
                        input="0.25 0.5\n", capture_output=True, text=True).stdout.strip()
vm_py = frepkit.evaluate(vm, numpy.array([[0.25, 0.5]]))
check(float(vm_out) == float(vm_py[0]), ".vm value in Python equals frepkit eval's (%s)" % vm_out)
homotopic = os.path.join(source_dir, "Examples", "homotopic")
libs = [os.path.join(homotopic, n + ".hf") for n in ("cat", "robot", "nihon", "roblet")]
blend = frepkit.load(file=os.path.join(homotopic, "blend.hf"), libraries=libs)
whole = frepkit.load(file=os.path.join(homotopic, "meta5d.hf"))
points = numpy.array([[0.5, 1.0, 2.0, 0.3, 0.7], [-3.0, 0.25, 4.0, 0.9, 0.1]])
check(numpy.array_equal(frepkit.evaluate(blend, points), frepkit.evaluate(whole, points)),
      "blend.hf with the key shapes as libraries equals meta5d.hf")
try:
    frepkit.load(file=model_file, object="nosuch")
    check(False, "an unknown object raises FRepError")
except frepkit.FRepError as e:
    check(any("no object named 'nosuch' (objects: " in m for m in e.messages),
          "unknown object: the engine's message (%s)" % e.messages)

# The solid's own bounds are the default intervals (solid_bounds=True); a half-space warns.
def coordinate_range(obj, i):
    r = [0.0, 0.0]
    obj.GetCoordinateRange(i, r)
    return tuple(r)


unit = frepkit.load(text="my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2 - x[4]^2; }")
unit_ranges = [coordinate_range(unit, i) for i in range(4)]
check(all(-1.2 < lo <= -1.0 and 1.0 <= hi < 1.2 for lo, hi in unit_ranges),
      "a unit 4-D ball gets about [-1.05, 1.05] on each axis: %s" % unit_ranges)
hfp = frepkit.load(text="my_model(x[3], a[1]) { my_model = 1 - x[1]^2 - x[2]^2 - x[3]^2; }",
                   solid_bounds=False)
check(coordinate_range(hfp, 0) == (-10.0, 10.0), "solid_bounds=False: [-10, 10]")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    half = frepkit.load(text="my_model(x[3], a[1]) { my_model = x[1]; }")
check(len(caught) == 1 and "reaches the edge" in str(caught[0].message),
      "a half-space: one Python warning (%s)" % [str(w.message) for w in caught])
check(coordinate_range(half, 0) == (-10.0, 10.0), "a half-space keeps [-10, 10]")

# Overloaded names: vtkHyperFunSource's ObjectName is the model's object (not vtkObject's).
named = vtkHyperFunSource()
named.SetObjectName("box")
named.SetFileName(model_file)
frepkit.update(named)
check(named.GetObjectName() == "box" and named.GetOutput().GetDimension() == 3,
      "ObjectName selects the object 'box' (3-D)")

finish()
