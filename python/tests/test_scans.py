"""Trees from laser scans from Python (docs/scans.md), against shapes whose answers are known."""
import pathlib

import numpy as np
import pytest

import fspm

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cylinder_points(radius=0.15, height=3.0, rings=300, per_ring=48, seed=4):
    """Points on the side of a vertical cylinder standing on z = 0: a bare trunk."""
    rng = np.random.default_rng(seed)
    z = np.repeat(np.linspace(0.0, height, rings), per_ring)
    phi = rng.uniform(0.0, 2.0 * np.pi, z.size)
    return np.column_stack([radius * np.cos(phi), radius * np.sin(phi), z])


def test_species_presets_are_pirks_table_3_1():
    presets = {p["name"]: p for p in fspm.species_presets()}
    assert len(presets) == 10
    # Pirk (2012) Table 3.1: pine beta 1.3, gamma 1.2, f_s 0.98; palm 1.8, 1.3, 0.80.
    assert (presets["pine"]["beta"], presets["pine"]["gamma"], presets["pine"]["f_s"]) == (
        1.3, 1.2, 0.98)
    assert (presets["palm"]["beta"], presets["palm"]["gamma"], presets["palm"]["f_s"]) == (
        1.8, 1.3, 0.8)


def test_a_cylinder_encodes_to_a_trunk_of_its_diameter_and_height():
    model = fspm.encode_points(cylinder_points(), species="pine")
    assert (model.species, model.beta, model.gamma) == ("pine", 1.3, 1.2)
    # d_root from a circle fitted to the trunk points: the cylinder's diameter.
    assert model.root_diameter == pytest.approx(0.30, rel=0.03)
    skeleton = model.skeleton
    # The skeleton starts at the lowest point and follows the axis (bin centroids of rings).
    assert skeleton.starts[:, 2].min() == pytest.approx(0.0, abs=1e-9)
    assert np.median(np.hypot(skeleton.ends[:, 0], skeleton.ends[:, 1])) < 0.05
    # Eq. 3.1 tapers the diameter towards the top while the cylinder does not, so by eq. 3.2 its
    # upper part becomes a cluster: skeleton and clusters together reach the top, 3 m.
    top = max([skeleton.ends[:, 2].max()] + [c["vertices"][:, 2].max() for c in model.clusters])
    assert top == pytest.approx(3.0, abs=0.05)
    assert sum(c["point_count"] for c in model.clusters) > 0


def test_keywords_override_the_species():
    model = fspm.encode_points(cylinder_points(), species="pine", gamma=1.7, root_diameter=0.5)
    assert model.gamma == 1.7 and model.beta == 1.3
    assert model.root_diameter == 0.5
    with pytest.raises(ValueError, match="pinee"):
        fspm.encode_points(cylinder_points(), species="pinee")


def test_clusters_files_round_trip(tmp_path):
    model = fspm.encode_points(cylinder_points())
    path = str(tmp_path / "trunk.clusters")
    fspm.write_clusters(model, path)
    back = fspm.read_clusters(path)
    assert len(back.skeleton) == len(model.skeleton)
    assert back.root_diameter == pytest.approx(model.root_diameter)
    np.testing.assert_allclose(back.skeleton.ends, model.skeleton.ends, atol=1e-6)


def test_point_files_read_as_written(tmp_path):
    points = cylinder_points(rings=5, per_ring=4)
    path = tmp_path / "trunk.xyz"
    np.savetxt(path, points)
    np.testing.assert_allclose(fspm.read_points(str(path)), points, rtol=1e-12)
    with pytest.raises(OSError):
        fspm.read_points(str(tmp_path / "missing.xyz"))


def test_read_points_of_a_gltf_applies_the_node_transform(tmp_path):
    import base64
    import json
    # A triangle moved by its node's translation (glTF 2.0 sec. 3.5.3).
    corners = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype="<f4")
    data = corners.tobytes() + np.array([0, 1, 2], dtype="<u4").tobytes()
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "leaf", "mesh": 0, "translation": [1, 2, 3]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5125, "count": 3, "type": "SCALAR"}],
    }
    path = tmp_path / "leaf.gltf"
    path.write_text(json.dumps(gltf))
    np.testing.assert_allclose(fspm.read_points(str(path)), corners + [1, 2, 3], rtol=1e-12)


def test_simulated_scans_depend_only_on_the_seed():
    tree = fspm.Tree.from_arrays(
        parents=[-1, 0], starts=[[0, 0, 0], [0, 0, 1]], ends=[[0, 0, 1], [0.5, 0, 1.5]],
        radii=[0.1, 0.05])
    a = fspm.simulate_scan(tree, seed=3, density_per_m2=5000)
    b = fspm.simulate_scan(tree, seed=3, density_per_m2=5000)
    c = fspm.simulate_scan(tree, seed=4, density_per_m2=5000)
    assert a.shape[1] == 3 and a.shape[0] > 100
    np.testing.assert_array_equal(a, b)
    assert a.shape != c.shape or not np.array_equal(a, c)
    # Points lie on the cylinders' surfaces, up to the range noise (3 mm, 6 sigma).
    radial = np.hypot(a[:, 0], a[:, 1])
    trunk = a[a[:, 2] < 0.9]
    assert np.abs(np.hypot(trunk[:, 0], trunk[:, 1]) - 0.1).max() < 0.02
    assert radial.max() < 0.7


def test_decoding_textures_the_clusters_below_the_skeleton():
    tree = fspm.read_tree(str(ROOT / "examples" / "trees" / "open_a12.treeb"))
    model = fspm.encode_points(fspm.simulate_scan(tree, seed=3), f_s=0.9)
    assert len(model.clusters) > 0
    decoded = fspm.decode_clusters(model, branchlets=3, seed=2)
    n = len(model.skeleton)
    # The skeleton keeps its node ids; every textured cluster adds at least one patch.
    np.testing.assert_allclose(decoded.ends[:n], model.skeleton.ends)
    assert len(decoded) > n
    parents = decoded.parents
    assert all(0 <= parents[k] < k for k in range(n, len(decoded)))
    again = fspm.decode_clusters(model, branchlets=3, seed=2)
    np.testing.assert_array_equal(decoded.ends, again.ends)
    # Up to the scanned branch length; Pirk's rule alone stops short of it on this tree.
    scanned = sum(c["branch_length"] for c in model.clusters)
    assert scanned > 0

    def twig_length(t):
        lengths = np.linalg.norm(t.ends - t.starts, axis=1)
        return lengths[n:][np.asarray(t.kinds)[n:] == 0].sum()  # 0: internode

    pirk = fspm.decode_clusters(model, branchlets=3, seed=2, docking_only=True)
    assert twig_length(pirk) < twig_length(decoded)
    # Each cluster ends within half a patch of its length (patches are at most the species'
    # size): a few metres over the whole tree.
    assert 0.9 * scanned <= twig_length(decoded) <= 1.3 * scanned
    with pytest.raises(ValueError):
        fspm.decode_clusters(model, species="pinee")


def test_a_cylinder_measures_to_its_diameter_height_and_volume():
    m = fspm.measure_points(cylinder_points())
    assert m["tree_found"] and m["warnings"] == []
    # A bare trunk of radius 0.15 m and height 3 m: dbh 0.30 m, volume pi 0.15^2 3 = 0.212 m^3.
    assert m["dbh_m"] == pytest.approx(0.30, rel=0.03)
    assert m["height_m"] == pytest.approx(3.0, rel=0.02)
    assert m["woody_volume_m3"] == pytest.approx(np.pi * 0.15**2 * 3.0, rel=0.15)
    assert m["crown_base_m"] is None
    assert m["cylinders"].shape[1] == 12
    assert m["cylinders"][0, 8] == 0  # TreeQSM numbering: no parent for the first


def test_a_stray_return_is_left_out_as_fspm_encode_does():
    # One return 20 m beside a 3 m trunk: kept, it would widen the crown to about 10 m.
    stray = np.vstack([cylinder_points(), [[20.0, 0.0, 2.5]]])
    m = fspm.measure_points(stray)
    assert m["isolated_points"] == 1
    assert m["crown_width_m"] < 1.0
    assert any("isolated points" in w for w in m["warnings"])


def test_projected_coordinates_measure_the_same():
    near = fspm.measure_points(cylinder_points())
    far = fspm.measure_points(cylinder_points() + np.array([500000.0, 5800000.0, 300.0]))
    assert far["dbh_m"] == pytest.approx(near["dbh_m"], abs=1e-3)
    assert far["cylinders"][0, 0] == pytest.approx(near["cylinders"][0, 0] + 500000.0, abs=1e-3)


def test_las_files_are_read(tmp_path):
    # LAS 1.2, point format 0 (20-byte records), written from ASPRS LAS 1.4 R15 table 3.
    import struct
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24:26] = bytes([1, 2])
    struct.pack_into("<HI", header, 94, 227, 227)
    struct.pack_into("<BHI", header, 104, 0, 20, 2)
    struct.pack_into("<6d", header, 131, 0.01, 0.01, 0.01, 1000.0, 2000.0, 30.0)
    records = struct.pack("<3i8x", 1, 2, 3) + struct.pack("<3i8x", -100, 0, 250)
    path = tmp_path / "two.las"
    path.write_bytes(bytes(header) + records)
    assert fspm.read_points(str(path)) == pytest.approx(
        np.array([[1000.01, 2000.02, 30.03], [999.0, 2000.0, 32.5]]))


def test_pirk_split_keeps_a_shorter_main_skeleton():
    # Eq. 3.2 alone (fspm encode --pirk-split) stops on the trunk of a grown tree, where the
    # default follows the limbs: fewer main nodes, and more of the points in clusters.
    tree = fspm.read_tree(str(ROOT / "examples" / "trees" / "open_a12.treeb"))
    points = fspm.simulate_scan(tree, seed=1)
    default = fspm.encode_points(points)
    pirk = fspm.encode_points(points, pirk_split=True)
    assert len(pirk.skeleton) * 3 < len(default.skeleton)

    def clustered(model):
        return sum(c["point_count"] for c in model.clusters)

    assert clustered(pirk) > clustered(default)
    assert pirk.root_diameter == pytest.approx(default.root_diameter)
