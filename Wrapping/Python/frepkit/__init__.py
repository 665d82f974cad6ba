"""FRepKit: function-representation (FRep) modelling in any number of dimensions, for VTK.

The FRepKit VTK modules wrapped with VTK's own Python wrapping, on top of ParaView's
``vtkmodules`` (Debian: python3-paraview)::

    from frepkit import vtkHyperFunSource, vtkFRepSlice, vtkFRepPolygonizer

The classes are the C++ classes (Documentation/vtk-sources.md, vtk-filters.md, mapping.md).
What Python gets instead of the engine's C++ types is vtkFRepEvaluator (F and s[] of an object
at many points, from and to VTK arrays) and the helpers below, which work with numpy arrays and
turn VTK errors (the diagnostics of bad HyperFun text carry file:line:col) into exceptions:

    load(text=None, file=None, ...)  -> a vtkFRepObject, or FRepError with the diagnostics
    parametric(surface, resolution)  -> a closed parametric surface (VTK's or (u, v) -> xyz) as
                                        a 3-D vtkFRepObject: its tessellation's signed distance
    evaluate(obj, points)            -> numpy F (and s[]) at an (N, k) numpy array of points
    update(algorithm)                -> algorithm.Update(), raising FRepError on VTK errors
    ErrorObserver(*objects)          -> collects the ErrorEvent messages of VTK objects

See Documentation/python.md.
"""

# ParaView's VTK first: the wrapped modules' base classes (vtkObject, vtkDataObject,
# vtkAlgorithm, ...) are its classes, and the extension modules import them by name.
import warnings

import vtkmodules  # noqa: F401
from vtkmodules import vtkCommonCore as _vtkCommonCore
from vtkmodules import vtkCommonDataModel as _vtkCommonDataModel  # noqa: F401
from vtkmodules import vtkCommonExecutionModel as _vtkCommonExecutionModel  # noqa: F401

from .FRepKitSources import *  # noqa: F401,F403,E402
from .FRepKitFilters import *  # noqa: F401,F403,E402
from .FRepKitIO import *  # noqa: F401,F403,E402
from .FRepKitMapping import *  # noqa: F401,F403,E402
from .FRepKitSources import vtkFRepEvaluator, vtkHyperFunSource, vtkPolyDataToFRep  # noqa: E402

__all__ = [name for name, value in list(globals().items())
           if name.startswith("vtk") and isinstance(value, type)] + [
    "FRepError", "ErrorObserver", "load", "evaluate", "update", "parametric"]


class FRepError(RuntimeError):
    """A VTK error reported by FRepKit (or VTK) while the helper ran; ``messages`` lists each
    message without VTK's "ERROR: In file, line" prefix, e.g.
    "<string>:2:12: error: expected ';' after the statement"."""

    def __init__(self, messages):
        self.messages = list(messages)
        super().__init__("\n".join(self.messages) if self.messages else "VTK error")


def _strip(text):
    # vtkErrorMacro's text: "ERROR: In FILE, line N\nCLASS (0x...): MESSAGE\n\n".
    text = text.strip()
    first, _, rest = text.partition("\n")
    if first.startswith("ERROR: In ") and rest:
        text = rest
    head, sep, tail = text.partition("): ")
    if sep and " (" in head and "\n" not in head:
        text = tail
    return text.strip()


class ErrorObserver:
    """Collects the ErrorEvent messages of VTK objects (or those of `event`, e.g.
    "WarningEvent") and keeps them off VTK's output window while attached. Use as a context
    manager, or call detach() when done::

        with frepkit.ErrorObserver(source) as errors:
            source.Update()
        print(errors.messages)
    """

    def __init__(self, *objects, event="ErrorEvent"):
        self.messages = []
        self._tags = []
        self._event = event
        for obj in objects:
            self.attach(obj)

    def _callback(self, caller, event, calldata):
        self.messages.append(_strip(calldata) if isinstance(calldata, str) else str(calldata))

    _callback.CallDataType = _vtkCommonCore.VTK_STRING

    def attach(self, obj):
        if obj is None:
            return
        # A bound method loses the CallDataType attribute: wrap it in a function that has it.
        def callback(caller, event, calldata, observer=self):
            observer._callback(caller, event, calldata)
        callback.CallDataType = _vtkCommonCore.VTK_STRING
        self._tags.append((obj, obj.AddObserver(self._event, callback)))

    def detach(self):
        for obj, tag in self._tags:
            obj.RemoveObserver(tag)
        self._tags = []

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.detach()
        return False


def _upstream(algorithm):
    """The algorithm, every algorithm upstream of it, and their executives."""
    seen, order, todo = set(), [], [algorithm]
    while todo:
        a = todo.pop()
        if a is None or id(a) in seen:
            continue
        seen.add(id(a))
        order.append(a)
        executive = a.GetExecutive()
        if executive is not None and id(executive) not in seen:
            seen.add(id(executive))
            order.append(executive)
        for port in range(a.GetNumberOfInputPorts()):
            for i in range(a.GetNumberOfInputConnections(port)):
                connection = a.GetInputConnection(port, i)
                if connection is not None:
                    todo.append(connection.GetProducer())
    return order


def update(algorithm, port=None):
    """algorithm.Update() (or Update(port)); raises FRepError if the algorithm, anything
    upstream of it or their executives report a VTK error. Returns the algorithm."""
    with ErrorObserver(*_upstream(algorithm)) as errors:
        if port is None:
            algorithm.Update()
        else:
            algorithm.Update(port)
    if errors.messages:
        raise FRepError(errors.messages)
    return algorithm


def load(text=None, file=None, object=None, parameters=None, ranges=None, default_range=None,
         libraries=None, solid_bounds=True):
    """Compiles HyperFun text (or the model file `file`: .hf, or a .vm tape) into a
    vtkFRepObject with every coordinate free. `object`: the object to take (default my_model,
    else the first); `parameters`: a[1..]; `ranges`: [(lo, hi), ...] per coordinate x1.. (None
    for a coordinate, or a short list: the solid's own bounds when `solid_bounds`, as
    vtkHyperFunSource.UseSolidBounds finds them, else `default_range`, [-10, 10] by default; a
    solid that cannot be bounded, e.g. a half-space, gets `default_range` with a Python
    warning); `libraries`: files the model may call, HyperFun
    .hf files (their objects) or shared libraries implementing frepkit_user.h (their
    functions). Raises FRepError with every diagnostic ("file:line:col: error: ...") if the
    model does not load; the messages are the engine's, the same as frepkit's."""
    if (text is None) == (file is None):
        raise ValueError("load: give exactly one of text= and file=")
    source = vtkHyperFunSource()
    if file is not None:
        source.SetFileName(str(file))
    else:
        source.SetModelText(text)
    for library in libraries or []:
        source.AddUserLibrary(str(library))
    if object is not None:
        source.SetObjectName(object)
    for i, value in enumerate(parameters or []):
        source.SetParameter(i, float(value))
    if default_range is not None:
        source.SetDefaultCoordinateRange(float(default_range[0]), float(default_range[1]))
    for i, r in enumerate(ranges or []):
        if r is not None:
            source.SetCoordinateRange(i, float(r[0]), float(r[1]))
    source.SetUseSolidBounds(bool(solid_bounds))
    with ErrorObserver(source, event="WarningEvent") as warned:
        update(source)
    for message in warned.messages:
        warnings.warn(message, stacklevel=2)
    output = source.GetOutput()
    if output.GetDimension() == 0 and output.GetModelDimension() == 0:
        raise FRepError(["the HyperFun program produced no object"])
    result = output.NewInstance()
    result.ShallowCopy(output)
    return result


def evaluate(obj, points, attributes=False, errors=False, threads=0):
    """F of the vtkFRepObject `obj` at `points` (a numpy array of shape (N, k), k = the
    object's dimension; (k,) for one point), evaluated by the engine's batch evaluator: the
    values of frepkit eval and of the C++ evaluators, bit for bit. Returns a numpy array F of
    shape (N,); with attributes=True also s of shape (N, m); with errors=True also the run-time
    error id per point (0 = none; vtkFRepEvaluator.GetErrorMessage(id) names it). Points that
    raise a run-time error have F = NaN. A wrong shape or a bad object raises FRepError."""
    import numpy
    from vtkmodules.util import numpy_support

    array = numpy.ascontiguousarray(points, dtype=numpy.float64)
    if array.ndim == 1:
        array = array.reshape(1, -1)
    if array.ndim != 2:
        raise FRepError(["evaluate: points must have shape (N, k), not %s" % (array.shape,)])
    vtk_points = numpy_support.numpy_to_vtk(array, deep=1)
    values = _vtkCommonCore.vtkDoubleArray()
    s = _vtkCommonCore.vtkDoubleArray() if attributes else None
    ids = _vtkCommonCore.vtkIntArray() if errors else None
    evaluator = vtkFRepEvaluator()
    evaluator.SetObject(obj)
    evaluator.SetNumberOfThreads(int(threads))
    with ErrorObserver(evaluator) as observed:
        ok = evaluator.Evaluate(vtk_points, values, s, ids)
    if not ok or observed.messages:
        raise FRepError(observed.messages or ["evaluate failed"])
    result = [numpy_support.vtk_to_numpy(values).copy()]
    if attributes:
        m = evaluator.GetNumberOfAttributes()
        result.append(numpy_support.vtk_to_numpy(s).reshape(-1, m).copy() if m > 0
                      else numpy.zeros((array.shape[0], 0)))
    if errors:
        result.append(numpy_support.vtk_to_numpy(ids).copy())
    return result[0] if len(result) == 1 else tuple(result)


def _grid_surface(function, nu, nv):
    """The closed (u, v) grid of `function` over [0, 1)^2 as triangles, wrapped in u and v so
    that no seam is open; collapsed rows (a pole) are merged by the caller's cleaning."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    points = vtkPoints()
    for j in range(nv):
        for i in range(nu):
            points.InsertNextPoint(*[float(c) for c in function(i / nu, j / nv)])
    cells = vtkCellArray()
    for j in range(nv):
        for i in range(nu):
            a, b = j * nu + i, j * nu + (i + 1) % nu
            c, d = ((j + 1) % nv) * nu + (i + 1) % nu, ((j + 1) % nv) * nu + i
            for tri in ((a, b, c), (a, c, d)):
                cells.InsertNextCell(3, tri)
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(cells)
    return poly


def parametric(surface, resolution=128):
    """A closed parametric surface as a 3-D vtkFRepObject (issue 28, item 5): F is the signed
    distance to its watertight tessellation (vtkPolyDataToFRep: positive inside, enclosures for
    culling), so it slices, meshes, ray-casts and combines like any FRep object. `surface` is
    one of VTK's closed parametric functions (vtkParametricTorus(), vtkParametricEllipsoid(),
    vtkParametricSuperEllipsoid(), ...; tessellated by vtkParametricFunctionSource at
    `resolution` x `resolution`) or a Python function (u, v) -> (x, y, z) over [0, 1) x [0, 1)
    that closes on itself in both u and v (a torus-like surface; a pole, all points alike at
    v = 0, is merged). The seams are joined by merging coincident points (vtkCleanPolyData) and
    the orientation fixed by vtkPolyDataToFRep; a surface that is still not closed raises
    FRepError naming its open edges. The error of F is that of the tessellation."""
    from vtkmodules.vtkCommonComputationalGeometry import vtkParametricFunction
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter
    from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource
    resolution = int(resolution)
    if resolution < 3:
        raise ValueError("parametric: resolution must be at least 3")
    if isinstance(surface, vtkParametricFunction):
        tessellation = vtkParametricFunctionSource()
        tessellation.SetParametricFunction(surface)
        tessellation.SetUResolution(resolution)
        tessellation.SetVResolution(resolution)
        tessellation.SetWResolution(resolution)
        update(tessellation)
        mesh = tessellation.GetOutput()
    elif callable(surface):
        mesh = _grid_surface(surface, resolution, resolution)
    else:
        raise TypeError("parametric: give a vtkParametricFunction or a function (u, v) -> (x, y, z)")
    clean = vtkCleanPolyData()
    clean.SetInputData(mesh)
    clean.SetTolerance(1e-9)
    clean.ConvertPolysToLinesOff()
    clean.ConvertLinesToPointsOff()
    clean.ConvertStripsToPolysOn()
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(clean.GetOutputPort())
    triangles.PassLinesOff()
    triangles.PassVertsOff()
    to_frep = vtkPolyDataToFRep()
    to_frep.SetInputConnection(triangles.GetOutputPort())
    update(to_frep)
    result = to_frep.GetOutput().NewInstance()
    result.ShallowCopy(to_frep.GetOutput())
    return result
