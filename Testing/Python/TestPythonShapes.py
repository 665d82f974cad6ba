"""What vtkImplicitFunctionToFRep, vtkPolyDataToFRep and vtkImageDataToFRep compute, from Python
(ctest Python.Shapes.python3 and Python.Shapes.pvpython):

  TestPythonShapes.py

- vtkImplicitFunctionToFRep of a vtkSphere: F = -f bit for bit at random points, also with a
  Transform on the function;
- vtkPolyDataToFRep of a closed triangulated sphere: |F| equals vtkImplicitPolyDataDistance's
  distance to 1e-9 and the sign is + inside, - outside (points away from the surface);
- vtkImageDataToFRep of a sampled field: F = value - IsoValue exactly at the grid points and
  trilinear between them;
- the three as functions of a HyperFun program (vtkHyperFunSource.AddShape): F of
  `max(ball(x), cube(x))` is the max of the two objects' F, bit for bit.
Exits 1 on any failed check."""

import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402


import frepkit  # noqa: E402
from frepkit import (vtkHyperFunSource, vtkImageDataToFRep, vtkImplicitFunctionToFRep,  # noqa: E402
                     vtkPolyDataToFRep)
from vtkmodules.vtkCommonCore import vtkDoubleArray  # noqa: E402
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkSphere  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkImplicitPolyDataDistance  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkTriangleFilter  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402

rng = numpy.random.default_rng(17)
points = rng.uniform(-3, 3, size=(2000, 3))

# --- vtkImplicitFunctionToFRep: F = -f, exactly ---------------------------------------------
sphere = vtkSphere()
sphere.SetCenter(0.5, -0.25, 0)
sphere.SetRadius(1.5)
implicit = vtkImplicitFunctionToFRep()
implicit.SetImplicitFunction(sphere)
implicit.SetFunctionName("ball")
implicit.SerializeEvaluationOff()  # vtkSphere is thread-safe
implicit.SetBounds(-3, 3, -3, 3, -3, 3)
implicit.Update()
ball = implicit.GetOutputDataObject(0)
f_ball = frepkit.evaluate(ball, points)
expected = numpy.array([-sphere.EvaluateFunction(*p) for p in points])
check(numpy.array_equal(f_ball.view(numpy.uint64), expected.view(numpy.uint64)),
      "vtkImplicitFunctionToFRep: F = -vtkSphere bit for bit at %d points" % len(points))
check(ball.GetDimension() == 3, "... a 3-D object")
moved = vtkTransform()
moved.Translate(-1.0, 0.5, 0.25)  # VTK's functions take the transform of the point
sphere.SetTransform(moved)
implicit.Update()
f_moved = frepkit.evaluate(implicit.GetOutputDataObject(0), points)
expected = numpy.array([-sphere.FunctionValue(*p) for p in points])
check(numpy.array_equal(f_moved.view(numpy.uint64), expected.view(numpy.uint64))
      and not numpy.array_equal(f_moved, f_ball),
      "... with the function's Transform applied (F = -FunctionValue) bit for bit")
sphere.SetTransform(None)
implicit.Update()
ball = implicit.GetOutputDataObject(0)

# --- vtkPolyDataToFRep: the signed distance to a closed mesh ---------------------------------
source = vtkSphereSource()
source.SetRadius(2.0)
source.SetThetaResolution(48)
source.SetPhiResolution(48)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(source.GetOutputPort())
triangles.Update()
mesh = triangles.GetOutput()
to_frep = vtkPolyDataToFRep()
to_frep.SetInputData(mesh)
to_frep.SetFunctionName("pebble")
to_frep.Update()
pebble = to_frep.GetOutputDataObject(0)
f_mesh = frepkit.evaluate(pebble, points)
distance = vtkImplicitPolyDataDistance()
distance.SetInput(mesh)
d_vtk = numpy.array([distance.EvaluateFunction(*p) for p in points])
worst = numpy.max(numpy.abs(numpy.abs(f_mesh) - numpy.abs(d_vtk)))
print("largest | |F| - |d_vtk| | over %d points: %.3g" % (len(points), worst))
check(worst < 1e-9, "vtkPolyDataToFRep: |F| is VTK's distance to the mesh (%.3g)" % worst)
radius = numpy.linalg.norm(points, axis=1)
inside, outside = radius < 1.9, radius > 2.1
check(bool(numpy.all(f_mesh[inside] > 0)) and bool(numpy.all(f_mesh[outside] < 0)),
      "... F > 0 at the %d points inside, < 0 at the %d outside" % (inside.sum(), outside.sum()))

# --- vtkImageDataToFRep: trilinear value minus IsoValue ---------------------------------------
image = vtkImageData()
image.SetDimensions(9, 9, 9)
image.SetOrigin(-2, -2, -2)
image.SetSpacing(0.5, 0.5, 0.5)
grid = numpy.array([image.GetPoint(i) for i in range(image.GetNumberOfPoints())])
field = 4.0 - numpy.sum(grid ** 2, axis=1) + 0.3 * grid[:, 0] * grid[:, 1]
scalars = vtkDoubleArray()
scalars.SetName("field")
for v in field:
    scalars.InsertNextValue(v)
image.GetPointData().SetScalars(scalars)
volume = vtkImageDataToFRep()
volume.SetInputData(image)
volume.SetIsoValue(1.25)
volume.SetFunctionName("blob")
volume.Update()
blob = volume.GetOutputDataObject(0)
f_grid = frepkit.evaluate(blob, grid)
check(numpy.array_equal(f_grid, field - 1.25),
      "vtkImageDataToFRep: F = value - IsoValue exactly at all %d grid points" % len(grid))
# Between grid points: trilinear. Midpoints of cells, and points at a quarter along each axis.
index = rng.integers(0, 8, size=(200, 3))
fraction = rng.uniform(0, 1, size=(200, 3))
inner = -2 + 0.5 * (index + fraction)
values = field.reshape(9, 9, 9)  # [z][y][x]
trilinear = numpy.zeros(len(inner))
for corner in range(8):
    dx, dy, dz = corner & 1, (corner >> 1) & 1, (corner >> 2) & 1
    weight = ((fraction[:, 0] if dx else 1 - fraction[:, 0]) *
              (fraction[:, 1] if dy else 1 - fraction[:, 1]) *
              (fraction[:, 2] if dz else 1 - fraction[:, 2]))
    trilinear += weight * values[index[:, 2] + dz, index[:, 1] + dy, index[:, 0] + dx]
f_inner = frepkit.evaluate(blob, inner)
worst = numpy.max(numpy.abs(f_inner - (trilinear - 1.25)))
check(worst < 1e-12, "... trilinear inside the cells (200 points, largest difference %.3g)" % worst)

# --- the three in one HyperFun program --------------------------------------------------------
program = vtkHyperFunSource()
program.AddShape("ball", ball)
program.AddShape("pebble", pebble)
program.AddShape("blob", blob)
program.SetModelText("""
my_model(x[3], a[1])
{
  my_model = max(max(ball(x), pebble(x)), blob(x));
}""")
program.Update()
combined = program.GetOutputDataObject(0)
f_all = frepkit.evaluate(combined, points)
check(numpy.array_equal(f_all, numpy.maximum(numpy.maximum(f_ball, f_mesh),
                                             frepkit.evaluate(blob, points))),
      "a HyperFun program calling ball(x), pebble(x), blob(x): F is their max, bit for bit")

finish()
