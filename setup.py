"""The build step of `pip install --no-build-isolation .` (metadata in pyproject.toml): the
extension clumpkit._core comes from the project's own CMake build, configured and built here
(the Debian packages of scripts/deps; nothing is downloaded). CLUMPKIT_BUILD_DIR picks the build
folder (default build/, so a tree already built by scripts/build only relinks)."""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        source = os.path.dirname(os.path.abspath(__file__))
        build = os.environ.get("CLUMPKIT_BUILD_DIR", os.path.join(source, "build"))
        subprocess.run(["cmake", "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                        "-DCLUMPKIT_PYTHON=ON", "-DPython3_EXECUTABLE=" + sys.executable],
                       check=True)
        subprocess.run(["cmake", "--build", build, "--target", "clumpkit_python", "-j",
                        str(os.cpu_count() or 2)], check=True)
        name = os.path.basename(self.get_ext_filename(ext.name))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(build, "python", "clumpkit", name), target)


setup(ext_modules=[Extension("clumpkit._core", sources=[])], cmdclass={"build_ext": CMakeBuild})
