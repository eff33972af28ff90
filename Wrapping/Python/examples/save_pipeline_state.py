#!/usr/bin/env pvbatch
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the ParaView XML state polycubehex_pipeline.pvsm from the Python state
pipeline_state.py (the whole pipeline on Data/torus.obj, hexes coloured by scaled Jacobian):

    xvfb-run -a pvbatch Wrapping/Python/examples/save_pipeline_state.py \\
        --plugin build/lib/paraview-5.11/plugins/PolycubeHex/PolycubeHex.so \\
        --output Wrapping/Python/examples/polycubehex_pipeline.pvsm

The model's path in the state is made relative to the repository's top ("Data/torus.obj"), so the
shipped file holds no path of the machine that wrote it; the script refuses to write a state that
still names the source directory.
"""
import argparse
import os
import runpy

from paraview import simple

here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.path.normpath(os.path.join(here, "..", "..", ".."))
RELATIVE_MODEL = "Data/torus.obj"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--plugin", required=True, help="path to PolycubeHex.so")
    parser.add_argument("--output", default=os.path.join(here, "polycubehex_pipeline.pvsm"))
    args = parser.parse_args()
    model = os.path.join(source_dir, RELATIVE_MODEL)
    os.environ["POLYCUBEHEX_PLUGIN"] = os.path.abspath(args.plugin)
    os.environ["POLYCUBEHEX_MODEL"] = model
    # The Python state builds (and, by showing the hexes, runs) the whole pipeline.
    runpy.run_path(os.path.join(here, "pipeline_state.py"))
    # pvbatch's view is 400 x 400; the state keeps that size, and the scalar bar placed for it
    # looks oversized in a GUI-sized view. Save it at a typical GUI view size instead.
    simple.GetActiveView().ViewSize = [1200, 800]
    simple.Render()
    simple.SaveState(args.output)

    with open(args.output) as state:
        text = state.read()
    text = text.replace(model, RELATIVE_MODEL)
    for absolute in (source_dir, os.path.dirname(os.path.abspath(args.plugin))):
        if absolute in text:
            raise SystemExit("the state still names %s; not shipping it" % absolute)
    with open(args.output, "w") as state:
        state.write(text)
    print("wrote %s" % args.output)


if __name__ == "__main__":
    main()
