"""Bad calls from Python never crash (ctest Python.BadCalls): every method that an FRepKit class
adds to its VTK superclasses (those of VTK itself are VTK's business: vtkAlgorithm::
GetInputArrayInformation(-1) crashes in plain VTK too) is called on a fresh instance and on a
configured one with no arguments, None, negative and huge indices, strings, huge doubles and
bad lists. Python exceptions and VTK errors are expected; a crash ends the process, and the
test (which passes on the final line) with it."""

import sys

import frepkit
from vtkmodules.vtkCommonCore import vtkObject

vtkObject.GlobalWarningDisplayOff()  # thousands of expected VTK errors
BAD = [(), (None,), (-1,), (10 ** 6,), ("x",), (-1, -1), (0, 1e300, -1e300), (None, None),
       (-5, 0.0, 0.0), ([],), ([99, -3],), (0, None), (-1, "x", 2)]
MODEL = "my_model(x[4], a[1]) { my_model = 1 - x[1]^2 - x[4]^2; }"


def own_methods(cls):
    inherited = set()
    for k in cls.__mro__:
        if not k.__module__.startswith("frepkit"):
            inherited |= set(dir(k))
    return sorted(m for m in set(dir(cls)) - inherited if not m.startswith("_"))


calls = 0
classes = [getattr(frepkit, n) for n in sorted(frepkit.__all__) if n.startswith("vtk")]
for cls in classes:
    for configured in (False, True):
        obj = cls()
        if configured and hasattr(obj, "SetModelText"):
            obj.SetModelText(MODEL)
            obj.Update()
        if configured and hasattr(obj, "SetObject"):
            obj.SetObject(frepkit.load(text=MODEL))
        for name in own_methods(cls):
            method = getattr(obj, name)
            if not callable(method):
                continue
            for args in BAD:
                calls += 1
                try:
                    method(*args)
                except Exception:
                    pass
    print("%s: %d methods of its own survived" % (cls.__name__, len(own_methods(cls))),
          flush=True)
print("%d bad calls on %d classes, no crash" % (calls, len(classes)))
sys.exit(0 if len(classes) >= 14 else 1)
