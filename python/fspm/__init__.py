"""fspm: functional-structural plant modelling from Python.

Tree graphs come out as :class:`Tree` objects whose columns are numpy arrays sharing memory
with the C++ tree (no copy). Errors are raised as :class:`fspm.Error` subclasses carrying the
same messages as the command line.
"""
from ._fspm import (  # noqa: F401
    CompressedPlant,
    Error,
    IoError,
    ParseError,
    Tree,
    ValueError_ as ParameterError,
    distance,
    greenlab_reconstruct,
    greenlab_simulate,
    lsystem_derive,
    lsystem_interpret,
    parse_newick,
    read_plant,
    read_tree,
    run_experiment,
    to_newick,
    write_tree,
)



def read_results(directory):
    """The runs of an experiment's output directory (``fspm run ... --out DIR``).

    Returns a pandas DataFrame with the columns run, seed, status, seconds, one per swept
    parameter, one per metric and error; a list of dicts when pandas is not installed.
    """
    import os
    import sqlite3

    path = os.path.join(str(directory), "results.sqlite")
    if not os.path.isfile(path):
        raise IoError(f"{path}: no experiment results here (expected results.sqlite)")
    con = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    try:
        cur = con.execute("SELECT * FROM results ORDER BY run")
        columns = [c[0] for c in cur.description]
        rows = cur.fetchall()
    except sqlite3.DatabaseError as e:
        raise Error(f"{path}: cannot read the results database: {e}") from None
    finally:
        con.close()
    try:
        import pandas
    except ImportError:
        return [dict(zip(columns, r)) for r in rows]
    return pandas.DataFrame(rows, columns=columns)


__all__ = [
    "read_results", "CompressedPlant", "greenlab_simulate", "greenlab_reconstruct", "read_plant",
    "run_experiment",
    "Error", "IoError", "ParseError", "ParameterError", "Tree", "distance", "lsystem_derive",
    "lsystem_interpret", "parse_newick", "read_tree", "to_newick", "write_tree",
]
