# SPDX-License-Identifier: BSD-3-Clause
"""Determinism: the same input and settings give the same hex mesh bit for bit, run after run
and with 1 or 2 threads (POLYCUBEHEX_THREADS). The whole pipeline runs through the command line
on 3holes (6.7k tets after TetGen: above the 4096 tets where the energy's loops go parallel;
cuts, frame field, polycube, hexes with padding and smoothing), so every stage's reductions are
covered."""
import os
import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

launcher = os.environ["POLYCUBEHEX_LAUNCHER"]
data = os.environ["POLYCUBEHEX_DATA"]
output_dir = os.environ["POLYCUBEHEX_OUTPUT"]
os.makedirs(output_dir, exist_ok=True)


def mesh_with(threads, name):
    path = os.path.join(output_dir, "determinism_%s.vtu" % name)
    environment = dict(os.environ, POLYCUBEHEX_THREADS=str(threads))
    result = subprocess.run([launcher, os.path.join(data, "3holes.obj"), "-o", path,
                             "--hexes", "3000"], capture_output=True, text=True,
                            env=environment)
    assert result.returncode == 0, result.stderr
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    return (vtk_to_numpy(grid.GetPoints().GetData()).copy(),
            vtk_to_numpy(grid.GetCells().GetConnectivityArray()).copy(),
            vtk_to_numpy(grid.GetCellData().GetArray("ScaledJacobian")).copy())


runs = {"1 thread": mesh_with(1, "a"), "1 thread again": mesh_with(1, "b"),
        "2 threads": mesh_with(2, "c")}
reference = runs["1 thread"]
print("hexes:", len(reference[2]))
for name, (points, cells, quality) in runs.items():
    assert points.shape == reference[0].shape, name
    assert (points == reference[0]).all(), "%s: positions differ" % name
    assert (cells == reference[1]).all(), "%s: connectivity differs" % name
    assert (quality == reference[2]).all(), "%s: scaled Jacobians differ" % name
print("TestDeterminism: ok")
sys.exit(0)
