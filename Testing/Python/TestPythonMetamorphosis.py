"""vtkFRepMetamorphosis from the Python package frepkit (ctest Python.Metamorphosis.python3 and
.pvpython):

  TestPythonMetamorphosis.py SOURCE_DIR

- the four Homotopic Fun keys (Examples/homotopic) on a 2 x 2 lattice: a 5-D vtkFRepObject whose
  values at 2000 points equal meta5d.hf's meta5d (frepkit.load + frepkit.evaluate), bit for bit;
- aligned by size (SetAlignment(ALIGN_SIZE)): the lattice's corners are still the keys exactly,
  and the middle differs;
- normalised by distance (SetNormalisation(NORMALISE_DISTANCE)): at the corners every point is
  on the key's side (the zero sets kept) and the values differ from the keys' (the distances);
- timed (SetTiming(TIMING_EASE)) and with key weights (AddKeyWeight("nihon", "3")): the corners
  are still the keys bit for bit, the middle differs; a bad key-weight expression raises
  FRepError naming the key weight and its column;
- a lattice that does not match the keys: frepkit.update raises FRepError with the engine's
  message.
Exits 1 on any failed check."""

import os
import sys

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from python_checks import check, finish  # noqa: E402

source_dir = sys.argv[1]
homotopic = os.path.join(source_dir, "Examples", "homotopic")

import frepkit  # noqa: E402
from frepkit import vtkFRepMetamorphosis  # noqa: E402


def morph(alignment=vtkFRepMetamorphosis.ALIGN_NONE, axes=(2, 2)):
    m = vtkFRepMetamorphosis()
    for key in ("cat", "robot", "nihon", "roblet"):
        m.AddKey(os.path.join(homotopic, key + ".hf"), key)
    for n in axes:
        m.AddLatticeAxis(n)
    m.SetAlignment(alignment)
    return m


m = morph()
frepkit.update(m)
blend = m.GetOutput()
check(blend.GetDimension() == 5, "2 x 2 lattice of 3-D keys: a 5-D object (%d)" % blend.GetDimension())
paper = frepkit.load(file=os.path.join(homotopic, "meta5d.hf"), object="meta5d")
rng = numpy.random.default_rng(29)
points = numpy.column_stack([rng.uniform(-10, 10, (2000, 3)), rng.uniform(0, 1, (2000, 2))])
points[:400, 3:] = rng.integers(0, 2, (400, 2))  # 400 points at the corners (the keys)
ours, theirs = frepkit.evaluate(blend, points), frepkit.evaluate(paper, points)
check(numpy.array_equal(ours, theirs), "the morph equals meta5d.hf at 2000 points, bit for bit")

aligned = morph(vtkFRepMetamorphosis.ALIGN_SIZE)
frepkit.update(aligned)
values = frepkit.evaluate(aligned.GetOutput(), points)
corners = numpy.isin(points[:, 3], (0.0, 1.0)) & numpy.isin(points[:, 4], (0.0, 1.0))
check(numpy.array_equal(values[corners], theirs[corners]),
      "aligned by size, the corners are the keys (%d points)" % corners.sum())
check(not numpy.array_equal(values[~corners], theirs[~corners]), "aligned, the middle differs")

normalised = morph()
normalised.SetNormalisation(vtkFRepMetamorphosis.NORMALISE_DISTANCE)
frepkit.update(normalised)
values = frepkit.evaluate(normalised.GetOutput(), points)
check(numpy.array_equal(values[corners] >= 0, theirs[corners] >= 0),
      "normalised by distance, the corners are inside exactly where the keys are (%d points)" % corners.sum())
check(not numpy.array_equal(values[corners], theirs[corners]), "normalised, the corners' values change")

weighted = morph()
weighted.SetTiming(vtkFRepMetamorphosis.TIMING_EASE)
weighted.AddKeyWeight("nihon", "3")
weighted.AddKeyWeight("robot", "1 + max(mx[3], 0)")
frepkit.update(weighted)
values = frepkit.evaluate(weighted.GetOutput(), points)
check(numpy.array_equal(values[corners], theirs[corners]),
      "timed and weighted, the corners are the keys bit for bit (%d points)" % corners.sum())
check(not numpy.array_equal(values[~corners], theirs[~corners]), "timed and weighted, the middle differs")
weighted.RemoveAllKeyWeights()
weighted.AddKeyWeight("nihon", "2 +* 1")
try:
    frepkit.update(weighted)
    check(False, "a bad key weight raises FRepError")
except frepkit.FRepError as e:
    check("key weight 'nihon':1:4" in str(e), "a bad key weight raises FRepError at its column: %s" % str(e).splitlines()[0])

bad = morph(axes=(3,))
try:
    frepkit.update(bad)
    check(False, "a lattice of 3 for 4 keys raises FRepError")
except frepkit.FRepError as e:
    check("the lattice 3 has 3 nodes, 4 keys were given" in str(e),
          "a lattice of 3 for 4 keys raises FRepError: %s" % str(e).splitlines()[0])
finish()
