# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Build of the Python package ssmd (pyproject.toml names setuptools as the
backend): the compiled module ssmd._ssmd is the CMake target
ssmd_python_module of this repository, built in Release for the interpreter
that runs the build.

The CMake build directory is kept between builds, so that a second
`pip install .` or `pip wheel .` of the same tree compiles nothing new:
by default build/temp.<platform>/cmake, or the directory named by the
environment variable SSMD_CMAKE_BUILD_DIR. That one may also be the
project's own build directory (scripts/install_python_package.sh does this):
an existing configuration is used as it is. CMAKE_ARGS adds arguments to a
new configuration; SSMD_JOBS (or CMAKE_BUILD_PARALLEL_LEVEL) sets the number
of compile jobs.
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


def project_version():
    """The version of project() in CMakeLists.txt, the package's one version source."""
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*Spectral_surface_mesh_deformation\s+VERSION\s+(\d+\.\d+\.\d+)", text)
    if not match:
        raise RuntimeError("no project(Spectral_surface_mesh_deformation VERSION x.y.z) in CMakeLists.txt")
    return match.group(1)


def cmake_cache_value(cache, name):
    for line in cache.read_text(encoding="utf-8", errors="replace").splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return None


class CMakeTarget(Extension):
    """An extension module that is a target of the project's CMake build."""

    def __init__(self, name, target, output):
        super().__init__(name, sources=[])
        self.target = target
        self.output = output   # the module's path in the build directory, without suffix


class build_cmake_ext(build_ext):
    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            raise RuntimeError("building ssmd needs CMake 3.16 or later (Debian: apt-get install cmake)")
        build_dir = Path(os.environ.get("SSMD_CMAKE_BUILD_DIR") or Path(self.build_temp) / "cmake").resolve()
        cache = build_dir / "CMakeCache.txt"
        if cache.exists():
            source = cmake_cache_value(cache, "CMAKE_HOME_DIRECTORY")
            if source is None or Path(source).resolve() != ROOT:
                raise RuntimeError("the CMake build directory %s belongs to the source tree %s, not to %s: "
                                   "unset SSMD_CMAKE_BUILD_DIR or name another directory"
                                   % (build_dir, source, ROOT))
        else:
            self.configure(cmake, build_dir)
        jobs = os.environ.get("SSMD_JOBS") or os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") \
            or str(self.parallel or os.cpu_count() or 1)
        self.announce("building %s in %s" % (ext.target, build_dir), level=2)
        if subprocess.call([cmake, "--build", str(build_dir), "--target", ext.target, "--parallel", jobs]) != 0:
            if not (build_dir / "python" / "CMakeFiles" / (ext.target + ".dir")).exists():
                raise RuntimeError("the CMake build in %s has no target %s: pybind11 was not found "
                                   "(Debian: apt-get install pybind11-dev), or the build is sanitized "
                                   "or configured with SSMD_BUILD_PYTHON=OFF" % (build_dir, ext.target))
            raise RuntimeError("building %s failed (see the messages above)" % ext.target)
        # The module's name carries the ABI of the interpreter it was built
        # for: a build directory configured for another Python has none.
        built = build_dir / (ext.output + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.exists():
            raise RuntimeError("%s was not built: the CMake build in %s is configured for another "
                               "Python (%s) than %s; unset SSMD_CMAKE_BUILD_DIR or name another directory"
                               % (built.name, build_dir, cmake_cache_value(cache, "PYTHON_EXECUTABLE"),
                                  sys.executable))
        destination = Path(self.get_ext_fullpath(ext.name))
        destination.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, destination)

    def configure(self, cmake, build_dir):
        arguments = [
            cmake, "-S", str(ROOT), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            "-DPYTHON_EXECUTABLE=" + sys.executable,
            "-DSSMD_BUILD_PYTHON=ON",
            # only the module: no tests, examples, benchmarks, tools or documentation
            "-DSSMD_BUILD_TESTS=OFF", "-DSSMD_BUILD_EXAMPLES=OFF", "-DSSMD_BUILD_BENCHMARKS=OFF",
            "-DSSMD_BUILD_TOOLS=OFF", "-DSSMD_BUILD_DOC=OFF", "-DSSMD_BUILD_FUZZERS=OFF",
        ]
        try:
            # pybind11 from the build environment (pip's isolated build);
            # otherwise CMake finds the system's (Debian: pybind11-dev).
            import pybind11
            arguments.append("-Dpybind11_DIR=" + pybind11.get_cmake_dir())
        except (ImportError, AttributeError):
            pass
        arguments += shlex.split(os.environ.get("CMAKE_ARGS", ""))
        build_dir.mkdir(parents=True, exist_ok=True)
        self.announce("configuring %s" % build_dir, level=2)
        if subprocess.call(arguments) != 0:
            raise RuntimeError("the CMake configuration failed: the C++ dependencies (CGAL, Eigen, Boost, "
                               "Spectra, pybind11) are listed in scripts/install_dependencies.sh")


# The metadata that setuptools writes next to setup.py goes into build/ too,
# out of the source tree.
(ROOT / "build").mkdir(exist_ok=True)

setup(
    version=project_version(),
    options={"egg_info": {"egg_base": "build"}},
    ext_modules=[CMakeTarget("ssmd._ssmd", "ssmd_python_module", "python/ssmd/_ssmd")],
    cmdclass={"build_ext": build_cmake_ext},
)
