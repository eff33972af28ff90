# SPDX-License-Identifier: BSD-3-Clause
"""A corpus of bad inputs, generated into the build tree, each through the whole pipeline by the
command-line program (every filter in turn), then each readable one straight into every filter
on its own. Each must end in one of three ways, never a crash,
a hang or an invalid mesh reported as success:
  status 1: a stage refused it, with one readable line naming the stage (and, where the case says
            so, the expected words);
  status 0: a valid hex mesh (ValidHexMesh 1 in the quality table);
  status 2: a mesh written for inspection but reported as not valid.
"""
import math
import os
import subprocess
import sys

launcher = os.environ["POLYCUBEHEX_LAUNCHER"]
corpus = os.path.join(os.environ["POLYCUBEHEX_OUTPUT"], "bad_inputs")
os.makedirs(corpus, exist_ok=True)

# -- Small geometry helpers ------------------------------------------------------------------

CUBE_V = [(x, y, z) for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)]
# Outward triangles of the unit cube on CUBE_V (index = 4x + 2y + z).
CUBE_F = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
          (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]


def shifted(vertices, offset):
    return [(x + offset[0], y + offset[1], z + offset[2]) for x, y, z in vertices]


def off_text(vertices, faces, declared=None):
    counts = declared or (len(vertices), len(faces))
    lines = ["OFF", "%d %d 0" % counts]
    lines += ["%r %r %r" % v for v in vertices]
    lines += ["%d %s" % (len(f), " ".join(str(i) for i in f)) for f in faces]
    return "\n".join(lines) + "\n"


def obj_text(vertices, faces):
    lines = ["v %r %r %r" % v for v in vertices]
    lines += ["f %s" % " ".join(str(i + 1) for i in f) for f in faces]
    return "\n".join(lines) + "\n"


def medit_text(vertices, tets, triangles=(), hexahedra=(), declared_tets=None):
    lines = ["MeshVersionFormatted 1", "Dimension 3", "Vertices", str(len(vertices))]
    lines += ["%r %r %r 0" % v for v in vertices]
    if tets or declared_tets:
        lines += ["Tetrahedra", str(declared_tets if declared_tets is not None else len(tets))]
        lines += ["%s 0" % " ".join(str(i + 1) for i in t) for t in tets]
    if triangles:
        lines += ["Triangles", str(len(triangles))]
        lines += ["%s 0" % " ".join(str(i + 1) for i in t) for t in triangles]
    if hexahedra:
        lines += ["Hexahedra", str(len(hexahedra))]
        lines += ["%s 0" % " ".join(str(i + 1) for i in h) for h in hexahedra]
    return "\n".join(lines + ["End"]) + "\n"


# Five positive tets of the unit cube (corners as in CUBE_V).
CUBE_TETS = [(0, 4, 2, 1), (6, 2, 4, 7), (5, 1, 7, 4), (3, 7, 1, 2), (1, 4, 2, 7)]


def tet_volume(p, t):
    a, b, c, d = (p[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    w = [d[k] - a[k] for k in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0


CUBE_TETS = [t if tet_volume(CUBE_V, t) > 0 else (t[0], t[2], t[1], t[3]) for t in CUBE_TETS]


def wedge(degrees):
    """A triangular prism whose cross-section has a `degrees` angle at its sharp edge."""
    a = math.radians(degrees)
    base = [(0.0, 0.0), (1.0, 0.0), (math.cos(a), math.sin(a))]
    vertices = [(x, y, z) for z in (0.0, 1.0) for x, y in base]
    faces = [(0, 2, 1), (3, 4, 5), (0, 1, 4), (0, 4, 3), (1, 2, 5), (1, 5, 4),
             (2, 0, 3), (2, 3, 5)]
    return vertices, faces


def legacy_vtk(points, cells):
    lines = ["# vtk DataFile Version 3.0", "mixed cells", "ASCII", "DATASET UNSTRUCTURED_GRID",
             "POINTS %d double" % len(points)]
    lines += ["%r %r %r" % p for p in points]
    size = sum(len(c[1]) + 1 for c in cells)
    lines += ["CELLS %d %d" % (len(cells), size)]
    lines += ["%d %s" % (len(c[1]), " ".join(str(i) for i in c[1])) for c in cells]
    lines += ["CELL_TYPES %d" % len(cells)] + [str(c[0]) for c in cells]
    return "\n".join(lines) + "\n"


# -- The corpus: (file name, contents (str or bytes or None for "do not create"), expected) ----
two_cubes = CUBE_V + shifted(CUBE_V, (3.0, 0.0, 0.0))
two_cube_faces = CUBE_F + [tuple(i + 8 for i in f) for f in CUBE_F]
touching = CUBE_V + shifted(CUBE_V, (1.0, 1.0, 1.0))
overlapping = CUBE_V + shifted(CUBE_V, (0.5, 0.5, 0.5))
flipped = list(CUBE_F)
flipped[0] = (0, 3, 1)
with_nan = list(CUBE_V)
with_nan[3] = (float("nan"), 1.0, 1.0)
with_inf = list(CUBE_V)
with_inf[3] = (float("inf"), 1.0, 1.0)
huge = [tuple(1e200 * c for c in v) for v in CUBE_V]
duplicated = CUBE_V + CUBE_V  # every point twice; the faces use the first copies
wedge10 = wedge(10.0)
inverted = [CUBE_TETS[0][:1] + (CUBE_TETS[0][2], CUBE_TETS[0][1]) + CUBE_TETS[0][3:]] + \
    CUBE_TETS[1:]
flat_v = CUBE_V + [(0.5, 0.5, 0.0)]
flat_tets = CUBE_TETS + [(0, 4, 2, 8)]

cases = [
    ("empty.obj", "", "read"),
    ("empty.off", "", "read"),
    ("header_only.off", "OFF\n0 0 0\n", "read"),
    ("vertices_only.obj", obj_text(CUBE_V, []), "read"),
    ("single_triangle.off", off_text(CUBE_V[:3], [(0, 1, 2)]), "tetrahedralize"),
    ("open_cube.off", off_text(CUBE_V, CUBE_F[:-2]), "tetrahedralize"),
    ("nonmanifold_edge.off", off_text(CUBE_V + [(0.5, -1.0, 0.5)],
                                      CUBE_F + [(0, 1, 8)]), "tetrahedralize"),
    ("nonmanifold_vertex.off", off_text(touching, CUBE_F + [tuple(i + 8 for i in f)
                                                            for f in CUBE_F]), None),
    ("self_intersecting.off", off_text(overlapping, CUBE_F + [tuple(i + 8 for i in f)
                                                              for f in CUBE_F]), None),
    ("flipped_face.off", off_text(CUBE_V, flipped), "tetrahedralize"),
    ("nan.off", off_text(with_nan, CUBE_F), "read"),
    ("inf.off", off_text(with_inf, CUBE_F), "read"),
    ("huge.off", off_text(huge, CUBE_F), None),
    ("duplicated_points.off", off_text(duplicated, CUBE_F), None),
    ("two_solids.off", off_text(two_cubes, two_cube_faces), None),
    ("wedge_10_degrees.off", off_text(*wedge10), None),
    ("degenerate_triangle.off", off_text(CUBE_V + [(0.0, 0.0, 0.0)],
                                         CUBE_F[:-1] + [(1, 7, 8), (8, 7, 3)]), None),
    ("truncated.off", off_text(CUBE_V, CUBE_F)[:60], "read"),
    ("index_out_of_range.off", off_text(CUBE_V, CUBE_F[:-1] + [(1, 7, 99)]), "read"),
    ("two_vertex_face.off", off_text(CUBE_V, CUBE_F + [(0, 1)]), None),
    ("wrong_counts.off", off_text(CUBE_V, CUBE_F, declared=(8, 20)), "read"),
    ("binary_garbage.off", bytes(range(256)) * 4, "read"),
    ("empty.mesh", "", "read"),
    ("truncated.mesh", medit_text(CUBE_V, CUBE_TETS)[:120], "read"),
    ("wrong_tet_count.mesh", medit_text(CUBE_V, CUBE_TETS, declared_tets=9), "read"),
    ("inverted_tet.mesh", medit_text(CUBE_V, inverted), None),
    ("flat_tet.mesh", medit_text(flat_v, flat_tets), None),
    ("index_out_of_range.mesh", medit_text(CUBE_V, CUBE_TETS[:-1] + [(0, 1, 2, 40)]), "read"),
    ("nan.mesh", medit_text(with_nan, CUBE_TETS), "read"),
    ("triangles_only.mesh", medit_text(CUBE_V, [], triangles=CUBE_F), None),
    ("tets_and_hexes.mesh", medit_text(CUBE_V, CUBE_TETS,
                                       hexahedra=[(0, 4, 6, 2, 1, 5, 7, 3)]), None),
    ("mixed_cells.vtk", legacy_vtk(CUBE_V, [(10, t) for t in CUBE_TETS] +
                                   [(12, (0, 4, 6, 2, 1, 5, 7, 3))]), None),
    ("single_tet.mesh", medit_text([CUBE_V[i] for i in CUBE_TETS[0]], [(0, 1, 2, 3)]), None),
    ("duplicated_points.mesh", medit_text(duplicated, CUBE_TETS + [tuple(i + 8 for i in t)
                                                                   for t in CUBE_TETS]), None),
    ("no_such_file.obj", None, "no such file"),
    ("unknown_extension.xyz", "1 2 3\n", "unknown extension"),
]

failures = []
for name, contents, expected in cases:
    path = os.path.join(corpus, name)
    if contents is not None:
        with open(path, "wb" if isinstance(contents, bytes) else "w") as f:
            f.write(contents)
    output = os.path.join(corpus, os.path.splitext(name)[0] + "_hexes.vtu")
    if os.path.exists(output):
        os.remove(output)
    try:
        result = subprocess.run([launcher, path, "-o", output, "--hexes", "500"],
                                capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        failures.append("%s: hung (no answer in 300 s)" % name)
        continue
    err = result.stderr.strip()
    last = err.splitlines()[-1] if err else ""
    if result.returncode == 0:
        verdict = "valid hex mesh" if "| ValidHexMesh | 1 |" in result.stdout else None
    elif result.returncode == 1:
        verdict = last if last.startswith("polycubehex: error: ") else None
    elif result.returncode == 2:
        verdict = last if "not valid" in last else None
    else:
        verdict = None
    print("%-28s status %d: %s" % (name, result.returncode, verdict or err[-300:]))
    if verdict is None or "Traceback" in err:
        failures.append("%s: status %d, %s" % (name, result.returncode, err[-500:]))
    elif expected is not None and (result.returncode != 1 or expected not in last):
        failures.append("%s: expected a refusal mentioning '%s', got: %s" % (
            name, expected, verdict))
    if result.returncode == 1 and os.path.exists(output):
        failures.append("%s: refused but wrote %s" % (name, output))

# The same inputs straight into every filter on its own (not only what the previous stage lets
# through): each Update either fails (with an error) or succeeds with an output; none may crash.
import polycubehex  # noqa: E402
from polycubehex.pipeline import PipelineError, read  # noqa: E402
from vtkmodules.vtkCommonCore import vtkLogger, vtkObject  # noqa: E402

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
vtkObject.GlobalWarningDisplayOff()
filters = [polycubehex.vtkTetrahedralizeFilter, polycubehex.vtkHandleCutFilter,
           polycubehex.vtkFrameFieldFilter, polycubehex.vtkPolycubeDeformFilter,
           polycubehex.vtkHexExtractFilter, polycubehex.vtkHexMeshQuality]
direct = 0
for name, contents, expected in cases:
    try:
        data, _ = read(os.path.join(corpus, name))
    except PipelineError:
        continue  # refused by the reader: covered above
    outcomes = []
    for make in filters:
        algorithm = make()
        algorithm.SetInputData(data)
        ok = algorithm.GetExecutive().Update()
        output = algorithm.GetOutputDataObject(0)
        if ok and output is None:
            failures.append("%s: %s succeeded without an output" % (name, make.__name__))
        outcomes.append("%s %s" % (make.__name__[3:], "ok" if ok else "refused"))
        direct += 1
    print("%-28s direct: %s" % (name, ", ".join(outcomes)))
print("%d direct filter runs" % direct)

print("%d cases" % len(cases))
assert len(cases) >= 30
if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
print("TestBadInputs: ok")
sys.exit(0)
