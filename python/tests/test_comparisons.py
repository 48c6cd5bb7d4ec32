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
