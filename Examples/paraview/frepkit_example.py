"""Command line of the FRepKit ParaView examples: where the plug-in is, where to write pictures.

  pvpython EXAMPLE.py [--plugin FRepKit.so] [--output DIR] [--resolution N] [--frames N]

The plug-in defaults to $FREPKIT_PARAVIEW_PLUGIN, else build/lib/paraview-5.11/plugins/FRepKit/
FRepKit.so of the source tree. Without --output nothing is rendered (no X display needed)."""

import argparse
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.dirname(os.path.dirname(HERE))


def arguments(description, resolution=64, frames=0):
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--plugin", default=os.environ.get(
        "FREPKIT_PARAVIEW_PLUGIN",
        os.path.join(SOURCE_DIR, "build", "lib", "paraview-5.11", "plugins", "FRepKit",
                     "FRepKit.so")))
    parser.add_argument("--output", default="", help="directory for the pictures")
    parser.add_argument("--resolution", type=int, default=resolution)
    parser.add_argument("--frames", type=int, default=frames)
    args = parser.parse_args()
    if args.output:
        os.makedirs(args.output, exist_ok=True)
    return args


def example_file(*parts):
    return os.path.join(SOURCE_DIR, "Examples", *parts)
