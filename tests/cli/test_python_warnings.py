"""A Python warning that reaches the command line is one clean line (issue 20, item 10).

On main, Python's own format reached stderr: ``/abs/path/file.py:67: UserWarning: Glyph 27
() missing from font(s) DejaVu Sans.`` and a second line quoting the source. rock avoids the
warnings it knows at their cause (tests/plots/test_control_characters.py,
tests/cli/test_extreme_forces_json.py); any other is shown as ``warning: TEXT (Category)``,
without a path (rockcli.cli.main.show_python_warning).

The command runs in a subprocess, with Python's default warning filters (pytest's make every
warning an error), started by a script in tmp_path that wraps `rock record info` so that it
overflows a numpy scalar: a real RuntimeWarning, located in a file with an absolute path.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from tests.cli.conftest import PULSES, ROOT

SCRIPT = """\
import sys

import numpy as np

from rockcli.cli import record
from rockcli.cli.main import cli

info = record.record.commands["info"]
original = info.callback


def overflowing(*args, **kwargs):
    np.float64(1e308) * 10.0  # RuntimeWarning: overflow encountered in scalar multiply
    return original(*args, **kwargs)


info.callback = overflowing
cli(sys.argv[1:], prog_name="rock")
"""


def test_a_python_warning_is_one_line_without_a_path(tmp_path: Path) -> None:
    script = tmp_path / "provoke.py"
    script.write_text(SCRIPT, encoding="utf-8")
    path = os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    done = subprocess.run(
        [sys.executable, str(script), "record", "info", str(PULSES[0])],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONPATH": path},  # this checkout's rockcli, not an installed one
    )
    assert done.returncode == 0, done.stderr
    assert done.stderr == "warning: overflow encountered in scalar multiply (RuntimeWarning)\n"
    assert str(tmp_path) not in done.stderr and "provoke.py" not in done.stderr
    assert "PGA" in done.stdout  # the command ran to its end


def test_the_warning_format_is_restored_after_the_command() -> None:
    import warnings

    from click.testing import CliRunner

    from rockcli.cli.main import cli

    before = warnings.showwarning
    result = CliRunner().invoke(cli, ["record", "info", str(PULSES[0])])
    assert result.exit_code == 0, result.output
    assert warnings.showwarning is before
