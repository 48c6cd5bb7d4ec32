"""Scenes, light, growth and plastic adaptation from Python, against closed forms."""
import json
import math

import numpy as np
import pytest

import fspm
from conftest import ROOT


def cap_light(radius, height, translucency=0.0):
    """Light under a sphere straight above (Pirk eq. 4.3 with I = cos^2 from the zenith): the cap
    of half angle a removes (1 - g) * 2 pi (1 - cos^3 a) / 3 of the hemisphere integral 2 pi / 3."""
    cos_a = math.sqrt(1.0 - (radius / height) ** 2)
    return 1.0 - (1.0 - translucency) * (1.0 - cos_a ** 3)


def test_light_of_an_empty_scene_is_exactly_one():
    points = np.random.default_rng(1).uniform(-10, 10, size=(50, 3))
    light, directions = fspm.light(fspm.Scene(), points)
    assert light.shape == (50,) and directions.shape == (50, 3)
    np.testing.assert_array_equal(light, 1.0)
    np.testing.assert_allclose(directions, np.tile([0, 0, 1.0], (50, 1)), atol=1e-12)


@pytest.mark.parametrize("radius,height,translucency", [(1.0, 2.0, 0.0), (0.5, 3.0, 0.0),
                                                        (1.0, 4.0, 0.4)])
def test_sphere_straight_above(radius, height, translucency):
    scene = fspm.Scene()
    scene.add_sphere((0, 0, height), radius, translucency=translucency)
    light, directions = fspm.light(scene, [[0.0, 0.0, 0.0]])
    assert light[0] == pytest.approx(cap_light(radius, height, translucency), abs=1e-12)
    np.testing.assert_allclose(directions[0], [0, 0, 1], atol=1e-12)  # symmetric shadow
    # The brute-force reference (sampled directions, no analytic caps) converges to it.
    scene.directions = 16384
    brute, _ = fspm.LightModel(scene).evaluate_brute_force((0, 0, 0))
    assert brute == pytest.approx(light[0], abs=0.01)


def test_light_arrays_view_one_buffer():
    light, directions = fspm.LightModel(fspm.Scene()).evaluate(np.zeros((4, 3)))
    # light[i] and directions[i] are one C++ LightSample: a double then three doubles.
    assert directions.ctypes.data == light.ctypes.data + 8
    assert light.strides == (32,) and directions.strides == (32, 8)
    empty_light, empty_dirs = fspm.light(fspm.Scene(), np.zeros((0, 3)))
    assert empty_light.shape == (0,) and empty_dirs.shape == (0, 3)


def test_scene_from_json_dict_and_file():
    text = json.dumps({"sky": {"brightest": [0, 0, 1], "directions": 128},
                       "occluders": [{"type": "sphere", "center": [0, 0, 2], "radius": 1.0,
                                      "translucency": 0.0}]})
    from_text = fspm.parse_scene_json(text)
    from_dict = fspm.parse_scene_json(json.loads(text))
    assert from_text.directions == from_dict.directions == 128
    np.testing.assert_array_equal(from_text.spheres, [[0, 0, 2, 1, 0]])
    assert fspm.light(json.loads(text), [0, 0, 0])[0][0] == pytest.approx(cap_light(1, 2))
    wall = fspm.read_scene_file(str(ROOT / "examples/environment/wall_scene.json"))
    assert wall.boxes == 1 and wall.ground == 0.0
    # Below the ground everything is dark, above it nothing is in the way straight up.
    assert wall.inside_solid((0, 0, -1)) and not wall.inside_solid((0, 0, 1))


def test_scene_and_light_errors():
    with pytest.raises(fspm.ParseError, match=r"<scene>:1:"):
        fspm.parse_scene_json("{ not json")
    with pytest.raises(fspm.ParameterError, match="radius"):
        fspm.parse_scene_json({"occluders": [{"type": "sphere", "center": [0, 0, 1],
                                              "radius": -1}]})
    with pytest.raises(fspm.IoError, match="missing.json"):
        fspm.read_scene_file("/nonexistent/missing.json")
    with pytest.raises(fspm.ParameterError, match=r"points: expected an array of shape \(N, 3\), "
                                                  r"got shape \(4, 2\)"):
        fspm.light(fspm.Scene(), np.zeros((4, 2)))
    with pytest.raises(fspm.ParameterError, match="directions"):
        fspm.light(fspm.Scene(), np.zeros((1, 3)), directions=0)
    with pytest.raises(fspm.ParameterError, match="non-zero direction"):
        fspm.Scene().brightest = (0, 0, 0)
    with pytest.raises(fspm.ParameterError, match=r"\[0, 1\)"):
        fspm.Scene().significance = 1.5
    with pytest.raises(fspm.ParameterError, match="1048576"):
        fspm.Scene().directions = 1 << 21
    with pytest.raises(TypeError):
        fspm.light("scene.json", np.zeros((1, 3)))


def test_scene_obstacles_are_checked_by_the_library():
    scene = fspm.Scene()
    with pytest.raises(ValueError, match="radius"):
        scene.add_sphere((0, 0, 1), 0.0)
    with pytest.raises(ValueError, match="min < max"):
        scene.add_box((0, 0, 0), (1, 0, 1))
    with pytest.raises(ValueError, match="translucency"):
        scene.add_wall((0, 0), (1, 0), 2.0, translucency=2.0)
    with pytest.raises(ValueError, match="thickness"):
        scene.add_wall((0, 0), (0, 0), 2.0)
    with pytest.raises(ValueError, match="translucency"):
        scene.set_ground(0.0, translucency=5.0)
    with pytest.raises(ValueError, match="height"):
        scene.set_ground(float("nan"))
    assert "0 spheres, 0 boxes" in repr(scene)  # nothing refused was added
    scene.add_wall((0, 0), (1, 0), 2.0, translucency=0.5)
    assert "1 boxes" in repr(scene)


def test_growth_parameters_presets_dicts_and_toml(tmp_path):
    a = fspm.growth_preset("A")
    assert (a.phototropism, a.gravitropism) == (0.25, 0.12)  # Pirk 4.5.4, type A
    b = fspm.GrowthParams(preset="B", years=3)
    assert (b.phototropism, b.gravitropism, b.years) == (0.45, 0.44, 3)
    assert fspm.GrowthParams(**b.to_dict()).to_dict() == b.to_dict()
    parsed = fspm.parse_growth_params('preset = "C"\nyears = 4\n')
    assert parsed.years == 4 and parsed.gravitropism == 0.23
    from_file = fspm.read_growth_params(str(ROOT / "examples/environment/tree_a.toml"))
    assert from_file.to_dict() == fspm.GrowthParams(preset="A", years=20).to_dict()
    np.testing.assert_array_equal(from_file.gravity_direction, [0, 0, -1])
    with pytest.raises(fspm.ParameterError, match='unknown preset "Z"' ):
        fspm.growth_preset("Z")
    with pytest.raises(TypeError, match="unknown parameter 'yeras'"):
        fspm.GrowthParams(yeras=3)
    with pytest.raises(ValueError, match="<params>:1.*unknown key 'no_such_key'"):
        fspm.parse_growth_params("no_such_key = 1\n")
    bad = fspm.GrowthParams(years=-1)
    with pytest.raises(fspm.ParameterError, match="years"):
        bad.validate()
    with pytest.raises(fspm.ParameterError, match="years"):
        fspm.grow_tree(bad)


def test_growth_light_models_and_tropism_pairings():
    p = fspm.GrowthParams(preset="B", light_model="sky", preset_tropisms="appendix")
    assert p.light_model == "sky" and (p.phototropism, p.gravitropism) == (0.45, 0.03)
    assert p.alpha == fspm.growth_preset("B", light_model="sky").alpha
    assert fspm.growth_preset("B").light_model == "shadow_grid"
    assert fspm.growth_preset("C", preset_tropisms="appendix").phototropism == 0.44
    with pytest.raises(fspm.ParameterError, match="light_model"):
        fspm.GrowthParams(light_model="voxels")
    with pytest.raises(fspm.ParameterError, match="preset_tropisms"):
        fspm.GrowthParams(preset="A", preset_tropisms="captions")
    q = fspm.GrowthParams(preset="A", years=5, voxel_size_m=0.2, sky_light_fraction=0.5)
    assert q.to_dict()["voxel_size_m"] == 0.2
    # No light, no growth: the first internode only.
    assert fspm.grow_tree(fspm.GrowthParams(preset="A", years=5, sky_light_fraction=0.0)).internodes == 1


def test_grow_tree_is_deterministic_and_consistent():
    params = fspm.GrowthParams(preset="A", years=6, seed=3)
    r = fspm.grow_tree(params)
    tree = r.tree
    kinds = tree.kinds
    assert r.internodes == int((kinds == 0).sum()) > 6
    assert r.clusters == int((kinds == 1).sum()) == len(r.cluster_spheres)
    assert r.grown == r.internodes + r.shed
    assert r.height_m == pytest.approx(tree.ends[:, 2].max() - tree.starts[0, 2])
    light = tree.attribute("light")[kinds == 0]
    sensed = ~np.isnan(light)  # nan: the node had no bud in the last cycle
    assert np.isnan(light[0]) and sensed.sum() > 0
    assert ((light[sensed] >= 0) & (light[sensed] <= 1)).all()
    # Same seed, same tree; the dict form is the same parameters.
    again = fspm.grow_tree(params.to_dict()).tree
    np.testing.assert_array_equal(again.ends, tree.ends)
    # A wall right beside the trunk takes light away, so the tree grows away from it (-x).
    walled = fspm.grow_tree(params, {"occluders": [
        {"type": "wall", "from": [0.6, -20], "to": [0.6, 20], "height": 8, "thickness": 0.2}]})
    assert walled.tree.ends[:, 0].mean() < tree.ends[:, 0].mean()


def test_plastic_adaptation():
    tree = fspm.read_tree(str(ROOT / "examples/trees/open_a12.treeb"))  # a 12-year tree of type A
    analysis = fspm.analyze_tree(tree, {"light_model": "sky"})  # Pirk's eq. 4.3 cluster light
    assert analysis.skeleton.shape == (len(tree),)
    assert analysis.clusters.shape[1] == 5 and len(analysis.clusters) > 0
    # An unchanged (open) scene adapts to exactly the input tree.
    same = fspm.adapt_tree(tree, analysis, fspm.Scene())
    assert same.pruned_nodes == 0 and same.bent_segments == 0
    np.testing.assert_array_equal(same.tree.attribute("displacement"), 0.0)
    # A wall at x = 0.7 bends the crown away from it and prunes the shaded side.
    wall = {"occluders": [{"type": "wall", "from": [0.7, -20], "to": [0.7, 20], "height": 6,
                           "thickness": 0.2}]}
    adapted = fspm.adapt_tree(tree, analysis, wall)
    assert adapted.mean_tip_shift[0] < 0
    scene = fspm.Scene()
    scene.add_wall((0.7, -20), (0.7, 20), height=6, thickness=0.2)
    same_wall = fspm.adapt_tree(tree, fspm.analyze_tree(tree, {"pruning_strength": 0.8, "light_model": "sky"}), scene)
    np.testing.assert_array_equal(same_wall.tree.ends, adapted.tree.ends)
    assert adapted.mean_tip_displacement_m > 0
    pruned = adapted.tree.attribute("pruned")
    assert int(pruned.sum()) == adapted.pruned_nodes > 0
    assert len(fspm.remove_pruned(adapted.tree)) == len(tree) - adapted.pruned_nodes
    # Two trees side by side, adapted together.
    both = fspm.adapt_trees([tree, tree], [analysis, analysis], fspm.Scene())
    assert len(both) == 2 and all(len(r.tree) == len(tree) for r in both)
    other = fspm.grow_tree(fspm.GrowthParams(preset="B", years=3)).tree
    with pytest.raises(fspm.ParameterError):
        fspm.adapt_tree(other, analysis, fspm.Scene())
    with pytest.raises(fspm.ParameterError):
        fspm.adapt_trees([tree], [analysis, analysis], fspm.Scene())
    with pytest.raises(fspm.ParameterError):
        fspm.analyze_tree(fspm.Tree())


def test_light_releases_the_gil():
    # While one thread is inside a long light computation, another keeps running Python.
    import threading
    import time

    rng = np.random.default_rng(1)
    scene = fspm.Scene()
    for c in rng.uniform(-3, 3, size=(300, 3)):
        scene.add_sphere(c + [0, 0, 5], 0.5, translucency=0.3)
    span = {}

    def work(points):
        span["start"] = time.perf_counter()
        fspm.light(scene, points)
        span["end"] = time.perf_counter()

    # More points until one call lasts long enough to tell (a fast machine needs more).
    count = 20000
    for _ in range(8):
        points = rng.uniform(-3, 3, size=(count, 3))
        worker = threading.Thread(target=work, args=(points,))
        ticks = []
        worker.start()
        while worker.is_alive():
            ticks.append(time.perf_counter())
            time.sleep(0.001)
        worker.join()
        if span["end"] - span["start"] > 0.1:
            break
        count *= 2
    inside = [t for t in ticks if span["start"] + 0.02 < t < span["end"] - 0.02]
    assert len(inside) >= 5


def test_canopy_light_under_a_real_sky(tmp_path):
    sky = tmp_path / "sky.toml"
    sky.write_text('sky = { site = { latitude = 50, longitude = 8, elevation = 200, '
                   'utc_offset = 1 }, date = "2024-06-01" }\n')
    params = fspm.parse_growth_params(
        'preset = "A"\nyears = 8\n' + sky.read_text())
    tree = fspm.grow_tree(params).tree
    # Grown under a real sky, the leaves carry their PAR.
    assert "par_umol_m2_s" in tree.attribute_names()
    c = fspm.canopy_light(tree, str(sky))
    assert c["sky"] == "site"
    per = c["per_cluster"]
    assert len(per["node"]) == c["clusters"] > 0
    assert np.allclose(per["sunlit_leaf_area_m2"] + per["shaded_leaf_area_m2"],
                       per["leaf_area_m2"])
    assert np.allclose(per["star"], 0.5 * per["lie"])
    assert math.isclose(per["absorbed_par_mol_day"].sum(), c["absorbed_par_mol_day"],
                        rel_tol=1e-9)
    assert 0 < c["lie"] <= 1
    assert "absorbed_par_mol_day" not in fspm.canopy_light(tree)
