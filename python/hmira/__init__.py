"""hmira: polygon-mesh algorithms for numpy users."""
from . import _core  # noqa: F401
