"""Builds the Python package genbsp with CMake, for pip.

The compiled module and the package's files are made by the CMake target
genbsp_python in a build folder (GENBSP_BUILD_DIR, default build/python-pip;
an existing configured build folder is reused as it is) and copied into the
wheel.  CMAKE_ARGS adds arguments to the configure step.
"""

import os
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(os.environ.get("GENBSP_BUILD_DIR", ROOT / "build" / "python-pip")).resolve()
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release", "-DGENBSP_BUILD_PYTHON=ON",
                 "-DGENBSP_BUILD_TESTS=OFF", "-DGENBSP_BUILD_BENCH=OFF", "-DGENBSP_BUILD_DOCS=OFF",
                 f"-DPython_EXECUTABLE={sys.executable}", *shlex.split(os.environ.get("CMAKE_ARGS", ""))],
                check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "genbsp_python", "-j", str(os.cpu_count() or 1)], check=True)
        target = Path(self.get_ext_fullpath(ext.name)).parent
        target.mkdir(parents=True, exist_ok=True)
        for f in (build / "python" / "genbsp").iterdir():
            shutil.copy2(f, target / f.name)


setup(packages=[], ext_modules=[Extension("genbsp._genbsp", sources=[])], cmdclass={"build_ext": CMakeBuild})
