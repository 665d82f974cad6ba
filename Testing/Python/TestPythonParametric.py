"""frepkit.parametric: closed parametric surfaces as FRep objects (issue 28, item 5; ctest
Python.Parametric.python3 and .pvpython):

  TestPythonParametric.py

- VTK's torus (ring radius 1, cross-section radius 0.3) at 128 x 128: F at 2000 random points is
  the torus's signed distance within the tessellation's error (0.01), the sign right wherever
  |distance| > 0.01;
- VTK's ellipsoid (1, 0.6, 0.4) and superellipsoid: inside at the centre, outside beyond the
  radii, F(0) about the smallest radius;
- a torus of the user's own, (u, v) -> (x, y, z): the same distances as VTK's;
- a surface that is not closed (VTK's Moebius strip) raises FRepError naming open edges; a
  resolution below 3 and a non-surface raise ValueError / TypeError.
Exits 1 on any failed check."""

import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402

import frepkit  # noqa: E402
from vtkmodules.vtkCommonComputationalGeometry import (  # noqa: E402
    vtkParametricEllipsoid, vtkParametricSuperEllipsoid, vtkParametricTorus)


def torus_distance(p, ring=1.0, tube=0.3):
    q = numpy.sqrt(p[:, 0] ** 2 + p[:, 1] ** 2) - ring
    return tube - numpy.sqrt(q ** 2 + p[:, 2] ** 2)


rng = numpy.random.default_rng(5)
points = rng.uniform([-1.5, -1.5, -0.5], [1.5, 1.5, 0.5], size=(2000, 3))
exact = torus_distance(points)

vtk_torus = vtkParametricTorus()
vtk_torus.SetRingRadius(1.0)
vtk_torus.SetCrossSectionRadius(0.3)
obj = frepkit.parametric(vtk_torus, resolution=128)
check(obj.GetDimension() == 3, "VTK's torus is a 3-D FRep object")
f = frepkit.evaluate(obj, points)
error = numpy.max(numpy.abs(f - exact))
check(error < 0.01, "VTK's torus: F within %.4f of the signed distance (goal 0.01)" % error)
far = numpy.abs(exact) > 0.01
check(numpy.all((f[far] >= 0) == (exact[far] >= 0)), "VTK's torus: the sign right beyond 0.01")


def my_torus(u, v):
    a, b = 2 * math.pi * u, 2 * math.pi * v
    return ((1 + 0.3 * math.cos(b)) * math.cos(a), (1 + 0.3 * math.cos(b)) * math.sin(a),
            0.3 * math.sin(b))


mine = frepkit.parametric(my_torus, resolution=128)
g = frepkit.evaluate(mine, points)
error = numpy.max(numpy.abs(g - exact))
check(error < 0.01, "a user's torus: F within %.4f of the signed distance" % error)

for name, surface, smallest in (("ellipsoid", vtkParametricEllipsoid(), 0.4),
                                ("superellipsoid", vtkParametricSuperEllipsoid(), None)):
    if name == "ellipsoid":
        surface.SetXRadius(1.0)
        surface.SetYRadius(0.6)
        surface.SetZRadius(0.4)
    solid = frepkit.parametric(surface, resolution=96)
    centre, beyond = frepkit.evaluate(solid, numpy.array([[0.0, 0.0, 0.0], [0.0, 0.0, 1.6]]))
    check(centre > 0 and beyond < 0, "%s: inside at the centre (%.3f), outside beyond (%.3f)"
          % (name, centre, beyond))
    if smallest is not None:
        check(abs(centre - smallest) < 0.01, "%s: F(0) = %.4f, the smallest radius %.1f"
              % (name, centre, smallest))


from vtkmodules.vtkCommonComputationalGeometry import vtkParametricMobius  # noqa: E402

try:
    frepkit.parametric(vtkParametricMobius(), resolution=16)  # one edge: open
    check(False, "an open surface raises FRepError")
except frepkit.FRepError as e:
    check("open" in str(e), "an open surface raises FRepError: %s" % str(e).splitlines()[0])
for bad, error_type in ((lambda: frepkit.parametric(vtk_torus, resolution=2), ValueError),
                        (lambda: frepkit.parametric(42), TypeError)):
    try:
        bad()
        check(False, "%s raised" % error_type.__name__)
    except error_type:
        check(True, "%s for a bad call" % error_type.__name__)
finish()
