# SPDX-License-Identifier: BSD-3-Clause
"""The polycubehex command line and polycubehex.mesh(): a torus surface to a valid hex mesh file
near the requested count, with the quality table printed and written as Markdown or as an HTML
page (well-formed, its hex count that of the written mesh); bad input (a missing file, a file that
is not what its name says, an unknown output format) exits with status 1 and a readable message
instead of a traceback."""
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
try:
    polycubehex.mesh(os.path.join(data, "torus.obj"), guidance="sideways")
    raise AssertionError("an unknown guidance was accepted")
except polycubehex.PipelineError as error:
    print("refused:", error)
print("TestCommandLine: ok")
sys.exit(0)
