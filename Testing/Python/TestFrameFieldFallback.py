# SPDX-License-Identifier: BSD-3-Clause
"""polycubehex.mesh() recovers when the polycube stage refuses the frame field of the aligned
initial field. Kitten (genus 1) with CutMeshBoundaryAlignmentWeight 70: that field has no singular
edge, so the frame filter keeps it, but the map it describes (eq. 7 with the cut transitions)
inverts tets, and the deformation refuses it. The helper then computes the frame field again from
the base weight (30), which gives a valid polycube, and says so in a warning. Without the retry
the same call raises PipelineError (checked first, on the frame and polycube filters alone: with
FrameField guidance the polycube filter refuses that field; with automatic guidance, its default,
it gives the l1 polycube instead, with a warning)."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader

import polycubehex

data = os.environ["POLYCUBEHEX_DATA"]
reader = vtkUnstructuredGridReader()
reader.SetFileName(os.path.join(data, "kitten.vtk"))
reader.Update()
tets = reader.GetOutput()


def run(algorithm, data_object):
    algorithm.SetInputData(data_object)
    ok = algorithm.GetExecutive().Update()
    return algorithm.GetOutputDataObject(0) if ok else None


def field(data_object, name):
    return data_object.GetFieldData().GetArray(name).GetValue(0)


# The filters alone: the aligned field at 70 is kept (no singular edge) and the polycube refuses.
cuts = run(polycubehex.vtkHandleCutFilter(), tets)
frames_filter = polycubehex.vtkFrameFieldFilter()
frames_filter.SetCutMeshBoundaryAlignmentWeight(70)
frames = run(frames_filter, cuts)
print("aligned at 70: kept weight %g, singular edges %d" % (
    field(frames, "InitialAlignmentWeight"), field(frames, "SingularEdgeCount")))
assert field(frames, "InitialAlignmentWeight") == 70
assert field(frames, "SingularEdgeCount") == 0
strict = polycubehex.vtkPolycubeDeformFilter()
strict.SetGuidance(strict.FRAME_FIELD)
assert run(strict, frames) is None, \
    "the deformation accepted the aligned field: this test needs another weight"

# Automatic guidance (the filter's default) gives the l1 polycube instead, and warns.
automatic = polycubehex.vtkPolycubeDeformFilter()
warnings = []
automatic.AddObserver(vtkCommand.WarningEvent, lambda caller, event: warnings.append(event))
polycube = run(automatic, frames)
assert polycube is not None, "automatic guidance refused the frame field instead of falling back"
guidance = polycube.GetFieldData().GetAbstractArray("Guidance").GetValue(0)
print("automatic guidance on the refused field: %s, %d corners, %d warnings" % (
    guidance, field(polycube, "CornerCount"), len(warnings)))
assert guidance == "Uniform", guidance
assert field(polycube, "InvertedTetCount") == 0
assert warnings, "the fallback to Uniform was not reported"

# The helper: the same settings give a valid raw hex mesh from the base weight's field.
hexes, report = polycubehex.mesh(tets, hex_count=3000, smoothing=False,
                                 settings={"frames": {"CutMeshBoundaryAlignmentWeight": 70}})
kept = report["stages"]["frames"]
print("helper: kept weight %g, corners %d, hexes %d, inverted %d, seconds %s" % (
    field(kept, "InitialAlignmentWeight"), report["CornerCount"], report["HexCount"],
    report["InvertedHexCount"], report["seconds"]))
for warning in report["warnings"]:
    print("warning:", warning[:200])
assert field(kept, "InitialAlignmentWeight") == 30
assert field(kept, "SingularEdgeCount") == 0
assert report["Guidance"] == "FrameField"
assert any("computed again from the base weight 30" in w for w in report["warnings"])
assert hexes.GetNumberOfCells() > 0
# The closed form on kitten: 36 corners (BENCHMARKS.md); the l1 polycube has 52.
assert report["CornerCount"] < 52, report["CornerCount"]
print("TestFrameFieldFallback: ok")
sys.exit(0)
