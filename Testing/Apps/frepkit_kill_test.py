#!/usr/bin/env python3
"""Kills every frepkit subcommand at random moments and checks what is left on disk.

For each subcommand (eval, mesh, slice, hfp, map, demo) the reference outputs of an "old" and a
"new" run are made first, each uninterrupted. Then, trial after trial, a directory holding the
complete old outputs is overwritten by the new run, which gets SIGINT or SIGTERM after a random
delay (seeded). Afterwards every output must be byte for byte the old or the new reference, no
temporary (NAME.tmp-PID) may be left anywhere in the directory, and the exit code must say what
happened: 0 (finished first: every output new), 128 + the signal (stopped), or death by the
signal itself outside frepkit's guard: before it is installed or after the command has finished
(then every output is old, or every output is new).

map and demo write dozens of files; their old and new runs are the same settings with --force
(every frame rendered again: other settings would change the frames' fingerprint and remove the
stale frames up front), so for them the check is "complete and equal to the reference", not
"old or new". Their manifests record timings: they are compared without the "seconds" and
"stages" entries.

  frepkit_kill_test.py FREPKIT SOURCE_DIR SHARED_DIR [--seed N] [--seconds S]
"""
import argparse
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time


def timed_run(command, cwd):
    start = time.monotonic()
    run = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"reference run failed ({run.returncode}): {' '.join(command)}\n{run.stderr}")
    return time.monotonic() - start


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in ("seconds", "stages")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def content(path):
    """A file's content as compared: bytes, or a manifest without its timings."""
    with open(path, "rb") as f:
        data = f.read()
    if path.endswith("manifest.json"):
        try:
            return ("json", json.dumps(without_timings(json.loads(data)), sort_keys=True))
        except ValueError:
            return ("broken json", data)
    return ("bytes", data)


def snapshot(directory):
    """Every file under directory (relative name -> content)."""
    files = {}
    for root, _, names in os.walk(directory):
        for name in names:
            full = os.path.join(root, name)
            files[os.path.relpath(full, directory)] = content(full)
    return files


def temporaries(directory):
    return [os.path.join(r, n) for r, _, ns in os.walk(directory) for n in ns if ".tmp-" in n]


MIN_TRIALS = 6


class Case:
    """One subcommand: how to make the old and the new outputs in a directory (cwd = it)."""

    def __init__(self, name, old, new, settle=0.0):
        self.name, self.old, self.new = name, old, new
        self.settle = settle  # the same settings for old and new (map, demo): see the docstring


def make_cases(frepkit, source, shared, work):
    examples = os.path.join(source, "Examples")
    # A points file of 300,000 points for eval (old: the first 100,000).
    rng = random.Random(7)
    points = os.path.join(work, "points.txt")
    few = os.path.join(work, "few_points.txt")
    with open(points, "w") as p, open(few, "w") as q:
        for i in range(300000):
            line = "%.6f %.6f %.6f\n" % tuple(rng.uniform(-10, 10) for _ in range(3))
            p.write(line)
            if i < 100000:
                q.write(line)
    robot = os.path.join(examples, "homotopic", "robot.hf")
    # hfp on a model of the shared HyperFun collection (a torus united with a piriform).
    hfp_model = os.path.join(shared, "hyperfun", "models", "y7goto__hfa", "HFMain_defaultHFCode.hf")
    if not os.path.isfile(hfp_model):
        sys.exit(f"missing {hfp_model} (../shared)")
    ball = os.path.join(work, "morph4d.hf")
    shutil.copy(os.path.join(examples, "mapping", "morph4d.hf"), ball)
    mapping = os.path.join(work, "small.json")
    with open(mapping, "w") as f:
        json.dump({
            "coordinates": {
                "x1": [{"type": "world", "axis": "x", "range": [-2.4, 2.4]}],
                "x2": [{"type": "world", "axis": "y", "range": [-2.4, 2.4]}],
                "x3": [{"type": "world", "axis": "z", "range": [-2.4, 2.4]}],
                "x4": [{"type": "dynamic", "range": [0, 1]},
                       {"type": "spreadsheet", "axis": "columns", "range": [0, 1], "step": 0.5},
                       {"type": "audio", "parameter": "pitch", "range": [0, 1],
                        "target": [262, 523]}]},
            "animation": {"duration": 0.5, "fps": 12},
            "world": {"resolution": 32},
            "render": {"width": 120, "height": 90}}, f)
    fk = [frepkit]
    return [
        Case("eval",
             fk + ["eval", robot, "-p", few, "--output", "values.txt"],
             fk + ["eval", robot, "-p", points, "--output", "values.txt"]),
        Case("mesh",
             fk + ["mesh", robot, "--grid", "48", "-o", "robot.stl", "-q"],
             fk + ["mesh", robot, "--grid", "160", "-o", "robot.stl", "-q"]),
        Case("slice",
             fk + ["slice", robot, "--fix", "x3=0", "--grid", "300", "-o", "robot.png", "-q"],
             fk + ["slice", robot, "--fix", "x3=0", "--grid", "1000", "-o", "robot.png", "-q"]),
        Case("hfp",
             fk + ["hfp", hfp_model, "-g", "40", "-stl", "shape.stl", "-wrl", "shape.wrl"],
             fk + ["hfp", hfp_model, "-g", "120", "-stl", "shape.stl", "-wrl", "shape.wrl"]),
        Case("map",
             fk + ["map", ball, mapping, "-O", ".", "-q", "--force"],
             fk + ["map", ball, mapping, "-O", ".", "-q", "--force"], settle=1),
        Case("demo",
             fk + ["demo", "homotopic", "-O", ".", "-q", "--force", "--frames", "3",
                   "--resolution", "8", "--mesh-grid", "40", "--method", "mesh",
                   "--examples", examples],
             fk + ["demo", "homotopic", "-O", ".", "-q", "--force", "--frames", "3",
                   "--resolution", "8", "--mesh-grid", "40", "--method", "mesh",
                   "--examples", examples],
             settle=1),
    ]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("frepkit")
    parser.add_argument("source")
    parser.add_argument("shared")
    parser.add_argument("--seed", type=int, default=18)
    parser.add_argument("--seconds", type=float, default=80.0)  # references included
    args = parser.parse_args()
    rng = random.Random(args.seed)
    # ctest's timeout sends SIGTERM: leave through the finally below, which removes the work.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("terminated"))
    start = time.monotonic()
    work = tempfile.mkdtemp(prefix="frepkit-kill-")
    failures = []
    try:
        cases = make_cases(os.path.realpath(args.frepkit), os.path.realpath(args.source),
                           os.path.realpath(args.shared), work)
        # References first (they also tell how long a run takes, the range of the delays).
        references = {}
        for case in cases:
            old_dir = os.path.join(work, case.name + "-old")
            new_dir = os.path.join(work, case.name + "-new")
            os.makedirs(old_dir)
            os.makedirs(new_dir)
            timed_run(case.old, old_dir)
            duration = timed_run(case.new, new_dir)
            old, new = snapshot(old_dir), snapshot(new_dir)
            if not case.settle and any(old.get(k) == v for k, v in new.items()):
                sys.exit(f"{case.name}: the old and new references must differ in every file")
            references[case.name] = (old_dir, old, new, duration)
        print(f"seed {args.seed}; references made in {time.monotonic() - start:.1f} s")
        for index, case in enumerate(cases):
            old_dir, old, new, duration = references[case.name]
            # What is left of the whole budget, shared by the subcommands still to try; at least
            # MIN_TRIALS each whatever the machine's load.
            budget = (start + args.seconds - time.monotonic()) / (len(cases) - index)
            counts = {"trials": 0, "finished": 0, "stopped": 0, "killed outside the guard": 0,
                      "temporary seen at the signal": 0, "all old": 0, "all new": 0, "mixed": 0}
            deadline = time.monotonic() + budget
            trial_dir = os.path.join(work, case.name + "-trial")
            while time.monotonic() < deadline or counts["trials"] < MIN_TRIALS:
                shutil.rmtree(trial_dir, ignore_errors=True)
                shutil.copytree(old_dir, trial_dir)
                delay = rng.uniform(0, 1.15 * duration)
                sig = rng.choice([signal.SIGINT, signal.SIGTERM])
                process = subprocess.Popen(case.new, cwd=trial_dir, stdout=subprocess.DEVNULL,
                                           stderr=subprocess.PIPE, text=True)
                time.sleep(delay)
                if temporaries(trial_dir):
                    counts["temporary seen at the signal"] += 1
                if process.poll() is None:
                    process.send_signal(sig)
                _, stderr = process.communicate()
                code = process.returncode
                counts["trials"] += 1
                label = f"{case.name} trial {counts['trials']} ({sig.name} after {delay:.3f} s)"
                after = snapshot(trial_dir)
                left = temporaries(trial_dir)
                if left:
                    failures.append(f"{label}: temporaries left: {left}")
                names = set(old) | set(new)
                extra = set(after) - names
                if extra:
                    failures.append(f"{label}: unexpected files {sorted(extra)}")
                state = {"old": 0, "new": 0}
                for name in sorted(names):
                    got = after.get(name)
                    if got is not None and got == new.get(name):
                        state["new"] += 1  # map/demo: old == new, counted as new
                    elif got is not None and got == old.get(name):
                        state["old"] += 1
                    else:
                        failures.append(f"{label}: {name} is neither the old nor the new file"
                                        f" ({'missing' if got is None else got[0] + ', differs'})")
                if code == 0:
                    counts["finished"] += 1
                    if state["old"]:
                        failures.append(f"{label}: exit 0 but {state['old']} files are old")
                elif code == 128 + sig:
                    counts["stopped"] += 1
                elif code == -sig:
                    # The default action: the signal came before frepkit installed its guard
                    # (nothing written yet) or after the command had finished (all written).
                    counts["killed outside the guard"] += 1
                    if state["new"] and state["old"]:
                        failures.append(f"{label}: killed by the signal between two outputs")
                else:
                    failures.append(f"{label}: exit code {code}: {stderr.strip()[-300:]}")
                if state["new"] and state["old"]:
                    counts["mixed"] += 1
                elif state["new"]:
                    counts["all new"] += 1
                else:
                    counts["all old"] += 1
            if case.settle:
                del counts["all old"], counts["mixed"]  # old == new: not distinguishable
            print(f"{case.name}: run {duration:.2f} s; " +
                  ", ".join(f"{k} {v}" for k, v in counts.items()))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for failure in failures[:40]:
        print("FAIL:", failure)
    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
