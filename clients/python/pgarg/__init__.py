"""pgarg: a Python client of the arg extension (search 3D models by shape) for psycopg 3."""

from .adapters import register_arg
from .load import LoadFailure, LoadReport, content_key, load_models, mesh_files
from .search import nearest
from .server import build, global_vector, info
from .value import Arg
from .weights import ArgWeights

__all__ = [
    "Arg", "ArgWeights", "LoadFailure", "LoadReport", "build", "content_key", "global_vector",
    "info", "load_models", "mesh_files", "nearest", "register_arg",
]
__version__ = "0.1.0"
