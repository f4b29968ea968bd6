"""rock's version (the package's, pyproject.toml's)."""

__version__ = "0.1.0"
