#!/usr/bin/env python3
"""The public/private line of FRepKit's plain C++ libraries, visible in the tree (issue 26, item 3).

A library is a folder with a CMakeLists.txt under one of the library roots (FRep/<floor>: all
floors are the one engine library; Multimedia/<lib>; Support/<lib>). Its API is the headers
listed in PUBLIC_HEADERS of frepkit_add_library or in frepkit_add_public_headers (what installs);
every other header is private and lives in the folder's detail/ subfolder. The check fails when

  - a header outside detail/ is not listed as public (a private header in plain sight),
  - a listed header does not exist or lies under detail/ (an API that does not install right),
  - a detail/ header is included from outside its library (FRep/* counts as one library), except
    by the tests, benchmarks and fuzz harnesses, which may look inside.

Usage: check_public_headers.py REPO. Python 3 standard library only."""

import os
import re
import sys

LIBRARY_ROOTS = ("FRep", "Multimedia", "Support")
OPEN_TO_ALL = ("Testing", "Benchmarks")
SOURCE_SUFFIXES = (".h", ".hpp", ".c", ".cpp", ".cxx", ".txx")
LIST_RE = re.compile(r"(?:PUBLIC_HEADERS|frepkit_add_public_headers\(\s*\S+)([^)]*)")
INCLUDE_RE = re.compile(r'^[ \t]*#[ \t]*include[ \t]*[<"]([^">]+)[">]', re.M)


def library_folders(repo):
    """[(folder relative to repo, library name)] of every plain library folder."""
    found = []
    for root in LIBRARY_ROOTS:
        base = os.path.join(repo, root)
        if not os.path.isdir(base):
            continue
        for name in sorted(os.listdir(base)):
            folder = os.path.join(root, name)
            if os.path.isfile(os.path.join(repo, folder, "CMakeLists.txt")):
                found.append((folder, root if root == "FRep" else folder))
    return found


def listed_public(cmake_text):
    """The header paths (relative to the folder) that a CMakeLists.txt lists as public."""
    names = set()
    for match in LIST_RE.finditer(cmake_text):
        names.update(re.findall(r"[\w./-]+\.h\b", match.group(1)))
    return names


def headers_in(repo, folder):
    """Every header under folder, relative to it."""
    result = set()
    for dirpath, _, files in os.walk(os.path.join(repo, folder)):
        for name in files:
            if name.endswith((".h", ".hpp")):
                result.add(os.path.relpath(os.path.join(dirpath, name), os.path.join(repo, folder)))
    return result


def is_private(relative):
    return relative.split(os.sep)[0] == "detail"


def check_lists(repo, folders):
    errors = []
    for folder, _ in folders:
        with open(os.path.join(repo, folder, "CMakeLists.txt"), encoding="utf-8") as f:
            public = listed_public(f.read())
        present = headers_in(repo, folder)
        for header in sorted(present):
            if not is_private(header) and header not in public:
                errors.append(f"{folder}/{header}: not listed as public; a private header goes in "
                              f"{folder}/detail/")
        for header in sorted(public):
            if header not in present:
                errors.append(f"{folder}/CMakeLists.txt: public header {header} does not exist")
            elif is_private(header):
                errors.append(f"{folder}/CMakeLists.txt: {header} is listed as public but lies in "
                              "detail/")
    return errors


def check_includes(repo, folders):
    """Includes of another library's detail/ headers, outside the tests and benchmarks."""
    owner = {}  # include name ("Eval/detail/x.h") -> library
    for folder, library in folders:
        root = folder.split("/")[0]
        for header in headers_in(repo, folder):
            if is_private(header):
                owner[os.path.relpath(os.path.join(folder, header), root)] = library
    errors = []
    for dirpath, dirnames, files in os.walk(repo):
        relative_dir = os.path.relpath(dirpath, repo)
        dirnames[:] = [d for d in dirnames if not d.startswith((".", "build"))]
        top = relative_dir.split(os.sep)[0]
        if top in OPEN_TO_ALL:
            continue
        for name in files:
            if not name.endswith(SOURCE_SUFFIXES):
                continue
            path = os.path.normpath(os.path.join(relative_dir, name))
            parts = path.split(os.sep)
            library = None
            if parts[0] in LIBRARY_ROOTS and len(parts) > 2:
                library = "FRep" if parts[0] == "FRep" else "/".join(parts[:2])
            with open(os.path.join(repo, path), encoding="utf-8", errors="replace") as f:
                text = f.read()
            for match in INCLUDE_RE.finditer(text):
                target = owner.get(match.group(1))
                if target is not None and target != library:
                    line = text.count("\n", 0, match.start()) + 1
                    errors.append(f"{path}:{line}: includes {match.group(1)}, private to {target}")
    return errors


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-2], file=sys.stderr)
        return 2
    repo = os.path.abspath(argv[1])
    folders = library_folders(repo)
    errors = check_lists(repo, folders) + check_includes(repo, folders)
    for error in errors:
        print(error)
    public = sum(len([h for h in headers_in(repo, f) if not is_private(h)]) for f, _ in folders)
    private = sum(len([h for h in headers_in(repo, f) if is_private(h)]) for f, _ in folders)
    print(f"check_public_headers: {len(folders)} library folders, {public} public and {private} "
          f"private headers, {len(errors)} error(s)")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
