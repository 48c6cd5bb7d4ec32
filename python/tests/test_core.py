"""Tests of the fspm Python module against independent expectations."""
import os
import pathlib

import numpy as np
import pytest

import fspm

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_newick_round_trip_and_labels():
    t = fspm.parse_newick("(100,(200,300)1)1000;")
    assert len(t) == 5
    np.testing.assert_array_equal(t.attribute("label"), [1000, 100, 1, 200, 300])
    np.testing.assert_array_equal(t.parents, [-1, 0, 0, 2, 2])  # signed: the root's parent is -1
    assert t.parents.dtype == np.int32
    assert fspm.to_newick(t) == "(100,(200,300)1)1000;"


def test_columns_are_read_only_views_without_copy():
    t = fspm.parse_newick("((1,2)3,4)5;")
    a, b = t.radii, t.radii
    assert a.ctypes.data == b.ctypes.data  # same C++ memory, no copy
    assert not a.flags.writeable
    assert t.starts.shape == (len(t), 3)
    del t
    assert a.sum() == 0.0  # the view keeps the tree alive


def test_errors_are_python_exceptions_with_locations(tmp_path):
    with pytest.raises(fspm.ParseError, match=r"1:4: expected a branch length"):
        fspm.parse_newick("(1:,2);")
    with pytest.raises(fspm.IoError):
        fspm.read_tree(str(tmp_path / "missing.tree"))
    with pytest.raises(TypeError):
        fspm.read_tree(42)


def test_errors_are_also_the_matching_builtin_exceptions(tmp_path):
    # A parse error is a ValueError, a file error an OSError, a bad parameter a ValueError, and
    # all of them fspm.Error.
    with pytest.raises(ValueError):
        fspm.parse_newick("(1:,2);")
    with pytest.raises(OSError):
        fspm.read_tree(str(tmp_path / "missing.tree"))
    with pytest.raises(ValueError, match="expected canopy, sky or shadow_grid"):
        fspm.AnalysisParams(light_model="sunny")
    for exc in (fspm.ParseError, fspm.IoError, fspm.ParameterError):
        assert issubclass(exc, fspm.Error)
    assert issubclass(fspm.ParseError, ValueError) and issubclass(fspm.IoError, OSError)


def test_builtin_exceptions_catch_errors_raised_in_cpp(tmp_path):
    # Each raised from C++ and caught by the built-in class alone, as a user would write it.
    try:
        fspm.read_tree(str(tmp_path / "missing.tree"))
    except FileNotFoundError as e:
        assert isinstance(e, fspm.IoError) and isinstance(e, fspm.MissingFileError)
        assert "missing.tree: cannot open for reading: No such file or directory" in str(e)
    else:
        pytest.fail("no FileNotFoundError for a missing file")
    (tmp_path / "bad.nwk").write_text("((1,2);\n")
    try:
        fspm.read_tree(str(tmp_path / "bad.nwk"))
    except ValueError as e:
        assert isinstance(e, fspm.ParseError) and not isinstance(e, OSError)
        assert "bad.nwk" in str(e)
    else:
        pytest.fail("no ValueError for a malformed file")
    # A directory is an OSError, but it exists: not a FileNotFoundError.
    try:
        fspm.read_tree(str(tmp_path))
    except OSError as e:
        assert not isinstance(e, FileNotFoundError) and "is a directory" in str(e)
    else:
        pytest.fail("no OSError for a directory")
    try:
        fspm.set_memory_limit("lots")
    except ValueError as e:
        assert isinstance(e, fspm.ParameterError) and "expected a size" in str(e)
    else:
        pytest.fail("no ValueError for a bad parameter")


def test_write_and_read_every_format(tmp_path):
    t = fspm.parse_newick("((1,2)3,(4,(5,6)7)8)9;")
    for ext in ("tree", "treeb", "nwk"):
        path = str(tmp_path / f"t.{ext}")
        fspm.write_tree(t, path)
        back = fspm.read_tree(path)
        assert fspm.to_newick(back) == "((1,2)3,(4,(5,6)7)8)9;"
    assert back.summary()["tips"] == 5


def test_topological_distance_of_one_inserted_node():
    # B is A with one node inserted above the two leaves: exactly one edit.
    a = fspm.parse_newick("(1,2)3;")
    b = fspm.parse_newick("((1,2)4)3;")
    r = fspm.distance(a, b, mapping=True)
    assert r["distance"] == 1.0
    assert r["nodes_a"] == 3 and r["nodes_b"] == 4
    assert len(r["mapping"]) == 3


def test_lsystem_derive_matches_closed_form():
    # ABOP Fig. 1.24a: F -> F[+F]F[-F]F, so after n steps there are 5^n F modules.
    r = fspm.lsystem_derive(str(ROOT / "examples/lsystems/abop_1_24a.l"), steps=3)
    assert r["steps"] == 3
    assert r["symbols"]["F"] == 5 ** 3
    tree = fspm.lsystem_interpret(str(ROOT / "examples/lsystems/abop_1_24a.l"), steps=2)
    assert tree.summary()["internodes"] == 5 ** 2


def test_lsystem_derive_compressed_counts_what_cannot_be_held():
    # 5^20 F modules at n = 20: only the substructure graph holds them.
    r = fspm.lsystem_derive(str(ROOT / "examples/lsystems/abop_1_24a.l"), steps=20,
                            compressed=True)
    assert r["symbols"]["F"] == 5 ** 20
    assert r["symbols"]["+"] == (5 ** 20 - 1) // 4
    assert r["graph_nodes"] <= 25
    small = fspm.lsystem_derive(str(ROOT / "examples/lsystems/monopodial_tree.l"), compressed=True)
    plain = fspm.lsystem_derive(str(ROOT / "examples/lsystems/monopodial_tree.l"))
    assert small["symbols"] == plain["symbols"]
    with pytest.raises(ValueError, match="context-sensitive"):
        fspm.lsystem_derive(str(ROOT / "examples/lsystems/context_sensitive_plant.l"),
                            compressed=True)


def test_lsystem_derive_reports_counts_past_64_bits_as_saturated():
    # ABOP Fig. 1.24a after n steps: 5^n F, (5^n - 1) / 4 each of +, -, [ and ] twice that, so
    # 5^n + 6 (5^n - 1) / 4 modules: about 3.7e18 at n = 26, 1.9e19 > 2^64 - 1 at n = 27, where
    # 5^27 F still fit.
    path = str(ROOT / "examples/lsystems/abop_1_24a.l")
    exact = fspm.lsystem_derive(path, steps=26, compressed=True)
    assert exact["saturated"] is False
    assert exact["modules"] == 5 ** 26 + 6 * (5 ** 26 - 1) // 4
    past = fspm.lsystem_derive(path, steps=27, compressed=True)
    assert 5 ** 27 + 6 * (5 ** 27 - 1) // 4 > 2 ** 64 - 1
    assert past["saturated"] is True
    assert past["modules"] is None
    assert past["symbols"]["F"] == 5 ** 27
    assert past["explicit_bytes"] is None
    assert past["compression"] > 1e15  # a lower bound
    far = fspm.lsystem_derive(path, steps=40, compressed=True)
    assert far["saturated"] is True
    assert far["symbols"]["F"] is None and far["symbols"]["+"] is None
    assert fspm.lsystem_derive(path, steps=3)["saturated"] is False
    assert "None" in fspm.lsystem_derive.__doc__ and "saturated" in fspm.lsystem_derive.__doc__


def abop_1_24_counts(n, f_per_x, x_per_x):
    """F and X counts after n steps of X -> (f_per_x F's, x_per_x X's), F -> FF, axiom X,
    by the recurrence of the productions: x' = x_per_x x, f' = 2 f + f_per_x x."""
    f, x = 0, 1
    for _ in range(n):
        f, x = 2 * f + f_per_x * x, x_per_x * x
    return f, x


def test_lsystem_derive_compressed_follows_the_recurrence_at_twenty_steps():
    # Fig. 1.24d: X -> F[+X]F[-X]+X (2 F, 3 X); Fig. 1.24f: X -> F-[[X]+X]+F[+FX]-X (3 F, 4 X).
    for name, f_per_x, x_per_x in (("abop_1_24d.l", 2, 3), ("abop_1_24f.l", 3, 4)):
        r = fspm.lsystem_derive(str(ROOT / "examples/lsystems" / name), steps=20, compressed=True)
        f, x = abop_1_24_counts(20, f_per_x, x_per_x)
        assert r["symbols"]["F"] == f, name
        assert r["symbols"]["X"] == x, name
        assert r["compression"] == pytest.approx(r["explicit_bytes"] / r["graph_bytes"])
        assert r["compression"] > 1e6


def sorted_ends(tree):
    ends = np.round(np.asarray(tree.ends), 6)
    return ends[np.lexsort(ends.T[::-1])]


def test_lsystem_plant_expands_to_the_explicit_turtle_tree(tmp_path):
    path = str(ROOT / "examples/lsystems/abop_1_24d.l")
    plant = fspm.lsystem_plant(path, steps=4)
    assert plant.has_geometry
    f, _ = abop_1_24_counts(4, 2, 3)
    assert plant.organs == f
    tree = fspm.greenlab_reconstruct(plant)
    explicit = fspm.lsystem_interpret(path, steps=4)  # the string derived and drawn explicitly
    assert len(tree) == len(explicit) == f
    np.testing.assert_allclose(sorted_ends(tree), sorted_ends(explicit), atol=1e-5)
    plant.save(str(tmp_path / "d.ctree"))
    back = fspm.read_plant(str(tmp_path / "d.ctree"))
    assert back.has_geometry and len(back) == len(plant) and back.organs == f
    # Fig. 1.24a at n = 20: a group per prototype (the axiom, F after 1..20 steps) and the five
    # internodes of F(1), standing for 5^20 internodes.
    big = fspm.lsystem_plant(str(ROOT / "examples/lsystems/abop_1_24a.l"), steps=20)
    assert len(big) == 26
    assert big.organs == 5 ** 20
    flat = fspm.lsystem_plant(path, steps=4, compressed=False)
    assert len(flat) == f + 1  # one group, every internode its own record
    np.testing.assert_allclose(sorted_ends(fspm.greenlab_reconstruct(flat)), sorted_ends(tree),
                               atol=1e-5)


def test_developmental_stages_grow_into_the_given_tree():
    tree = fspm.read_tree(str(ROOT / "examples/trees/open_a12.treeb"))
    model = fspm.developmental_model(tree)
    assert model.chain_count > 1 and model.levels[0] == 1
    totals = [float(model.stage(t).lengths.sum()) for t in (0.0, 0.3, 0.6, 0.9, 1.0)]
    assert totals[0] == 0.0
    assert all(a < b for a, b in zip(totals, totals[1:]))
    last = model.stage(1.0)
    assert len(last) == len(tree)
    assert np.allclose(last.radii, tree.radii) and np.allclose(last.ends, tree.ends)
    assert abs(fspm.seasonal_time(1.0, 3) - 1.0) < 1e-12
    with pytest.raises(ValueError):
        fspm.developmental_model(fspm.Tree())


def test_developmental_stages_with_added_branches():
    # A vertical trunk of eight unit edges with horizontal laterals at z = 4..7: crown ratio 0.5,
    # the bare trunk from z = 1 to 4 takes the three lowest laterals' copies (docs/stages.md).
    parents = [-1] + list(range(7)) + [3, 4, 5, 6]
    starts = [(0, 0, k) for k in range(8)] + [(0, 0, z) for z in (4, 5, 6, 7)]
    ends = [(0, 0, k + 1) for k in range(8)] + [(1 if k % 2 else -1, 0, k + 1) for k in range(3, 7)]
    tree = fspm.Tree.from_arrays(np.array(parents), np.array(starts, float), np.array(ends, float),
                                 radii=np.array([0.1] * 8 + [0.05] * 4))
    assert fspm.developmental_model(tree).added_branch_count == 0
    model = fspm.developmental_model(tree, added=True)
    assert model.added_branch_count == 3
    assert abs(model.crown_ratio - 0.5) < 1e-12
    last = model.stage(1.0)
    assert len(last) == len(tree) and np.allclose(last.ends, tree.ends)
    with pytest.raises(ValueError):
        fspm.developmental_model(tree, added=True, added_gamma=0.0)


def test_developmental_stages_with_shed_branches():
    # A vertical trunk of four unit edges with a lateral of two along +x at the end of the third;
    # tips of 1 cm, the root edge one tip pipe thicker than the trunk above needs (r^2.5 of 3
    # tips): one shed branch, a copy of the lateral, 8 (t - 0.25) long and shed at t = 0.5
    # (docs/stages.md; tests/stages/shed_branches_test.cpp).
    parents = [-1, 0, 1, 2, 2, 4]
    starts = [(0, 0, 0), (0, 0, 1), (0, 0, 2), (0, 0, 3), (0, 0, 3), (1, 0, 3)]
    ends = [(0, 0, 1), (0, 0, 2), (0, 0, 3), (0, 0, 4), (1, 0, 3), (2, 0, 3)]
    pipes = [3, 2, 2, 1, 1, 1]
    tree = fspm.Tree.from_arrays(np.array(parents), np.array(starts, float), np.array(ends, float),
                                 radii=np.array([0.01 * p ** 0.4 for p in pipes]))
    assert fspm.developmental_model(tree).shed_branch_count == 0
    model = fspm.developmental_model(tree, shed_branches=True, growth_profiles="by_chain")
    assert model.shed_branch_count == 1
    assert len(model.stage(0.4)) == 4 and len(model.stage(0.5)) == 2
    last = model.stage(1.0)
    assert len(last) == len(tree) and np.allclose(last.radii, tree.radii)
    with pytest.raises(ValueError):
        fspm.developmental_model(tree, growth_profiles="linear")


def test_read_results_of_a_sweep(tmp_path):
    out = tmp_path / "sweep"
    summary = fspm.run_experiment(str(ROOT / "examples/experiments/branching.toml"), str(out),
                                  jobs=2)
    assert summary["ran"] == 36 and summary["ok"] == 36
    df = fspm.read_results(out)
    # 2 steps x 3 values of r2 x 3 angles x 2 replicates, as the experiment file declares.
    assert len(df) == 36
    assert set(df["status"]) == {"ok"}
    assert {"steps", "define.r2", "define.a0", "internodes", "height"} <= set(df.columns)
    # More derivation steps never give fewer internodes for the same parameters.
    means = df.groupby("steps")["internodes"].mean()
    assert means[8] > means[6]
    with pytest.raises(fspm.IoError):
        fspm.read_results(tmp_path / "nothing-here")


def test_greenlab_jaeger_figure_1(tmp_path):
    # Jaeger et al. (2010), Figure 1: the binary tree has 6 metamers, stored as 4 node records.
    plant = fspm.greenlab_simulate(str(ROOT / "examples/greenlab/jaeger_figure1.toml"))
    assert plant.graph_nodes == 4
    assert plant.metamers == 6
    tree = fspm.greenlab_reconstruct(plant, leaves=False)
    assert tree.summary()["internodes"] == 6
    plant.save(str(tmp_path / "p.ctree"))
    assert fspm.read_plant(str(tmp_path / "p.ctree")).metamers == 6
    with pytest.raises(fspm.Error):
        fspm.greenlab_reconstruct(plant, age=99)


def test_geometry_columns_match_the_tree():
    # Every internode starts where its parent ends, and the summary's height is the highest end.
    tree = fspm.lsystem_interpret(str(ROOT / "examples/lsystems/monopodial_tree.l"), steps=4)
    assert tree.starts.shape == tree.ends.shape == (len(tree), 3)
    child = np.arange(1, len(tree))
    np.testing.assert_allclose(tree.starts[child], tree.ends[tree.parents[child]], atol=1e-9)
    assert tree.ends[:, 2].max() - tree.starts[0, 2] == pytest.approx(tree.summary()["height"])
    np.testing.assert_allclose(np.linalg.norm(tree.directions, axis=1), 1.0, atol=1e-9)


def test_greenlab_line_tree_matches_the_explicit_tree():
    # Same records in the same order; single precision against double.
    plant = fspm.greenlab_simulate(str(ROOT / "examples/greenlab/rauh.toml"))
    tree = fspm.greenlab_reconstruct(plant)
    lines = fspm.greenlab_reconstruct_lines(plant)
    assert len(lines) == len(tree)
    assert lines.starts.dtype == np.float32 and lines.starts.shape == (len(tree), 3)
    np.testing.assert_array_equal(lines.parents, tree.parents)
    np.testing.assert_array_equal(lines.kinds, tree.kinds)
    np.testing.assert_allclose(lines.starts, tree.starts, atol=1e-5)
    np.testing.assert_allclose(lines.lengths, tree.lengths, rtol=1e-6)
    assert len(lines.to_tree()) == len(tree)


def test_import_without_numpy_names_the_missing_package():
    import subprocess
    import sys

    code = "import sys; sys.modules['numpy'] = None; import fspm"
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert r.returncode != 0
    assert "fspm needs numpy" in r.stderr


def test_memory_limit_raises_memory_error_before_allocating(tmp_path):
    grammar = tmp_path / "double.l"
    grammar.write_text("derivation length: 40\nAxiom: F\nF --> FF\n")
    default = fspm.memory_limit()
    fspm.set_memory_limit("1M")
    try:
        assert fspm.memory_limit() == 1 << 20
        # Step k writes 2^k modules of 2 bytes beside the 2^(k-1) it reads: 3 * 2^k bytes, first
        # above 1 MiB at step 19.
        with pytest.raises(MemoryError, match="derivation step 19 needs about 1.5 MiB, above the "
                                              "memory limit of 1 MiB"):
            fspm.lsystem_derive(str(grammar))
        with pytest.raises(fspm.MemoryLimitError):
            fspm.lsystem_derive(str(grammar))
        fspm.set_memory_limit(3 << 20)
        assert fspm.memory_limit() == 3 << 20
        with pytest.raises(ValueError, match="expected a size"):
            fspm.set_memory_limit("lots")
    finally:
        fspm.set_memory_limit(None)
    assert fspm.memory_limit() == default
    assert fspm.lsystem_derive(str(grammar), steps=10)["modules"] == 1024


def test_newick_taxon_names_are_read_and_written_back():
    tree, names = fspm.parse_newick_named("((A:1,B:2)C:0.5,'D d':1);")
    assert len(tree) == 5
    assert names == ["", "C", "A", "B", "D d"]
    assert fspm.to_newick(tree, names) == "((A:1,B:2)C:0.5,'D d':1);"
    assert fspm.to_newick(tree) == "((:1,:2):0.5,:1);"


def test_developmental_stages_with_overlap_region():
    # A vertical trunk of ten unit edges, a lateral rising at 45 degrees from z = 4 to 6 and
    # horizontal laterals at z = 5..9: the overlap region z in [4, 7) takes copies only where
    # stratified clipping exceeds main-axis cutting, at z = 5 (docs/stages.md).
    parents = [-1] + list(range(9)) + [3, 4, 5, 6, 7, 8]
    starts = [(0, 0, k) for k in range(10)] + [(0, 0, z) for z in range(4, 10)]
    ends = ([(0, 0, k + 1) for k in range(10)] + [(2, 0, 6)] +
            [(1 if k % 2 else -1, 0, k + 1) for k in range(4, 9)])
    tree = fspm.Tree.from_arrays(np.array(parents), np.array(starts, float), np.array(ends, float),
                                 radii=np.array([0.1] * 10 + [0.08] + [0.05] * 5))
    assert fspm.developmental_model(tree, added=True).overlap_branch_count == 0
    model = fspm.developmental_model(tree, added_overlap=True)
    assert model.overlap_branch_count == 1 and model.added_branch_count == 4


def test_developmental_stages_with_branch_edits():
    # Trunk of four unit edges (nodes 0, 1 up; 2, 3 leaning to -x at 45 degrees), a lateral of two
    # unit edges along +x at z = 1 (nodes 4, 5). By eq. 5.3-5.4 the lateral grows 8/3 per unit of t
    # from t = 0.25 (docs/stages.md): made 0.15 younger it is 8/3 (1 - 0.4) = 1.6 long at t = 1;
    # copied to the end of node 2 (reached at t = 0.75) it is 8/3 (1 - 0.75) = 2/3 long.
    h = 0.5 ** 0.5
    parents = [-1, 0, 1, 2, 0, 4]
    starts = [(0, 0, 0), (0, 0, 1), (0, 0, 2), (-h, 0, 2 + h), (0, 0, 1), (1, 0, 1)]
    ends = [(0, 0, 1), (0, 0, 2), (-h, 0, 2 + h), (-2 * h, 0, 2 + 2 * h), (1, 0, 1), (2, 0, 1)]
    tree = fspm.Tree.from_arrays(np.array(parents), np.array(starts, float), np.array(ends, float),
                                 radii=np.array([0.05] * 4 + [0.02] * 2))
    younger = fspm.developmental_model(tree, age_branches=[(5, -0.15)]).stage(1.0)
    assert abs(younger.lengths[4] + younger.lengths[5] - 1.6) < 1e-9
    copied = fspm.developmental_model(tree, copy_branches=[(4, 2)]).stage(1.0)
    assert len(copied) == 7 and copied.parents[6] == 2
    assert abs(copied.lengths[6] - 2.0 / 3.0) < 1e-9
    assert np.allclose(copied.starts[6], (-h, 0, 2 + h))
    with pytest.raises(ValueError):
        fspm.developmental_model(tree, age_branches=[(1, 0.1)])  # the trunk
