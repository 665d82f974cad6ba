#!/usr/bin/env python3
"""Function length outside tests and benchmarks (issue 26, item 7): no function over LIMIT lines.

A brace counter over C++ text with comments, string and character literals and preprocessor
lines blanked out. A brace opens a function body when, at namespace or class scope, the text
since the previous statement ends in a parameter list (and optional qualifiers, a trailing
return type or a constructor's initialiser list); braces inside a body (blocks, lambdas, local
classes) belong to that body. A function's length is counted from the line of its name to the
line of its closing brace, both included.

The functions still longer than LIMIT are listed in an allow-list (path, qualified name, lines).
The check fails when a function not on the list is longer than LIMIT, when a listed one grew, or
when a listed one is gone or no longer too long (remove it: the list can only shrink).

  check_function_length.py ROOT --allow LIST        the check (ctest Architecture.FunctionLength)
  check_function_length.py ROOT --report [--limit N] every function over N lines, longest first
"""

import argparse
import os
import re
import sys

LIMIT = 150
EXTENSIONS = (".cpp", ".cxx", ".cc", ".h", ".hpp", ".hxx")
# Tests, benchmarks, generated and third-party code are outside the rule.
EXCLUDED_DIRS = {"Testing", "Benchmarks", "build", "ThirdParty", "third_party", ".git"}


def blank_non_code(text):
    """Comments, literals and preprocessor lines replaced by spaces; newlines kept."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if c == "\n":
            out.append(c)
            i += 1
            at_line_start = True
            continue
        if at_line_start and c in " \t":
            out.append(c)
            i += 1
            continue
        if at_line_start and c == "#":
            # A preprocessor line, with its continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        at_line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
            continue
        if text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        m = re.match(r'(?:u8|u|U|L)?R"([^(\s]*)\(', text[i:i + 40])
        if m and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            close = ")" + m.group(1) + '"'
            end = text.find(close, i + m.end())
            end = n if end < 0 else end + len(close)
            out.append(re.sub(r"[^\n]", " ", text[i:end]))
            i = end
            continue
        if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):
            # A string or character literal (a digit separator 1'000 is not one).
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
            continue
        out.append(c)
        i += 1
    return "".join(out)


CONTAINER = re.compile(r"^(?:template\s*<.*>\s*)?(?:\[\[.*?\]\]\s*)?"
                       r"(?:typedef\s+)?(?:namespace|class|struct|union|enum|extern\s*$)\b|"
                       r"^namespace\s*$", re.S)
NAME = re.compile(r"([A-Za-z_~][\w:<>,~ ]*?(?:operator\s*[^\s(]+|[A-Za-z_~]\w*))\s*$")


def top_level_paren_end(header):
    """Index just after the first parenthesised group at depth 0, or -1."""
    depth = 0
    start = -1
    for k, ch in enumerate(header):
        if ch == "(":
            if depth == 0 and start < 0:
                start = k
            depth += 1
        elif ch == ")":
            depth -= 1
            if depth == 0 and start >= 0:
                return start, k + 1
    return -1, -1


def function_name(header):
    start, _ = top_level_paren_end(header)
    if start < 0:
        return None
    before = header[:start]
    if re.search(r"operator\s*\(\s*\)\s*$", header[:header.find(")", start) + 1]):
        before = header[:start] + "()"
    before = before.strip()
    m = re.search(r"((?:[A-Za-z_]\w*(?:<[^<>]*>)?::)*~?(?:operator\s*\S+|[A-Za-z_]\w*))$", before)
    return m.group(1) if m else before.split()[-1] if before.split() else None


def functions(text):
    """(name, first line, last line) of every function body in a source text."""
    code = blank_non_code(text)
    result = []
    # Scope stack entries: "container", "function", "other", "init" (a member initialiser).
    stack = []
    header_start = 0
    fn_start_line = 0
    fn_name = None
    for i, ch in enumerate(code):
        if ch in ";":
            if not stack or stack[-1] == "container":
                header_start = i + 1
        elif ch == "{":
            in_body = any(s == "function" for s in stack)
            if in_body:
                stack.append("other")
                continue
            header = code[header_start:i]
            flat = " ".join(header.split())
            _, paren_end = top_level_paren_end(flat)
            if CONTAINER.match(flat) or flat.startswith("extern") or flat == "":
                stack.append("container" if flat else "other")
                header_start = i + 1
                continue
            if paren_end < 0:
                stack.append("other")
                continue
            after = flat[paren_end:]
            ctor_init = re.search(r"(?<!:):(?!:)", after) is not None
            prev = flat.rstrip()[-1:] if flat.rstrip() else ""
            if ctor_init and (prev.isalnum() or prev in "_>"):
                stack.append("init")
                continue
            if re.search(r"=\s*$", flat) or "=" in after.split("->")[0].replace("==", ""):
                # An initialiser (x = {...}) or a lambda at namespace scope counts as a function
                # only when it has a body after a parameter list.
                if not re.search(r"\]\s*(?:<[^>]*>\s*)?\(", flat):
                    stack.append("other")
                    continue
            stack.append("function")
            first = header_start + (len(header) - len(header.lstrip()))
            fn_start_line = code.count("\n", 0, first) + 1
            fn_name = function_name(flat)
        elif ch == "}":
            if not stack:
                continue
            kind = stack.pop()
            if kind == "function":
                last_line = code.count("\n", 0, i) + 1
                result.append((fn_name or "?", fn_start_line, last_line))
                header_start = i + 1
            elif kind in ("container",):
                header_start = i + 1
            elif kind == "other" and not any(s == "function" for s in stack):
                header_start = i + 1
    return result


def source_files(root):
    for directory, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs
                         if d not in EXCLUDED_DIRS and not d.startswith("build")
                         and not d.startswith("."))
        for name in sorted(files):
            if name.endswith(EXTENSIONS):
                yield os.path.join(directory, name)


def long_functions(root, limit):
    found = []
    for path in source_files(root):
        with open(path, encoding="utf-8", errors="replace") as f:
            text = f.read()
        rel = os.path.relpath(path, root).replace(os.sep, "/")
        for name, first, last in functions(text):
            length = last - first + 1
            if length > limit:
                found.append((rel, name, length, first))
    return found


def read_allow_list(path):
    allowed = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = line.split()
            if len(parts) != 3 or not parts[2].isdigit():
                sys.exit(f"{path}:{number}: expected 'path name lines', got {line!r}")
            allowed[(parts[0], parts[1])] = int(parts[2])
    return allowed


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("root")
    parser.add_argument("--allow", help="the allow-list of functions still over the limit")
    parser.add_argument("--limit", type=int, default=LIMIT)
    parser.add_argument("--report", action="store_true")
    args = parser.parse_args()

    found = long_functions(args.root, args.limit)
    if args.report or not args.allow:
        for rel, name, length, first in sorted(found, key=lambda t: -t[2]):
            print(f"{length:5d}  {rel}:{first}  {name}")
        return 0

    allowed = read_allow_list(args.allow)
    problems = []
    seen = {}
    for rel, name, length, first in found:
        key = (rel, name)
        seen[key] = max(seen.get(key, 0), length)
    for (rel, name), length in sorted(seen.items()):
        if (rel, name) not in allowed:
            problems.append(f"{rel}: {name} is {length} lines (limit {args.limit}): split it")
        elif length > allowed[(rel, name)]:
            problems.append(f"{rel}: {name} grew to {length} lines (allowed {allowed[(rel, name)]},"
                            f" limit {args.limit}): split it")
    for (rel, name), length in sorted(allowed.items()):
        if (rel, name) not in seen:
            problems.append(f"{rel}: {name} is no longer over {args.limit} lines (or gone):"
                            f" remove it from {os.path.basename(args.allow)}")
        elif seen[(rel, name)] < length:
            problems.append(f"{rel}: {name} is now {seen[(rel, name)]} lines, listed as {length}:"
                            f" lower its entry in {os.path.basename(args.allow)}")
    for p in problems:
        print(p)
    print(f"{len(seen)} function(s) over {args.limit} lines, {len(allowed)} allowed;"
          f" {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
