"""The real records' fixture of the CLI tests (skips when ../shared is absent)."""

from tests.cli.conftest import shared_records

__all__ = ["shared_records"]
