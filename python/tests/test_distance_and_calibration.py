"""Trees from arrays, edit distances with cost models, and GL1 calibration from Python."""
import copy

import numpy as np
import pytest

import fspm
from conftest import ROOT, forked_tree

TRUTH = {"resistance": 0.8, "age.1.internode_sink": 0.6, "age.2.leaf_sink": 0.7,
         "age.1.leaf_beta_a": 2.5}


def test_tree_from_arrays():
    tree = forked_tree()
    assert len(tree) == 7 and tree.summary()["tips"] == 2
    np.testing.assert_array_equal(tree.parents[1:], [0, 1, 2, 3, 2, 5])
    np.testing.assert_array_equal(tree.orders, [0, 0, 0, 1, 1, 1, 1])
    np.testing.assert_allclose(tree.lengths[0], 1.0)  # derived from start and end
    t = fspm.Tree.from_arrays([-1, 0], np.zeros((2, 3)), np.ones((2, 3)),
                              attributes={"light": [0.25, 0.5]})
    np.testing.assert_array_equal(t.attribute("light"), [0.25, 0.5])
    with pytest.raises(fspm.ParameterError, match=r"parents\[1\]"):
        fspm.Tree.from_arrays([-1, 1], np.zeros((2, 3)), np.ones((2, 3)))
    with pytest.raises(fspm.ParameterError, match="radii: expected 2 values"):
        fspm.Tree.from_arrays([-1, 0], np.zeros((2, 3)), np.ones((2, 3)), radii=[1.0])
    with pytest.raises(fspm.ParameterError, match="ends"):
        fspm.Tree.from_arrays([-1, 0], np.zeros((2, 3)), np.ones((3, 3)))


def test_distance_cost_models():
    a = fspm.parse_newick("(1,2)3;")
    b = fspm.parse_newick("(1,5)3;")
    # Relabelling 2 -> 5 costs |2 - 5| = 3, less than deleting 2 and inserting 5 (2 + 5).
    assert fspm.distance(a, b, cost="absolute", attributes=["label"])["distance"] == 3.0
    labels = (fspm.node_attribute_values(a, "label"), fspm.node_attribute_values(b, "label"))
    np.testing.assert_array_equal(labels[1], [3, 1, 5])
    assert fspm.distance(a, b, features=labels, unit_cost=0.0)["distance"] == 3.0
    # With a unit cost of 10 per deletion the relabel is still cheaper: same distance.
    assert fspm.distance(a, b, features=labels, unit_cost=10.0)["distance"] == 3.0
    # Topologically the trees are the same.
    assert fspm.distance(a, b)["distance"] == 0.0


def test_distance_main_skeleton_and_solvers():
    tree = forked_tree()
    np.testing.assert_array_equal(fspm.main_skeleton_nodes(tree, 0.02), [0, 1, 2])
    pruned = fspm.Tree.from_arrays(tree.parents[:5], tree.starts[:5], tree.ends[:5],
                                   radii=tree.radii[:5])
    # The two trees differ by the second branch (two nodes), not in their main skeleton.
    assert fspm.distance(tree, pruned)["distance"] == 2.0
    r = fspm.distance(tree, pruned, main_skeleton=0.02, mapping=True)
    assert r["distance"] == 0.0 and r["nodes_a"] == r["nodes_b"] == 3
    assert r["mapping"] == [(0, 0), (1, 1), (2, 2)]
    rng = np.random.default_rng(3)
    for _ in range(5):
        x = fspm.parse_newick(random_newick(rng, 12))
        y = fspm.parse_newick(random_newick(rng, 12))
        h = fspm.distance(x, y, cost="absolute", attributes=["label"])
        f = fspm.distance(x, y, cost="absolute", attributes=["label"], solver="min-cost-flow")
        assert h["distance"] == pytest.approx(f["distance"], abs=1e-9)
    with pytest.raises(fspm.ParameterError, match="simplex"):
        fspm.distance(tree, pruned, solver="simplex")
    with pytest.raises(fspm.ParameterError, match="one row per node"):
        fspm.distance(a_tree(), a_tree(), features=(np.zeros(2), np.zeros(3)))
    with pytest.raises(fspm.ParameterError, match="no_such"):
        fspm.distance(tree, pruned, cost="standardized", attributes=["no_such"])


def a_tree():
    return fspm.parse_newick("(1,2)3;")


def random_newick(rng, n):
    """A random tree of n labelled nodes in Newick."""
    children = {0: []}
    for i in range(1, n):
        children[int(rng.integers(0, i))].append(i)
        children[i] = []

    def text(i):
        label = str(int(rng.integers(1, 9)))
        if not children[i]:
            return label
        return "(" + ",".join(text(c) for c in children[i]) + ")" + label

    return text(0) + ";"


def test_gl1_calibration_recovers_known_parameters():
    start = fspm.read_plant_params(str(ROOT / "examples/greenlab/gl1_plant.toml"))
    assert start.functional and start.calibration_parameters == list(TRUTH)
    truth = copy.deepcopy(start)
    for name, value in TRUTH.items():
        truth.set_parameter(name, value)
    assert start.get_parameter("resistance") == 1.12  # the copy is independent
    targets = fspm.read_targets_csv(str(ROOT / "examples/greenlab/gl1_targets.csv"))
    # Exact targets made by the model itself at known parameters: the fit must find them.
    exact = fspm.predict_targets(truth, targets)
    synthetic = [fspm.Target(t.quantity, t.age, t.cycle, v) for t, v in zip(targets, exact)]
    fit = fspm.fit_gl1(start, synthetic)
    assert fit.converged and fit.names == list(TRUTH)
    np.testing.assert_allclose(fit.estimates, list(TRUTH.values()), rtol=1e-5)
    np.testing.assert_allclose(fit.initial, [start.get_parameter(n) for n in TRUTH])
    assert fit.final_cost < 1e-12 < fit.initial_cost
    assert fit.fitted.get_parameter("age.2.leaf_sink") == pytest.approx(0.7, rel=1e-5)
    assert len(fit.residuals) == len(targets)
    # The noisy example targets: the fit lands within a few standard errors of the truth.
    noisy = fspm.fit_gl1(start, targets, names=["resistance"])
    assert noisy.names == ["resistance"]
    assert abs(noisy.estimates[0] - 0.8) < 0.05 and noisy.standard_errors[0] > 0
    text = (ROOT / "examples/greenlab/gl1_plant.toml").read_text()
    refitted = fspm.parse_plant_params(fspm.fitted_toml(text, noisy))
    assert refitted.get_parameter("resistance") == pytest.approx(noisy.estimates[0])
    plant = fspm.greenlab_simulate(fit.fitted)
    assert plant.metamers == fspm.greenlab_simulate(str(ROOT / "examples/greenlab/gl1_plant.toml")).metamers


def test_calibration_errors(tmp_path):
    params = fspm.read_plant_params(str(ROOT / "examples/greenlab/gl1_plant.toml"))
    with pytest.raises(fspm.ParameterError, match="no_such"):
        params.get_parameter("no_such")
    with pytest.raises(fspm.ParseError, match=r"t.csv:2"):
        fspm.parse_targets_csv("quantity,age,cycle,value\nleaf_mass,1,x,1\n", "t.csv")
    with pytest.raises(fspm.ParameterError):
        fspm.fit_gl1(params, [fspm.Target("leaf_mass", 1, 99, 1.0)])
    with pytest.raises(fspm.IoError):
        fspm.read_plant_params(str(tmp_path / "missing.toml"))
    with pytest.raises(fspm.ParseError):
        fspm.parse_plant_params("[plant\n")
    no_gl1 = fspm.read_plant_params(str(ROOT / "examples/greenlab/jaeger_figure1.toml"))
    with pytest.raises(fspm.ParameterError, match="functional"):
        fspm.fit_gl1(no_gl1, [fspm.Target("production", 0, 1, 1.0)], names=["resistance"])
