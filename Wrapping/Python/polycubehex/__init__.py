# SPDX-License-Identifier: BSD-3-Clause
"""PolycubeHex: all-hex meshing with closed-form induced polycubes (Fang et al. 2016).

The VTK classes of the module PolycubeHex::Filters are available from this package in
pvpython and in any Python that imports ParaView's ``vtkmodules``::

    from polycubehex import vtkMeditReader, vtkTetrahedralizeFilter

and the whole pipeline in one call (``polycubehex.pipeline``)::

    hexes, report = polycubehex.mesh("Data/torus.obj", hex_count=5000)
"""

# The wrapped classes need VTK's own Python modules loaded first.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkIOCore  # noqa: F401

from .PolycubeHexFilters import *  # noqa: F401,F403
from .pipeline import PipelineError, mesh  # noqa: F401,E402

__version__ = "0.1.0"
