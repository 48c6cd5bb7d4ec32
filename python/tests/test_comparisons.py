"""Experiment comparisons from Python: run_experiment computes them, compare_results redoes them."""
import csv

import fspm

EXPERIMENT = """
[experiment]
name = "chains"
seed = 4
replicates = 4
[model]
kind = "synthetic"
[sweep]
nodes = [3, 8]
[distance]
cost = "topological"
[[comparison]]
name = "3-8"
a = { nodes = 3 }
b = { nodes = 8 }
"""


def test_run_experiment_writes_pairs_with_closed_form_distances(tmp_path):
    path = tmp_path / "chains.toml"
    path.write_text(EXPERIMENT)
    out = tmp_path / "out"
    summary = fspm.run_experiment(str(path), str(out), jobs=2)
    assert summary["ok"] == 8
    with open(out / "pairs.csv") as f:
        rows = list(csv.DictReader(f))
    # Chains of 3 and 8 internodes: delete (or insert) the 5 surplus nodes.
    assert len(rows) == 4
    assert all(float(r["distance"]) == 5.0 for r in rows)
    assert len({r["run_a"] for r in rows} | {r["run_b"] for r in rows}) == 8
    (out / "pairs.csv").unlink()
    again = fspm.compare_results(str(out), jobs=1)
    assert again["pairs"] == 4
    assert (out / "pairs.csv").exists()


def test_replicates_override_and_missing_directory(tmp_path):
    path = tmp_path / "chains.toml"
    path.write_text(EXPERIMENT)
    summary = fspm.run_experiment(str(path), str(tmp_path / "small"), jobs=1, replicates=2)
    assert summary["total_runs"] == 4
    try:
        fspm.compare_results(str(tmp_path / "nowhere"))
    except fspm.Error as e:
        assert "nowhere" in str(e)
    else:
        raise AssertionError("expected an error for a missing result directory")


def test_adapt_kind_sweeps_a_given_tree_from_python(tmp_path):
    """Model kind adapt: one open-grown tree moved toward a wall; the analysis is shared."""
    from conftest import ROOT

    tree = fspm.grow_tree(fspm.GrowthParams(preset="A", years=8)).tree
    tree_path = tmp_path / "open.tree"
    fspm.write_tree(tree, str(tree_path))
    wall = ROOT / "examples" / "environment" / "wall_scene.json"
    path = tmp_path / "adapt.toml"
    path.write_text(f"""
[experiment]
name = "adapt"
seed = 1
[model]
kind = "adapt"
file = "{tree_path}"
scene = "{wall}"
[sweep]
tree_x_m = [-30.0, 1.5]
[outputs]
metrics = ["nodes", "pruned_nodes", "tip_displacement", "analysis_seconds"]
""")
    summary = fspm.run_experiment(str(path), str(tmp_path / "out"), jobs=2)
    assert summary["ok"] == 2
    df = fspm.read_results(str(tmp_path / "out")).sort_values("tree_x_m")
    far, near = df.iloc[0], df.iloc[1]
    # 32 m from the wall the tree keeps its shape; 1 m from it the tips move away.
    assert far["pruned_nodes"] == 0 and far["tip_displacement"] < 0.05
    assert near["tip_displacement"] > far["tip_displacement"]
    assert near["nodes"] + near["pruned_nodes"] == far["nodes"]
    assert far["analysis_seconds"] == near["analysis_seconds"]
