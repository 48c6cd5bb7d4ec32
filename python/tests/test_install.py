"""`pip install --no-build-isolation --no-deps .` into a fresh virtual environment: no download,
an importable module outside the source tree, and nothing left behind in the repository.

By default pip builds `_fspm` in the CMake build directory the tests import fspm from
(FSPM_CMAKE_BUILD_DIR, already built, so this is quick); FSPM_TEST_FULL_INSTALL=1 makes pip
configure and build everything from scratch in a temporary directory instead.
"""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import fspm
from conftest import ROOT

PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def tree_state():
    """Top-level entries, egg-info directories and untracked files of the repository."""
    entries = {p.name for p in ROOT.iterdir()}
    egg_info = {str(p) for p in ROOT.rglob("*.egg-info")}
    untracked = set()
    if shutil.which("git") and (ROOT / ".git").exists():
        out = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "--ignored",
                              "--", "python", "setup.py", "pyproject.toml"],
                             capture_output=True, text=True)
        untracked = {ln for ln in out.stdout.splitlines() if ln[:2] in ("??", "!!")}
        untracked = {ln for ln in untracked if "__pycache__" not in ln}
    return entries, egg_info, untracked


def test_pip_install_into_a_venv(tmp_path):
    venv = tmp_path / "venv"
    made = subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", "--without-pip",
                           str(venv)], capture_output=True, text=True)
    if made.returncode != 0:
        pytest.skip(f"python3 -m venv is not available: {made.stderr.strip()}")
    python = venv / "bin" / "python"
    if subprocess.run([str(python), "-m", "pip", "--version"], capture_output=True).returncode:
        pytest.skip("pip is not available (apt install python3-pip)")

    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PIP_INDEX_URL")}
    env["PIP_NO_INDEX"] = "1"  # a download would fail rather than happen
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    build_dir = pathlib.Path(fspm.__file__).resolve().parents[2]
    if (build_dir / "CMakeCache.txt").exists() and not os.environ.get("FSPM_TEST_FULL_INSTALL"):
        env["FSPM_CMAKE_BUILD_DIR"] = str(build_dir)
    before = tree_state()
    install = subprocess.run([str(python), "-m", "pip", "install", "--no-build-isolation",
                              "--no-deps", str(ROOT)], cwd=tmp_path, env=env,
                             capture_output=True, text=True)
    assert install.returncode == 0, install.stdout[-3000:] + install.stderr[-3000:]
    assert "Successfully installed fspm" in install.stdout

    check = (
        "import fspm, numpy as np\n"
        "print(fspm.__file__)\n"
        "light, _ = fspm.light(fspm.Scene(), np.zeros((3, 3)))\n"
        "assert (light == 1.0).all()\n"
        "t = fspm.parse_newick('(1,2)3;')\n"
        "assert fspm.distance(t, fspm.parse_newick('((1,2)4)3;'))['distance'] == 1.0\n"
    )
    run = subprocess.run([str(python), "-c", check], cwd=tmp_path, env=env, capture_output=True,
                         text=True)
    assert run.returncode == 0, run.stderr
    assert pathlib.Path(run.stdout.strip()).resolve().is_relative_to(venv.resolve())
    assert tree_state() == before  # no build/, *.egg-info or other leftovers in the tree
