# SPDX-License-Identifier: BSD-3-Clause
"""Client-server: pvserver on 127.0.0.1 (a free port), pvpython connected to it, the plugin
loaded on both sides, the whole pipeline run on the server (a surface to hexes), and the summary
fetched to the client. Users mesh models too large for their desktop this way."""
import os
import socket
import subprocess
import sys
import time

import paraview.simple as simple
from paraview import servermanager

plugin = os.environ["POLYCUBEHEX_PLUGIN"]
data = os.environ["POLYCUBEHEX_DATA"]

with socket.socket() as probe:  # a port nobody uses
    probe.bind(("127.0.0.1", 0))
    port = probe.getsockname()[1]

environment = dict(os.environ)
server = subprocess.Popen(["pvserver", "--server-port=%d" % port, "--hostname=127.0.0.1",
                           "--force-offscreen-rendering", "--disable-xdisplay-test"],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                          env=environment)
try:
    # Wait until it listens.
    deadline = time.time() + 60
    while True:
        try:
            with socket.create_connection(("127.0.0.1", port), timeout=1):
                break
        except OSError:
            assert server.poll() is None, "pvserver exited: %s" % server.stdout.read()
            assert time.time() < deadline, "pvserver did not listen within 60 s"
            time.sleep(0.5)

    connection = simple.Connect("127.0.0.1", port)
    assert connection is not None and servermanager.ActiveConnection.IsRemote()
    simple.LoadPlugin(plugin, remote=False, ns=globals())  # the client's proxies
    simple.LoadPlugin(plugin, remote=True, ns=globals())   # the server's filters

    # The file is read on the server (same machine here, same path).
    surface = simple.OpenDataFile(os.path.join(data, "torus.obj"))
    tets = TetrahedralizeTetGen(Input=surface)  # noqa: F821 (defined by LoadPlugin)
    cuts = HandleCut(Input=tets)  # noqa: F821
    frames = FrameField(Input=cuts)  # noqa: F821
    polycube = PolycubeDeform(Input=frames)  # noqa: F821
    hexes = HexExtract(Input=polycube, TargetHexCount=1500)  # noqa: F821
    hexes.UpdatePipeline()

    # Only the summary travels: the field data of a one-cell extract would do as well, but the
    # data information already carries the counts.
    info = hexes.GetDataInformation()
    print("server: %d hexes, %d points" % (info.GetNumberOfCells(), info.GetNumberOfPoints()))
    # The closed form (Automatic) on this coarse torus: its section is about four hexes wide, so
    # rounding the planes to integers moves the count by up to a quarter.
    assert abs(info.GetNumberOfCells() - 1500) <= 375, info.GetNumberOfCells()
    summary = servermanager.Fetch(hexes).GetFieldData()
    valid = summary.GetArray("ValidHexMesh").GetTuple1(0)
    betti = summary.GetArray("BettiNumber").GetTuple1(0)
    print("fetched: ValidHexMesh %d, BettiNumber %d, SJ min %.3f" % (
        valid, betti, summary.GetArray("ScaledJacobianMin").GetTuple1(0)))
    assert valid == 1 and betti == 1
    simple.Disconnect()
finally:
    server.terminate()
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        server.kill()
print("TestClientServer: ok")
sys.exit(0)
