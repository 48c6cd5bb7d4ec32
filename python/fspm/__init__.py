"""fspm: functional-structural plant modelling from Python.

Tree graphs come out as :class:`Tree` objects whose columns are numpy arrays sharing memory
with the C++ tree (no copy). Errors are raised as :class:`fspm.Error` subclasses carrying the
same messages as the command line.
"""
from ._fspm import (  # noqa: F401
    Error,
    IoError,
    ParseError,
    Tree,
    ValueError_ as ParameterError,
    distance,
    lsystem_derive,
    lsystem_interpret,
    parse_newick,
    read_tree,
    to_newick,
    write_tree,
)

__all__ = [
    "Error", "IoError", "ParseError", "ParameterError", "Tree", "distance", "lsystem_derive",
    "lsystem_interpret", "parse_newick", "read_tree", "to_newick", "write_tree",
]
