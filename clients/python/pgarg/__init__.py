"""pgarg: a Python client of the arg extension (search 3D models by shape) for psycopg 3."""

from .adapters import register_arg
from .value import Arg
from .weights import ArgWeights

__all__ = ["Arg", "ArgWeights", "register_arg"]
__version__ = "0.1.0"
