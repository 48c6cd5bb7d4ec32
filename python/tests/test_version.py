"""fspm.__version__ is the version of project(fspm VERSION ...) in CMakeLists.txt, the one the
command line prints and the packages carry."""
import pathlib
import re
import subprocess

import fspm
from conftest import ROOT


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(fspm\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", text).group(1)


def test_version_is_the_project_version():
    assert re.fullmatch(r"[0-9]+\.[0-9]+\.[0-9]+", fspm.__version__)
    assert fspm.__version__ == project_version()


def test_version_is_what_the_command_line_prints():
    # The module is imported from BUILD/python/fspm; the command line is BUILD/bin/fspm.
    exe = pathlib.Path(fspm.__file__).resolve().parents[2] / "bin" / "fspm"
    if not exe.exists():
        import pytest
        pytest.skip(f"no command line beside the module ({exe})")
    out = subprocess.run([str(exe), "--version"], capture_output=True, text=True, check=True)
    lines = out.stdout.strip().splitlines()
    assert lines[0] == f"fspm {fspm.__version__}"
    # Then the commit the build was configured from and the optional parts it has.
    assert re.fullmatch(r"commit ([0-9a-f]{12}|unknown)", lines[1])
    assert lines[2].startswith("features:")


def test_citation_names_the_project_version():
    lines = (ROOT / "CITATION.cff").read_text().splitlines()
    assert f"version: {project_version()}" in lines
