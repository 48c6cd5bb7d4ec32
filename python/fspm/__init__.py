"""fspm: functional-structural plant modelling from Python.

Tree graphs come out as :class:`Tree` objects whose columns are numpy arrays sharing memory
with the C++ tree (no copy). Errors are raised as :class:`fspm.Error` subclasses carrying the
same messages as the command line; long computations release the GIL.

Families (names follow the C++ API):

* trees: ``read_tree``, ``write_tree``, ``read_mtg`` (an ``Mtg``: ``to_dataframe``, ``to_tree``), ``parse_newick``, ``Tree.from_arrays``, ``distance``
* L-systems: ``lsystem_derive``, ``lsystem_interpret``, ``lsystem_plant`` (a ``CompressedPlant``
  with turtle geometry)
* GreenLab: ``greenlab_simulate``, ``greenlab_reconstruct``, ``greenlab_reconstruct_lines``
  (a single-precision ``LineTree``), ``read_plant_params``,
  ``fit_gl1``, ``predict_targets``, ``read_targets_csv``
* environment: ``Scene``, ``read_scene_file``, ``parse_scene_json``, ``light``, ``LightModel``,
  ``GrowthParams``, ``grow_tree``, ``canopy_light``, ``analyze_tree``, ``adapt_tree``,
  ``adapt_trees``, ``remove_pruned``
* statistics: ``mean``, ``standard_deviation``, ``mean_confidence_interval``,
  ``student_t_test``, ``welch_t_test``, ``paired_t_test``, ``mann_whitney_u_test``, ``cohens_d``
* graphics: ``mesh_tree``, ``MeshOptions``, ``write_mesh`` (.obj/.ply/.vtp/.glb), ``write_pvd``,
  ``render`` (VTK offscreen, to a numpy image and .png)
* experiments: ``run_experiment``, ``compare_results``, ``read_results``
"""
try:
    import numpy  # noqa: F401  (every column and image is a numpy array)
except ImportError as missing:
    raise ImportError(
        "fspm needs numpy: install it (Debian: apt install python3-numpy; pip: pip install numpy)"
    ) from missing

from ._fspm import __version__  # noqa: F401  (project(fspm VERSION) in CMakeLists.txt)
from ._fspm import (  # noqa: F401
    AdaptationResult,
    AnalysisParams,
    ClusterModel,
    CompressedPlant,
    DevelopmentalModel,
    Error,
    FitResult,
    GrowthParams,
    GrowthResult,
    IoError,
    LightModel,
    LineTree,
    MannWhitneyResult,
    MemoryLimitError,
    MeshOptions,
    Mtg,
    ParseError,
    PlantParams,
    Scene,
    TTestResult,
    Target,
    Tree,
    TreeAnalysis,
    TriangleMesh,
    adapt_tree,
    adapt_trees,
    analyze_tree,
    canopy_light,
    cohens_d,
    decode_clusters,
    count_mesh,
    display_available,
    developmental_model,
    distance,
    encode_points,
    fit_gl1,
    fitted_toml,
    format_significant,
    greenlab_reconstruct,
    greenlab_reconstruct_lines,
    greenlab_simulate,
    grow_tree,
    growth_preset,
    light,
    load,
    lsystem_derive,
    lsystem_interpret,
    lsystem_plant,
    main_skeleton_nodes,
    mann_whitney_u_test,
    mean,
    mean_confidence_interval,
    measure_points,
    memory_limit,
    mesh_tree,
    node_attribute_values,
    paired_t_test,
    parse_growth_params,
    parse_newick,
    parse_newick_named,
    parse_plant_params,
    parse_scene_json,
    parse_targets_csv,
    predict_targets,
    read_growth_params,
    read_image,
    read_plant,
    read_plant_params,
    read_points,
    read_clusters,
    read_scene_file,
    read_targets_csv,
    read_tree,
    read_mtg,
    remove_pruned,
    render_available,
    render_mesh,
    run_experiment,
    compare_results,
    seasonal_time,
    simulate_scan,
    species_presets,
    set_memory_limit,
    sides_for_radius,
    standard_deviation,
    student_t_test,
    to_newick,
    variance,
    welch_t_test,
    write_glb,
    write_image,
    write_mesh,
    write_obj,
    write_ply,
    write_clusters,
    write_pvd,
    write_tree,
    write_vtp,
    ValueError as ParameterError,
    FileNotFoundError as MissingFileError,
)

# Crowns from photographs need OpenImageIO (built with the VTK option).
try:
    from ._fspm import CrownModel, reconstruct_crown  # noqa: F401
except ImportError:
    pass



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


def _mtg_to_dataframe(self, scale):
    """The entities of one scale as a pandas DataFrame: one row an entity (vertex, label, symbol,
    index, complex, parent, edge), one column a feature (numbers as floats, NaN where empty;
    dates and text as strings)."""
    import pandas

    return pandas.DataFrame(self.columns(scale))


Mtg.to_dataframe = _mtg_to_dataframe


def _human(value):
    if isinstance(value, float):
        return format_significant(value)
    if isinstance(value, tuple):
        return "(" + ", ".join(_human(v) for v in value) + ")"
    if isinstance(value, list):
        return "[" + ", ".join(_human(v) for v in value) + "]"
    return repr(value)


class Summary(dict):
    """The main numbers of a result: a dict holding every digit, shown (repr, print) to four
    significant digits as the command line prints them (``format_significant``)."""

    def __repr__(self):
        return "{" + ", ".join(f"{k!r}: {_human(v)}" for k, v in self.items()) + "}"

    __str__ = __repr__


def _tree_summary(self):
    """Node counts, height (m) and total length (m) as a Summary."""
    return Summary(_tree_summary_dict(self))


_tree_summary_dict = Tree.summary
Tree.summary = _tree_summary


def _growth_summary(self):
    """Internodes, leaf clusters, internodes shed and grown, height_m (m) as a Summary."""
    return Summary(internodes=self.internodes, clusters=self.clusters, shed=self.shed,
                   grown=self.grown, height_m=self.height_m)


def _adaptation_summary(self):
    """Nodes, pruned nodes, bent segments, surviving tips and their mean displacement (m) as a
    Summary."""
    return Summary(nodes=len(self.tree), pruned_nodes=self.pruned_nodes,
                   bent_segments=self.bent_segments, tips=self.tips,
                   mean_tip_displacement_m=self.mean_tip_displacement_m)


def _analysis_summary(self):
    """Skeleton nodes, clusters, skeleton radius, internode length and height path (m) as a
    Summary."""
    return Summary(skeleton_nodes=int(self.skeleton.sum()), clusters=len(self.clusters),
                   skeleton_radius_m=self.skeleton_radius_m,
                   internode_length_m=self.internode_length_m, height_path_m=self.height_path_m,
                   max_age=self.max_age)


def _fit_summary(self):
    """Parameter name -> (estimate, standard error), the final cost and the iterations as a
    Summary."""
    s = Summary(self.to_dict())
    s["final_cost"] = self.final_cost
    s["iterations"] = self.iterations
    return s


def _dict_summary(self):
    """Every field as a Summary (a dict shown to four significant digits)."""
    return Summary(self.to_dict())


GrowthResult.summary = _growth_summary
AdaptationResult.summary = _adaptation_summary
TreeAnalysis.summary = _analysis_summary
FitResult.summary = _fit_summary
TTestResult.summary = _dict_summary
MannWhitneyResult.summary = _dict_summary

_xvfb = None


def _ensure_display():
    """VTK's OpenGL context needs an X display. Without one, start a private Xvfb server for this
    process (as `fspm render` re-runs itself under xvfb-run), stopped when Python exits."""
    global _xvfb
    import os

    if display_available():
        return
    import atexit
    import shutil
    import subprocess

    xvfb = shutil.which("Xvfb")
    if xvfb is None or _xvfb is not None:
        raise IoError("no X display for VTK: set DISPLAY or install xvfb (apt install xvfb)")
    read_end, write_end = os.pipe()
    proc = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", "1280x1024x24",
                             "-nolisten", "tcp"], pass_fds=(write_end,),
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    with os.fdopen(read_end) as f:
        number = f.readline().strip()
    if not number:
        proc.kill()
        raise IoError("no X display for VTK and Xvfb did not start")
    _xvfb = proc

    def stop():
        proc.terminate()
        proc.wait()

    atexit.register(stop)
    os.environ["DISPLAY"] = ":" + number


def render(tree_or_mesh, path=None, *, width=1024, height=768, view="iso", color_by="",
           ground=True, scalar_bar=True, **mesh_options):
    """Render a Tree (meshed with ``mesh_options``, e.g. ``leaves=True``) or a TriangleMesh
    offscreen with VTK, as ``fspm render`` does. Returns the image as a (height, width, 4) uint8
    array and writes it to ``path`` (.png, .tif, .jpg ...) when given. Starts a private Xvfb when
    there is no X display. Raises ParameterError when fspm was built without VTK."""
    if not render_available():
        raise ParameterError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not "
                             "available")
    if path is not None:
        path = str(path)
    mesh = tree_or_mesh
    if isinstance(tree_or_mesh, Tree):
        mesh = mesh_tree(tree_or_mesh, **mesh_options)
    elif mesh_options:
        raise TypeError("mesh options are only used when rendering a Tree")
    if color_by:
        mesh.attribute(color_by)  # an unknown attribute fails before any window is opened
    _ensure_display()
    image = render_mesh(mesh, width=width, height=height, view=view, color_by=color_by,
                        ground=ground, scalar_bar=scalar_bar)
    if path is not None:
        write_image(image, path)
    return image


# fspm.FileNotFoundError and fspm.ValueError carry the built-in names (and are subclasses of the
# built-ins, so `except FileNotFoundError:` catches them). Bound last: code above this line that
# names the built-ins keeps meaning the built-ins.
from ._fspm import FileNotFoundError, ValueError  # noqa: E402,F401,A004

__all__ = sorted(
    [n for n in dir() if not n.startswith("_") and n not in ("annotations",)],
)
