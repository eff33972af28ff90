#!/usr/bin/env pvbatch
# SPDX-License-Identifier: BSD-3-Clause
"""Two pictures of a hex mesh (a .vtu from the command line or HexExtract): its surface coloured
by scaled Jacobian, and a slice through its middle, hexes coloured the same way (inverted hexes
show in dark red at the bottom of the scale). Run with pvbatch under an X server:

    xvfb-run -a pvbatch Wrapping/Python/examples/render_hex_quality.py hexes.vtu --output-dir out
"""
import argparse
import os

import paraview.simple as simple


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("hexes", help="a hex mesh with the cell array ScaledJacobian (.vtu)")
    parser.add_argument("--output-dir", default=".")
    parser.add_argument("--normal", default="0,0,1", help="slice normal (default 0,0,1)")
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.hexes))[0]

    hexes = simple.OpenDataFile(args.hexes)
    hexes.UpdatePipeline()
    view = simple.CreateRenderView()
    view.ViewSize = [1200, 900]
    view.OrientationAxesVisibility = 1
    view.Background = [1, 1, 1]

    lut = simple.GetColorTransferFunction("ScaledJacobian")
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.InvertTransferFunction()
    lut.AutomaticRescaleRangeMode = "Never"  # the same scale on both pictures
    lut.RescaleTransferFunction(-0.2, 1.0)

    shown = simple.Show(hexes, view)
    shown.Representation = "Surface With Edges"
    simple.ColorBy(shown, ("CELLS", "ScaledJacobian"))
    shown.LookupTable = lut
    shown.SetScalarBarVisibility(view, True)
    view.ResetCamera()
    view.CameraPosition = [p + d for p, d in zip(view.CameraFocalPoint, (1.0, -1.5, 1.2))]
    view.ResetCamera()
    simple.Render(view)
    surface_png = os.path.join(args.output_dir, name + "_scaled_jacobian.png")
    simple.SaveScreenshot(surface_png, view)

    # The slice keeps whole hexes (Crinkle) so that each cell shows its own quality.
    simple.Hide(hexes, view)
    normal = [float(c) for c in args.normal.split(",")]
    cut = simple.Slice(Input=hexes)
    cut.SliceType = "Plane"
    cut.SliceType.Normal = normal
    cut.Crinkleslice = 1
    bounds = hexes.GetDataInformation().GetBounds()
    cut.SliceType.Origin = [0.5 * (bounds[2 * i] + bounds[2 * i + 1]) for i in range(3)]
    sliced = simple.Show(cut, view)
    sliced.Representation = "Surface With Edges"
    simple.ColorBy(sliced, ("CELLS", "ScaledJacobian"))
    sliced.LookupTable = lut
    lut.RescaleTransferFunction(-0.2, 1.0)
    sliced.SetScalarBarVisibility(view, True)
    view.CameraPosition = [p + 2.0 * n for p, n in zip(view.CameraFocalPoint, normal)]
    view.CameraViewUp = [0, 1, 0] if abs(normal[1]) < 0.9 else [0, 0, 1]
    view.ResetCamera()
    simple.Render(view)
    slice_png = os.path.join(args.output_dir, name + "_slice.png")
    simple.SaveScreenshot(slice_png, view)
    print("wrote", surface_png, slice_png)


if __name__ == "__main__":
    main()
