"""The build of the Python package part_decomposition (metadata in pyproject.toml): the compiled core
is the CMake target part_decomposition_python, the same as -DPART_DECOMPOSITION_BUILD_PYTHON=ON
builds, for the Python that runs pip (sys.executable, a virtual environment's if pip is in one).

Offline on Debian 12:  pip install --no-build-isolation --no-index .
Environment: CMAKE_BUILD_PARALLEL_LEVEL (default 2 jobs), PART_DECOMPOSITION_CMAKE_ARGS (more
arguments for the CMake configuration, e.g. -DCGAL_DIR=...).
"""

import glob
import os
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
# pip builds in the source tree: its scratch goes to one ignored directory, apart from the
# build/ of the CMake instructions
BUILD_BASE = "build-pip"


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        found = re.search(r"project\(Part_decomposition\s+VERSION\s+([0-9.]+)", f.read())
    if not found:
        raise RuntimeError("no project(Part_decomposition VERSION ...) in CMakeLists.txt")
    return found.group(1)


def run(command):
    print(" ".join(shlex.quote(c) for c in command), flush=True)
    try:
        subprocess.run(command, check=True)
    except FileNotFoundError:
        sys.exit("part_decomposition needs CMake to build: apt-get install cmake (see README.md)")


class CMakeBuild(build_ext):
    """Builds the extension with CMake instead of setuptools' compiler calls."""

    def build_extension(self, ext):
        # kept between builds: a second pip install only recompiles what changed
        build_dir = os.path.join(os.path.abspath(self.build_temp), "cmake")
        configure = ["cmake", "-S", ROOT, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release",
                     "-DPART_DECOMPOSITION_BUILD_PYTHON=ON", "-DPART_DECOMPOSITION_BUILD_EXAMPLES=OFF",
                     "-DPART_DECOMPOSITION_BUILD_TESTS=OFF", "-DPART_DECOMPOSITION_BUILD_BENCHMARKS=OFF",
                     # one program links the package here: its module compiles the pipeline in less
                     # time than the compiled library's three files plus the module (same labels)
                     "-DPART_DECOMPOSITION_HEADER_ONLY=ON",
                     "-DPython3_EXECUTABLE=" + sys.executable]
        try:
            # the pybind11 of an isolated build (pyproject.toml's requires); else CMake finds Debian's
            import pybind11
            configure.append("-Dpybind11_DIR=" + pybind11.get_cmake_dir())
        except ImportError:
            pass
        configure += shlex.split(os.environ.get("PART_DECOMPOSITION_CMAKE_ARGS", ""))
        build = ["cmake", "--build", build_dir, "--target", "part_decomposition_python"]
        if not os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL"):
            build += ["--parallel", "2"]
        run(configure)
        run(build)
        built = glob.glob(os.path.join(build_dir, "python", "part_decomposition", "_core.*"))
        if len(built) != 1:
            raise RuntimeError("expected one compiled _core in %s, found %r" % (build_dir, built))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    ext_modules=[Extension("part_decomposition._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
)
