"""Runs TestPluginMPI.py with pvbatch on 1 rank and with mpiexec -n N pvbatch (N = 2 unless
given) and checks: the same total triangle count, point count and bounds as one process; every
rank made a non-empty piece smaller than the whole (each computed only its piece, a slab along
z: the ranks' z ranges follow each other), for the polygoniser and for the reader's default mesh
(port 1), and rank 0's reader meshed port 1 only once, for its piece; the same sampled image
(extent and values). Run with any Python:
  python3 TestPluginMPIDriver.py PLUGIN SOURCE_DIR [N]"""

import json
import os
import subprocess
import sys
import tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frepkit_test_support import Checker, arguments  # noqa: E402

plugin, source_dir, rest = arguments()
ranks = int(rest[0]) if rest else 2
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "TestPluginMPI.py")
work = tempfile.mkdtemp(prefix="frepkit-mpi-")
t = Checker("TestPluginMPI")

environment = dict(os.environ)
# OpenMPI refuses root without these (containers, CI); harmless otherwise.
environment.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
environment.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")


def run(command, out):
    print(" ".join(command), flush=True)
    done = subprocess.run(command, env=environment, capture_output=True, text=True, timeout=900)
    if done.returncode != 0 or not os.path.exists(out):
        print(done.stdout[-4000:], done.stderr[-4000:])
        t.check(False, "%s failed (status %d)" % (command[0], done.returncode))
        return None
    with open(out) as stream:
        return json.load(stream)


one_out = os.path.join(work, "one.json")
many_out = os.path.join(work, "many.json")
one = run(["pvbatch", script, plugin, source_dir, one_out], one_out)
many = run(["mpiexec", "--oversubscribe", "-n", str(ranks), "pvbatch", script, plugin,
            source_dir, many_out], many_out)
if one and many:
    print(json.dumps({"1 rank": one, "%d ranks" % ranks: many}, indent=1))
    t.check(one["ranks"] == 1 and many["ranks"] == ranks, "rank counts %d, %d" % (one["ranks"], many["ranks"]))
    a, b = one["polygonizer"], many["polygonizer"]
    t.check(a["cells"] > 1000, "one process meshes %d triangles" % a["cells"])
    t.check(a["cells"] == b["cells"], "%d triangles on 1 rank, %d on %d" % (a["cells"], b["cells"], ranks))
    t.check(b["fetched_cells"] == b["cells"], "the fetched pieces hold every triangle")
    for k in range(6):
        t.near(b["bounds"][k], a["bounds"][k], 1e-5, "bounds[%d]" % k)
    t.check(len(b["ranks"]) == ranks, "every rank made a piece: %s" % b["ranks"])
    for r, (cells, zlo, zhi) in b["ranks"].items():
        t.check(0 < cells < a["cells"], "rank %s has %d of %d triangles" % (r, cells, a["cells"]))
    slabs = [b["ranks"][str(r)] for r in range(ranks) if str(r) in b["ranks"]]
    for lower, upper in zip(slabs, slabs[1:]):
        t.check(lower[2] <= upper[1] + 1e-6, "slabs along z in rank order: %s" % slabs)
    t.check(sum(s[0] for s in slabs) == a["cells"], "the pieces add up")
    # The reader's default mesh (port 1) splits like the polygoniser: each rank meshes only its
    # slab (the pieces add up to the one-process mesh), and rank 0 meshed once: the first,
    # whole-object request on port 0 (from FRep Slice) does not mesh port 1 in a parallel run.
    a, b = one["default_mesh"], many["default_mesh"]
    t.check(a["cells"] > 1000, "default mesh: %d triangles" % a["cells"])
    t.check(a["cells"] == b["cells"], "default mesh: %d triangles on 1 rank, %d on %d"
            % (a["cells"], b["cells"], ranks))
    for k in range(6):
        t.near(b["bounds"][k], a["bounds"][k], 1e-5, "default mesh bounds[%d]" % k)
    t.check(len(b["ranks"]) == ranks, "default mesh: every rank made a piece: %s" % b["ranks"])
    for r, (cells, zlo, zhi) in b["ranks"].items():
        t.check(0 < cells < a["cells"], "default mesh: rank %s has %d of %d triangles"
                % (r, cells, a["cells"]))
    mesh_slabs = [b["ranks"][str(r)] for r in range(ranks) if str(r) in b["ranks"]]
    for lower, upper in zip(mesh_slabs, mesh_slabs[1:]):
        t.check(lower[2] <= upper[1] + 1e-6, "default mesh slabs along z: %s" % mesh_slabs)
    t.check(sum(s[0] for s in mesh_slabs) == a["cells"], "default mesh: the pieces add up")
    meshed = [c for c in many["reader_runs"] if c is not None]
    t.check(meshed == [b["ranks"]["0"][0]],
            "rank 0 meshed port 1 once, only its piece: triangles per reader run %s "
            "(None: port 1 not generated), 1 rank: %s" % (many["reader_runs"], one["reader_runs"]))
    t.check([c for c in one["reader_runs"] if c is not None] == [a["cells"]],
            "1 rank: the whole default mesh once: %s" % one["reader_runs"])
    print("default mesh: %d triangles on 1 rank; on %d ranks per rank: %s"
          % (a["cells"], ranks, {r: v[0] for r, v in b["ranks"].items()}))
    # The sampler: every rank samples its extent; the same whole extent and values. (Point
    # counts add the planes shared by neighbouring extents.)
    t.check(one["sampler"]["extent"] == many["sampler"]["extent"], "sampler whole extent")
    t.check(one["sampler"]["f_range"] == many["sampler"]["f_range"], "sampler F range")
    t.check(many["sampler"]["points"] >= one["sampler"]["points"] == 32 ** 3, "sampler points")
    # The ranks share the mapper's cells: the same cells in all, not N copies.
    t.check(one["mapper"]["cells"] > 1000, "mapper: %d cells" % one["mapper"]["cells"])
    t.check(one["mapper"] == many["mapper"], "mapper: %s on 1 rank, %s on %d"
            % (one["mapper"], many["mapper"], ranks))
if t.report():
    sys.exit(1)
