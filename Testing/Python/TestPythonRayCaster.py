"""vtkFRepRayCaster from the Python package frepkit, run by /usr/bin/python3 and by pvpython
(ctest Python.RayCaster.python3 and Python.RayCaster.pvpython):

  TestPythonRayCaster.py SOURCE_DIR

- a 5-D model (Examples/homotopy5d.hf) -> vtkFRepSlice (x4 = 0.5, x5 = 0.25) ->
  vtkFRepRayCaster: a 160 x 120 picture whose arrays read into numpy: Colour (unsigned char
  RGBA, the active scalars), Depth (float); pixels are covered and the centre pixel (the origin
  is inside the slice) has a finite depth, the corners +inf; 1 and 2 threads give the same
  arrays;
- a sphere of radius 5 in parallel projection: the covered pixels within 1 % of the projected
  disc, the depth at the centre pixel D - 5 (D the eye's distance to the box centre);
- the 5-D model unsliced: frepkit.update raises FRepError naming vtkFRepSlice.
Exits 1 on any failed check."""

import math
import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402


source_dir = sys.argv[1]
model_file = os.path.join(source_dir, "Examples", "homotopy5d.hf")

import frepkit  # noqa: E402
from frepkit import vtkHyperFunSource, vtkFRepSlice, vtkFRepRayCaster  # noqa: E402
from vtkmodules.util import numpy_support  # noqa: E402


def arrays(caster):
    image = caster.GetOutput()
    nx, ny, nz = image.GetDimensions()
    pd = image.GetPointData()
    colour = numpy_support.vtk_to_numpy(pd.GetArray("Colour")).reshape(ny, nx, 4)
    depth = numpy_support.vtk_to_numpy(pd.GetArray("Depth")).reshape(ny, nx)
    return image, colour, depth


# --- a slice of a 5-D model ----------------------------------------------------------------
reader = vtkHyperFunSource()
reader.SetFileName(model_file)
for i in range(3):
    reader.SetCoordinateRange(i, -4, 4)
slice_ = vtkFRepSlice()
slice_.SetInputConnection(reader.GetOutputPort())
slice_.SetFixedValueByName("x4", 0.5)
slice_.SetFixedValueByName("x5", 0.25)
caster = vtkFRepRayCaster()
caster.SetInputConnection(slice_.GetOutputPort())
caster.SetWidth(160)
caster.SetHeight(120)
caster.SetNumberOfThreads(1)
frepkit.update(caster)
image, colour, depth = arrays(caster)
check(image.GetDimensions() == (160, 120, 1),
      "a 160 x 120 x 1 image: %s" % (image.GetDimensions(),))
check(colour.dtype == numpy.uint8 and
      image.GetPointData().GetScalars().GetName() == "Colour",
      "Colour: unsigned char RGBA, the active scalars")
check(depth.dtype == numpy.float32, "Depth: float")
covered = int(numpy.isfinite(depth).sum())
print("homotopy5d at x4 = 0.5, x5 = 0.25: %d of %d pixels covered, %d rays, %d hits"
      % (covered, depth.size, caster.GetNumberOfRays(), caster.GetNumberOfHits()))
check(covered > 0.02 * depth.size, "%d pixels covered" % covered)
centre = float(depth[60, 80])
check(math.isfinite(centre) and centre > 0, "finite depth at the centre pixel: %g" % centre)
check(all(math.isinf(float(depth[j, i])) for j, i in ((0, 0), (0, 159), (119, 0), (119, 159))),
      "+inf depth in the corners")
check(int(colour[60, 80, 3]) == 255 and tuple(colour[0, 0]) == (255, 255, 255, 255),
      "opaque shape over the opaque white background")
caster.SetNumberOfThreads(2)
frepkit.update(caster)
_, colour2, depth2 = arrays(caster)
check(numpy.array_equal(colour, colour2) and
      numpy.array_equal(depth.view(numpy.uint32), depth2.view(numpy.uint32)),
      "1 and 2 threads: the same Colour and Depth")

# --- a sphere in parallel projection: the exact disc ------------------------------------------
sphere = vtkHyperFunSource()
sphere.SetModelText("my_model(x[3], a[1]) { my_model = 25 - x[1]^2 - x[2]^2 - x[3]^2; }")
for i in range(3):
    sphere.SetCoordinateRange(i, -6, 6)
ortho = vtkFRepRayCaster()
ortho.SetInputConnection(sphere.GetOutputPort())
ortho.SetWidth(201)
ortho.SetHeight(151)
ortho.SetParallelProjection(1)
ortho.SetSupersample(1)
frepkit.update(ortho)
_, _, sdepth = arrays(ortho)
pixels_per_unit = 0.5 * 151 / ortho.GetCameraParallelScale()
disc = math.pi * (5 * pixels_per_unit) ** 2
hits = int(numpy.isfinite(sdepth).sum())
eye = numpy.array(ortho.GetCameraPosition())
D = float(numpy.linalg.norm(eye - numpy.array(ortho.GetCameraFocalPoint())))
print("sphere: %d pixels hit, disc %.1f; centre depth %.6f, D - 5 = %.6f"
      % (hits, disc, sdepth[75, 100], D - 5))
check(abs(hits - disc) <= 0.01 * disc, "covered pixels within 1 %% of the disc (%d, %.1f)"
      % (hits, disc))
check(abs(float(sdepth[75, 100]) - (D - 5)) <= 1e-5 * D, "centre depth D - 5")

# --- an n-D object is refused -----------------------------------------------------------------
unsliced = vtkFRepRayCaster()
unsliced.SetInputConnection(reader.GetOutputPort())
try:
    frepkit.update(unsliced)
    check(False, "a 5-D object raises FRepError")
except frepkit.FRepError as e:
    check(any("vtkFRepSlice" in m for m in e.messages), "a 5-D object: %s" % e.messages)
check(unsliced.GetOutput().GetNumberOfPoints() == 0, "... and an empty image")

finish()
