# SPDX-License-Identifier: BSD-3-Clause
"""The plugin loads in pvpython; every proxy of every Filters/*.xml is created through
paraview.simple under its menu name; File > Open picks our readers; filters sit in the
PolycubeHex menu category."""
import glob
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import paraview.simple as simple
from paraview import servermanager

plugin = os.environ["POLYCUBEHEX_PLUGIN"]
data = os.environ["POLYCUBEHEX_DATA"]
filters_dir = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Filters")
simple.LoadPlugin(plugin, remote=False, ns=globals())

# Every proxy declared by the plugin's XMLs.
proxies = []
for path in sorted(glob.glob(os.path.join(filters_dir, "vtk*.xml"))):
    for group in ElementTree.parse(path).getroot():
        for proxy in group:
            proxies.append((group.get("name"), proxy.get("name"), proxy.get("label"), proxy))
assert proxies, "no proxy XML found in %s" % filters_dir

pxm = servermanager.ProxyManager()
model = simple.OpenDataFile(os.path.join(data, "rockerarm.mesh"))
for group, name, label, element in proxies:
    assert pxm.GetPrototypeProxy(group, name) is not None, "%s/%s not registered" % (group, name)
    if group != "filters":
        continue
    # paraview.simple exposes a filter under its label with non-alphanumerics removed.
    function_name = re.sub(r"[^0-9a-zA-Z_]", "", label)
    function = getattr(simple, function_name, None) or globals().get(function_name)
    assert function is not None, "paraview.simple has no %s for %s" % (function_name, name)
    created = function(Input=model)
    assert created.GetXMLName() == name, (created.GetXMLName(), name)
    category = element.find("Hints/ShowInMenu")
    assert category is not None and category.get("category") == "PolycubeHex", name
    simple.Delete(created)
    print("created", function_name)

# File > Open picks our reader for .mesh and .off files.
mesh = simple.OpenDataFile(os.path.join(data, "rockerarm.mesh"))
assert mesh is not None, "no reader offered for .mesh"
assert mesh.GetXMLName() == "PolycubeHexMeditReader", mesh.GetXMLName()
mesh.UpdatePipeline()
info = mesh.GetDataInformation()
assert info.GetNumberOfCells() == 30813, info.GetNumberOfCells()
assert info.GetNumberOfPoints() == 8040, info.GetNumberOfPoints()

surface = simple.OpenDataFile(os.path.join(data, "fertility.off"))
assert surface.GetXMLName() == "PolycubeHexOFFReader", surface.GetXMLName()
surface.UpdatePipeline()
assert surface.GetDataInformation().GetNumberOfCells() == 9000

# The writer is offered for .mesh files.
output = os.path.join(os.environ["POLYCUBEHEX_OUTPUT"], "pvpython_roundtrip.mesh")
simple.SaveData(output, proxy=mesh)
again = simple.OpenDataFile(output)
again.UpdatePipeline()
assert again.GetDataInformation().GetNumberOfCells() == 30813

# The Python package imports in pvpython too, next to the plugin.
import polycubehex  # noqa: E402

assert hasattr(polycubehex, "vtkHexExtractFilter") and hasattr(polycubehex, "vtkMeditReader")

print("TestPVPlugin: ok (%d proxies)" % len(proxies))
sys.exit(0)
