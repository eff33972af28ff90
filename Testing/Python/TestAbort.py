# SPDX-License-Identifier: BSD-3-Clause
"""Every stage can be aborted: each filter of the pipeline is asked to abort at its first
progress event (what ParaView's progress bar does when the user cancels). It must stop without a
crash, produce no partial result, and run normally when updated again."""
import os
import sys

from vtkmodules.vtkCommonCore import vtkCommand, vtkLogger, vtkObject
from vtkmodules.vtkIOGeometry import vtkOBJReader

import polycubehex

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
vtkObject.GlobalWarningDisplayOff()
reader = vtkOBJReader()
reader.SetFileName(os.path.join(os.environ["POLYCUBEHEX_DATA"], "torus.obj"))
reader.Update()

data = reader.GetOutput()
for make in (polycubehex.vtkTetrahedralizeFilter, polycubehex.vtkHandleCutFilter,
             polycubehex.vtkFrameFieldFilter, polycubehex.vtkPolycubeDeformFilter,
             polycubehex.vtkHexExtractFilter):
    stage = make()
    stage.SetInputData(data)
    seen = []

    def cancel(caller, event):
        seen.append(caller.GetProgress())
        caller.SetAbortExecute(1)

    tag = stage.AddObserver(vtkCommand.ProgressEvent, cancel)
    ok = stage.GetExecutive().Update()
    output = stage.GetOutputDataObject(0)
    cells = output.GetNumberOfCells() if output is not None else 0
    print("%s aborted at %s: update %s, %d cells" % (make.__name__, seen[:1], ok, cells))
    assert seen, "%s reported no progress, so it cannot be cancelled" % make.__name__
    assert not ok or cells == 0, "%s kept a partial result after an abort" % make.__name__

    # Again, without the abort: a normal result.
    stage.RemoveObserver(tag)
    stage.SetAbortExecute(0)
    stage.Modified()
    assert stage.GetExecutive().Update(), "%s failed after an abort" % make.__name__
    result = stage.GetOutputDataObject(0)
    copy = result.NewInstance()
    copy.ShallowCopy(result)
    assert copy.GetNumberOfCells() > 0
    data = copy
print("TestAbort: ok")
sys.exit(0)
