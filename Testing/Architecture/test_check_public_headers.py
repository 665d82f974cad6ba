#!/usr/bin/env python3
"""Self-tests of check_public_headers.py: a small tree that passes, and one change per rule that
must fail it. Python 3 standard library only."""

import contextlib
import io
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True   # no __pycache__ in the source tree
import check_public_headers as checker  # noqa: E402


def write(root, path, text=""):
    full = os.path.join(root, path)
    os.makedirs(os.path.dirname(full), exist_ok=True)
    with open(full, "w", encoding="utf-8") as f:
        f.write(text)


class PublicHeaders(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp()
        write(self.root, "FRep/Eval/CMakeLists.txt",
              "target_sources(E PRIVATE a.cpp)\nfrepkit_add_public_headers(E\n  api.h\n)\n")
        write(self.root, "FRep/Eval/api.h", '#include "Eval/detail/inner.h"\n')
        write(self.root, "FRep/Eval/detail/inner.h")
        write(self.root, "FRep/Mesh/CMakeLists.txt", "frepkit_add_public_headers(E mesh.h)\n")
        write(self.root, "FRep/Mesh/mesh.h", '#include "Eval/detail/inner.h"\n')  # one library
        write(self.root, "Multimedia/Pics/CMakeLists.txt",
              "frepkit_add_library(Pics\n  SOURCES p.cpp\n  PUBLIC_HEADERS\n    pics.h)\n")
        write(self.root, "Multimedia/Pics/pics.h")
        write(self.root, "Multimedia/Pics/detail/raster.h")
        write(self.root, "Testing/pics_test.cpp", '#include "Pics/detail/raster.h"\n')

    def tearDown(self):
        shutil.rmtree(self.root)

    def run_checker(self):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = checker.main(["check_public_headers.py", self.root])
        return status, out.getvalue()

    def test_a_clean_tree_passes(self):
        status, out = self.run_checker()
        self.assertEqual(status, 0, out)
        self.assertIn("3 public and 2 private headers, 0 error(s)", out)

    def test_an_unlisted_header_outside_detail_fails(self):
        write(self.root, "Multimedia/Pics/hidden.h")
        status, out = self.run_checker()
        self.assertEqual(status, 1)
        self.assertIn("Multimedia/Pics/hidden.h: not listed as public", out)

    def test_a_listed_header_that_is_missing_fails(self):
        os.remove(os.path.join(self.root, "FRep/Mesh/mesh.h"))
        status, out = self.run_checker()
        self.assertEqual(status, 1)
        self.assertIn("public header mesh.h does not exist", out)

    def test_a_listed_header_in_detail_fails(self):
        write(self.root, "FRep/Mesh/CMakeLists.txt",
              "frepkit_add_public_headers(E mesh.h detail/x.h)\n")
        write(self.root, "FRep/Mesh/detail/x.h")
        status, out = self.run_checker()
        self.assertEqual(status, 1)
        self.assertIn("detail/x.h is listed as public but lies in detail/", out)

    def test_another_library_including_a_detail_header_fails(self):
        write(self.root, "Multimedia/Pics/p.cpp", '#include "Eval/detail/inner.h"\n')
        status, out = self.run_checker()
        self.assertEqual(status, 1)
        self.assertIn("Multimedia/Pics/p.cpp:1: includes Eval/detail/inner.h, private to FRep",
                      out)

    def test_a_program_including_a_detail_header_fails(self):
        write(self.root, "Apps/tool/main.cpp", '\n#include "Pics/detail/raster.h"\n')
        status, out = self.run_checker()
        self.assertEqual(status, 1)
        self.assertIn("Apps/tool/main.cpp:2: includes Pics/detail/raster.h, private to "
                      "Multimedia/Pics", out)


if __name__ == "__main__":
    unittest.main()
