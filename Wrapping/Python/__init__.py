"""vtkRelief: fine surface detail (relief mapping) on coarse meshes, for VTK pipelines.

Every wrapped class of the project is importable from this package, e.g.
``from vtkrelief import vtkOpenGLReliefMapper``.
"""
# The relief mappers subclass VTK's OpenGL mapper: load VTK's modules first so
# their classes are registered before ours.
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

from .vtkReliefIO import *  # noqa: F401,F403
from .vtkReliefFilters import *  # noqa: F401,F403
from .vtkReliefRendering import *  # noqa: F401,F403
