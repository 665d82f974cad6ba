#!/usr/bin/env python3
"""Runs a program with LeakSanitizer preloaded and fails on every leak that is ours.

  lsan_report_check.py LIBLSAN THIRD_PARTY_LIST -- COMMAND...

LIBLSAN is gcc's runtime (liblsan.so.0), preloaded into the normal build: it replaces malloc and
reports, at exit, every block no pointer reaches. Qt, VTK, Mesa and X keep caches and singletons
they never free; LSan's own suppressions cannot tell those apart from our leaks (a suppression
matches ANY frame of the allocation's stack, and every allocation of a Qt program has Qt's
event loop below it). So the rule here is on the frame that asked for the memory: the first
frame that is not the allocator (liblsan, libc, libstdc++, the loader). A direct leak whose
allocating frame lies in a library named in THIRD_PARTY_LIST (one file-name prefix a line,
"libQt5Core", "libvtk", ...; '#' comments) is theirs; any other direct leak — our executable,
our libraries, or a library nobody listed — fails. Indirect leaks (reachable only from a leaked
block) follow their direct leak and are not judged on their own.

The command's own exit code must be 0. Prints the leaks by owner.
"""
import os
import re
import subprocess
import sys
import tempfile

ALLOCATOR = ("liblsan", "libc.so", "libc-", "libstdc++", "ld-linux", "libgcc_s")
FRAME = re.compile(r"^\s*#\d+ 0x[0-9a-f]+(?: in (?P<function>.*?))?\s+\(?"
                   r"(?P<module>/[^+()\s]+|<unknown module>)\+?(?:0x|\))")
LEAK = re.compile(r"^(Direct|Indirect) leak of (\d+) byte\(s\) in (\d+) object")


def allocating_module(frames):
    for function, module in frames:
        name = os.path.basename(module)
        if not name.startswith(ALLOCATOR):
            return name, function
    return None, None


def parse(report):
    """[(kind, bytes, objects, [(function, module)...], raw lines)] of every leak in a report."""
    leaks = []
    for line in report.splitlines():
        match = LEAK.match(line)
        if match:
            leaks.append((match.group(1), int(match.group(2)), int(match.group(3)), [], [line]))
            continue
        if leaks and line.strip().startswith("#"):
            leaks[-1][4].append(line)
        frame = FRAME.match(line)
        if frame and leaks:
            leaks[-1][3].append((frame.group("function") or "?", frame.group("module")))
    return leaks


def main():
    if len(sys.argv) < 5 or sys.argv[3] != "--":
        sys.exit(__doc__)
    liblsan, listing, command = sys.argv[1], sys.argv[2], sys.argv[4:]
    third_party = []
    with open(listing) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line:
                third_party.append(line)
    with tempfile.TemporaryDirectory() as work:
        log = os.path.join(work, "lsan")
        env = dict(os.environ)
        env["LD_PRELOAD"] = liblsan
        # exitcode=0: the verdict is ours, not LSan's. The fast (frame-pointer) unwinder: the
        # slow one deadlocks in libgcc_s when llvmpipe's JIT registers its unwind tables (seen).
        # Its first frame after the interceptor is exact (the return address of malloc/new,
        # which LSan both replaces), and that is the frame the rule reads.
        env["LSAN_OPTIONS"] = ("exitcode=0:malloc_context_size=24:"
                               "symbolize=1:report_objects=0:log_path=" + log)
        run = subprocess.run(command, env=env)
        reports = [os.path.join(work, n) for n in os.listdir(work) if n.startswith("lsan")]
        text = "".join(open(r, errors="replace").read() for r in reports)
    if run.returncode != 0:
        print(text[-4000:])
        print(f"FAIL: {command[0]} exited with {run.returncode}")
        return 1
    if "LeakSanitizer" not in text and reports:
        print(text[-4000:])
    leaks = parse(text)
    ours, theirs, indirect, unmapped = [], {}, 0, 0
    for kind, size, objects, frames, raw in leaks:
        if kind == "Indirect":
            indirect += size
            continue
        module, function = allocating_module(frames)
        if module == "<unknown module>":
            # Code in no mapped file: llvmpipe's JIT or a plug-in Qt has unloaded. Ours is
            # always mapped (the executable, libFRepKit*.so are never unloaded).
            unmapped += size
        elif module and any(module.startswith(p) for p in third_party):
            theirs[module] = theirs.get(module, 0) + size
        else:
            ours.append((size, objects, module, raw))
    print(f"LeakSanitizer: {len(leaks)} leak reports ({sum(1 for l in leaks if l[0] == 'Direct')}"
          f" direct, {indirect} bytes indirect); reports found: {len(reports)}")
    print(f"  allocated from code in no mapped file (JIT, unloaded plug-ins): {unmapped} bytes")
    for module, size in sorted(theirs.items(), key=lambda m: -m[1]):
        print(f"  third-party (listed): {module}: {size} bytes")
    for size, objects, module, raw in ours:
        print(f"FAIL: {size} bytes in {objects} objects allocated from {module}:")
        for line in raw[:14]:
            print("    ", line.strip())
    if not reports:
        # LSan writes its log only when it found something; check that it was really loaded.
        print("note: no leak report (nothing leaked, or LSan did not run)")
    print(f"{len(ours)} leaks of ours")
    return 1 if ours else 0


if __name__ == "__main__":
    sys.exit(main())
