# SPDX-License-Identifier: BSD-3-Clause
"""Renders a model's cuts with their handle loops, and its frame field as arrow glyphs.

Run with pvbatch under an X server (Debian's ParaView renders through GLX):
    xvfb-run -a pvbatch render_cuts_and_frames.py Data/fertility.off --output-dir out \\
        --plugin build/lib/paraview-5.11/plugins/PolycubeHex/PolycubeHex.so
with the build tree's python package on PYTHONPATH (for the glyph helper).
Writes <model>_cuts.png and <model>_frames.png.
"""
import argparse
import os

from paraview import simple


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("model", help="a closed surface (.off .obj) or a tet mesh (.mesh .vtk)")
    parser.add_argument("--plugin", required=True, help="path to PolycubeHex.so")
    parser.add_argument("--output-dir", default=".")
    parser.add_argument("--size", type=int, nargs=2, default=[1200, 900])
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    from polycubehex.visualization import (show_cuts, show_faint_boundary, show_frame_glyphs,
                                           white_view)

    name = os.path.splitext(os.path.basename(args.model))[0]
    os.makedirs(args.output_dir, exist_ok=True)
    source = simple.OpenDataFile(args.model)
    is_surface = os.path.splitext(args.model)[1].lower() in (".off", ".obj", ".stl", ".ply")
    tets = TetrahedralizeTetGen(Input=source) if is_surface else source  # noqa: F821
    cuts = HandleCut(Input=tets)  # noqa: F821

    # The cuts, coloured by CutId, with their handle loops as black tubes.
    view = white_view(args.size)
    show_cuts(tets, cuts, view)
    view.ResetCamera()
    simple.SaveScreenshot(os.path.join(args.output_dir, name + "_cuts.png"), view,
                          ImageResolution=args.size)

    # The frame field: FrameU red, FrameV green, FrameW blue.
    frames = FrameField(Input=cuts)  # noqa: F821
    frames.MaximumGlyphCount = 2500
    view = white_view(args.size)
    show_faint_boundary(tets, view, 0.12)
    show_frame_glyphs(frames, view)
    view.ResetCamera()
    simple.SaveScreenshot(os.path.join(args.output_dir, name + "_frames.png"), view,
                          ImageResolution=args.size)
    print("wrote %s_cuts.png and %s_frames.png in %s" % (name, name, args.output_dir))


if __name__ == "__main__":
    main()
