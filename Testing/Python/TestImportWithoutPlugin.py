# SPDX-License-Identifier: BSD-3-Clause
"""`from polycubehex import ...` works in Debian's python3.11 with ParaView's VTK, no plugin."""
import os
import sys

from polycubehex import vtkMeditReader, vtkMeditWriter, vtkOFFReader

data = os.environ["POLYCUBEHEX_DATA"]
output = os.environ["POLYCUBEHEX_OUTPUT"]

reader = vtkMeditReader()
reader.SetFileName(os.path.join(data, "rockerarm.mesh"))
reader.Update()
grid = reader.GetOutput()
assert grid.GetNumberOfPoints() == 8040, grid.GetNumberOfPoints()
assert grid.GetNumberOfCells() == 30813, grid.GetNumberOfCells()

off = vtkOFFReader()
off.SetFileName(os.path.join(data, "fertility.off"))
off.Update()
assert off.GetOutput().GetNumberOfPolys() == 9000, off.GetOutput().GetNumberOfPolys()

# Round trip through the writer.
path = os.path.join(output, "python_roundtrip.mesh")
writer = vtkMeditWriter()
writer.SetInputConnection(reader.GetOutputPort())
writer.SetFileName(path)
assert writer.Write() == 1
again = vtkMeditReader()
again.SetFileName(path)
again.Update()
assert again.GetOutput().GetNumberOfCells() == 30813

# A missing file fails cleanly: an error naming the file, an empty output, no exception.
errors = []
bad = vtkMeditReader()
bad.AddObserver("ErrorEvent", lambda caller, event: errors.append(event))
bad.SetFileName(os.path.join(output, "does-not-exist.mesh"))
bad.Update()
assert bad.GetOutput().GetNumberOfCells() == 0
assert errors, "the reader reported no error for a missing file"
print("TestImportWithoutPlugin: ok")
sys.exit(0)
