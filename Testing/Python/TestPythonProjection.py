"""vtkFRepProjection from the Python package frepkit (ctest Python.Projection.python3 and
.pvpython):

  TestPythonProjection.py

- a sphere moving along x as x4 goes 0 -> 1, projected along x4: a 3-D vtkFRepObject whose values
  at 1000 random points (frepkit.evaluate) keep the projector's contract against the capsule's
  closed form (never above it; within the tolerance of it inside the band; beyond it the sign);
- polygonised: the capsule's volume (vtkMassProperties) within 2 %;
- a coordinate the model lacks: frepkit.update raises FRepError with the filter's message;
- vtkFRepSweep: a ball moved along the same segment gives the same capsule (the contract at the
  same points), its output's box the ball's swept along the path; a one-point path raises
  FRepError;
- vtkFRepSpaceTimeQuery: the moving sphere's section volume at 3 times (the ball's, 2 %), when
  the point (0, 0, 0) is inside (x4 in [0.25, 0.75]), where two balls part (x4 = 0.375), as
  numpy arrays of its table's columns.
Exits 1 on any failed check."""

import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402

import frepkit  # noqa: E402
from frepkit import vtkFRepPolygonizer, vtkFRepProjection, vtkFRepSpaceTimeQuery, vtkFRepSweep, vtkHyperFunSource  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkMassProperties, vtkTriangleFilter  # noqa: E402

source = vtkHyperFunSource()
source.SetModelText("moving(x[4], a[1]) { moving = 0.25 - ((x[1] + 1 - 2*x[4])^2 + x[2]^2 + x[3]^2); }")
projection = vtkFRepProjection()
projection.SetInputConnection(source.GetOutputPort())
projection.SetProjectedCoordinate(3)
projection.SetProjectedRange(0.0, 1.0)
frepkit.update(projection)
swept = projection.GetOutput()
check(swept.GetDimension() == 3, "the sweep is 3-D (got %d)" % swept.GetDimension())

rng = numpy.random.default_rng(28)
points = rng.uniform([-1.6, -0.7, -0.7], [1.6, 0.7, 0.7], size=(1000, 3))
values = frepkit.evaluate(swept, points)
t = numpy.clip((points[:, 0] + 1.0) / 2.0, 0.0, 1.0)
capsule = 0.25 - ((points[:, 0] + 1 - 2 * t) ** 2 + points[:, 1] ** 2 + points[:, 2] ** 2)
tol, band = projection.GetTolerance(), projection.GetBand()
above = numpy.count_nonzero(values > capsule + 1e-12)
inner = (values >= -band) & (values < band)
off = numpy.count_nonzero(inner & (values < capsule - tol))
outer = numpy.count_nonzero((values < -band) & (capsule >= -band + tol))
check(above == 0, "never above the capsule (%d points above)" % above)
check(off == 0, "within the tolerance inside the band (%d of %d off)" % (off, inner.sum()))
check(outer == 0, "beyond the band: outside (%d wrong)" % outer)

mesher = vtkFRepPolygonizer()
mesher.SetInputConnection(projection.GetOutputPort())
mesher.SetModelBounds(-1.6, 1.6, -0.7, 0.7, -0.7, 0.7)
mesher.SetSampleDimensions(48, 24, 24)
triangles = vtkTriangleFilter()
triangles.SetInputConnection(mesher.GetOutputPort())
mass = vtkMassProperties()
mass.SetInputConnection(triangles.GetOutputPort())
frepkit.update(mass)
exact = math.pi * 0.25 * 2 + 4.0 / 3.0 * math.pi * 0.125
check(abs(mass.GetVolume() - exact) < 0.02 * exact,
      "the sweep's volume %.4f (capsule %.4f)" % (mass.GetVolume(), exact))

projection.SetProjectedCoordinate(6)
try:
    frepkit.update(projection)
    check(False, "a coordinate the model lacks raises FRepError")
except frepkit.FRepError as e:
    check("cannot project along coordinate 6" in str(e), "FRepError says why: %s" % e)

# A profile along a path: the ball (x4 fixed out of the model) along (-1, 0, 0) -> (1, 0, 0).
ball = vtkHyperFunSource()
ball.SetModelText("ball(x[3], a[1]) { ball = 0.25 - (x[1]^2 + x[2]^2 + x[3]^2); }")
for axis in range(3):
    ball.SetCoordinateRange(axis, -0.5, 0.5)
sweep = vtkFRepSweep()
sweep.SetInputConnection(ball.GetOutputPort())
sweep.AddPathPoint(-1, 0, 0)
sweep.AddPathPoint(1, 0, 0)
frepkit.update(sweep)
capsule_object = sweep.GetOutput()
box = [0.0, 0.0]
capsule_object.GetCoordinateRange(0, box)
check(box == [-1.5, 1.5], "the sweep's x range is the ball's moved along the path: %s" % box)
swept_values = frepkit.evaluate(capsule_object, points)
above = numpy.count_nonzero(swept_values > capsule + 1e-12)
inner = (swept_values >= -band) & (swept_values < band)
off = numpy.count_nonzero(inner & (swept_values < capsule - tol))
check(above == 0 and off == 0, "vtkFRepSweep: the capsule (%d above, %d off)" % (above, off))
sweep.RemoveAllPathPoints()
sweep.AddPathPoint(0, 0, 0)
try:
    frepkit.update(sweep)
    check(False, "a one-point path raises FRepError")
except frepkit.FRepError as e:
    check("at least 2 points" in str(e), "FRepError says why: %s" % e)

# The questions of space-time, in the object's box (the sphere's whole way).
source.SetCoordinateRange(0, -1.6, 1.6)
source.SetCoordinateRange(1, -0.7, 0.7)
source.SetCoordinateRange(2, -0.7, 0.7)
query = vtkFRepSpaceTimeQuery()
query.SetInputConnection(source.GetOutputPort())
query.SetSteps(3)
frepkit.update(query)
volumes = vtk_to_numpy(query.GetOutput().GetColumnByName("volume"))
ball = 4.0 / 3.0 * math.pi * 0.125
check(len(volumes) == 3 and numpy.all(numpy.abs(volumes - ball) < 0.02 * ball),
      "the section is the ball at every time: %s" % volumes)
query.SetQueryToPresence()
query.SetPoint(0.0, 0.0, 0.0)
frepkit.update(query)
enter = vtk_to_numpy(query.GetOutput().GetColumnByName("enter"))
leave = vtk_to_numpy(query.GetOutput().GetColumnByName("leave"))
check(len(enter) == 1 and abs(enter[0] - 0.25) < 2e-4 and abs(leave[0] - 0.75) < 2e-4,
      "the origin is inside for x4 in [0.25, 0.75]: %s %s" % (enter, leave))

# TOPOLOGY: two balls of radius 0.45 at x1 = +-(0.3 + 0.4 x4) part at x4 = 0.375 (the grid of 49
# samples over [-2, 2] and [-1, 1] has a point at the origin, where they meet).
parting = vtkHyperFunSource()
parting.SetModelText("p(x[4], a[1]) { c = 0.3 + 0.4*x[4]; p = max(0.2025 - ((x[1] - c)^2 + x[2]^2 + x[3]^2),"
                     " 0.2025 - ((x[1] + c)^2 + x[2]^2 + x[3]^2)); }")
for axis, (lo, hi) in enumerate([(-2, 2), (-1, 1), (-1, 1)]):
    parting.SetCoordinateRange(axis, lo, hi)
query.SetInputConnection(parting.GetOutputPort())
query.SetQueryToTopology()
query.SetSteps(5)
query.SetSamples(49)
query.SetTimeTolerance(1e-3)
frepkit.update(query)
table = query.GetOutput()
before = vtk_to_numpy(table.GetColumnByName("before"))
after = vtk_to_numpy(table.GetColumnByName("after"))
pieces = vtk_to_numpy(table.GetColumnByName("pieces_after"))
check(len(before) == 1 and before[0] <= 0.375 <= after[0] and after[0] - before[0] <= 1e-3 and pieces[0] == 2,
      "the balls part at x4 = 0.375: %s %s %s" % (before, after, pieces))
finish()
