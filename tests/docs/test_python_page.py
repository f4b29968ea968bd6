"""docs/python.md: its examples run, in order, from the repository's folder (the API's
documents are the command line's JSON: the page itself asserts it for `rock compare`), and
what it says a loop prints is what it prints."""

from __future__ import annotations

import contextlib
import io
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "python.md"


def test_the_pages_examples_run(monkeypatch: pytest.MonkeyPatch) -> None:
    text = PAGE.read_text(encoding="utf-8")
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) >= 4
    monkeypatch.chdir(ROOT)
    namespace: dict[str, object] = {}
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        for block in blocks:
            exec(compile(block, str(PAGE), "exec"), namespace)  # noqa: S102
    said = re.search(r"prints\n\n```\n(.*?)```", text, re.S)
    assert said is not None
    assert printed.getvalue().endswith(said[1])


def test_the_api_is_exported_lazily() -> None:
    """``import rockcli`` loads none of the analyses; each name of the API resolves."""
    import subprocess
    import sys

    code = "import sys, rockcli; print('rockcli.api' in sys.modules, 'numpy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=ROOT).stdout.split()  # fmt: skip
    assert out == ["False", "False"]
    import rockcli

    for name in rockcli.API:
        assert callable(getattr(rockcli, name)) and getattr(rockcli, name).__doc__
    with pytest.raises(AttributeError):
        rockcli.no_such_function  # noqa: B018
