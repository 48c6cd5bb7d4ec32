"""Tree meshes, mesh files and renders from Python, against the closed form of the tubes."""
import json
import math
import re
import struct

import numpy as np
import pytest

import fspm
from conftest import chain_tree, forked_tree


def tube(segments, sides):
    """A capped tube of `segments` segments and `sides` sides: (segments + 1) rings of sides + 1
    vertices (a seam) plus two caps of sides + 1; 2 * segments * sides wall triangles plus one
    fan of `sides` triangles per cap."""
    return (segments + 1) * (sides + 1) + 2 * (sides + 1), 2 * segments * sides + 2 * sides


def test_chain_mesh_matches_the_closed_form():
    # r = 0.01 m, edge 0.01 m: ceil(2 pi) = 7 sides.
    tree = chain_tree(3, 0.01)
    sides = math.ceil(2 * math.pi * 0.01 / 0.01)
    assert fspm.sides_for_radius(0.01) == sides == 7
    mesh = fspm.mesh_tree(tree)
    vertices, triangles = tube(3, sides)
    assert (mesh.vertex_count, mesh.triangle_count()) == (vertices, triangles)
    assert mesh.positions.shape == (vertices, 3) and mesh.positions.dtype == np.float32
    assert mesh.triangles.shape == (triangles, 3) and mesh.triangles.dtype == np.uint32
    assert mesh.triangles.max() == vertices - 1
    # Every wall vertex lies on the tube surface, 0.01 m from the z axis.
    radial = np.hypot(mesh.positions[:, 0], mesh.positions[:, 1])
    assert np.isclose(radial, 0.01, atol=1e-6).sum() >= 4 * sides
    np.testing.assert_allclose(np.linalg.norm(mesh.normals, axis=1), 1.0, atol=1e-5)
    # Coarser edges, fewer sides: ceil(2 pi 0.01 / 0.02) = 4.
    coarse = fspm.mesh_tree(tree, edge_length_m=0.02)
    assert coarse.triangle_count() == tube(3, 4)[1]
    no_caps = fspm.mesh_tree(tree, fspm.MeshOptions(caps=False))
    assert no_caps.triangle_count() == 2 * 3 * sides


def test_forked_tree_and_counts():
    tree = forked_tree()
    # Trunk r 0.05: ceil(31.4) = 32 clamped to max_sides 16; branches r 0.01: 7 sides.
    expected = tube(3, 16)[1] + 2 * tube(2, 7)[1]
    mesh = fspm.mesh_tree(tree)
    assert mesh.triangle_count() == mesh.triangle_count("bark") == expected
    assert mesh.triangle_count("leaf") == 0
    assert mesh.triangle_count("obstacle") == 0
    counts = fspm.count_mesh(tree)
    assert counts["triangles"] == expected and counts["tubes"] == 3
    assert counts["vertices"] == mesh.vertex_count
    assert fspm.mesh_tree(tree, max_sides=32).triangle_count() == (
        tube(3, 32)[1] + 2 * tube(2, 7)[1])
    assert set(mesh.attribute_names()) >= {"age", "birth_time", "order"}
    order = mesh.attribute("order")
    assert order.dtype == np.float32 and set(np.unique(order)) == {0.0, 1.0}


def test_leaf_clusters_become_foliage():
    # Grown trees keep their leaves as clusters (leaf nodes of length 0): with leaves=True each
    # is a cloud of 32 leaves (4 vertices, 2 triangles each) or a crown sphere of 8 x 12 cells
    # (9 * 13 vertices, 2 * 12 * 7 triangles).
    grown = fspm.grow_tree(fspm.GrowthParams(preset="A", years=5, seed=2))
    tree = grown.tree
    bare = fspm.mesh_tree(tree)
    cloud = fspm.mesh_tree(tree, leaves=True, foliage_seed=5)
    assert cloud.triangle_count("leaf") == 64 * grown.clusters > 0
    assert cloud.vertex_count == bare.vertex_count + 128 * grown.clusters
    assert fspm.count_mesh(tree, leaves=True)["clusters"] == grown.clusters
    np.testing.assert_array_equal(
        fspm.mesh_tree(tree, leaves=True, foliage_seed=5).positions, cloud.positions)
    volumes = fspm.mesh_tree(tree, leaves=True, foliage="volumes")
    assert volumes.triangle_count("crown") == 168 * grown.clusters
    assert volumes.vertex_count == bare.vertex_count + 117 * grown.clusters
    with pytest.raises(fspm.ParameterError, match="volumes"):
        fspm.MeshOptions(foliage="fog")


def test_mesh_options_validate_names_the_field():
    fspm.MeshOptions().validate()
    with pytest.raises(fspm.ParameterError, match="max_sides"):
        fspm.MeshOptions(min_sides=8, max_sides=4).validate()


def test_mesh_views_keep_the_mesh_alive():
    mesh = fspm.mesh_tree(chain_tree(2, 0.01))
    positions = mesh.positions
    assert not positions.flags.writeable
    assert positions.ctypes.data == mesh.positions.ctypes.data
    top = positions[:, 2].max()
    del mesh
    assert positions[:, 2].max() == top == pytest.approx(2.0)


def test_mesh_files(tmp_path):
    mesh = fspm.mesh_tree(forked_tree())
    v, t = mesh.vertex_count, mesh.triangle_count()
    fspm.write_obj(mesh, str(tmp_path / "t.obj"))
    lines = (tmp_path / "t.obj").read_text().splitlines()
    assert sum(ln.startswith("v ") for ln in lines) == v
    assert sum(ln.startswith("f ") for ln in lines) == t
    assert (tmp_path / "t.mtl").exists()
    mesh.write(str(tmp_path / "t.ply"))
    header = (tmp_path / "t.ply").read_bytes().split(b"end_header")[0].decode()
    assert f"element vertex {v}" in header and f"element face {t}" in header
    fspm.write_mesh(mesh, str(tmp_path / "t.vtp"))
    head = (tmp_path / "t.vtp").read_bytes().split(b"<AppendedData")[0].decode()
    points = re.search(r'NumberOfPoints="(\d+)"', head).group(1)
    polys = re.search(r'NumberOfPolys="(\d+)"', head).group(1)
    assert (int(points), int(polys)) == (v, t)
    fspm.write_glb(mesh, str(tmp_path / "t.glb"))
    data = (tmp_path / "t.glb").read_bytes()
    magic, version, length = struct.unpack_from("<4sII", data)
    assert (magic, version, length) == (b"glTF", 2, len(data))
    chunk_length, = struct.unpack_from("<I", data, 12)
    gltf = json.loads(data[20:20 + chunk_length])
    indices = sum(gltf["accessors"][p["indices"]]["count"]
                  for m in gltf["meshes"] for p in m["primitives"])
    assert indices == 3 * t
    frames = fspm.write_pvd(chain_tree(3, 0.01), str(tmp_path / "g.pvd"), ages=[0, 1, 2])
    assert [f["triangles"] for f in frames] == [tube(n, 7)[1] for n in (1, 2, 3)]


def test_mesh_errors(tmp_path):
    tree = chain_tree(2, 0.01)
    with pytest.raises(TypeError, match="unknown parameter 'edge'"):
        fspm.mesh_tree(tree, edge=0.1)
    with pytest.raises(fspm.ParameterError, match="junction mode 'glued'"):
        fspm.mesh_tree(tree, junctions="glued")
    with pytest.raises(fspm.ParameterError):
        fspm.mesh_tree(tree, edge_length_m=-1.0)
    mesh = fspm.mesh_tree(tree)
    with pytest.raises(fspm.ParameterError, match="light"):
        mesh.attribute("light")
    with pytest.raises(fspm.ParameterError):
        fspm.write_mesh(mesh, str(tmp_path / "t.xyz"))
    with pytest.raises(fspm.IoError):
        fspm.write_mesh(mesh, str(tmp_path / "no-such-dir" / "t.obj"))
    with pytest.raises(fspm.ParameterError, match="material"):
        mesh.triangle_count("wood")


@pytest.mark.skipif(not fspm.render_available(), reason="fspm built without VTK")
def test_render_to_array_and_png(tmp_path):
    tree = forked_tree()
    image = fspm.render(tree, tmp_path / "t.png", width=96, height=64, view="front")
    assert image.shape == (64, 96, 4) and image.dtype == np.uint8
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 10  # a picture, not a blank frame
    back = fspm.read_image(str(tmp_path / "t.png"))
    np.testing.assert_array_equal(back, image)
    coloured = fspm.render(fspm.mesh_tree(tree), width=96, height=64, color_by="order")
    assert not np.array_equal(coloured, image)
    with pytest.raises(fspm.ParameterError, match="light"):
        fspm.render(tree, width=32, height=32, color_by="light")
    with pytest.raises(fspm.ParameterError):
        fspm.render(tree, width=32, height=32, view="diagonal")


@pytest.mark.skipif(fspm.render_available(), reason="fspm built with VTK")
def test_render_without_vtk_says_so():
    with pytest.raises(fspm.ParameterError, match="without VTK"):
        fspm.render(forked_tree())
