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


# The stages whose filter properties `settings` may set, by the key it uses.
STAGES = ("tetrahedralize", "cuts", "frames", "polycube", "hexes")


def _configure(stage, algorithm, properties):
    """Calls algorithm.Set<Name>(value) for each Name: value; a clear error for a wrong name or
    value, before anything runs."""
    for name, value in properties.items():
        setter = getattr(algorithm, "Set" + str(name), None)
        if setter is None or not callable(setter):
            raise PipelineError("settings: %s (%s) has no property '%s'" % (
                stage, algorithm.GetClassName(), name))
        getter = getattr(algorithm, "Get" + str(name), None)
        current = getter() if callable(getter) else None
        if isinstance(current, (bool, int, float)) and not isinstance(value, (bool, int, float)):
            # VTK's wrapping would take any object as a flag by its truth value.
            raise PipelineError("settings: %s.%s = %r: expected a number (now %r)" % (
                stage, name, value, current))
        try:
            setter(value)
        except TypeError as error:
            raise PipelineError("settings: %s.%s = %r: %s" % (stage, name, value, error))


def _field_value(data, name):
    array = data.GetFieldData().GetArray(name) if data is not None else None
    return array.GetValue(0) if array is not None and array.GetNumberOfValues() > 0 else None


def _polycube(deform, framer, frames, cuts, timed, warnings):
    """Runs the polycube stage; returns (frames, polycube). On a model with handles the frame
    filter starts from a tightly aligned initial field; when the closed form refuses the field
    that gave (a frame field need not describe a valid map), the frame field is computed again
    from the base weight (the paper's §6 remedy) and the stage runs again. With automatic
    guidance the last attempt is automatic too, so the filter itself falls back to Uniform when
    even that field describes no map."""
    aligned = _field_value(frames, "InitialAlignmentWeight")
    retry = deform.GetGuidance() != deform.UNIFORM and aligned is not None and \
        aligned != framer.GetBoundaryAlignmentWeight()
    if not retry:
        return frames, timed("polycube", deform, frames)
    automatic = deform.GetGuidance() == deform.AUTOMATIC
    if automatic:
        deform.SetGuidance(deform.FRAME_FIELD)  # to see a refusal instead of the fallback
    try:
        return frames, timed("polycube", deform, frames)
    except PipelineError as error:
        warnings.append(
            "frame field: the field from the aligned initial field (weight %g) was refused (%s); "
            "computed again from the base weight %g (CutMeshBoundaryAlignmentWeight 0)" % (
                aligned, error, framer.GetBoundaryAlignmentWeight()))
    finally:
        if automatic:
            deform.SetGuidance(deform.AUTOMATIC)
    framer.SetCutMeshBoundaryAlignmentWeight(0.0)
    frames = timed("frame field", framer, cuts)
    return frames, timed("polycube", deform, frames)


def mesh(source, hex_count=10000, guidance="automatic", padding=True, smoothing=True,
         progress=None, settings=None):
    """Runs the whole pipeline.

    source     a file name (surface: .obj .stl .ply .off .vtp; tets: .mesh .vtk .vtu) or a
               vtkPolyData / vtkUnstructuredGrid
    hex_count  target number of hexes, padding included
    guidance   "automatic", "framefield" or "uniform" (the l1 baseline)
    progress   optional callable(stage, fraction)
    settings   optional {stage: {Property: value}} for any filter property, stage one of
               "tetrahedralize", "cuts", "frames", "polycube", "hexes"; e.g.
               {"polycube": {"NormalDifferenceWeight": 2}}. Applied after the arguments above,
               so {"hexes": {"TargetHexCount": 5000}} wins over hex_count.
    Returns (hexes, report): the vtkUnstructuredGrid of hexes and a dict with the quality
    measures (REPORT_FIELDS), the seconds per stage, the warnings and the stages' outputs.
    Raises PipelineError with the refusing stage's message.

    With frame-field guidance on a model with handles, the frame filter starts from a tightly
    aligned field (CutMeshBoundaryAlignmentWeight). Should the polycube stage refuse the field
    it gives (a frame field need not describe a valid map, Fang et al. §6), the frame field is
    computed once more from the base weight and the polycube stage runs again; a warning says
    so and the seconds include both runs. With automatic guidance, a frame field that still
    describes no valid map gives the l1 polycube (the filter's own fallback, with a warning).
    """
    if guidance.lower() not in GUIDANCE:
        raise PipelineError("guidance must be one of %s" % ", ".join(GUIDANCE))
    settings = dict(settings or {})
    unknown = sorted(set(settings) - set(STAGES))
    if unknown:
        raise PipelineError("settings: unknown stage %s (use %s)" % (
            ", ".join(repr(u) for u in unknown), ", ".join(STAGES)))
    tetrahedralize = vtkTetrahedralizeFilter()
    cutter = vtkHandleCutFilter()
    framer = vtkFrameFieldFilter()
    deform = vtkPolycubeDeformFilter()
    deform.SetGuidance(GUIDANCE[guidance.lower()])
    extract = vtkHexExtractFilter()
    extract.SetTargetHexCount(int(hex_count))
    extract.SetPadding(bool(padding))
    extract.SetSmoothing(bool(smoothing))
    for stage, algorithm in zip(STAGES, (tetrahedralize, cutter, framer, deform, extract)):
        _configure(stage, algorithm, settings.get(stage, {}))
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
        try:
            return _run(stage, algorithm, data, progress, warnings)
        finally:
            # A stage run twice (the frame field's retry below) counts both runs.
            seconds[stage] = seconds.get(stage, 0.0) + time.perf_counter() - begin

    tets = timed("tetrahedralize", tetrahedralize, data) if is_surface else data
    cuts = timed("cuts", cutter, tets)
    frames = timed("frame field", framer, cuts)
    frames, polycube = _polycube(deform, framer, frames, cuts, timed, warnings)
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

