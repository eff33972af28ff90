# SPDX-License-Identifier: BSD-3-Clause
"""The plugin loads in pvpython, registers its readers, and every proxy can be created."""
import os
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

plugin = os.environ["POLYCUBEHEX_PLUGIN"]
data = os.environ["POLYCUBEHEX_DATA"]
LoadPlugin(plugin, remote=False, ns=globals())

# Every proxy of the plugin, by its XML name; each must be constructible.
pxm = servermanager.ProxyManager()
expected_sources = ["PolycubeHexMeditReader", "PolycubeHexOFFReader"]
expected_filters = [
    name
    for name in ("PolycubeHexTetrahedralize", "PolycubeHexMeshQuality")
    if pxm.GetPrototypeProxy("filters", name) is not None
]
for group, names in (("sources", expected_sources), ("filters", expected_filters)):
    for name in names:
        proxy = servermanager._getPyProxy(pxm.NewProxy(group, name))
        assert proxy is not None, "cannot create %s/%s" % (group, name)

# File > Open picks our reader for .mesh files.
mesh = OpenDataFile(os.path.join(data, "rockerarm.mesh"))
assert mesh is not None, "no reader offered for .mesh"
assert mesh.GetXMLName() == "PolycubeHexMeditReader", mesh.GetXMLName()
mesh.UpdatePipeline()
info = mesh.GetDataInformation()
assert info.GetNumberOfCells() == 30813, info.GetNumberOfCells()
assert info.GetNumberOfPoints() == 8040, info.GetNumberOfPoints()

surface = OpenDataFile(os.path.join(data, "fertility.off"))
assert surface.GetXMLName() == "PolycubeHexOFFReader", surface.GetXMLName()
surface.UpdatePipeline()
assert surface.GetDataInformation().GetNumberOfCells() == 9000

print("filters found:", expected_filters)
print("TestPVPlugin: ok")
sys.exit(0)
