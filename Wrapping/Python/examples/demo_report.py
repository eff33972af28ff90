#!/usr/bin/env pvbatch
# SPDX-License-Identifier: BSD-3-Clause
"""The whole pipeline on one model in ParaView, with a report (Markdown and HTML) and a picture
per stage:
the cuts with their handle loops, the frame field, the labelled polycube, the hex mesh coloured
by scaled Jacobian, a slice through it, and the scaled Jacobian histogram.

    xvfb-run -a pvbatch demo_report.py Data/rockerarm.mesh --output-dir build/demo \\
        --plugin build/lib/paraview-5.11/plugins/PolycubeHex/PolycubeHex.so --hexes 17594

with the build tree's python package on PYTHONPATH. Writes report.md, report.html (one page that
shows the PNGs beside it), <model>_hexes.vtu and <model>_hexes.mesh, and the PNGs.
"""
import argparse
import os
import time

from paraview import servermanager, simple

def black_bar(lut, view, title):
    """A scalar bar readable on the white background."""
    bar = simple.GetScalarBar(lut, view)
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    bar.Visibility = 1


def oblique(view):
    """The same three-quarter view for every 3D picture."""
    view.CameraPosition = [1, -1.5, 1.2]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]


def save(view, directory, name, size):
    path = os.path.join(directory, name)
    view.ResetCamera()
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=size)
    return name


def field_values(proxy, names):
    fields = servermanager.Fetch(proxy).GetFieldData()
    values = {}
    for name in names:
        array = fields.GetAbstractArray(name)
        if array is not None and array.GetNumberOfValues() > 0:
            value = array.GetVariantValue(0)
            values[name] = value.ToString() if value.IsString() else value.ToDouble()
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", help="a closed surface (.off .obj) or a tet mesh (.mesh .vtk)")
    parser.add_argument("--plugin", required=True, help="path to PolycubeHex.so")
    parser.add_argument("--output-dir", default=".")
    parser.add_argument("--hexes", type=int, default=10000)
    parser.add_argument("--size", type=int, nargs=2, default=[1000, 750])
    args = parser.parse_args()
    simple.LoadPlugin(args.plugin, remote=False, ns=globals())
    from polycubehex.pipeline import ErrorCatcher
    from polycubehex.report import REPORT_FIELDS, format_report, write_report
    from polycubehex.visualization import (show_cuts, show_faint_boundary, show_frame_glyphs,
                                           white_view)

    out = args.output_dir
    os.makedirs(out, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.model))[0]
    seconds = {}
    warnings = []

    def run(stage, proxy):
        # pvbatch runs the filters in this process: their warnings (why ValidHexMesh is 0, say)
        # are caught from the VTK objects and go into the report, not only to the terminal.
        catcher = ErrorCatcher(proxy.GetClientSideObject())
        start = time.perf_counter()
        proxy.UpdatePipeline()
        seconds[stage] = time.perf_counter() - start
        warnings.extend("%s: %s" % (stage, w) for w in catcher.warnings + catcher.errors)
        return proxy

    source = simple.OpenDataFile(args.model)
    is_surface = os.path.splitext(args.model)[1].lower() in (".off", ".obj", ".stl", ".ply")
    tets = run("tetrahedralize", TetrahedralizeTetGen(Input=source)) if is_surface \
        else source  # noqa: F821 (the plugin defines the filters)
    cuts = run("cuts", HandleCut(Input=tets))  # noqa: F821
    frames = run("frame field", FrameField(Input=cuts, MaximumGlyphCount=2500))  # noqa: F821
    polycube = run("polycube", PolycubeDeform(Input=frames))  # noqa: F821
    hexes = run("hexes", HexExtract(Input=polycube, TargetHexCount=args.hexes))  # noqa: F821
    if hexes.GetDataInformation().GetNumberOfCells() == 0:
        raise SystemExit("the pipeline produced no hexes; see the messages above")
    simple.SaveData(os.path.join(out, name + "_hexes.vtu"), proxy=hexes)
    simple.SaveData(os.path.join(out, name + "_hexes.mesh"), proxy=hexes)  # the MEDIT writer

    pictures = []

    # Cuts: the boundary faint, each cut surface in its own colour, the handle loops as tubes.
    view = white_view(args.size)
    show_cuts(tets, cuts, view)
    oblique(view)
    pictures.append(("Cuts (§2): the boundary faint, one cut surface per handle (coloured by"
                     " CutId), the handle loops as black tubes",
                     save(view, out, name + "_cuts.png", args.size)))

    view = white_view(args.size)
    show_faint_boundary(tets, view, 0.12)
    show_frame_glyphs(frames, view)
    oblique(view)
    pictures.append(("Frame field (§3): the three frame axes at sample points inside the"
                     " model, FrameU red, FrameV green, FrameW blue",
                     save(view, out, name + "_frames.png", args.size)))

    view = white_view(args.size)
    charts = simple.Show(simple.OutputPort(polycube, 1), view)
    simple.ColorBy(charts, ("CELLS", "PolycubeLabel"))
    charts.LookupTable.ApplyPreset("Rainbow Uniform", True)
    charts.LookupTable.RescaleTransferFunction(0, 5)
    black_bar(charts.LookupTable, view, "PolycubeLabel")
    oblique(view)
    pictures.append(("Polycube (§4.2): the deformed boundary, each face coloured by its label"
                     " 0..5 = +X -X +Y -Y +Z -Z",
                     save(view, out, name + "_polycube.png", args.size)))

    lut = simple.GetColorTransferFunction("ScaledJacobian")
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.InvertTransferFunction()
    lut.AutomaticRescaleRangeMode = "Never"
    view = white_view(args.size)
    shown = simple.Show(hexes, view)
    shown.Representation = "Surface With Edges"
    simple.ColorBy(shown, ("CELLS", "ScaledJacobian"))
    lut.RescaleTransferFunction(-0.2, 1.0)
    black_bar(lut, view, "scaled Jacobian")
    oblique(view)
    pictures.append(("Hex mesh (§4.3): the boundary hexes with their edges, coloured by scaled"
                     " Jacobian (blue 1 = a perfect cube, red at or below 0 = inverted)",
                     save(view, out, name + "_hexes.png", args.size)))

    hex_bounds = hexes.GetDataInformation().GetBounds()
    cut = simple.Slice(Input=hexes, Crinkleslice=1)
    cut.SliceType.Origin = [0.5 * (hex_bounds[2 * i] + hex_bounds[2 * i + 1]) for i in range(3)]
    cut.SliceType.Normal = [0, 0, 1]
    view = white_view(args.size)
    sliced = simple.Show(cut, view)
    sliced.Representation = "Surface With Edges"
    simple.ColorBy(sliced, ("CELLS", "ScaledJacobian"))
    lut.RescaleTransferFunction(-0.2, 1.0)
    black_bar(lut, view, "scaled Jacobian")
    view.CameraPosition = [0, 0, 1]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    pictures.append(("Inside: the whole hexes crossed by the mid-height plane z = const,"
                     " seen from above, same colours",
                     save(view, out, name + "_slice.png", args.size)))

    histogram = simple.Histogram(Input=hexes, SelectInputArray=["CELLS", "ScaledJacobian"],
                                 BinCount=24, UseCustomBinRanges=1, CustomBinRanges=[-0.2, 1.0])
    chart = simple.CreateView("XYBarChartView")
    chart.ViewSize = args.size
    chart.BottomAxisTitle = "scaled Jacobian"
    chart.LeftAxisTitle = "hexes"
    chart.ShowLegend = 0  # one series: its name ("bin_values") says nothing
    bars = simple.Show(histogram, chart)
    bars.SeriesVisibility = ["bin_values"]
    simple.Render(chart)
    simple.SaveScreenshot(os.path.join(out, name + "_histogram.png"), chart,
                          ImageResolution=args.size)
    pictures.append(("Scaled Jacobian histogram: the number of hexes per bin, 24 bins from -0.2"
                     " to 1", name + "_histogram.png"))

    report = field_values(hexes, REPORT_FIELDS)
    report["tets"] = tets.GetDataInformation().GetNumberOfCells()
    report["seconds"] = seconds
    report["warnings"] = warnings
    table = format_report(report)
    settings = {"target hexes": args.hexes, "run in": "pvbatch with the PolycubeHex plugin",
                "outputs": "%s_hexes.vtu, %s_hexes.mesh" % (name, name)}
    for report_name in ("report.md", "report.html"):
        write_report(os.path.join(out, report_name), report, args.model, settings, pictures)
    print(table)
    print("wrote %s and report.html" % os.path.join(out, "report.md"))


if __name__ == "__main__":
    main()
