#!/usr/bin/env python3
"""Tests of check_function_length.py: what counts as a function body and what does not, and the
allow-list rules (a new long function, one that grew, a stale entry)."""

import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_function_length as cfl  # noqa: E402


def spans(text):
    return [(name, first, last) for name, first, last in cfl.functions(text)]


class Functions(unittest.TestCase):
    def test_free_function_and_member_definition(self):
        text = "int f(int a)\n{\n  return a;\n}\n\nvoid S::g() const\n{\n}\n"
        self.assertEqual(spans(text), [("f", 1, 4), ("S::g", 6, 8)])

    def test_blocks_lambdas_and_local_classes_belong_to_the_body(self):
        text = ("void f()\n{\n  auto l = [&](int x) { return x; };\n  struct L { int m() { return 1; } };\n"
                "  if (true)\n  {\n  }\n}\n")
        self.assertEqual(spans(text), [("f", 1, 8)])

    def test_braces_in_comments_strings_and_preprocessor_lines_do_not_count(self):
        text = ('void f()\n{\n  // }\n  /* { */\n  const char* s = "}{";\n  char c = \'}\';\n'
                '#define X {\n  auto r = R"(})";\n}\n')
        self.assertEqual(spans(text), [("f", 1, 9)])

    def test_constructor_initialisers_with_braces(self):
        text = "S::S(int a)\n  : a_{ a }\n  , b_(a)\n{\n  run();\n}\n"
        self.assertEqual(spans(text), [("S::S", 1, 6)])

    def test_namespaces_classes_and_initialisers_are_not_functions(self):
        text = ("namespace n\n{\nstruct S\n{\n  int x = 0;\n  void f() { }\n};\n"
                "const int table[] = { 1, 2 };\nenum class E { A, B };\n}\n")
        self.assertEqual(spans(text), [("f", 6, 6)])

    def test_operators(self):
        text = "bool operator<(const A& a, const A& b)\n{\n  return a.x < b.x;\n}\n"
        self.assertEqual(spans(text), [("operator<", 1, 4)])


class AllowList(unittest.TestCase):
    def run_check(self, body_lines, allow):
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "Lib"))
            with open(os.path.join(root, "Lib", "a.cpp"), "w") as f:
                f.write("void f()\n{\n" + "  x();\n" * body_lines + "}\n")
            os.makedirs(os.path.join(root, "Testing"))
            with open(os.path.join(root, "Testing", "t.cpp"), "w") as f:
                f.write("void t()\n{\n" + "  x();\n" * 400 + "}\n")
            allow_path = os.path.join(root, "allow.txt")
            with open(allow_path, "w") as f:
                f.write(allow)
            argv = sys.argv
            sys.argv = ["check", root, "--allow", allow_path]
            try:
                with open(os.devnull, "w") as devnull:
                    stdout = sys.stdout
                    sys.stdout = devnull
                    try:
                        return cfl.main()
                    finally:
                        sys.stdout = stdout
            finally:
                sys.argv = argv

    def test_short_function_and_tests_pass(self):
        self.assertEqual(self.run_check(100, ""), 0)

    def test_new_long_function_fails(self):
        self.assertEqual(self.run_check(200, ""), 1)

    def test_listed_long_function_passes(self):
        self.assertEqual(self.run_check(200, "Lib/a.cpp f 203\n"), 0)

    def test_listed_function_that_grew_fails(self):
        self.assertEqual(self.run_check(210, "Lib/a.cpp f 203\n"), 1)

    def test_listed_function_that_shrank_must_lower_its_entry(self):
        self.assertEqual(self.run_check(190, "Lib/a.cpp f 203\n"), 1)

    def test_stale_entry_fails(self):
        self.assertEqual(self.run_check(100, "Lib/a.cpp f 203\n"), 1)


if __name__ == "__main__":
    unittest.main()
