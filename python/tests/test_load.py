"""fspm.load: any input file as the data it holds, chosen by its extension or, without one, by its
first bytes. Expected values come from the files themselves, read here with plain Python (JSON,
struct, text lines), or from the files written by hand in the test."""
import json
import pathlib
import shutil
import struct

import numpy as np
import pytest

import fspm
from conftest import chain_tree

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


def las_point_count(path):
    """The point count of a LAS header (ASPRS LAS 1.4, table 3): the 64-bit count at byte 247 when
    set (version 1.4), else the legacy 32-bit count at byte 107."""
    data = pathlib.Path(path).read_bytes()
    assert data[:4] == b"LASF"
    legacy = struct.unpack_from("<I", data, 107)[0]
    minor = data[25]
    if minor >= 4:
        count = struct.unpack_from("<Q", data, 247)[0]
        if count:
            return count
    return legacy


def test_trees_of_every_format():
    newick = fspm.load(str(EXAMPLES / "trees/small.nwk"))
    assert isinstance(newick, fspm.Tree)
    # ((1,2)3,(4,(5,6)7)8)9: nine labelled nodes, one internode each.
    assert len(newick) == 9
    for name in ("open_a12.treeb", "growth_units.mtg"):
        tree = fspm.load(str(EXAMPLES / "trees" / name))
        assert isinstance(tree, fspm.Tree) and len(tree) > 0


def test_a_binary_tree_without_extension_is_told_by_its_magic(tmp_path):
    source = EXAMPLES / "trees/open_a12.treeb"
    assert source.read_bytes()[:8] == b"FSPMTREB"
    bare = tmp_path / "tree_without_extension"
    shutil.copy(source, bare)
    assert len(fspm.load(str(bare))) == len(fspm.load(str(source)))


def test_plants_scenes_and_lsystems():
    plant = fspm.load(str(EXAMPLES / "greenlab/jaeger_figure1.toml"))
    assert isinstance(plant, fspm.PlantParams)
    scene_path = EXAMPLES / "environment/wall_scene.json"
    scene = fspm.load(str(scene_path))
    assert isinstance(scene, fspm.Scene)
    walls = [o for o in json.loads(scene_path.read_text())["obstacles"] if o["type"] == "wall"]
    assert scene.boxes == len(walls) == 1 and scene.ground == 0.0
    tree = fspm.load(str(EXAMPLES / "lsystems/monopodial_tree.l"))
    assert isinstance(tree, fspm.Tree) and len(tree) > 0


def test_a_compressed_plant_round_trips(tmp_path):
    plant = fspm.greenlab_simulate(fspm.load(str(EXAMPLES / "greenlab/jaeger_figure1.toml")))
    path = tmp_path / "plant.ctree"
    plant.save(str(path))
    loaded = fspm.load(str(path))
    assert isinstance(loaded, fspm.CompressedPlant) and len(loaded) == len(plant)


def test_an_obj_mesh_has_a_fan_of_triangles_per_face():
    path = EXAMPLES / "trees/y_tubes.obj"
    expected = sum(len(line.split()) - 3 for line in path.read_text().splitlines()
                   if line.startswith("f "))
    mesh = fspm.load(str(path))
    assert isinstance(mesh, fspm.TriangleMesh)
    assert mesh.triangle_count() == expected


def test_las_point_sets():
    for path in sorted((EXAMPLES / "scans").glob("*.las")):
        points = fspm.load(str(path))
        assert isinstance(points, np.ndarray) and points.shape == (las_point_count(path), 3)


PLY_POINTS = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n" \
             "property float z\nend_header\n0 0 0\n1 0 0\n0 2 0.5\n"
PLY_FACE = PLY_POINTS.replace("end_header", "element face 1\nproperty list uchar int "
                              "vertex_indices\nend_header") + "3 0 1 2\n"


def test_ply_is_a_point_set_without_faces_and_a_mesh_with_them(tmp_path):
    points_path = tmp_path / "points.ply"
    points_path.write_text(PLY_POINTS)
    np.testing.assert_array_equal(fspm.load(str(points_path)), [[0, 0, 0], [1, 0, 0], [0, 2, 0.5]])
    mesh_path = tmp_path / "triangle.ply"
    mesh_path.write_text(PLY_FACE)
    mesh = fspm.load(str(mesh_path))
    assert isinstance(mesh, fspm.TriangleMesh)
    assert mesh.vertex_count == 3 and mesh.triangle_count() == 1
    # No extension: the "ply" line tells the kind.
    bare = tmp_path / "scan"
    bare.write_text(PLY_POINTS)
    assert fspm.load(str(bare)).shape == (3, 3)


def test_xyz_points_and_cluster_files(tmp_path):
    xyz = tmp_path / "points.xyz"
    xyz.write_text("0 0 0\n1 2 3\n")
    np.testing.assert_array_equal(fspm.load(str(xyz)), [[0, 0, 0], [1, 2, 3]])
    rng = np.random.default_rng(4)
    z = np.repeat(np.linspace(0.0, 3.0, 300), 48)
    phi = rng.uniform(0.0, 2.0 * np.pi, z.size)
    model = fspm.encode_points(np.column_stack([0.15 * np.cos(phi), 0.15 * np.sin(phi), z]))
    path = tmp_path / "trunk.clusters"
    fspm.write_clusters(model, str(path))
    loaded = fspm.load(str(path))
    assert isinstance(loaded, fspm.ClusterModel)
    assert len(loaded.skeleton) == len(model.skeleton)


def test_errors_are_the_built_in_exceptions(tmp_path):
    unknown = tmp_path / "notes.bin"
    unknown.write_text("nothing fspm reads")
    with pytest.raises(ValueError, match="expected .tree"):
        fspm.load(str(unknown))
    with pytest.raises(FileNotFoundError):
        fspm.load(str(tmp_path / "missing.bin"))
    with pytest.raises(FileNotFoundError):
        fspm.load(str(tmp_path / "missing.tree"))


@pytest.mark.skipif(not fspm.render_available(), reason="VTK reads .vtp and .pvd")
def test_meshes_and_growth_sequences_written_by_fspm(tmp_path):
    tree = chain_tree(4, 0.05)
    mesh = fspm.mesh_tree(tree)
    for name in ("tree.vtp", "tree.glb", "tree.ply"):
        fspm.write_mesh(mesh, str(tmp_path / name))
        loaded = fspm.load(str(tmp_path / name))
        assert isinstance(loaded, fspm.TriangleMesh), name
        assert loaded.triangle_count() == mesh.triangle_count(), name
    frames = fspm.write_pvd(tree, str(tmp_path / "growth.pvd"), ages=[1.0, 3.0])
    steps = fspm.load(str(tmp_path / "growth.pvd"))
    assert [t for t, _ in steps] == [1.0, 3.0]
    assert [m.triangle_count() for _, m in steps] == [f["triangles"] for f in frames]
