"""Exit codes mean one thing each (issue 7, item 8): 0 done, 1 a verdict gate, 2 bad input,
3 an internal error (one line; the traceback only with ROCK_DEBUG=1), 130 on Ctrl-C, and a
closed pipe on standard output ends quietly with 0."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from click.testing import CliRunner

from rockcli.cli.main import EXIT_INTERNAL, EXIT_INTERRUPTED, cli
from tests.cli.conftest import PULSES, ROOT

ALTAR = str(ROOT / "examples" / "altar.toml")


def _raise(exc: BaseException):
    def boom(*args: object, **kwargs: object) -> None:
        raise exc

    return boom


def test_unexpected_exception_is_one_line_and_exit_3(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROCK_DEBUG", raising=False)
    monkeypatch.setattr("rockcli.analyses.kinematic.run_kinematic", _raise(ZeroDivisionError("x")))
    result = CliRunner().invoke(cli, ["kinematic", ALTAR])
    assert result.exit_code == EXIT_INTERNAL == 3
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith("internal error: ZeroDivisionError: x — please report it")
    assert "ROCK_DEBUG=1" in lines[0]
    assert "Traceback" not in result.stderr


def test_rock_debug_shows_the_traceback(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROCK_DEBUG", "1")
    monkeypatch.setattr("rockcli.analyses.kinematic.run_kinematic", _raise(ZeroDivisionError("x")))
    result = CliRunner().invoke(cli, ["kinematic", ALTAR])
    assert result.exit_code == EXIT_INTERNAL
    assert "Traceback" in result.stderr and "ZeroDivisionError" in result.stderr
    assert result.stderr.strip().splitlines()[-1].startswith("internal error:")


def test_ctrl_c_says_interrupted_and_exits_130(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("rockcli.analyses.kinematic.run_kinematic", _raise(KeyboardInterrupt()))
    result = CliRunner().invoke(cli, ["kinematic", ALTAR])
    assert result.exit_code == EXIT_INTERRUPTED == 130
    assert result.stderr.strip() == "interrupted"


def test_bad_input_is_still_exit_2(tmp_path) -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(tmp_path / "none.toml")])
    assert result.exit_code == 2
    assert result.stderr.startswith("error: ")


@pytest.mark.parametrize("fmt", ["table", "json"])
def test_closed_pipe_exits_0_without_noise(fmt: str) -> None:
    # `rock kinematic … | head -1`: the reader is gone before rock writes (closing our end of
    # the pipe first makes the EPIPE certain, not a race). Today: exit 1 (rich's and click's
    # own pipe handlers) and, for a late flush, Python's "Exception ignored" lines.
    with subprocess.Popen(
        [sys.executable, "-m", "rockcli", "kinematic", ALTAR, "--format", fmt],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        env={**os.environ, "ROCK_DEBUG": "1"},
    ) as proc:
        assert proc.stdout is not None and proc.stderr is not None
        proc.stdout.close()
        err = proc.stderr.read().decode()
        assert proc.wait(timeout=120) == 0, err
    assert err == ""


def _with_status(real, status: str):
    """Wrap a document builder so that its first run reports `status`."""

    def wrapped(*args: object, **kwargs: object):
        out = real(*args, **kwargs)
        doc = out[0] if isinstance(out, tuple) else out
        runs = doc["rocking"]["runs"] if "rocking" in doc else doc["runs"]
        runs[0]["status"] = status
        return out

    return wrapped


@pytest.mark.parametrize(
    ("command", "target"),
    [
        ("assess", "rockcli.terminal.assess.assessment_output_document"),
        ("compare", "rockcli.terminal.compare.comparison_output_document"),
    ],
)
def test_a_non_finite_run_prints_the_report_then_exits_3(
    monkeypatch: pytest.MonkeyPatch, command: str, target: str
) -> None:
    # A run whose integration produced NaN/inf ends with status "non-finite" (issue 7, item 3):
    # the report is shown (the other polarity may be informative), then exit 3 with one line.
    import importlib

    module, name = target.rsplit(".", 1)
    real = getattr(importlib.import_module(module), name)
    monkeypatch.setattr(target, _with_status(real, "non-finite"))
    result = CliRunner().invoke(cli, [command, ALTAR, "--record", str(PULSES[0])])
    assert result.exit_code == EXIT_INTERNAL, result.stderr
    assert "verdict" in result.stdout
    line = result.stderr.strip()
    assert line.startswith(
        "internal error: the rocking integration produced a non-finite state (polarity +1: "
    )
    assert line.endswith(
        "); the result above is not reliable — please report it to the rock maintainers"
    )


def test_the_cli_names_the_engines_non_finite_status() -> None:
    # cli/exits.py spells the status itself so that `rock --help` does not import the engine
    # (numpy); it must stay the engine's own value.
    from rockcli.cli.exits import NON_FINITE
    from rockcli.dynamics.result import RunStatus

    assert NON_FINITE == RunStatus.NONFINITE.value
