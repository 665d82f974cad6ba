"""The distributed run (pvbatch, 1 or N ranks): HyperFun Reader -> FRep Slice -> FRep
Polygonizer on Meta5D-like data (Examples/homotopy5d.hf at x4 = x5 = 0.5), plus the reader's
default mesh on port 1 and the sampler. Each rank's piece is tagged with its rank (a
Programmable Filter adds the cell array Rank), the pieces are fetched to rank 0, and the
numbers are written as JSON to the file given after the two usual arguments:
  mpiexec -n 2 pvbatch TestPluginMPI.py PLUGIN SOURCE_DIR OUT.json
TestPluginMPIDriver.py runs it with 1 and 2 ranks and compares."""

import builtins  # paraview.simple's * brings numpy-interface min and max
import json
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import arguments  # noqa: E402

from paraview.simple import *  # noqa: E402,F401,F403
from paraview import servermanager  # noqa: E402

plugin, source_dir, rest = arguments()
out_path = rest[0]
LoadPlugin(plugin, remote=False, ns=globals())

reader = HyperFunReader(FileName=os.path.join(source_dir, "Examples", "homotopy5d.hf"))
reader.CoordinateRanges = [-4, 4, -4, 4, -4, 4, 0, 1, 0, 1]
reader.GeometryResolution = 48
# The reader's executions on rank 0 (where the script runs): the triangles of port 1 after each
# one that generated port 1, None after one that left it alone (DATA_NOT_GENERATED, still set
# when the algorithm's EndEvent fires).
from vtkmodules.vtkCommonExecutionModel import vtkDemandDrivenPipeline  # noqa: E402

reader_runs = []
vtk_reader = reader.GetClientSideObject()


def _reader_ran(caller, event):
    skipped = caller.GetOutputInformation(1).Get(vtkDemandDrivenPipeline.DATA_NOT_GENERATED())
    reader_runs.append(None if skipped else caller.GetOutputDataObject(1).GetNumberOfCells())


vtk_reader.AddObserver("EndEvent", _reader_ran)
fslice = FRepSlice(Input=reader)
fslice.X4 = 0.5
fslice.X5 = 0.5
poly = FRepPolygonizer(Input=fslice, SampleDimensions=[96, 96, 96])
sampler = FRepSampler(Input=fslice, SampleDimensions=[32, 32, 32])

TAG = """
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonCore import vtkIntArray
out = self.GetOutput()
out.ShallowCopy(self.GetInput())
controller = vtkMultiProcessController.GetGlobalController()
rank = controller.GetLocalProcessId() if controller else 0
tag = vtkIntArray()
tag.SetName("Rank")
tag.SetNumberOfTuples(out.GetNumberOfCells())
tag.Fill(rank)
out.GetCellData().AddArray(tag)
"""


def pieces(producer, port=0):
    """Total cells and bounds (data information, reduced over the ranks) and, per rank, the
    cells and z range of its own piece (fetched with the Rank tags)."""
    tagger = ProgrammableFilter(Input=OutputPort(producer, port), Script=TAG,
                                OutputDataSetType="Same as Input")
    tagger.UpdatePipeline()
    info = tagger.GetDataInformation()
    merged = servermanager.Fetch(tagger)
    ranks = merged.GetCellData().GetArray("Rank")
    per_rank = {}
    for c in range(merged.GetNumberOfCells()):
        r = int(ranks.GetValue(c))
        z = merged.GetCell(c).GetBounds()[4:6]
        entry = per_rank.setdefault(r, [0, z[0], z[1]])
        entry[0] += 1
        entry[1] = builtins.min(entry[1], z[0])
        entry[2] = builtins.max(entry[2], z[1])
    return {"cells": info.GetNumberOfCells(), "points": info.GetNumberOfPoints(),
            "bounds": list(info.GetBounds()), "fetched_cells": merged.GetNumberOfCells(),
            "ranks": {str(k): v for k, v in sorted(per_rank.items())}}


controller = servermanager.vtkProcessModule.GetProcessModule().GetGlobalController()
result = {
    "ranks": controller.GetNumberOfProcesses() if controller else 1,
    "polygonizer": pieces(poly),
    "default_mesh": pieces(reader, 1),
}
result["reader_runs"] = reader_runs
sampler.UpdatePipeline()
sinfo = sampler.GetDataInformation()
f = sampler.PointData["F"].GetRange()
result["sampler"] = {"points": sinfo.GetNumberOfPoints(), "extent": list(sinfo.GetExtent()),
                     "f_range": list(f)}
# The mapper shares the cells between the ranks (cell i on rank i % n): the same cells in all.
mreader = HyperFunReader(FileName=os.path.join(source_dir, "Examples", "homotopic", "meta5d.hf"),
                         GenerateGeometry=0)
mreader.CoordinateRanges = [-10, 10, -10, 10, -10, 10, 0, 1, 0, 1]
mapper = MultimediaMapper(Input=mreader, Resolution=24, MappingFileName=os.path.join(
    source_dir, "Examples", "paraview", "meta5d-spreadsheet.json"))
mapper.UpdatePipeline()
minfo = mapper.GetDataInformation()
result["mapper"] = {"cells": minfo.GetNumberOfCells(),
                    "datasets": minfo.DataInformation.GetNumberOfDataSets()}
with open(out_path, "w") as stream:
    json.dump(result, stream, indent=1)
