#!/usr/bin/env python3
"""Documentation.ReadmeListsEverything: the README's lists cannot drift from the code.

  readme_lists_everything.py README.md FREPKIT TARGETS_FILE

- the subcommands the README's status paragraph lists ("the command-line tool `frepkit`
  (`check`, ...)") equal those `frepkit --help` prints;
- the CMake targets of "`find_package(FRepKit)` gives the targets ..." equal the FRepKit::
  targets the package exports (FRepKit-targets.cmake, as installed).
Exit 0 when both agree, 1 with the differences otherwise."""
import re
import subprocess
import sys


def readme_subcommands(text):
    match = re.search(r"the command-line tool\s+`frepkit`\s+\((.*?)\), the VTK modules", text, re.S)
    if not match:
        raise SystemExit("README.md: the status paragraph's list of subcommands "
                         "('the command-line tool `frepkit` (`check`, ...)') was not found")
    return set(re.findall(r"`([a-z]+)`", match.group(1)))


def help_subcommands(frepkit):
    out = subprocess.run([frepkit, "--help"], capture_output=True, text=True, check=True).stdout
    section = out.split("Subcommands:", 1)[1]
    return set(re.findall(r"^  ([a-z]+)\s", section, re.M))


def readme_targets(text):
    match = re.search(r"`find_package\(FRepKit\)` gives the targets (.*?);\s+it finds", text, re.S)
    if not match:
        raise SystemExit("README.md: the sentence '`find_package(FRepKit)` gives the targets ...; "
                         "it finds' was not found")
    return {"FRepKit::" + name for name in re.findall(r"`(?:FRepKit)?::(\w+)`", match.group(1))}


def exported_targets(path):
    with open(path, encoding="utf-8") as f:
        return set(re.findall(r"add_library\((FRepKit::\w+)", f.read()))


def compare(what, documented, actual):
    if documented == actual:
        print("ok: the README lists every %s: %s" % (what, ", ".join(sorted(actual))))
        return 0
    for name in sorted(actual - documented):
        print("FAIL: %s %s is missing from the README" % (what, name))
    for name in sorted(documented - actual):
        print("FAIL: the README lists %s %s, which does not exist" % (what, name))
    return 1


def main():
    readme, frepkit, targets = sys.argv[1:4]
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    failures = compare("subcommand", readme_subcommands(text), help_subcommands(frepkit))
    failures += compare("CMake target", readme_targets(text), exported_targets(targets))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
