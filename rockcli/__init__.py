"""rock: out-of-plane seismic assessment of masonry macro-elements.

From Python (docs/python.md)::

    import rockcli
    record = rockcli.read_record("records/ricker_Tp0.5s_0.5g.txt")
    result = rockcli.compare("examples/altar.toml", record)
    result.document  # what `rock compare … --format json` prints

The functions are imported on first use (PEP 562): ``import rockcli`` loads nothing heavy, and
the modules inside rock that read the version load none of them.
"""

from rockcli.version import __version__

#: The API (rockcli.api), by name.
API = ("Result", "assess", "compare", "kinematic", "load_model", "read_record")

__all__ = ["__version__", *API]


def __getattr__(name: str):  # PEP 562
    if name in API:
        from rockcli import api

        return getattr(api, name)
    raise AttributeError(f"module 'rockcli' has no attribute {name!r}")
