#!/usr/bin/env pvbatch
# SPDX-License-Identifier: BSD-3-Clause
"""The polycube of a model with handles, both guidances side by side: Uniform (the l1 baseline,
uncut) and FrameField (the paper's closed form, on the cut mesh with the cut transitions hard).
Each picture is the labelled polycube surface coloured by label; the corner counts are printed.
On Data/torus.obj the closed form is a straight bar with 0 corners, the uncut polycube a
square ring with 16. Run with pvbatch under an X server, from the repository's top:

    xvfb-run -a pvbatch Wrapping/Python/examples/render_closed_form.py Data/torus.obj --output-dir out

The plugin is taken from POLYCUBEHEX_PLUGIN, else from build/ beside this source tree.
"""
import argparse
import os

import paraview.simple as simple
from paraview import servermanager

from polycubehex.visualization import white_view


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", help="a surface (.obj, .off, ...) or a tet mesh (.mesh, .vtk)")
    parser.add_argument("--output-dir", default=".")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    plugin = os.environ.get("POLYCUBEHEX_PLUGIN", os.path.join(
        here, "..", "..", "..", "build", "lib", "paraview-5.11", "plugins", "PolycubeHex",
        "PolycubeHex.so"))
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    names = globals()  # the plugin's filters, by their XML labels

    model = simple.OpenDataFile(args.model)
    surface = os.path.splitext(args.model)[1].lower() in (".obj", ".off", ".stl", ".ply", ".vtp")
    tets = names["TetrahedralizeTetGen"](Input=model) if surface else model
    frames = names["FrameField"](Input=names["HandleCut"](Input=tets))
    name = os.path.splitext(os.path.basename(args.model))[0]
    for guidance in ("Uniform", "FrameField"):
        polycube = names["PolycubeDeform"](Input=frames, Guidance=guidance)
        view = white_view((1200, 800))
        view.OrientationAxesVisibility = 1
        display = simple.Show(simple.OutputPort(polycube, 1), view)
        display.Representation = "Surface With Edges"
        simple.ColorBy(display, ("CELLS", "PolycubeLabel"))
        labels = simple.GetColorTransferFunction("PolycubeLabel")
        labels.AutomaticRescaleRangeMode = "Never"
        labels.RescaleTransferFunction(0.0, 5.0)
        view.CameraPosition = [1.0, -1.2, 0.9]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        simple.ResetCamera(view)
        path = os.path.join(args.output_dir, "%s_polycube_%s.png" % (name, guidance.lower()))
        simple.SaveScreenshot(path, view, ImageResolution=[1200, 800])
        fields = servermanager.Fetch(polycube).GetFieldData()
        print("%s, %s: %d corners -> %s" % (
            name, guidance, fields.GetArray("CornerCount").GetValue(0), path))


if __name__ == "__main__":
    main()
