#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Read a model, tetrahedralize it if it is a surface, and report mesh statistics.

Runs in pvpython or in Debian's python3.11 (ParaView's VTK) with the build tree's
polycubehex package on PYTHONPATH:

    python3.11 tetrahedralize_and_report.py Data/fertility.off --output-dir out/
"""
import argparse
import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkLogger
from vtkmodules.vtkFiltersCore import (vtkCleanPolyData, vtkExtractEdges,
                                       vtkPolyDataConnectivityFilter)
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter, vtkMeshQuality
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

from polycubehex import vtkMeditReader, vtkMeditWriter, vtkOFFReader, vtkTetrahedralizeFilter

SURFACE_READERS = {".obj": vtkOBJReader, ".stl": vtkSTLReader, ".ply": vtkPLYReader,
                   ".off": vtkOFFReader}
VOLUME_READERS = {".mesh": vtkMeditReader, ".vtk": vtkUnstructuredGridReader,
                  ".vtu": vtkXMLUnstructuredGridReader}


def boundary_statistics(grid):
    """Boundary triangles, components and genus (from each component's Euler characteristic)."""
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    surface.Update()
    connectivity = vtkPolyDataConnectivityFilter()
    connectivity.SetInputConnection(surface.GetOutputPort())
    connectivity.SetExtractionModeToAllRegions()
    connectivity.ColorRegionsOn()
    connectivity.Update()
    regions = connectivity.GetNumberOfExtractedRegions()
    genera = []
    for region in range(regions):
        one = vtkPolyDataConnectivityFilter()
        one.SetInputConnection(surface.GetOutputPort())
        one.SetExtractionModeToSpecifiedRegions()
        one.AddSpecifiedRegion(region)
        one.Update()
        clean = vtkCleanPolyData()
        clean.SetInputConnection(one.GetOutputPort())
        clean.Update()
        edges = vtkExtractEdges()
        edges.SetInputConnection(clean.GetOutputPort())
        edges.Update()
        v = clean.GetOutput().GetNumberOfPoints()
        f = clean.GetOutput().GetNumberOfPolys()
        e = edges.GetOutput().GetNumberOfLines()
        genera.append((2 - (v - e + f)) // 2)
    return surface.GetOutput().GetNumberOfPolys(), genera


def tet_statistics(grid):
    """Volume, and vtkMeshQuality's minimum dihedral angle and radius ratio of the tets."""
    sizes = vtkCellSizeFilter()
    sizes.SetInputData(grid)
    sizes.Update()
    volumes = sizes.GetOutput().GetCellData().GetArray("Volume")
    lo, hi = volumes.GetRange()
    total = sum(volumes.GetValue(i) for i in range(volumes.GetNumberOfTuples()))
    stats = {"volume": total, "min tet volume": lo, "max tet volume": hi}
    for name, setter in (("min dihedral angle (deg)", "SetTetQualityMeasureToMinAngle"),
                         ("radius ratio", "SetTetQualityMeasureToRadiusRatio")):
        quality = vtkMeshQuality()
        quality.SetInputData(grid)
        getattr(quality, setter)()
        quality.Update()
        values = quality.GetOutput().GetFieldData().GetArray("Mesh Tetrahedron Quality")
        # Columns: minimum, average, maximum, variance, count.
        stats[name] = (values.GetComponent(0, 0), values.GetComponent(0, 1),
                       values.GetComponent(0, 2))
    return stats


def main(argv=None):
    # VTK's INFO lines (e.g. from vtkExtractEdges) would drown the report.
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input", help="a closed surface (.off .obj .stl .ply) or a tet mesh "
                                      "(.mesh .vtk .vtu)")
    parser.add_argument("--output-dir", default=".", help="where to write tets.vtu, tets.mesh "
                                                          "and report.md")
    parser.add_argument("--radius-edge-ratio", type=float, default=2.0,
                        help="TetGen quality bound (default 2.0)")
    args = parser.parse_args(argv)

    extension = os.path.splitext(args.input)[1].lower()
    if not os.path.isfile(args.input):
        sys.exit("error: no such file: %s" % args.input)
    if extension not in SURFACE_READERS and extension not in VOLUME_READERS:
        sys.exit("error: unsupported file type '%s'" % extension)
    os.makedirs(args.output_dir, exist_ok=True)

    timings = {}
    start = time.perf_counter()
    reader = (SURFACE_READERS.get(extension) or VOLUME_READERS[extension])()
    reader.SetFileName(args.input)
    if not reader.GetExecutive().Update() or reader.GetOutput().GetNumberOfCells() == 0:
        sys.exit("error: could not read %s (see the message above)" % args.input)
    timings["read"] = time.perf_counter() - start

    if extension in SURFACE_READERS:
        start = time.perf_counter()
        tetrahedralize = vtkTetrahedralizeFilter()
        tetrahedralize.SetInputConnection(reader.GetOutputPort())
        tetrahedralize.SetRadiusEdgeRatio(args.radius_edge_ratio)
        if not tetrahedralize.GetExecutive().Update():
            sys.exit("error: tetrahedralization failed (see the message above)")
        grid = tetrahedralize.GetOutput()
        timings["tetrahedralize"] = time.perf_counter() - start
    else:
        grid = reader.GetOutput()

    triangles, genera = boundary_statistics(grid)
    stats = tet_statistics(grid)
    bounds = grid.GetBounds()
    diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5

    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetFileName(os.path.join(args.output_dir, "tets.vtu"))
    writer.Write()
    medit = vtkMeditWriter()
    medit.SetInputData(grid)
    medit.SetFileName(os.path.join(args.output_dir, "tets.mesh"))
    medit.Write()

    rows = [
        ("input", os.path.basename(args.input)),
        ("vertices", grid.GetNumberOfPoints()),
        ("tetrahedra", grid.GetNumberOfCells()),
        ("boundary triangles", triangles),
        ("boundary components", len(genera)),
        ("genus per component", ", ".join(str(g) for g in genera)),
        ("first Betti number", sum(genera)),
        ("bounding-box diagonal", "%.6g" % diagonal),
        ("volume", "%.6g" % stats["volume"]),
        ("tet volume min / max", "%.3g / %.3g" % (stats["min tet volume"],
                                                  stats["max tet volume"])),
        ("min dihedral angle min / mean (deg)", "%.2f / %.2f" % stats["min dihedral angle (deg)"][:2]),
        ("radius ratio mean / max", "%.3f / %.3f" % (stats["radius ratio"][1],
                                                     stats["radius ratio"][2])),
    ] + [("seconds: %s" % k, "%.2f" % v) for k, v in timings.items()]
    width = max(len(k) for k, _ in rows)
    table = "\n".join("| %s | %s |" % (k.ljust(width), v) for k, v in rows)
    header = "| %s | %s |\n|%s|---|" % ("measure".ljust(width), "value", "-" * (width + 2))
    report = "# PolycubeHex mesh report\n\n%s\n%s\n" % (header, table)
    with open(os.path.join(args.output_dir, "report.md"), "w") as out:
        out.write(report)
    print(report)
    print("wrote %s" % os.path.join(args.output_dir, "tets.vtu"))
    if stats["min tet volume"] <= 0:
        sys.exit("error: the tet mesh has non-positive tets")
    return 0


if __name__ == "__main__":
    sys.exit(main())
