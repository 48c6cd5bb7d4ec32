"""Exceptions named as Python's own, summary() on every result object, numbers shown to four
significant digits, and the normalized edit distance."""
import builtins

import pytest

import fspm
from conftest import chain_tree


def test_exceptions_carry_the_builtin_names(tmp_path):
    assert fspm.FileNotFoundError.__name__ == "FileNotFoundError"
    assert fspm.ValueError.__name__ == "ValueError"
    assert issubclass(fspm.FileNotFoundError, builtins.FileNotFoundError)
    assert issubclass(fspm.FileNotFoundError, fspm.IoError)
    assert issubclass(fspm.ValueError, builtins.ValueError)
    assert issubclass(fspm.ValueError, fspm.Error)
    # The older names stay as aliases.
    assert fspm.MissingFileError is fspm.FileNotFoundError
    assert fspm.ParameterError is fspm.ValueError
    # No exception class of the module ends in an underscore.
    names = [n for n in dir(fspm._fspm) if isinstance(getattr(fspm._fspm, n), type)
             and issubclass(getattr(fspm._fspm, n), BaseException)]
    assert names and not [n for n in names if n.endswith("_")], names
    with pytest.raises(fspm.FileNotFoundError) as missing:
        fspm.read_tree(str(tmp_path / "missing.tree"))
    assert type(missing.value).__name__ == "FileNotFoundError"
    with pytest.raises(fspm.ValueError) as bad:
        fspm.student_t_test([], [1.0, 2.0])
    assert type(bad.value).__name__ == "ValueError"


def test_format_significant_rounds_to_four_digits():
    assert fspm.format_significant(5.190458949999998) == "5.19"
    assert fspm.format_significant(5.4799999999999995) == "5.48"
    assert fspm.format_significant(-3.18e-18) == "0"
    assert fspm.format_significant(6059.0) == "6059"
    assert fspm.format_significant(3.14159, 2) == "3.1"


def test_summary_keeps_every_digit_and_shows_four():
    s = fspm.Summary(height=5.190458949999998, nodes=12, interval=(0.1234567, 2.0))
    assert s["height"] == 5.190458949999998  # the value itself is untouched
    assert repr(s) == "{'height': 5.19, 'nodes': 12, 'interval': (0.1235, 2)}"
    assert str(s) == repr(s)
    assert isinstance(s, dict)


def test_every_result_object_has_a_summary():
    tree = chain_tree(3, 0.05, length=1.7300000000000002)
    s = tree.summary()
    assert isinstance(s, fspm.Summary)
    assert s["nodes"] == 3 and s["height"] == pytest.approx(5.19)
    assert "'height': 5.19" in repr(s)

    grown = fspm.grow_tree(fspm.GrowthParams(preset="A", years=3))
    g = grown.summary()
    assert isinstance(g, fspm.Summary)
    assert g["internodes"] == grown.internodes and g["height_m"] == grown.height_m

    t = fspm.student_t_test([0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0],
                            [1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4])
    ts = t.summary()
    assert ts["p"] == t.p
    # R: t.test(extra ~ group, data = sleep, var.equal = TRUE): t = -1.8608, p = 0.07919.
    assert "'t': -1.861" in repr(ts) and "'p': 0.07919" in repr(ts)
    assert repr(t) == "TTestResult(t=-1.861, df=18, p=0.07919, estimate=-1.58)"

    u = fspm.mann_whitney_u_test([1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
    assert u.summary()["u"] == 0.0

    for cls in (fspm.Tree, fspm.GrowthResult, fspm.AdaptationResult, fspm.TreeAnalysis,
                fspm.FitResult, fspm.TTestResult, fspm.MannWhitneyResult):
        assert callable(getattr(cls, "summary")), cls
        assert cls.summary.__doc__, cls


def test_adaptation_and_analysis_summaries():
    tree = fspm.grow_tree(fspm.GrowthParams(preset="A", years=4)).tree
    analysis = fspm.analyze_tree(tree)
    a = analysis.summary()
    assert a["clusters"] == len(analysis.clusters)
    assert a["skeleton_nodes"] == int(analysis.skeleton.sum())
    adapted = fspm.adapt_tree(tree, analysis, fspm.Scene())
    r = adapted.summary()
    assert r["nodes"] == len(adapted.tree) and r["pruned_nodes"] == adapted.pruned_nodes


def test_distance_has_a_scale():
    # Hand-computed: 203 / (1601 + 1602) (labels of A and of B; absolute costs have no unit).
    a = fspm.parse_newick("(100,(200,300)1)1000;")
    b = fspm.parse_newick("((100,200)2,300)1000;")
    d = fspm.distance(a, b, cost="absolute", attributes=["label"])
    assert d["distance"] == 203.0
    assert d["deletion_cost_a"] == 1601.0 and d["insertion_cost_b"] == 1602.0
    assert d["normalized_distance"] == pytest.approx(203.0 / 3203.0, rel=1e-15)
    assert fspm.distance(a, a)["normalized_distance"] == 0.0
    # A chain of 2 against one of 6, topological: 4 / (2 + 6).
    assert fspm.distance(chain_tree(2, 0.1), chain_tree(6, 0.1))["normalized_distance"] == 0.5


def test_a_nul_byte_in_a_path_is_a_value_error(tmp_path):
    # As Python's open(): the system would read the path only up to the NUL, another file.
    (tmp_path / "t").write_text("(a,b)c;")
    with pytest.raises(builtins.ValueError, match="NUL byte"):
        fspm.read_tree(str(tmp_path / "t") + "\0.nwk")
