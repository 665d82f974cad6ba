#!/usr/bin/env python3
"""Runs a command under strace and checks that each named output was put in place durably:
fsync of the file under its temporary name, then the rename of that temporary onto the name,
then fsync of the file's directory, in this order (durable_rename in Multimedia/Media).

  durable_write_check.py OUTPUT[,OUTPUT...] -- COMMAND...

OUTPUTs are absolute paths; the command must write each of them (exit code 0). strace's -y
prints the path behind every descriptor, so fsync(3</dir/out.stl.tmp-42>) names its file.
Exit 0 when every output passes, 1 otherwise (each failure is printed).
"""
import os
import re
import subprocess
import sys
import tempfile

CALL = re.compile(r'^(?:\[pid\s+\d+\]\s+|\d+\s+)?(\w+)\((.*)\)\s+=\s+(-?\d+)')
FD_PATH = re.compile(r'^\d+<(.*)>$')


UNFINISHED = re.compile(r'^(\d+)\s+(.*) <unfinished \.\.\.>$')
RESUMED = re.compile(r'^(\d+)\s+<\.\.\. \w+ resumed>(.*)$')


def parse(trace):
    """(call, arguments text, result) for every completed system call, in the order they
    completed. With several threads strace splits a call into "<unfinished ...>" and
    "<... resumed>" lines: they are joined (per thread id) first."""
    calls = []
    pending = {}
    for line in trace.splitlines():
        unfinished = UNFINISHED.match(line)
        if unfinished:
            pending[unfinished.group(1)] = unfinished.group(2)
            continue
        resumed = RESUMED.match(line)
        if resumed and resumed.group(1) in pending:
            line = resumed.group(1) + " " + pending.pop(resumed.group(1)) + resumed.group(2)
        match = CALL.match(line)
        if match:
            calls.append((match.group(1), match.group(2), int(match.group(3))))
    return calls


def renamed(call, args):
    """(from, to) of a rename, renameat or renameat2 with absolute paths."""
    names = re.findall(r'"((?:[^"\\]|\\.)*)"', args)
    if call in ("rename", "renameat", "renameat2") and len(names) >= 2:
        return names[0], names[1]
    return None


def synced(call, args):
    if call not in ("fsync", "fdatasync"):
        return None
    match = FD_PATH.match(args.strip())
    return match.group(1) if match else None


def check(output, calls):
    """The problem with output's durable write, or None."""
    directory = os.path.dirname(output)
    for i, (call, args, result) in enumerate(calls):
        pair = renamed(call, args)
        if not pair or pair[1] != output or result != 0:
            continue
        temporary = pair[0]
        if not any(synced(c, a) == temporary and r == 0 for c, a, r in calls[:i]):
            return f"{output}: renamed from {temporary} without an fsync of it before"
        if not any(synced(c, a) == directory and r == 0 for c, a, r in calls[i + 1:]):
            return f"{output}: no fsync of {directory} after the rename"
        return None
    return f"{output}: never renamed into place"


def main():
    if "--" not in sys.argv or sys.argv.index("--") != 2:
        sys.exit(__doc__)
    outputs = [o for o in sys.argv[1].split(",") if o]
    command = sys.argv[3:]
    with tempfile.NamedTemporaryFile(suffix=".strace") as log:
        run = subprocess.run(["strace", "-f", "-y", "-qq", "-o", log.name, "-e",
                              "trace=fsync,fdatasync,rename,renameat,renameat2"] + command,
                             capture_output=True, text=True)
        trace = open(log.name).read()
    if run.returncode != 0:
        print(run.stdout, run.stderr, sep="\n")
        print(f"FAIL: {command[0]} exited with {run.returncode}")
        return 1
    calls = parse(trace)
    problems = [p for p in (check(o, calls) for o in outputs) if p]
    for output in outputs:
        print(("FAIL: " if any(p.startswith(output + ":") for p in problems) else "PASS: ") +
              output)
    for problem in problems:
        print("  ", problem)
    print(f"{len(calls)} traced calls, {len(outputs)} outputs, {len(problems)} failures")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
