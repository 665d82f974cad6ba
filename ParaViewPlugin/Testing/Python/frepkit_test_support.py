"""Shared helpers of the FRepKit plug-in tests (pvpython / pvbatch scripts).

Every test script takes the plug-in path as its first argument and the source tree's root as
its second; it loads the plug-in with LoadPlugin(path, remote=False, ns=globals()) and ends with
sys.exit(1) when any check failed (each failure printed with its line)."""

import inspect
import sys


def _say(text):
    """Prints to the process's real stderr: pvpython sends sys.stdout through VTK's output
    window, which CapturedMessages replaces."""
    sys.__stderr__.write(text + "\n")
    sys.__stderr__.flush()


class Checker:
    """Collects failed checks; report() prints them and gives the exit status."""

    def __init__(self, name):
        self.name = name
        self.failures = []
        self.count = 0

    def check(self, condition, what):
        self.count += 1
        if not condition:
            line = inspect.currentframe().f_back.f_lineno
            self.failures.append("line %d: %s" % (line, what))
            _say("FAILED (line %d): %s" % (line, what))
        return bool(condition)

    def near(self, value, expected, tolerance, what):
        return self.check(abs(value - expected) <= tolerance,
                          "%s: %r, expected %r +- %r" % (what, value, expected, tolerance))

    def report(self):
        _say("%s: %d checks, %d failed" % (self.name, self.count, len(self.failures)))
        return 1 if self.failures else 0


def arguments():
    if len(sys.argv) < 3:
        print("usage: pvpython %s PLUGIN SOURCE_DIR [...]" % sys.argv[0])
        sys.exit(2)
    return sys.argv[1], sys.argv[2], sys.argv[3:]


class CapturedMessages:
    """Replaces VTK's output window by a string window: what ParaView's Output Messages window
    shows (errors in red) is what VTK sends there. text() gives everything since the start or
    the last clear()."""

    def __init__(self):
        from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
        self.window = vtkStringOutputWindow()
        self.previous = vtkOutputWindow.GetInstance()
        self.start = 0
        vtkOutputWindow.SetInstance(self.window)
        # pvpython's sys.stdout/stderr write to VTK's output window: keep Python's own text
        # (prints, tracebacks) out of the captured messages.
        sys.stdout = sys.__stdout__
        sys.stderr = sys.__stderr__

    def text(self):
        return self.window.GetOutput()[self.start:]

    def clear(self):
        self.start = len(self.window.GetOutput())

    def restore(self):
        from vtkmodules.vtkCommonCore import vtkOutputWindow
        vtkOutputWindow.SetInstance(self.previous)
