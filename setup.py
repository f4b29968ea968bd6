"""Build hook: compile rock's numba kernels while the package is built, so that the first run
of an installed `rock` loads them instead of compiling them for 40 s with nothing on the screen.

The kernels are compiled by a subprocess on the built package (``build/lib``) into its
``rockcli/__pycache__/numba-<digest>`` folder, which the wheel then carries: the installed
package finds them there (rockcli/jitcache.py names the folder and the cache files after the
sources' content and their place in the package, not after where they are installed). The
compiled code is for this machine's processor and this numba version (numba's own key); on
another machine, or with another numba at run time, the kernels compile at their first run,
and `rock` says so on stderr. Everything else is in pyproject.toml.

Skipped for editable installs (they compile at their first run, as before) and when the
environment variable ROCK_NO_PRECOMPILE is set (e.g. to build a wheel for other machines).
"""

from __future__ import annotations

import os
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py

#: What the subprocess runs: compile every kernel and mark the cache complete.
COMPILE = (
    "from rockcli.kernels import compile_engine; "
    "print(f'rock: engine compiled into the package in {compile_engine():.0f} s')"
)


#: The validation casebook (examples/validation and the model its paper cases read) and where
#: the built package carries it, so that an installed `rock validate` and `rock report` run it.
CASEBOOK = (("examples/validation", "validation"), ("examples/altar.toml", "altar.toml"))
CASEBOOK_IN_PACKAGE = os.path.join("rockcli", "casebook", "bundled")


def copy_casebook(build_lib: str) -> None:
    """Copy the casebook's files into the built package (rockcli/casebook/bundled)."""
    import shutil

    here = os.path.dirname(os.path.abspath(__file__))
    target = os.path.join(build_lib, CASEBOOK_IN_PACKAGE)
    for source, name in CASEBOOK:
        origin = os.path.join(here, source)
        if os.path.isdir(origin):
            shutil.copytree(origin, os.path.join(target, name), dirs_exist_ok=True)
        elif os.path.isfile(origin):
            os.makedirs(target, exist_ok=True)
            shutil.copy2(origin, os.path.join(target, name))


class BuildWithKernels(build_py):
    """build_py, then the casebook copied in and the kernels compiled into the built package."""

    def run(self) -> None:
        super().run()
        if not getattr(self, "editable_mode", False):
            copy_casebook(self.build_lib)
        if getattr(self, "editable_mode", False) or os.environ.get("ROCK_NO_PRECOMPILE"):
            return
        lib = os.path.abspath(self.build_lib)
        env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
        env["PYTHONPATH"] = os.pathsep.join(p for p in (lib, env.get("PYTHONPATH")) if p)
        try:
            subprocess.run([sys.executable, "-c", COMPILE], env=env, cwd=lib, check=True)
        except (OSError, subprocess.CalledProcessError) as exc:
            print(
                f"rock: the engine was not compiled while building ({exc}); it compiles at "
                "its first run instead",
                file=sys.stderr,
            )


setup(cmdclass={"build_py": BuildWithKernels})
