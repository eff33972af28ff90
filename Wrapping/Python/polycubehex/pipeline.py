# SPDX-License-Identifier: BSD-3-Clause
"""The whole pipeline in one call, with VTK only (pvpython or Debian's python3.11)::

    import polycubehex
    hexes, report = polycubehex.mesh("Data/torus.obj", hex_count=5000)
    print(report["ScaledJacobianMin"], report["ValidHexMesh"])

Stages: read, tetrahedralize a surface with TetGen, cut the handles (§2), frame field (§3),
polycube (§4.1-4.2), hexes (§4.3). A stage that refuses its input raises ``PipelineError`` with
the stage's own message; nothing is left half-done in the caller's objects.
"""
import os
import re
import time

from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader, vtkUnstructuredGridWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader,
                                 vtkXMLUnstructuredGridWriter)

from .PolycubeHexFilters import (vtkFrameFieldFilter, vtkHandleCutFilter, vtkHexExtractFilter,
                                 vtkMeditReader, vtkMeditWriter, vtkOFFReader,
                                 vtkPolycubeDeformFilter, vtkTetrahedralizeFilter)
# The report's table lives in .report (pure Python); re-exported here for existing callers.
from .report import REPORT_FIELDS, format_report  # noqa: F401

SURFACE_READERS = {".obj": vtkOBJReader, ".stl": vtkSTLReader, ".ply": vtkPLYReader,
                   ".off": vtkOFFReader, ".vtp": vtkXMLPolyDataReader}
VOLUME_READERS = {".mesh": vtkMeditReader, ".vtk": vtkUnstructuredGridReader,
                  ".vtu": vtkXMLUnstructuredGridReader}
WRITERS = {".vtu": vtkXMLUnstructuredGridWriter, ".vtk": vtkUnstructuredGridWriter,
           ".mesh": vtkMeditWriter}
GUIDANCE = {"automatic": 0, "framefield": 1, "uniform": 2}


class PipelineError(RuntimeError):
    """A stage refused its input; the message is the stage's own."""


class ErrorCatcher:
    """Collects the messages of a VTK algorithm's ErrorEvent and WarningEvent."""

    def __init__(self, algorithm):
        self.errors = []
        self.warnings = []
        algorithm.AddObserver(vtkCommand.ErrorEvent, self._error)
        algorithm.AddObserver(vtkCommand.WarningEvent, self._warning)

    @staticmethod
    def _clean(message):
        # VTK prefixes "ERROR: In file, line N\nvtkClass (0x...): "; keep the readable part.
        return re.sub(r"^.*?\(0x[0-9a-fA-F]+\): ", "", str(message or ""), flags=re.S).strip()

    def _error(self, caller, event, message=None):
        self.errors.append(self._clean(message))

    def _warning(self, caller, event, message=None):
        self.warnings.append(self._clean(message))

    # VTK passes the message as call data of type string.
    _error.CallDataType = "string0"
    _warning.CallDataType = "string0"


def _run(stage, algorithm, data, progress, warnings):
    """Runs one stage on `data`; returns a copy of its output port 0."""
    catcher = ErrorCatcher(algorithm)
    if progress is not None:
        algorithm.AddObserver(vtkCommand.ProgressEvent,
                              lambda caller, event: progress(stage, caller.GetProgress()))
    if data is not None:
        algorithm.SetInputData(data)
    ok = algorithm.GetExecutive().Update()
    warnings.extend("%s: %s" % (stage, w) for w in catcher.warnings)
    if not ok or catcher.errors:
        message = catcher.errors[0] if catcher.errors else "the stage failed"
        raise PipelineError("%s: %s" % (stage, message))
    output = algorithm.GetOutputDataObject(0)
    copy = output.NewInstance()
    copy.ShallowCopy(output)
    return copy


def read(path):
    """Reads a surface or a tet mesh by its extension; returns (data, is_surface)."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in SURFACE_READERS and extension not in VOLUME_READERS:
        raise PipelineError("read: unknown extension '%s' (surfaces: %s; tet meshes: %s)" % (
            extension, ", ".join(sorted(SURFACE_READERS)), ", ".join(sorted(VOLUME_READERS))))
    if not os.path.isfile(path):
        raise PipelineError("read: no such file: %s" % path)
    reader = (SURFACE_READERS.get(extension) or VOLUME_READERS[extension])()
    reader.SetFileName(path)
    data = _run("read", reader, None, None, [])
    if data.GetNumberOfCells() == 0:
        raise PipelineError("read: %s has no cells" % path)
    return data, extension in SURFACE_READERS


def write(grid, path):
    """Writes the hex mesh as .vtu, .vtk or MEDIT .mesh."""
    extension = os.path.splitext(path)[1].lower()
    if extension not in WRITERS:
        raise PipelineError("write: unknown extension '%s' (use %s)" % (
            extension, ", ".join(sorted(WRITERS))))
    writer = WRITERS[extension]()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    catcher = ErrorCatcher(writer)
    if not writer.Write() or catcher.errors:
        raise PipelineError("write: %s" % (catcher.errors[0] if catcher.errors else path))


def mesh(source, hex_count=10000, guidance="automatic", padding=True, smoothing=True,
         progress=None):
    """Runs the whole pipeline.

    source     a file name (surface: .obj .stl .ply .off .vtp; tets: .mesh .vtk .vtu) or a
               vtkPolyData / vtkUnstructuredGrid
    hex_count  target number of hexes, padding included
    guidance   "automatic", "framefield" or "uniform" (the l1 baseline)
    progress   optional callable(stage, fraction)
    Returns (hexes, report): the vtkUnstructuredGrid of hexes and a dict with the quality
    measures (REPORT_FIELDS), the seconds per stage, the warnings and the stages' outputs.
    Raises PipelineError with the refusing stage's message.
    """
    if guidance.lower() not in GUIDANCE:
        raise PipelineError("guidance must be one of %s" % ", ".join(GUIDANCE))
    seconds = {}
    warnings = []
    start = time.perf_counter()
    if isinstance(source, str):
        data, is_surface = read(source)
    else:
        data, is_surface = source, source.IsA("vtkPolyData")
    seconds["read"] = time.perf_counter() - start

    def timed(stage, algorithm, data):
        begin = time.perf_counter()
        output = _run(stage, algorithm, data, progress, warnings)
        seconds[stage] = time.perf_counter() - begin
        return output

    tets = timed("tetrahedralize", vtkTetrahedralizeFilter(), data) if is_surface else data
    cuts = timed("cuts", vtkHandleCutFilter(), tets)
    frames = timed("frame field", vtkFrameFieldFilter(), cuts)
    deform = vtkPolycubeDeformFilter()
    deform.SetGuidance(GUIDANCE[guidance.lower()])
    polycube = timed("polycube", deform, frames)
    extract = vtkHexExtractFilter()
    extract.SetTargetHexCount(int(hex_count))
    extract.SetPadding(bool(padding))
    extract.SetSmoothing(bool(smoothing))
    hexes = timed("hexes", extract, polycube)

    report = {"tets": tets.GetNumberOfCells(), "seconds": seconds, "warnings": warnings,
              "stages": {"tets": tets, "cuts": cuts, "frames": frames, "polycube": polycube}}
    fields = hexes.GetFieldData()
    for name in REPORT_FIELDS:
        array = fields.GetAbstractArray(name)
        if array is not None and array.GetNumberOfValues() > 0:
            value = array.GetVariantValue(0)
            report[name] = value.ToString() if value.IsString() else value.ToDouble()
    return hexes, report

