"""rock's cached kernels load without numba's compile set-up (rockcli.jitcache.install_quick_load),
give the numbers of a normal load, and a function that is not cached still compiles after."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# In a fresh interpreter (the session's kernels are in the cache: tests/conftest.py):
# a rocking run, then whether numba's lowering registries were imported, then a new jitted
# function compiled and called in the same process.
SCRIPT = r"""
import json, sys
import numpy as np
from rockcli.kernels import warmup
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block
warmup()
block = Block(R=1.0, alpha=0.2, mass=1000.0, e=0.9)
t = np.arange(0.0, 2.0, 0.01)
run = simulate(block, t, 0.5 * np.sin(2 * np.pi * t), 0.01)
loaded_without_setup = "numba.np.arraymath" not in sys.modules
import numba
@numba.njit
def total(x):
    return np.sum(x * x)
print(json.dumps({"quick": loaded_without_setup, "max_ratio": float(run.max_ratio),
                  "compiled": float(total(np.arange(4.0)))}))
"""


def run(extra: str = "") -> dict[str, object]:
    out = subprocess.run(
        [sys.executable, "-c", extra + SCRIPT], capture_output=True, text=True, cwd=ROOT, check=True
    )
    return json.loads(out.stdout.splitlines()[-1])


def test_cached_kernels_load_without_the_compile_setup_and_compiling_still_works() -> None:
    quick = run()
    assert quick["quick"], "numba's lowering registries were loaded to run a cached kernel"
    # 0 + 1 + 4 + 9: numba compiled a new function after the quick load (its compiler sets
    # the target up itself).
    assert quick["compiled"] == 14.0


def test_the_quick_load_gives_the_numbers_of_numbas_own_load() -> None:
    # numba's own load_overload (with its refresh) put back before any kernel loads.
    own = run(
        "from rockcli import jitcache\n"
        "jitcache._quick_load_installed = True\n"  # never installed in this process
    )
    assert not own["quick"]
    assert own["max_ratio"] == run()["max_ratio"]  # bit for bit: the same machine code
