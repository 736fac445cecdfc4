"""shadelab's VTK classes for Python: the mesh readers (vtkShadelabMeshReader
and one per format), the normals (vtkShadelabMeshNormals) and the lecture's
shading on any vtkActor (vtkShadelabShading). Use them beside `vtkmodules`
as any VTK class:

    from shadelab import vtkShadelabMeshReader, vtkShadelabMeshNormals
"""

# VTK's Python modules that these classes derive from are imported by the
# wrapped library itself.
from .shadelab_filters import *  # noqa: F401,F403
