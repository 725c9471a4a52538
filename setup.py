"""`pip install .`: builds the `pdd` module with CMake, the pdd_python target only.

The metadata is in pyproject.toml; the version is read from CMakeLists.txt's
project(pdd VERSION ...), the one copy of the number. The C++ dependencies (CGAL, Boost,
oneTBB, muParser, pybind11-dev) come from the system: scripts/install-deps.sh. Offline, with
Debian's setuptools and numpy:

    python3 -m pip install --no-build-isolation .

CMAKE_BUILD_PARALLEL_LEVEL limits the compile jobs; CMAKE_ARGS adds configure arguments.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent

# Everything but the module: no programs, tests, examples, benchmarks, man pages or MPI.
CMAKE_OPTIONS = [
    "-DCMAKE_BUILD_TYPE=Release",
    "-DPDD_PYTHON=ON",
    "-DPDD_BUILD_DRIVERS=OFF",
    "-DPDD_BUILD_TESTS=OFF",
    "-DPDD_BUILD_EXAMPLES=OFF",
    "-DPDD_BUILD_BENCHMARKS=OFF",
    "-DPDD_MAN_PAGES=OFF",
    "-DPDD_WITH_MPI=OFF",
    "-DPDD_WERROR=OFF",
]


def project_version():
    """The version in CMakeLists.txt's project(pdd VERSION x.y.z)."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*pdd\s+VERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise RuntimeError("no project(pdd VERSION ...) in CMakeLists.txt")
    return match.group(1)


def configure_arguments():
    """CMake's configure arguments for this interpreter (and pip's pybind11, when there is one)."""
    args = CMAKE_OPTIONS + [f"-DPython_EXECUTABLE={sys.executable}"]
    if shutil.which("ninja"):
        args += ["-G", "Ninja"]
    try:  # a pybind11 from PyPI (build isolation); Debian's pybind11-dev is found without it
        import pybind11

        args.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
    except ImportError:
        pass
    return args + shlex.split(os.environ.get("CMAKE_ARGS", ""))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configures pdd in build_temp, builds pdd_python and copies the module where setuptools
    expects it."""

    def build_extension(self, ext):
        build = Path(self.build_temp).resolve() / "cmake"
        build.mkdir(parents=True, exist_ok=True)
        cmake(["-S", str(ROOT), "-B", str(build)] + configure_arguments())
        cmake(["--build", str(build), "--target", "pdd_python"])
        built = build / "python" / f"{ext.name}{sysconfig.get_config_var('EXT_SUFFIX')}"
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


def cmake(args):
    print("cmake " + " ".join(args), flush=True)
    subprocess.run(["cmake"] + args, check=True)


setup(
    version=project_version(),
    packages=[],
    py_modules=[],
    ext_modules=[CMakeExtension("pdd")],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build/pip"}},
    zip_safe=False,
)
