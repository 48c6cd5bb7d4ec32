"""Crowns from one photograph from Python (docs/crown.md), against the sphere a disc inflates to."""
import math

import numpy as np
import pytest

import fspm

pytestmark = pytest.mark.skipif(not hasattr(fspm, "reconstruct_crown"),
                                reason="fspm built without OpenImageIO")


def disc_pictures(tmp_path, radius_px=40, size=128):
    y, x = np.mgrid[0:size, 0:size]
    inside = np.hypot(x - (size - 1) / 2, y - (size - 1) / 2) <= radius_px
    photo = np.zeros((size, size, 3), np.uint8)
    photo[...] = (150, 190, 240)
    photo[inside] = (40, 90, 30)
    mask = np.zeros((size, size, 3), np.uint8)
    mask[inside] = 255
    fspm.write_image(photo, str(tmp_path / "photo.png"))
    fspm.write_image(mask, str(tmp_path / "mask.png"))
    return int(inside.any(axis=1).sum())


def test_a_disc_becomes_a_sphere(tmp_path):
    rows = disc_pictures(tmp_path)
    crown = fspm.reconstruct_crown(str(tmp_path / "photo.png"), str(tmp_path / "mask.png"),
                                   height_m=rows * 0.1, relief=0.0)
    assert crown.metres_per_pixel == pytest.approx(0.1)
    # The disc spans 80 pixels edge to edge, its silhouette placed on its border: a 4 m sphere.
    sphere = 4.0 / 3.0 * math.pi * 4.0 ** 3
    assert crown.volume_m3 == pytest.approx(sphere, rel=0.05)
    v = crown.vertices
    assert v.shape[1] == 3 and crown.triangles.max() < len(v)
    centre = np.array([0.0, 0.0, (v[:, 2].max() + v[:, 2].min()) / 2])
    r = np.linalg.norm(v - centre, axis=1)
    assert np.mean(np.abs(r - 4.0)) / 4.0 < 0.02
    assert set(crown.seconds) >= {"base_mesh", "relief", "texture_synthesis", "composition"}
    # The cubemaps as fspm crown writes them: the sphere's radius in every direction from its
    # centre, and the photograph's crown green.
    radius, color = crown.radius_cubemap, crown.color_cubemap
    n = radius.shape[0]
    assert radius.shape == (n, 6 * n, 1) and color.shape == (n, 6 * n, 3)
    assert np.allclose(crown.centre, centre, atol=0.1)
    assert np.mean(np.abs(radius - 4.0)) / 4.0 < 0.02
    mean = color.reshape(-1, 3).mean(axis=0)
    assert mean[1] > mean[0] and mean[1] > mean[2]


def test_mistakes_raise_builtin_exceptions(tmp_path):
    with pytest.raises(OSError):
        fspm.reconstruct_crown(str(tmp_path / "none.png"))
    disc_pictures(tmp_path)
    with pytest.raises(ValueError):
        fspm.reconstruct_crown(str(tmp_path / "photo.png"), height_m=-1.0)
