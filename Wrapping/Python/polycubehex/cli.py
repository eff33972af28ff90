# SPDX-License-Identifier: BSD-3-Clause
"""polycubehex: an all-hex mesh from a file, on the command line.

    polycubehex input.obj -o hexes.vtu [--hexes 10000] [--guidance automatic|framefield|uniform]
                [--no-padding] [--no-smoothing] [--report report.md|report.html]
                [--set STAGE.Property=value ...]

--set gives any property of a stage's filter (the names of the ParaView panels and of the
filters' Set methods), e.g. --set polycube.NormalDifferenceWeight=2 or
--set frames.CutMeshBoundaryAlignmentWeight=0; stages: tetrahedralize, cuts, frames,
polycube, hexes.

Input: a closed surface (.obj .stl .ply .off .vtp, tetrahedralized with TetGen) or a tet mesh
(.mesh .vtk .vtu). Output: .vtu, .vtk or MEDIT .mesh. Prints the quality table at the end.
Exit status: 0 for a valid hex mesh; 1 with the refusing stage's message when a stage refuses its
input; 2 when the mesh was written but is not valid (inverted hexes; the warnings say why).
"""
import argparse
import os
import sys

from vtkmodules.vtkCommonCore import vtkLogger

from .pipeline import STAGES, WRITERS, PipelineError, format_report, mesh, write
from .report import write_report


class ProgressLine:
    """One progress line per stage on a terminal; nothing when stderr is not a terminal."""

    def __init__(self, stream):
        self.stream = stream
        self.enabled = stream.isatty()
        self.stage = None

    def __call__(self, stage, fraction):
        if not self.enabled:
            return
        if stage != self.stage and self.stage is not None:
            self.stream.write("\n")
        self.stage = stage
        filled = int(30 * fraction)
        self.stream.write("\r%-15s [%s%s] %3d%%" % (stage, "#" * filled, "." * (30 - filled),
                                                   int(100 * fraction)))
        self.stream.flush()

    def finish(self):
        if self.enabled and self.stage is not None:
            self.stream.write("\n")


def parse_setting(text):
    """'stage.Property=value' -> (stage, Property, value), the value an int, a float or the text
    itself; ValueError (reported as a usage error) for any other form or an unknown stage."""
    key, separator, value = text.partition("=")
    stage, dot, name = key.partition(".")
    if not separator or not dot or not name or stage not in STAGES:
        raise ValueError("expected STAGE.Property=value with STAGE one of %s" % ", ".join(STAGES))
    for convert in (int, float):
        try:
            return stage, name, convert(value)
        except ValueError:
            pass
    return stage, name, value


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="polycubehex", description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__.split("\n\n", 1)[1])
    parser.add_argument("input", help="surface or tet mesh file")
    parser.add_argument("-o", "--output", required=True, help="hex mesh file (.vtu .vtk .mesh)")
    parser.add_argument("--hexes", type=int, default=10000,
                        help="target hex count, padding included (default 10000)")
    parser.add_argument("--guidance", choices=["automatic", "framefield", "uniform"],
                        default="automatic",
                        help="what guides the polycube: automatic (the default: framefield), framefield "
                        "(the closed form) or uniform (the l1 baseline)")
    parser.add_argument("--uniform", action="store_true", help="same as --guidance uniform")
    parser.add_argument("--no-padding", action="store_true", help="no padding layer")
    parser.add_argument("--no-smoothing", action="store_true", help="the raw extraction")
    parser.add_argument("--report", help="also write the quality table to this file: an HTML "
                        "page when it ends in .html, Markdown otherwise")
    parser.add_argument("--verbose", action="store_true", help="show VTK's own log lines")
    parser.add_argument("--set", action="append", default=[], metavar="STAGE.Property=value",
                        help="set a property of a stage's filter (repeatable), e.g. "
                        "polycube.NormalDifferenceWeight=2")
    args = parser.parse_args(argv)
    settings = {}
    for text in args.set:
        try:
            stage, name, value = parse_setting(text)
        except ValueError as error:
            parser.error("--set %s: %s" % (text, error))
        settings.setdefault(stage, {})[name] = value
    if args.hexes < 1:
        parser.error("--hexes must be at least 1")
    if os.path.splitext(args.output)[1].lower() not in WRITERS:
        parser.error("the output must end in %s" % ", ".join(sorted(WRITERS)))
    if not args.verbose:
        # Stage errors are reported once, below, instead of VTK's log lines.
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)

    progress = ProgressLine(sys.stderr)
    try:
        hexes, report = mesh(args.input, hex_count=args.hexes,
                             guidance="uniform" if args.uniform else args.guidance,
                             padding=not args.no_padding, smoothing=not args.no_smoothing,
                             progress=progress, settings=settings)
        write(hexes, args.output)
    except PipelineError as error:
        progress.finish()
        print("polycubehex: error: %s" % error, file=sys.stderr)
        return 1
    progress.finish()
    for warning in report["warnings"]:
        print("polycubehex: warning: %s" % warning, file=sys.stderr)
    table = format_report(report)
    print(table)
    print("wrote %s" % os.path.abspath(args.output))
    if args.report:
        guidance = "uniform" if args.uniform else args.guidance
        shown = {"output": args.output, "target hexes": args.hexes, "guidance": guidance,
                 "padding": "off" if args.no_padding else "on",
                 "smoothing": "off" if args.no_smoothing else "on"}
        shown.update({"%s.%s" % (stage, name): value for stage, properties in settings.items()
                      for name, value in properties.items()})
        write_report(args.report, report, args.input, shown)
    if report.get("ValidHexMesh") != 1:
        # Written for inspection, but never reported as a success.
        print("polycubehex: the hex mesh is not valid (%d inverted hexes); see the warnings" %
              report.get("InvertedHexCount", -1), file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
