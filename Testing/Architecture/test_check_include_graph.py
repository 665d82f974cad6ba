#!/usr/bin/env python3
"""Self-tests of check_include_graph.py: small synthetic trees, each breaking one rule, and a clean
tree that passes. Python 3 standard library only."""

import contextlib
import io
import os
import shutil
import subprocess
import sys
import tempfile
import textwrap
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True   # no __pycache__ in the source tree
import check_include_graph as checker  # noqa: E402

REPO = os.path.abspath(os.path.join(HERE, "..", ".."))

RULES = """\
# Test rules

Some prose.

## Include rules (checked by Testing/Architecture)

Explanation of the syntax.

```text
include-root  = Engine Plain     # "Low/low.h", "Pics/pics.h"
search        = App/extra
module-dirs   = Modules
module-header = vtk*.h
vtk           = vtk* QVTK* Kit*Module.h
qt            = Q[A-Z]* Qt[A-Z]*/* *.moc
generated     = Kit*Module.h *.moc

Engine/Low:   [no-vtk no-qt qualified]
Engine/High:  Engine/Low        [no-vtk no-qt qualified]
Plain/Pics:   Engine/*          [no-vtk no-qt qualified]
Modules/Src:  Engine/* Plain/*  [vtk no-qt]
Modules/Flt:  Modules/Src Engine/* Plain/*  [vtk no-qt]
App:          Engine/* Plain/* Modules/Src Modules/Flt  [qt]
Testing:      *
```

## Next section

Not rules.
"""

CLEAN_TREE = {
    "Engine/Low/low.h": '#pragma once\n#include <vector>\n#include "low_detail.h"\n',
    "Engine/Low/low_detail.h": "#pragma once\n",
    "Engine/Low/low.cpp": '#include "Low/low.h"\n#include <cmath>\n',
    "Engine/High/high.h": '#pragma once\n#include "Low/low.h"\n',
    "Engine/High/high.cpp": '#include "high.h"\n#include "High/high.h"\n',
    "Plain/Pics/pics.h": '#pragma once\n#include "High/high.h"\n',
    "Plain/Pics/Testing/pics_test.cpp": '#include "Pics/pics.h"\n#include <gtest/gtest.h>\n',
    "Modules/Src/vtkSrc.h": '#pragma once\n#include "KitSrcModule.h"\n#include "vtkAlgorithm.h"\n',
    "Modules/Src/vtkSrc.cxx": '#include "vtkSrc.h"\n#include "Low/low.h"\n#include "vtkNew.h"\n',
    "Modules/Flt/vtkFlt.h": '#pragma once\n#include "vtkSrc.h"\n#include "Pics/pics.h"\n',
    "App/main.cpp": ('#include "vtkFlt.h"\n#include <QWidget>\n#include "main.moc"\n'
                     '#include "extra_tool.h"\n'),
    "App/extra/extra_tool.h": "#pragma once\n",
    "Testing/everything.cpp": '#include "vtkFlt.h"\n#include "Low/low.h"\n',
    "README.md": "#include \"not/source.h\" is not C++\n",
    "build/generated.cpp": '#include "nothing_here.h"\n',
}


class TreeTest(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="archtest-")
        self.addCleanup(shutil.rmtree, self.root)

    def write(self, files):
        for path, text in files.items():
            full = os.path.join(self.root, path)
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w", encoding="utf-8") as handle:
                handle.write(text)

    def run_checker(self, changes=None, rules=RULES, extra_args=()):
        files = dict(CLEAN_TREE)
        files.update(changes or {})
        files = {path: text for path, text in files.items() if text is not None}
        files["Documentation/architecture.md"] = rules
        self.write(files)
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
            status = checker.main([self.root, *extra_args])
        return status, out.getvalue()

    def assertFails(self, changes, *expected):
        status, output = self.run_checker(changes)
        self.assertEqual(status, 1, output)
        for text in expected:
            self.assertIn(text, output)
        return output

    # ---------------------------------------------------------------------------------------

    def test_clean_tree_passes(self):
        status, output = self.run_checker()
        self.assertEqual(status, 0, output)
        self.assertIn("0 error(s)", output)

    def test_cycle_is_reported_with_its_path(self):
        output = self.assertFails(
            {"Engine/Low/low.cpp": '#include "Low/low.h"\n#include "High/high.h"\n'},
            "include cycle between units Engine/High -> Engine/Low -> Engine/High",
            'Engine/Low -> Engine/High: Engine/Low/low.cpp:2 "High/high.h"')
        # The edge that makes the cycle is also a forbidden edge.
        self.assertIn("Engine/Low/low.cpp:2: error: #include \"High/high.h\": Engine/Low may not "
                      "include Engine/High", output)

    def test_cycle_between_allowed_edges_is_still_a_cycle(self):
        rules = RULES.replace("Engine/Low:   [", "Engine/Low:   Engine/High [")
        status, output = self.run_checker(
            {"Engine/Low/low.cpp": '#include "High/high.h"\n'}, rules=rules)
        self.assertEqual(status, 1, output)
        self.assertIn("include cycle between units", output)
        self.assertNotIn("may not include", output)

    def test_three_unit_cycle(self):
        self.assertFails(
            {"Plain/Pics/pics.cpp": '#include "vtkFlt.h"\n'},
            "Plain/Pics may not include Modules/Flt",
            "include cycle between units Modules/Flt -> Plain/Pics -> Modules/Flt")

    def test_vtk_include_in_engine(self):
        self.assertFails(
            {"Engine/High/high.cpp": '#include "High/high.h"\n#include "vtkNew.h"\n'
                                     '#include <vtkPolyData.h>\n'},
            'Engine/High/high.cpp:2: error: #include "vtkNew.h": Engine/High is no-vtk but '
            'includes a VTK header',
            'Engine/High/high.cpp:3: error: #include <vtkPolyData.h>: Engine/High is no-vtk')

    def test_header_of_a_vtk_unit_in_a_plain_library(self):
        self.assertFails(
            {"Plain/Pics/pics.cpp": '#include <vtkSrc.h>\n'},
            "Plain/Pics is no-vtk but includes Modules/Src/vtkSrc.h, VTK code of Modules/Src",
            "Plain/Pics may not include Modules/Src")

    def test_qt_include(self):
        self.assertFails(
            {"Engine/Low/low.cpp": '#include "Low/low.h"\n#include <QString>\n'
                                   '#include <QtConcurrent/QtConcurrentRun>\n'},
            "Engine/Low/low.cpp:2: error: #include <QString>: Engine/Low is no-qt",
            "Engine/Low/low.cpp:3: error: #include <QtConcurrent/QtConcurrentRun>: Engine/Low is "
            "no-qt")

    def test_qt_include_in_a_vtk_module(self):
        self.assertFails({"Modules/Src/vtkSrc.cxx": '#include <QVTKOpenGLNativeWidget.h>\n'},
                         "Modules/Src is no-qt but includes a Qt header")

    def test_forbidden_edge(self):
        self.assertFails(
            {"Engine/High/high.cpp": '#include "Pics/pics.h"\n'},
            'Engine/High/high.cpp:1: error: #include "Pics/pics.h": Engine/High may not include '
            'Plain/Pics (Plain/Pics/pics.h); Engine/High may include: Engine/Low')

    def test_forbidden_edge_between_modules(self):
        self.assertFails({"Modules/Src/vtkSrc.cxx": '#include "vtkFlt.h"\n'},
                         "Modules/Src may not include Modules/Flt")

    def test_unqualified_include_through_a_search_folder(self):
        self.write({"App/extra/pics_like.h": "#pragma once\n"})
        self.assertFails(
            {"Plain/Pics/pics.cpp": '#include "pics_like.h"\n'},
            'Plain/Pics/pics.cpp:1: error: #include "pics_like.h": Plain/Pics must include headers '
            "by folder through an include root, not by a bare name")

    def test_unqualified_include_names_the_qualified_spelling(self):
        rules = RULES.replace("search        = App/extra", "search        = App/extra Plain/Pics")
        status, output = self.run_checker(
            {"Plain/Pics/Testing/pics_test.cpp": '#include "pics.h"\n'}, rules=rules)
        self.assertEqual(status, 1, output)
        self.assertIn('not by a bare name; write "Pics/pics.h"', output)

    def test_relative_include_into_another_folder(self):
        self.assertFails(
            {"Engine/High/high.cpp": '#include "../Low/low.h"\n'},
            "Engine/High must include other folders' headers through an include root, "
            "not by a relative path (Engine/Low/low.h is in Engine/Low)")

    def test_unqualified_is_allowed_in_units_without_the_flag(self):
        status, output = self.run_checker({"App/other.cpp": '#include "extra_tool.h"\n'})
        self.assertEqual(status, 0, output)

    def test_unresolved_include(self):
        self.assertFails(
            {"App/other.cpp": '#include "image.h"\n'},
            'App/other.cpp:1: error: #include "image.h": the quoted include resolves to no '
            "repository file")

    def test_ambiguous_bare_include(self):
        # Two modules with a vtkSrc.h: found by class name, the include could be either.
        self.write({"Modules/Flt/vtkSrc.h": "#pragma once\n"})
        self.assertFails({"App/other.cpp": '#include "vtkSrc.h"\n'},
                         'App/other.cpp:1: error: #include "vtkSrc.h": ambiguous include: found as '
                         "Modules/Flt/vtkSrc.h and as Modules/Src/vtkSrc.h")

    def test_unassigned_file(self):
        self.assertFails(
            {"NewFolder/thing.cpp": "int x;\n"},
            "NewFolder/thing.cpp: error: the file belongs to no unit of the include rules")

    def test_unassigned_file_directly_under_a_parent_of_units(self):
        self.assertFails({"Engine/engine.h": "#pragma once\n"},
                         "Engine/engine.h: error: the file belongs to no unit")

    def test_comments_and_strings_are_not_includes(self):
        status, output = self.run_checker({
            "Engine/Low/low.cpp": ('#include "Low/low.h"\n'
                                   '// #include <QWidget>\n'
                                   '/* #include "vtkNew.h"\n'
                                   '   #include "High/high.h" */\n'
                                   'const char* s = "#include <QWidget>";\n'),
        })
        self.assertEqual(status, 0, output)

    def test_include_after_a_block_comment_keeps_its_line_number(self):
        self.assertFails(
            {"Engine/Low/low.cpp": '/* a\n   b */\n#include "High/high.h"\n'},
            'Engine/Low/low.cpp:3: error: #include "High/high.h"')

    def test_build_folders_are_skipped(self):
        status, output = self.run_checker({"build-debug/x/y.cpp": '#include "nope.h"\n'})
        self.assertEqual(status, 0, output)

    def test_rules_option(self):
        rules_file = os.path.join(self.root, "other_rules.md")
        self.write({"other_rules.md": RULES.replace("Engine/High:  Engine/Low",
                                                    "Engine/High:  Engine/Low Plain/Pics")})
        status, output = self.run_checker({"Engine/High/high.cpp": '#include "Pics/pics.h"\n'},
                                          extra_args=["--rules", rules_file])
        self.assertNotIn("may not include", output)
        # The edge is allowed, but it closes the cycle Plain/Pics -> Engine/High -> Plain/Pics.
        self.assertIn("include cycle between units", output)
        self.assertEqual(status, 1)

    def test_rules_errors_exit_2(self):
        for broken, message in [
            (RULES.replace("[vtk no-qt]", "[vtk no-qt shiny]", 1), "unknown flag(s) shiny"),
            (RULES.replace("Modules/Src Engine/*", "Modules/Typo Engine/*"),
             "'Modules/Typo', which names no unit"),
            (RULES.replace("module-header", "module-headers"), "unknown directive"),
            (RULES.replace("## Include rules", "## Other rules"), "no heading"),
        ]:
            with self.subTest(message=message):
                status, output = self.run_checker(rules=broken)
                self.assertEqual(status, 2, output)
                self.assertIn(message, output)

    def test_command_line_exit_status(self):
        self.write(dict(CLEAN_TREE, **{"Documentation/architecture.md": RULES}))
        script = os.path.join(HERE, "check_include_graph.py")
        clean = subprocess.run([sys.executable, script, self.root], capture_output=True, text=True)
        self.assertEqual(clean.returncode, 0, clean.stdout + clean.stderr)
        self.write({"Engine/Low/bad.cpp": "#include <QWidget>\n"})
        broken = subprocess.run([sys.executable, script, self.root, "--graph"],
                                capture_output=True, text=True)
        self.assertEqual(broken.returncode, 1, broken.stdout + broken.stderr)
        self.assertIn("Engine/Low/bad.cpp:1: error: #include <QWidget>", broken.stdout)
        self.assertIn("unit graph", broken.stdout)

    @unittest.skipUnless(shutil.which("git"), "git not available")
    def test_git_tree_checks_new_files_and_skips_ignored_ones(self):
        self.write(dict(CLEAN_TREE, **{"Documentation/architecture.md": RULES}))
        git = ["git", "-C", self.root, "-c", "user.name=t", "-c", "user.email=t@t"]
        subprocess.run(git + ["init", "-q"], check=True)
        subprocess.run(git + ["add", "-A"], check=True)
        subprocess.run(git + ["commit", "-qm", "tree"], check=True)
        self.write({"Stray/untracked.cpp": "#include <QWidget>\n"})
        status, output = self.run_checker()
        self.assertEqual(status, 1, output)
        self.assertIn("Stray/untracked.cpp: error: the file belongs to no unit", output)
        self.write({".gitignore": "/Stray/\n"})
        status, output = self.run_checker()
        self.assertEqual(status, 0, output)


class RepositoryRulesTest(unittest.TestCase):
    """The rules documents of this repository parse."""

    def test_architecture_document_parses(self):
        path = os.path.join(REPO, "Documentation", "architecture.md")
        with open(path, encoding="utf-8") as handle:
            rules = checker.parse_rules(handle.read(), path)
        self.assertIn("FRep/Compiler", rules.units)
        self.assertIn("no-vtk", rules.units["FRep/Language"].flags)
        self.assertEqual(rules.settings["include-root"], ["FRep", "Multimedia", "Support"])


if __name__ == "__main__":
    unittest.main()
