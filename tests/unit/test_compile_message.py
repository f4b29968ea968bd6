"""The first run on a machine compiles the engine: `rock` says so on stderr, once, and keeps
stdout for its output; the compiled kernels are found again by content and place, wherever
the package is (rockcli.jitcache)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli import jitcache
from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
WALL = ROOT / "examples" / "wall.toml"
PULSE = ROOT / "records" / "one-sine_Tp1s_0.35g.txt"
MESSAGE = "compiling the rocking engine for this machine, once: ~45 s"


def test_the_message_goes_to_stderr_and_json_stays_clean(monkeypatch: pytest.MonkeyPatch) -> None:
    # As on a machine whose cache is empty: the kernels compile (here: load, they are cached)
    # at their first use, announced before and after on stderr.
    monkeypatch.setattr(jitcache, "_ready", False)
    monkeypatch.setattr(jitcache, "compiled", lambda: False)
    monkeypatch.setattr(jitcache, "mark_compiled", lambda seconds: None)
    monkeypatch.setattr(jitcache, "before_compile", jitcache.before_compile)
    monkeypatch.setattr(jitcache, "after_compile", jitcache.after_compile)
    result = CliRunner().invoke(
        cli, ["assess", str(WALL), "--record", str(PULSE), "--format", "json"]
    )
    assert result.exit_code == 0, result.stderr
    assert json.loads(result.stdout)["verdict"]
    lines = result.stderr.splitlines()
    assert lines[0] == MESSAGE
    assert lines[1].startswith("engine compiled in ") and "later runs start at once" in lines[1]


def test_no_message_when_the_cache_holds_the_engine(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(jitcache, "_ready", False)
    result = CliRunner().invoke(cli, ["assess", str(WALL), "--record", str(PULSE)])
    assert result.exit_code == 0 and "compiling" not in result.stderr


def test_the_marker_is_for_this_numba_and_processor(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(jitcache, "folder", lambda: tmp_path)
    assert not jitcache.compiled()
    jitcache.mark_compiled(12.3)
    assert jitcache.compiled()
    data = json.loads((tmp_path / jitcache.MARKER).read_text(encoding="utf-8"))
    data["machine"][1] = "another-cpu"
    (tmp_path / jitcache.MARKER).write_text(json.dumps(data), encoding="utf-8")
    assert not jitcache.compiled()


def test_cache_files_are_named_by_place_in_the_package() -> None:
    # numba's own locator would name the folder after the absolute path of the sources.
    from numba.core import config

    import rockcli.dynamics.kernel  # noqa: F401

    folder = Path(config.CACHE_DIR)
    assert any((folder / "rockcli_dynamics").glob("kernel.integrate-*.nbi"))
    assert any((folder / "rockcli_codecheck").glob("response_kernel.peak_response-*.nbi"))


@pytest.mark.slow
def test_first_run_with_an_empty_cache_says_it_compiles(tmp_path: Path) -> None:
    # The real thing, in a fresh process with an empty cache: the message once, then silence.
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)}
    args = [sys.executable, "-m", "rockcli", "assess", str(WALL), "--record", str(PULSE),
            "--format", "json"]  # fmt: skip
    first = subprocess.run(args, env=env, capture_output=True, text=True, timeout=900)
    assert first.returncode == 0, first.stderr[-2000:]
    assert first.stderr.splitlines()[0] == MESSAGE
    json.loads(first.stdout)
    assert any(tmp_path.rglob(jitcache.MARKER))
    second = subprocess.run(args, env=env, capture_output=True, text=True, timeout=900)
    assert second.returncode == 0 and second.stderr == ""


@pytest.mark.slow
def test_the_built_wheel_carries_the_compiled_engine(tmp_path: Path) -> None:
    # setup.py compiles the kernels into the built package; the wheel holds them, with the
    # marker, so that an installed rock starts without compiling on this machine. Built as
    # pip builds it for `pip install .` (an isolated environment with the build requirements).
    source = tmp_path / "src"
    for name in ("pyproject.toml", "setup.py", "README.md"):
        (source / name).parent.mkdir(parents=True, exist_ok=True)
        (source / name).write_bytes((ROOT / name).read_bytes())
    package_files = [
        p for p in (ROOT / "rockcli").rglob("*") if p.suffix in (".py", ".toml", ".j2")
    ]
    casebook = [*(ROOT / "examples" / "validation").rglob("*.toml"), ROOT / "examples/altar.toml"]
    for path in (*package_files, *casebook):
        if "__pycache__" in path.parts:
            continue
        target = source / path.relative_to(ROOT)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(path.read_bytes())
    env = {
        k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "ROCK_NO_PRECOMPILE")
    }
    done = subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", str(tmp_path / "dist"),
         str(source)],
        env=env, capture_output=True, text=True, timeout=1200,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr[-2000:]
    wheel = next((tmp_path / "dist").glob("rockcli-*.whl"))
    names = zipfile.ZipFile(wheel).namelist()
    cached = [n for n in names if n.startswith("rockcli/__pycache__/numba-")]
    assert any(n.endswith("/" + jitcache.MARKER) for n in cached)
    assert any("/rockcli_dynamics/kernel.integrate-" in n for n in cached)
    # The report's catalogues and templates, and the validation casebook with the model its
    # cases read (setup.py copies it in): an installed rock runs `validate` and `report`.
    for name in ("rockcli/document/messages/it.toml", "rockcli/document/templates/report.html.j2",
                 "rockcli/casebook/bundled/validation/paper.toml",
                 "rockcli/casebook/bundled/altar.toml"):  # fmt: skip
        assert name in names, name
