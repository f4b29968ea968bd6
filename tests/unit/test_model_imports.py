"""Model validation starts without numpy, scipy or numba (spec/engine.md, "Speed").

Run in a fresh interpreter: the test session itself has imported them already.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

HEAVY = "{'numpy', 'scipy', 'numba'}"


def run(code: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_loading_a_model_imports_no_numeric_stack() -> None:
    code = (
        "import sys, rockcli.model.load as L; L.load_model('examples/altar.toml'); "
        f"assert not {HEAVY} & set(sys.modules), {HEAVY} & set(sys.modules)"
    )
    result = run(code)
    assert result.returncode == 0, result.stderr


def test_deriving_the_block_and_the_template_import_no_numeric_stack() -> None:
    code = (
        "import sys\n"
        "from rockcli.model.load import load_model\n"
        "from rockcli.model.derive import to_block, describe, solver_options\n"
        "from rockcli.model.template import render_template\n"
        "m = load_model('examples/facade.toml'); to_block(m); describe(m); solver_options(m)\n"
        "render_template('facade')\n"
        f"assert not {HEAVY} & set(sys.modules), {HEAVY} & set(sys.modules)\n"
    )
    result = run(code)
    assert result.returncode == 0, result.stderr
