# SPDX-License-Identifier: BSD-3-Clause
"""The VTK-Python example doubles as a smoke test: torus.obj to tets, with a report whose
numbers are right (one boundary component of genus 1, positive tets)."""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "Wrapping", "Python", "examples"))
import tetrahedralize_and_report  # noqa: E402

data = os.environ["POLYCUBEHEX_DATA"]
output = os.path.join(os.environ["POLYCUBEHEX_OUTPUT"], "example_torus")
assert tetrahedralize_and_report.main([os.path.join(data, "torus.obj"),
                                       "--output-dir", output]) == 0
with open(os.path.join(output, "report.md")) as report:
    text = report.read()
assert "| boundary components                 | 1 |" in text, text
assert "| first Betti number                  | 1 |" in text, text
assert os.path.getsize(os.path.join(output, "tets.vtu")) > 0
assert os.path.getsize(os.path.join(output, "tets.mesh")) > 0

# A bad input exits with a message, not a traceback.
try:
    tetrahedralize_and_report.main([os.path.join(data, "no-such-model.obj")])
except SystemExit as exit_status:
    assert "no such file" in str(exit_status.code), exit_status.code
else:
    raise AssertionError("a missing file was accepted")
print("TestExampleTetrahedralize: ok")
