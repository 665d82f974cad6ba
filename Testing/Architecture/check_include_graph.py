#!/usr/bin/env python3
"""Check the folder-level #include graph of the repository against the include rules.

The rules are read from the first fenced block after the heading
"## Include rules (checked by Testing/Architecture)" in Documentation/architecture.md (or in the
file given with --rules). Their syntax is described in that document; in short:

    # comment
    include-root  = FRep Multimedia          quoted includes are looked up under these folders
    search        = Apps/frepkit ...          further include directories (names found there are bare)
    module-dirs   = Sources Filters ...       folders whose headers are found by file name ...
    module-header = vtk*.h                    ... when the include's name matches one of these
    vtk           = vtk* QVTK* ...            unresolved names that are VTK headers
    qt            = Q[A-Z]* Qt*/* ...         unresolved names that are Qt headers
    generated     = *.moc FRepKit*Module.h    unresolved names made by the build (not an error)
    ignore        = build* ThirdParty         folders (globs on the path) that are not scanned
    FRep/Compiler: FRep/Language FRep/Library   [no-vtk no-qt qualified]

A unit line names a folder, the units it may include (globs on unit names: "FRep/*", "*") and,
in brackets, its flags: no-vtk, no-qt, qualified, vtk (the unit is VTK code), qt (is Qt code).
A file belongs to the unit with the longest folder that contains it.

Checks: every include edge is allowed; the unit graph has no cycle; no-vtk / no-qt units include
no VTK / Qt header; every quoted include resolves (to a repository file, a generated header or an
external VTK/Qt header), unambiguously, and in "qualified" units other folders' headers are
included through an include root ("Compiler/tape.h"), never by a bare name; every C/C++ file
belongs to a unit. Exit status 0 when everything holds, 1 when something is broken, 2 on a usage
or rules error.

Python 3 standard library only.
"""

import argparse
import fnmatch
import os
import re
import subprocess
import sys
from collections import defaultdict

RULES_HEADING = re.compile(r"^#{1,6}\s+Include rules\b", re.IGNORECASE)
SOURCE_EXTENSIONS = {
    ".c", ".cc", ".cpp", ".cxx", ".c++", ".h", ".hh", ".hpp", ".hxx", ".h++",
    ".txx", ".tpp", ".ipp", ".inl", ".m", ".mm",
}
HEADER_EXTENSIONS = {".h", ".hh", ".hpp", ".hxx", ".h++", ".txx", ".tpp", ".ipp", ".inl"}
KNOWN_FLAGS = {"no-vtk", "no-qt", "qualified", "vtk", "qt"}
DIRECTIVES = {
    "include-root", "search", "module-dirs", "module-header", "vtk", "qt", "generated", "ignore",
}
DEFAULT_IGNORE = ["build", "build*", ".git", ".*"]
INCLUDE_LINE = re.compile(r'^\s*#\s*include\s*(?:(["<])([^">]*)[">]|(.*))')


class RulesError(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Rules


class Unit:
    def __init__(self, name, deps, flags, line):
        self.name = name
        self.deps = deps        # list of unit names or globs
        self.flags = flags      # set of flags
        self.line = line        # line in the rules file

    def allows(self, other):
        if other == self.name:
            return True
        return any(fnmatch.fnmatchcase(other, pattern) for pattern in self.deps)


class Rules:
    def __init__(self):
        self.settings = {name: [] for name in DIRECTIVES}
        self.units = {}
        self.source = ""

    def unit_of(self, path):
        """The unit holding a repository-relative path (longest folder prefix), or None."""
        best = None
        for name in self.units:
            if path.startswith(name + "/") and (best is None or len(name) > len(best)):
                best = name
        return best


def extract_rules_block(text, filename):
    """The lines of the first fenced block after the include-rules heading."""
    lines = text.splitlines()
    start = None
    for index, line in enumerate(lines):
        if RULES_HEADING.match(line):
            start = index + 1
            break
    if start is None:
        raise RulesError(f"{filename}: no heading '## Include rules ...' found")
    fence = None
    block = []
    for index in range(start, len(lines)):
        line = lines[index]
        stripped = line.strip()
        if fence is None:
            if stripped.startswith("```") or stripped.startswith("~~~"):
                fence = stripped[:3]
                first_line = index + 2   # 1-based number of the block's first line
            elif RULES_HEADING.match(line) is None and re.match(r"^#{1,2}\s", line):
                break   # the next section started without a block
            continue
        if stripped.startswith(fence):
            return first_line, block
        block.append(line)
    raise RulesError(f"{filename}: no fenced rules block after the include-rules heading")


def parse_rules(text, filename="rules"):
    rules = Rules()
    rules.source = filename
    first_line, block = extract_rules_block(text, filename)
    for offset, raw in enumerate(block):
        number = first_line + offset
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        where = f"{filename}:{number}"
        directive = re.match(r"^([a-z-]+)\s*=\s*(.*)$", line)
        if directive:
            key, value = directive.group(1), directive.group(2).split()
            if key not in DIRECTIVES:
                raise RulesError(f"{where}: unknown directive '{key}' "
                                 f"(known: {', '.join(sorted(DIRECTIVES))})")
            rules.settings[key].extend(value)
            continue
        unit = re.match(r"^([^:\s]+)\s*:\s*([^\[\]]*?)\s*(?:\[([^\]]*)\])?\s*$", line)
        if not unit:
            raise RulesError(f"{where}: cannot read rule line: {raw.strip()}")
        name = unit.group(1).strip("/")
        if any(ch in name for ch in "*?[]"):
            raise RulesError(f"{where}: a unit is a folder, not a pattern: {name}")
        if name in rules.units:
            raise RulesError(f"{where}: unit {name} is defined twice "
                             f"(first on line {rules.units[name].line})")
        deps = [dep.strip("/") for dep in unit.group(2).split()]
        flags = set((unit.group(3) or "").split())
        unknown = flags - KNOWN_FLAGS
        if unknown:
            raise RulesError(f"{where}: unknown flag(s) {' '.join(sorted(unknown))} "
                             f"(known: {' '.join(sorted(KNOWN_FLAGS))})")
        rules.units[name] = Unit(name, deps, flags, number)
    if not rules.units:
        raise RulesError(f"{filename}: the rules block names no unit")
    for unit in rules.units.values():
        for dep in unit.deps:
            if not any(fnmatch.fnmatchcase(other, dep) for other in rules.units):
                raise RulesError(f"{filename}:{unit.line}: {unit.name} may include '{dep}', "
                                 "which names no unit")
    if not rules.settings["ignore"]:
        rules.settings["ignore"] = list(DEFAULT_IGNORE)
    if not rules.settings["module-header"]:
        rules.settings["module-header"] = ["vtk*.h"]
    return rules


# --------------------------------------------------------------------------------------------
# Files and includes


def is_source(path):
    return os.path.splitext(path)[1].lower() in SOURCE_EXTENSIONS


def ignored(path, patterns):
    parts = path.split("/")[:-1]
    for index, part in enumerate(parts):
        prefix = "/".join(parts[: index + 1])
        for pattern in patterns:
            if fnmatch.fnmatchcase(part, pattern) or fnmatch.fnmatchcase(prefix, pattern):
                return True
    return False


def list_files(root):
    """Repository-relative paths of all files: git's tracked files when root is a git work tree,
    otherwise a walk of the folder."""
    root = os.path.abspath(root)
    try:
        top = subprocess.run(["git", "-C", root, "rev-parse", "--show-toplevel"],
                             capture_output=True, text=True, check=True).stdout.strip()
        if os.path.realpath(top) == os.path.realpath(root):
            # Tracked files and new ones git does not ignore: a file is checked from the moment
            # it exists, not from its first commit; build trees and the like are ignored.
            out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others",
                                  "--exclude-standard"],
                                 capture_output=True, check=True).stdout
            names = [name for name in out.decode("utf-8", "replace").split("\0") if name]
            # Files deleted in the work tree but not yet committed are gone.
            return sorted(name for name in names if os.path.isfile(os.path.join(root, name)))
    except (OSError, subprocess.CalledProcessError):
        pass
    found = []
    for folder, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d != ".git")
        rel = os.path.relpath(folder, root)
        for name in files:
            found.append(name if rel == "." else f"{rel}/{name}".replace(os.sep, "/"))
    return sorted(found)


def strip_comments(text):
    """The text with /* */ and // comments blanked, keeping line numbers and string literals."""
    out = []
    i, n = 0, len(text)
    state = None   # None, "block", "line", '"', "'"
    while i < n:
        ch = text[i]
        nxt = text[i + 1] if i + 1 < n else ""
        if state is None:
            if ch == "/" and nxt == "*":
                state, i = "block", i + 2
                out.append("  ")
                continue
            if ch == "/" and nxt == "/":
                state, i = "line", i + 2
                continue
            if ch in "\"'":
                state = ch
            out.append(ch)
        elif state == "block":
            if ch == "*" and nxt == "/":
                state, i = None, i + 2
                out.append("  ")
                continue
            out.append("\n" if ch == "\n" else " ")
        elif state == "line":
            if ch == "\n":
                state = None
                out.append(ch)
        else:   # inside a string or character literal
            if ch == "\\" and nxt:
                out.append(ch + nxt)
                i += 2
                continue
            if ch == state or ch == "\n":
                state = None
            out.append(ch)
        i += 1
    return "".join(out)


def read_includes(path):
    """[(line, kind, name)] with kind '"', '<' or 'macro' (a computed include)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            text = handle.read()
    except OSError:
        return []
    result = []
    for number, line in enumerate(strip_comments(text).splitlines(), start=1):
        if "include" not in line:
            continue
        match = INCLUDE_LINE.match(line)
        if not match:
            continue
        if match.group(1):
            result.append((number, match.group(1), match.group(2).strip()))
        else:
            result.append((number, "macro", (match.group(3) or "").strip()))
    return result


# --------------------------------------------------------------------------------------------
# Resolution


class Resolver:
    def __init__(self, rules, files):
        self.rules = rules
        self.files = set(files)
        self.module_headers = defaultdict(list)
        module_dirs = [d.strip("/") for d in rules.settings["module-dirs"]]
        for path in files:
            if os.path.splitext(path)[1].lower() not in HEADER_EXTENSIONS:
                continue
            if any(path.startswith(d + "/") for d in module_dirs):
                self.module_headers[os.path.basename(path)].append(path)

    def _join(self, folder, name):
        joined = os.path.normpath(os.path.join(folder, name)).replace(os.sep, "/")
        return None if joined.startswith("../") or joined == ".." else joined

    def resolve(self, including, kind, name):
        """(how, path, alternatives): how is 'relative', 'root', 'search', 'module' or None."""
        settings = self.rules.settings
        candidates = []
        if kind == '"':
            here = self._join(os.path.dirname(including), name)
            if here in self.files:
                candidates.append(("relative", here))
        for root in settings["include-root"]:
            path = self._join(root.strip("/"), name)
            if path in self.files:
                candidates.append(("root", path))
        for folder in settings["search"]:
            path = self._join(folder.strip("/"), name)
            if path in self.files:
                candidates.append(("search", path))
        if "/" not in name and any(fnmatch.fnmatchcase(name, p)
                                   for p in settings["module-header"]):
            for path in self.module_headers.get(name, []):
                candidates.append(("module", path))
        if not candidates:
            return None, None, []
        how, path = candidates[0]
        others = [p for h, p in candidates[1:] if p != path]
        return how, path, others


def matches(name, patterns):
    return any(fnmatch.fnmatchcase(name, p) for p in patterns)


# --------------------------------------------------------------------------------------------
# The check


class Report:
    def __init__(self):
        self.errors = []
        self.warnings = []

    def error(self, where, include, message):
        self.errors.append((where, include, message))

    def warn(self, message):
        self.warnings.append(message)


def find_cycles(edges):
    """Strongly connected components with more than one unit, as lists of units."""
    graph = defaultdict(set)
    for (a, b) in edges:
        if a != b:
            graph[a].add(b)
            graph.setdefault(b, set())
    index, low, on_stack, stack, result = {}, {}, set(), [], []
    counter = [0]

    def visit(start):
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter[0]
        counter[0] += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter[0]
                    counter[0] += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph[child]))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    result.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return result


def cycle_path(component, edges):
    """One cycle through the component, as a list of units ending where it started."""
    members = set(component)
    graph = defaultdict(list)
    for (a, b) in sorted(edges):
        if a != b and a in members and b in members:
            graph[a].append(b)
    start = component[0]
    # Breadth-first search for the shortest way back to start.
    previous = {start: None}
    queue = [start]
    while queue:
        node = queue.pop(0)
        for child in graph[node]:
            if child == start:
                path = [node]
                while previous[path[-1]] is not None:
                    path.append(previous[path[-1]])
                return list(reversed(path)) + [start]
            if child not in previous:
                previous[child] = node
                queue.append(child)
    return component + [start]


def check(root, rules):
    report = Report()
    settings = rules.settings
    all_files = list_files(root)
    sources = [p for p in all_files
               if is_source(p) and not ignored(p, settings["ignore"])]
    resolver = Resolver(rules, all_files)
    edges = defaultdict(list)      # (from unit, to unit) -> [(file:line, include)]
    unit_files = defaultdict(int)

    for path in sources:
        unit_name = rules.unit_of(path)
        if unit_name is None:
            report.error(path, None, "the file belongs to no unit of the include rules "
                         "(document its folder in the rules)")
            continue
        unit = rules.units[unit_name]
        unit_files[unit_name] += 1
        for line, kind, name in read_includes(os.path.join(root, path)):
            where = f"{path}:{line}"
            shown = f'"{name}"' if kind == '"' else (f"<{name}>" if kind == "<" else name)
            if kind == "macro":
                report.warn(f"{where}: computed #include {name} is not checked")
                continue
            how, target, others = resolver.resolve(path, kind, name)
            if target is None:
                is_vtk = matches(name, settings["vtk"])
                is_qt = matches(name, settings["qt"])
                if is_vtk and "no-vtk" in unit.flags:
                    report.error(where, shown, f"{unit_name} is no-vtk but includes a VTK header")
                if is_qt and "no-qt" in unit.flags:
                    report.error(where, shown, f"{unit_name} is no-qt but includes a Qt header")
                if kind == '"' and not (is_vtk or is_qt or matches(name, settings["generated"])):
                    report.error(where, shown, "the quoted include resolves to no repository "
                                 "file (nor a generated, VTK or Qt header named in the rules)")
                continue
            target_unit = rules.unit_of(target)
            if target_unit is None:
                # The header itself is reported as unassigned; no edge can be judged.
                continue
            edges[(unit_name, target_unit)].append((where, shown))
            target_flags = rules.units[target_unit].flags
            if not unit.allows(target_unit):
                allowed = " ".join(unit.deps) or "(nothing but itself)"
                report.error(where, shown, f"{unit_name} may not include {target_unit} "
                             f"({target}); {unit_name} may include: {allowed}")
            if "vtk" in target_flags and "no-vtk" in unit.flags:
                report.error(where, shown, f"{unit_name} is no-vtk but includes {target}, "
                             f"VTK code of {target_unit}")
            if "qt" in target_flags and "no-qt" in unit.flags:
                report.error(where, shown, f"{unit_name} is no-qt but includes {target}, "
                             f"Qt code of {target_unit}")
            if others and how in ("search", "module"):
                report.error(where, shown, f"ambiguous include: found as {target} and as "
                             f"{', '.join(others)} (a bare name that can be shadowed)")
            if "qualified" in unit.flags:
                if how == "relative" and target_unit != unit_name:
                    report.error(where, shown, f"{unit_name} must include other folders' "
                                 f"headers through an include root, not by a relative path "
                                 f"({target} is in {target_unit})")
                elif how in ("search", "module"):
                    qualified = qualified_name(target, settings["include-root"])
                    hint = f'; write "{qualified}"' if qualified else \
                        f"; {target} is under no include root"
                    report.error(where, shown, f"{unit_name} must include headers by folder "
                                 f"through an include root, not by a bare name{hint}")

    for name, unit in sorted(rules.units.items()):
        if unit_files[name] == 0:
            report.warn(f"unit {name} ({rules.source}:{unit.line}) holds no source file")

    for component in find_cycles(edges.keys()):
        path = cycle_path(component, edges.keys())
        steps = []
        for a, b in zip(path, path[1:]):
            where, include = edges[(a, b)][0]
            count = len(edges[(a, b)])
            more = f" and {count - 1} more" if count > 1 else ""
            steps.append(f"  {a} -> {b}: {where} {include}{more}")
        report.error(None, None, "include cycle between units " + " -> ".join(path) + "\n"
                     + "\n".join(steps))
    return report, edges, sources


def qualified_name(target, roots):
    for root in roots:
        root = root.strip("/")
        if target.startswith(root + "/"):
            return target[len(root) + 1:]
    return None


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=".",
                        help="the repository root (default: the current folder)")
    parser.add_argument("--rules", help="the rules document (default: "
                        "ROOT/Documentation/architecture.md)")
    parser.add_argument("--graph", action="store_true",
                        help="also print the unit graph (edges with include counts)")
    parser.add_argument("--warnings", action="store_true",
                        help="also print warnings (empty units, computed includes)")
    args = parser.parse_args(argv)

    root = os.path.abspath(args.root)
    rules_path = os.path.abspath(args.rules or os.path.join(root, "Documentation",
                                                            "architecture.md"))
    shown_rules = os.path.relpath(rules_path, root) \
        if rules_path.startswith(root + os.sep) else rules_path
    try:
        with open(rules_path, encoding="utf-8") as handle:
            rules = parse_rules(handle.read(), shown_rules)
    except OSError as error:
        print(f"check_include_graph: cannot read rules: {error}", file=sys.stderr)
        return 2
    except RulesError as error:
        print(f"check_include_graph: rules error: {error}", file=sys.stderr)
        return 2

    report, edges, sources = check(root, rules)

    if args.graph:
        print("unit graph (from -> to: includes):")
        for (a, b), uses in sorted(edges.items()):
            if a != b:
                print(f"  {a} -> {b}: {len(uses)}")
    if args.warnings:
        for message in report.warnings:
            print(f"warning: {message}")
    for where, include, message in report.errors:
        if where is None:
            print(f"error: {message}")
        elif include is None:
            print(f"{where}: error: {message}")
        else:
            print(f"{where}: error: #include {include}: {message}")
    unit_edges = sum(1 for (a, b) in edges if a != b)
    print(f"check_include_graph: {len(sources)} files, {len(rules.units)} units, "
          f"{unit_edges} unit edges, {len(report.errors)} error(s), "
          f"{len(report.warnings)} warning(s) [rules: {shown_rules}]")
    return 1 if report.errors else 0


if __name__ == "__main__":
    sys.exit(main())
