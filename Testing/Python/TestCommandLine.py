# SPDX-License-Identifier: BSD-3-Clause
"""The polycubehex command line and polycubehex.mesh(): a torus surface to a valid hex mesh file
near the requested count, with the quality table printed and written as Markdown or as an HTML
page (well-formed, its hex count that of the written mesh); bad input (a missing file, a file that
is not what its name says, an unknown output format) exits with status 1 and a readable message
instead of a traceback; --set and mesh(settings=...) reach the filters' properties, and a wrong
stage, property or value is refused."""
import html.parser
import os
import subprocess
import sys

from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkIOGeometry import vtkOBJReader

import polycubehex

launcher = os.environ["POLYCUBEHEX_LAUNCHER"]
data = os.environ["POLYCUBEHEX_DATA"]
output_dir = os.environ["POLYCUBEHEX_OUTPUT"]
os.makedirs(output_dir, exist_ok=True)


def run(*arguments):
    result = subprocess.run([launcher] + list(arguments), capture_output=True, text=True)
    return result.returncode, result.stdout, result.stderr


# End to end on the command line.
hex_file = os.path.join(output_dir, "cli_torus.vtu")
report_file = os.path.join(output_dir, "cli_torus.md")
code, out, err = run(os.path.join(data, "torus.obj"), "-o", hex_file, "--hexes", "2000",
                     "--report", report_file)
print(out, err)
assert code == 0, err
assert "| ValidHexMesh | 1 |" in out, out
assert "Traceback" not in err
reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(hex_file)
reader.Update()
grid = reader.GetOutput()
assert abs(grid.GetNumberOfCells() - 2000) <= 200, grid.GetNumberOfCells()
assert all(grid.GetCellType(c) == 12 for c in range(grid.GetNumberOfCells()))  # VTK_HEXAHEDRON
with open(report_file) as report:
    assert "ScaledJacobianMin" in report.read()



class ReportParser(html.parser.HTMLParser):
    """Checks that every element is closed in order and collects the quality table's rows."""
    VOID = {"meta", "img", "br", "hr", "link", "input"}

    def __init__(self):
        super().__init__()
        self.stack, self.rows, self.text, self.table = [], [], [], None

    def handle_starttag(self, tag, attrs):
        if tag not in self.VOID:
            self.stack.append(tag)
        if tag == "table":
            self.table = dict(attrs).get("class")
        if tag == "tr":
            self.row = []
        if tag == "td":
            self.text = []

    def handle_endtag(self, tag):
        assert self.stack and self.stack[-1] == tag, "</%s> closes %s" % (tag, self.stack)
        self.stack.pop()
        if tag == "td":
            self.row.append("".join(self.text).strip())
        if tag == "tr" and self.table == "quality" and self.row:
            self.rows.append(tuple(self.row))

    def handle_data(self, data):
        self.text.append(data)


def read_cells(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetNumberOfCells()


# --report with .html writes one HTML page whose table matches the written mesh.
html_hexes = os.path.join(output_dir, "cli_torus_html.vtu")
html_file = os.path.join(output_dir, "cli_torus.html")
code, out, err = run(os.path.join(data, "torus.obj"), "-o", html_hexes, "--hexes", "800",
                     "--report", html_file)
assert code == 0, err
with open(html_file, encoding="utf-8") as page:
    text = page.read()
assert text.startswith("<!DOCTYPE html>"), text[:100]
parser = ReportParser()
parser.feed(text)
parser.close()
assert not parser.stack, "unclosed elements: %s" % parser.stack
table = dict(parser.rows)
print("HTML report rows:", table)
assert int(table["HexCount"]) == read_cells(html_hexes), (table, read_cells(html_hexes))
assert table["ValidHexMesh"] == "1" and "ScaledJacobianMin" in table
assert "torus.obj" in text and "target hexes" in text

# Refusals: status 1, one readable line, no traceback, no output file.
bad = os.path.join(output_dir, "cli_not_an_off.off")
with open(bad, "w") as f:
    f.write("this is not an OFF file\n")
for arguments, expected in [
        ((os.path.join(data, "no_such_model.obj"), "-o", hex_file), "no such file"),
        ((bad, "-o", os.path.join(output_dir, "cli_bad.vtu")), "Cannot read OFF file"),
        ((os.path.join(data, "torus.obj"), "-o", os.path.join(output_dir, "x.txt")),
         "the output must end in")]:
    code, out, err = run(*arguments)
    print(err.strip())
    assert code != 0, arguments
    assert expected in err, err
    assert "Traceback" not in err, err
assert not os.path.exists(os.path.join(output_dir, "cli_bad.vtu"))

# --set reaches any filter property, after the options (so it wins over --hexes), and the report
# lists it; a wrong stage, property or value is refused before anything runs.
set_hexes = os.path.join(output_dir, "cli_torus_set.vtu")
set_report = os.path.join(output_dir, "cli_torus_set.md")
code, out, err = run(os.path.join(data, "torus.obj"), "-o", set_hexes, "--hexes", "2000",
                     "--set", "hexes.TargetHexCount=800", "--set", "hexes.ScaleRetries=0",
                     "--report", set_report)
assert code == 0, err
assert abs(read_cells(set_hexes) - 800) <= 200, read_cells(set_hexes)
with open(set_report) as report:
    assert "hexes.TargetHexCount: 800" in report.read()
for arguments, expected, status in [
        (("--set", "polycube.NoSuchThing=1"), "has no property 'NoSuchThing'", 1),
        (("--set", "hexes.Padding=abc"), "expected a number", 1),
        (("--set", "nostage.Padding=0"), "expected STAGE.Property=value", 2)]:
    code, out, err = run(os.path.join(data, "torus.obj"), "-o", set_hexes, *arguments)
    print(err.strip().splitlines()[-1])
    assert code == status, (arguments, code, err)
    assert expected in err and "Traceback" not in err, err

# The same pipeline from Python, on data already in memory.
obj = vtkOBJReader()
obj.SetFileName(os.path.join(data, "torus.obj"))
obj.Update()
hexes, report = polycubehex.mesh(obj.GetOutput(), hex_count=1500, smoothing=True)
assert report["ValidHexMesh"] == 1 and report["InvertedHexCount"] == 0, report
# Automatic is the closed form when a frame field exists: the torus becomes a bar, no corner.
assert report["Guidance"] == "FrameField" and report["CornerCount"] == 0, report
# The section is about four hexes wide: rounding its planes moves the count by up to a quarter.
assert abs(hexes.GetNumberOfCells() - 1500) <= 375, hexes.GetNumberOfCells()
# settings: the torus's frame field kept its aligned initial field (1000) above; with
# CutMeshBoundaryAlignmentWeight 0 it starts from the base weight.
aligned = report["stages"]["frames"].GetFieldData().GetArray("InitialAlignmentWeight").GetValue(0)
hexes, report = polycubehex.mesh(obj.GetOutput(), hex_count=1500, smoothing=False,
                                 settings={"frames": {"CutMeshBoundaryAlignmentWeight": 0}})
base = report["stages"]["frames"].GetFieldData().GetArray("InitialAlignmentWeight").GetValue(0)
print("initial alignment weight: default %g, with the setting %g" % (aligned, base))
assert aligned == 1000 and base == 30, (aligned, base)
for settings, expected in [({"frame field": {"AlignmentWeight": 1}}, "unknown stage"),
                           ({"polycube": {"Sideways": 1}}, "has no property 'Sideways'")]:
    try:
        polycubehex.mesh(obj.GetOutput(), hex_count=1500, settings=settings)
        raise AssertionError("settings %r were accepted" % settings)
    except polycubehex.PipelineError as error:
        print("refused:", error)
        assert expected in str(error), error
try:
    polycubehex.mesh(os.path.join(data, "torus.obj"), guidance="sideways")
    raise AssertionError("an unknown guidance was accepted")
except polycubehex.PipelineError as error:
    print("refused:", error)
print("TestCommandLine: ok")
sys.exit(0)
