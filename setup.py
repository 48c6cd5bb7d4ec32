"""Builds the fspm Python module with CMake and packages it (see pyproject.toml).

    pip install --no-build-isolation --no-deps .

CMake configures the repository in a temporary directory (Release, FSPM_WITH_PYTHON=ON, no tests,
benchmarks or command line) and builds only the extension `fspm._fspm`; nothing is written into
the source tree (setuptools' build/ and egg-info go to the same temporary directory). Environment:
  FSPM_CMAKE_ARGS       extra CMake arguments, e.g. "-DFSPM_WITH_VTK=OFF"
  FSPM_CMAKE_BUILD_DIR  an existing, configured build directory to build `_fspm` in instead
  FSPM_BUILD_JOBS       parallel compile jobs (default: the number of CPUs)
"""
import atexit
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
SCRATCH = Path(tempfile.mkdtemp(prefix="fspm-pip-"))
atexit.register(shutil.rmtree, SCRATCH, True)


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(fspm\s+VERSION\s+([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if shutil.which("cmake") is None:
            sys.exit("fspm: cmake is needed to build the module (apt install cmake)")
        jobs = os.environ.get("FSPM_BUILD_JOBS", str(os.cpu_count() or 1))
        build_dir = os.environ.get("FSPM_CMAKE_BUILD_DIR")
        if build_dir:
            build_dir = Path(build_dir).resolve()
            if not (build_dir / "CMakeCache.txt").exists():
                sys.exit(f"fspm: FSPM_CMAKE_BUILD_DIR={build_dir} is not a configured build")
        else:
            build_dir = SCRATCH / "cmake"
            configure = ["cmake", "-S", str(ROOT), "-B", str(build_dir),
                         "-DCMAKE_BUILD_TYPE=Release", "-DFSPM_WITH_PYTHON=ON",
                         "-DFSPM_BUILD_TESTS=OFF", "-DFSPM_BUILD_BENCH=OFF",
                         "-DFSPM_BUILD_CLI=OFF", f"-DPython_EXECUTABLE={sys.executable}"]
            if shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            configure += shlex.split(os.environ.get("FSPM_CMAKE_ARGS", ""))
            subprocess.run(configure, check=True)
            cache = (build_dir / "CMakeCache.txt").read_text()
            if re.search(r"^FSPM_WITH_PYTHON:BOOL=OFF", cache, re.M) or \
                    not (build_dir / "python").is_dir():
                sys.exit("fspm: CMake did not find Python 3 development files or pybind11 "
                         "(apt install python3-dev pybind11-dev)")
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_fspm", "-j", jobs],
                       check=True)
        built = glob.glob(str(build_dir / "python" / "fspm" / "_fspm*.so"))
        if len(built) != 1:
            sys.exit(f"fspm: expected one built _fspm module in {build_dir}/python/fspm")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)
        # OpenImageIO behind the module fspm loads on the first image it reads or writes
        # (fspm/image_codec.hpp): beside _fspm, where the loader looks.
        codec = build_dir / "lib" / "libfspm_image_codec.so"
        if codec.exists():
            shutil.copyfile(codec, target.parent / codec.name)


setup(
    name="fspm",
    version=project_version(),
    description="Functional-structural plant modelling: L-systems, GreenLab, light, plastic trees",
    packages=["fspm"],
    package_dir={"fspm": "python/fspm"},
    ext_modules=[Extension("fspm._fspm", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
    # Keep the source tree clean: setuptools' build directory and egg-info go to the scratch
    # directory removed at exit.
    options={"build": {"build_base": str(SCRATCH / "build")},
             "egg_info": {"egg_base": str(SCRATCH)}},
)
