# SPDX-License-Identifier: BSD-3-Clause
"""A ParaView Python state: the whole PolycubeHex pipeline with sensible representations.

In the GUI: File > Load State..., choose this file (ParaView accepts Python states), or start
    paraview --script=Wrapping/Python/examples/pipeline_state.py
The plugin is taken from POLYCUBEHEX_PLUGIN, else from build/ beside this source tree; the model
from POLYCUBEHEX_MODEL, else Data/torus.obj. The render view shows the hex mesh coloured by
scaled Jacobian (with a scalar bar) and, faint, the input's boundary; every stage stays in the
Pipeline Browser, so clicking the eye of Cuts, Frame Field or Polycube Deform shows it.
"""
import os

from paraview.simple import (ColorBy, ExtractSurface, GetActiveViewOrCreate,
                             GetColorTransferFunction, Hide, LoadPlugin, OpenDataFile,
                             RenameSource, ResetCamera, SetActiveSource, Show)

here = os.path.dirname(os.path.abspath(__file__))
source_dir = os.path.normpath(os.path.join(here, "..", "..", ".."))
plugin = os.environ.get("POLYCUBEHEX_PLUGIN", os.path.join(
    source_dir, "build", "lib", "paraview-5.11", "plugins", "PolycubeHex", "PolycubeHex.so"))
model = os.environ.get("POLYCUBEHEX_MODEL", os.path.join(source_dir, "Data", "torus.obj"))
LoadPlugin(plugin, remote=False, ns=globals())

view = GetActiveViewOrCreate("RenderView")
source = OpenDataFile(model)
RenameSource(os.path.basename(model), source)
surface_input = os.path.splitext(model)[1].lower() in (".obj", ".off", ".stl", ".ply", ".vtp")
tets = TetrahedralizeTetGen(Input=source) if surface_input else source  # noqa: F821
cuts = HandleCut(Input=tets)  # noqa: F821
frames = FrameField(Input=cuts)  # noqa: F821
polycube = PolycubeDeform(Input=frames)  # noqa: F821
hexes = HexExtract(Input=polycube, TargetHexCount=5000)  # noqa: F821

# The input's boundary, faint, for context.
boundary = ExtractSurface(Input=tets)
RenameSource("Input boundary", boundary)
outline = Show(boundary, view)
outline.Opacity = 0.15
outline.ColorArrayName = ["POINTS", ""]

# The hex mesh: whole cells with edges, coloured by scaled Jacobian on a fixed [-0.2, 1] scale
# (inverted hexes at the bottom, in red).
shown = Show(hexes, view)
shown.Representation = "Surface With Edges"
ColorBy(shown, ("CELLS", "ScaledJacobian"))
lut = GetColorTransferFunction("ScaledJacobian")
lut.ApplyPreset("Rainbow Uniform", True)
lut.InvertTransferFunction()
lut.AutomaticRescaleRangeMode = "Never"
lut.RescaleTransferFunction(-0.2, 1.0)
shown.SetScalarBarVisibility(view, True)
for stage in (source, tets, cuts, frames, polycube):
    Hide(stage, view)
SetActiveSource(hexes)
ResetCamera(view)
view.CameraPosition = [a + 2.0 * b for a, b in zip(view.CameraFocalPoint, (1.0, -1.5, 1.2))]
ResetCamera(view)
