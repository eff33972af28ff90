#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the hex stage alone on a model's polycube, caching the polycube, so that the hex stage
can be tuned in seconds instead of re-running the cuts, frames and deformation each time.

    PYTHONPATH=build/lib/python3/dist-packages python3.11 Testing/Benchmark/hex_stage.py \
        ../shared/data/rockerarm.mesh --guidance FrameField --hexes 17594 [--no-smoothing] [--no-padding] [--no-padding-placement] [--map-smoothing] [--soft-feature-angle 20] [--no-polish] [--mean-search-sweeps 3] [--untangling-paths 2] [--scale-retry-below 0.3] \
        [--polish-sharp-edge-angle 60] [--normal-difference-weight 1] [--homotopy-steps 40] [--cache /tmp/polycubes] [--output hexes.vtu] [--worst 10]

The first run writes <cache>/<model>_<guidance>.vtu (the deformation's port 0, its field data
included); later runs read it. Prints the hex stage's seconds per step and its quality fields,
and with --worst N the N worst hexes (scaled Jacobian, centre, and how many of their vertices
lie on the boundary). Not run by CTest.
"""
import argparse
import os
import sys
import time

import polycubehex
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader, vtkXMLUnstructuredGridWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchmark import load, run_filter, tetrahedralize  # noqa: E402


def polycube_of(path, guidance, cache, normal_difference_weight=None, homotopy_steps=0):
    name = os.path.splitext(os.path.basename(path))[0]
    suffix = "" if normal_difference_weight is None else "_wdiff%g" % normal_difference_weight
    suffix += "_homotopy%d" % homotopy_steps if homotopy_steps else ""
    cached = os.path.join(cache, "%s_%s%s.vtu" % (name, guidance, suffix))
    if os.path.exists(cached):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(cached)
        reader.Update()
        return reader.GetOutput()
    data, is_surface = load(path)
    grid = tetrahedralize(data) if is_surface else data
    source = grid
    if guidance == "FrameField":
        cuts = run_filter(polycubehex.vtkHandleCutFilter(), grid)
        source = run_filter(polycubehex.vtkFrameFieldFilter(), cuts)
    deform = polycubehex.vtkPolycubeDeformFilter()
    deform.SetGuidance(deform.UNIFORM if guidance == "Uniform" else deform.FRAME_FIELD)
    if normal_difference_weight is not None:
        deform.SetNormalDifferenceWeight(normal_difference_weight)
    deform.SetFlattenHomotopySteps(homotopy_steps)
    start = time.perf_counter()
    polycube = run_filter(deform, source)
    print("polycube: %.1f s" % (time.perf_counter() - start))
    if polycube is None:
        sys.exit("the deformation refused the model")
    os.makedirs(cache, exist_ok=True)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(cached)
    writer.SetInputData(polycube)
    writer.Write()
    return polycube


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("model")
    parser.add_argument("--guidance", choices=("Uniform", "FrameField"), default="FrameField")
    parser.add_argument("--hexes", type=int, default=10000)
    parser.add_argument("--no-smoothing", action="store_true")
    parser.add_argument("--no-padding", action="store_true")
    parser.add_argument("--no-padding-placement", action="store_true")
    parser.add_argument("--map-smoothing", action="store_true")
    parser.add_argument("--soft-feature-angle", type=float, default=None)
    parser.add_argument("--no-polish", action="store_true")
    parser.add_argument("--polish-release-angle", type=float, default=None)
    parser.add_argument("--polish-sharp-edge-angle", type=float, default=None)
    parser.add_argument("--mean-search-sweeps", type=int, default=None)
    parser.add_argument("--untangling-paths", type=int, default=None)
    parser.add_argument("--scale-retry-below", type=float, default=None)
    parser.add_argument("--normal-difference-weight", type=float, default=None,
                        help="the deformation's NormalDifferenceWeight (cached apart)")
    parser.add_argument("--homotopy-steps", type=int, default=0,
                        help="the deformation's FlattenHomotopySteps (cached apart)")
    parser.add_argument("--cache", default="/tmp/polycubehex-polycubes")
    parser.add_argument("--output", help="write the hexes (.vtu)")
    parser.add_argument("--worst", type=int, default=0)
    args = parser.parse_args()

    polycube = polycube_of(args.model, args.guidance, args.cache, args.normal_difference_weight,
                           args.homotopy_steps)
    extract = polycubehex.vtkHexExtractFilter()
    extract.SetTargetHexCount(args.hexes)
    extract.SetSmoothing(0 if args.no_smoothing else 1)
    extract.SetPadding(0 if args.no_padding else 1)
    extract.SetPaddingPlacement(0 if args.no_padding_placement else 1)
    extract.SetMapSmoothing(1 if args.map_smoothing else 0)
    extract.SetPolish(0 if args.no_polish else 1)
    if args.polish_release_angle is not None:
        extract.SetPolishReleaseAngle(args.polish_release_angle)
    if args.polish_sharp_edge_angle is not None:
        extract.SetPolishSharpEdgeAngle(args.polish_sharp_edge_angle)
    if args.mean_search_sweeps is not None:
        extract.SetMeanSearchSweeps(args.mean_search_sweeps)
    if args.untangling_paths is not None:
        extract.SetUntanglingPaths(args.untangling_paths)
    if args.scale_retry_below is not None:
        extract.SetScaleRetryBelow(args.scale_retry_below)
    if args.soft_feature_angle is not None:
        extract.SetSoftFeatureAngle(args.soft_feature_angle)
    start = time.perf_counter()
    hexes = run_filter(extract, polycube)
    print("hex stage: %.2f s" % (time.perf_counter() - start))
    if hexes is None:
        sys.exit("the hex stage refused the polycube")
    fields = hexes.GetFieldData()
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetAbstractArray(i)
        if array.GetNumberOfTuples() != 1 or array.GetNumberOfComponents() != 1:
            continue
        if hasattr(array, "GetTuple1"):
            print("  %-40s %g" % (array.GetName(), array.GetTuple1(0)))
        else:
            print("  %-40s %s" % (array.GetName(), array.GetVariantValue(0).ToString()))
    if args.worst > 0:
        print_worst_hexes(hexes, args.worst)
    if args.output:
        writer = vtkXMLUnstructuredGridWriter()
        writer.SetFileName(args.output)
        writer.SetInputData(hexes)
        writer.Write()


def print_worst_hexes(hexes, count):
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(hexes)
    surface.PassThroughPointIdsOn()
    surface.Update()
    ids = surface.GetOutput().GetPointData().GetArray("vtkOriginalPointIds")
    boundary = {int(ids.GetTuple1(i)) for i in range(ids.GetNumberOfTuples())}
    quality = hexes.GetCellData().GetArray("ScaledJacobian")
    order = sorted(range(hexes.GetNumberOfCells()), key=quality.GetTuple1)[:count]
    for cell in order:
        points = hexes.GetCell(cell).GetPointIds()
        corners = [points.GetId(k) for k in range(8)]
        centre = [sum(hexes.GetPoint(p)[axis] for p in corners) / 8 for axis in range(3)]
        print("  hex %6d  SJ %+.3f  centre (%.3f, %.3f, %.3f)  boundary vertices %d" % (
            cell, quality.GetTuple1(cell), *centre, sum(p in boundary for p in corners)))


if __name__ == "__main__":
    main()
