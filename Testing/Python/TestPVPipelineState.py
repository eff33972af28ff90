# SPDX-License-Identifier: BSD-3-Clause
"""The shipped ParaView XML state Wrapping/Python/examples/polycubehex_pipeline.pvsm: it names no
absolute path, loads in pvpython with the plugin (the model found through data_directory, as
"Search files under specified directory" does in the GUI), holds every stage, and its last filter
gives a valid hex mesh shown coloured by scaled Jacobian. Fails when the state no longer loads
(a renamed filter proxy), loses a stage, or gives no valid hexes."""
import os
import sys
import xml.etree.ElementTree as ElementTree

import paraview.simple as simple
from paraview import servermanager

source_dir = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
state = os.path.join(source_dir, "Wrapping", "Python", "examples", "polycubehex_pipeline.pvsm")
data = os.environ["POLYCUBEHEX_DATA"]

# Relocatable: every file name in the state is relative.
for prop in ElementTree.parse(state).getroot().iter("Property"):
    if prop.get("name") == "FileName":
        for element in prop.iter("Element"):
            assert not os.path.isabs(element.get("value")), element.get("value")

simple.LoadPlugin(os.environ["POLYCUBEHEX_PLUGIN"], remote=False, ns=globals())
simple.LoadState(state, data_directory=data, restrict_to_data_directory=True)

sources = {key[0]: proxy for key, proxy in simple.GetSources().items()}
print("loaded:", sorted(sources))
stages = {}
for proxy in sources.values():
    stages[proxy.GetXMLName()] = proxy
for name in ("PolycubeHexTetrahedralize", "PolycubeHexHandleCut", "PolycubeHexFrameField",
             "PolycubeHexDeform", "PolycubeHexExtract"):
    assert name in stages, "the state has no %s: %s" % (name, sorted(stages))
reader_file = [p for p in sources.values() if hasattr(p, "FileName")][0].FileName
assert os.path.samefile(reader_file, os.path.join(data, "torus.obj")), reader_file

hexes = stages["PolycubeHexExtract"]
hexes.UpdatePipeline()
grid = servermanager.Fetch(hexes)
fields = grid.GetFieldData()


def field(name):
    array = fields.GetAbstractArray(name)
    assert array is not None, "the hex mesh has no field %s" % name
    return array.GetVariantValue(0).ToDouble()


count = grid.GetNumberOfCells()
print("hexes %d, ValidHexMesh %d, scaled Jacobian min %.3f" % (
    count, field("ValidHexMesh"), field("ScaledJacobianMin")))
assert count > 1000, count
assert all(grid.GetCellType(c) == 12 for c in range(count))  # VTK_HEXAHEDRON
assert field("ValidHexMesh") == 1 and field("ScaledJacobianMin") > 0

# What the user sees: the hexes visible, with edges, coloured by the cells' scaled Jacobian.
view = simple.GetActiveViewOrCreate("RenderView")
shown = simple.GetDisplayProperties(hexes, view)
assert shown.Visibility == 1
assert shown.Representation == "Surface With Edges", shown.Representation
assert list(shown.ColorArrayName) == ["CELLS", "ScaledJacobian"], shown.ColorArrayName
simple.Render(view)
# Closing the state's views before exit: otherwise pvpython's exit under Xvfb can end in
# GLXBadContext while tearing the render windows down.
simple.RemoveViewsAndLayouts()
print("TestPVPipelineState: ok")
sys.exit(0)
