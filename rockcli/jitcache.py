"""Where numba caches rock's compiled kernels: a folder keyed on the kernels' own sources.

numba invalidates a cached function when *its* source file changes, not when a function it
compiles in from another file does: the kernel inlines the formulas of mechanics.py and
dynamics/motion.py, so an edit there would leave a stale kernel in the cache and give silently
wrong numbers (seen: doubling a spring moment in mechanics.py changed nothing). The cache
folder is therefore named after a digest of every source the kernels compile, so any edit
starts a fresh cache.

The folder is under ``$NUMBA_CACHE_DIR`` when set, else under the package's ``__pycache__``
when writable, else under the user's cache folder (``$XDG_CACHE_HOME`` or ``~/.cache``).
Each is probed by creating the folder and a file in it. When none is writable (a read-only
install with an unwritable home, the usual container), the cache goes to a private folder of
the temporary directory, ``rock-numba-<uid>-<digest>``; when even that fails, the kernels are
compiled without a cache (every process compiles them again). :data:`NOTE` then says so, for
the command line to show.
"""

from __future__ import annotations

import hashlib
import os
import stat
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

PACKAGE = Path(__file__).resolve().parent
#: Whether the kernels are compiled with numba's ``cache=True`` (set by :func:`configure`).
CACHE = True
#: One sentence for the user when the cache is not where it should be, else None.
NOTE: str | None = None
#: Permission bits of the temporary cache folder: the owner's only (numba's cache files are
#: pickles: a folder another user can write to could make this process load their code).
PRIVATE_MODE = 0o700
_configured = False
#: Every file whose code the compiled kernels contain.
KERNEL_SOURCES = (
    "mechanics.py",
    "dynamics/motion.py",
    "dynamics/layout.py",
    "dynamics/kernel.py",
    "codecheck/response_kernel.py",
)


def sources_digest() -> str:
    """A short digest of the kernels' sources."""
    from rockcli.version import __version__

    digest = hashlib.sha256(__version__.encode())
    for name in KERNEL_SOURCES:
        digest.update(name.encode())
        try:
            digest.update((PACKAGE / name).read_bytes())
        except OSError:  # an install without sources: the version alone keys the cache
            pass
    return digest.hexdigest()[:16]


def cache_base() -> Path:
    """The folder under which the keyed cache folder goes."""
    env = os.environ.get("NUMBA_CACHE_DIR")
    if env:
        return Path(env)
    local = PACKAGE / "__pycache__"
    try:
        local.mkdir(exist_ok=True)
        if os.access(local, os.W_OK):
            return local
    except OSError:
        pass
    user = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(user) / "rock"


def configure() -> bool:
    """Point numba's cache at a writable keyed folder; call before any ``njit(cache=CACHE)``.

    Returns :data:`CACHE`: False when no folder is writable and the kernels are compiled
    without a cache (then :data:`NOTE` says so). Idempotent: the probe runs once per process.
    """
    global CACHE, NOTE, _configured
    if _configured:
        return CACHE
    from numba.core import config

    digest = sources_digest()
    base = cache_base()
    folder = base / f"numba-{digest}"
    chosen: Path | None = folder if writable(folder) else None
    if chosen is not None and base == PACKAGE / "__pycache__":
        prune(base, keep=folder)
    if chosen is None:
        chosen = private_temp_folder(digest)
        NOTE = (
            f"the compiled-code cache folder {folder} is not writable: compiled code is cached "
            f"in {chosen} (set NUMBA_CACHE_DIR to a writable folder to keep it)"
            if chosen is not None
            else f"no writable folder for the compiled-code cache ({folder} nor the temporary "
            f"folder): the engine is compiled again in every run (set NUMBA_CACHE_DIR to a "
            f"writable folder)"
        )
    CACHE = chosen is not None
    if chosen is not None:
        config.CACHE_DIR = str(chosen)  # type: ignore[attr-defined]
        install_locator()
    _configured = True
    return CACHE


def folder() -> Path | None:
    """The cache folder in use (None: no cache, or not configured yet)."""
    from numba.core import config

    cache_dir = getattr(config, "CACHE_DIR", None)
    return Path(cache_dir) if CACHE and _configured and cache_dir else None


def install_locator() -> None:
    """Put :class:`PackageLocator` first among numba's cache locators (once)."""
    from numba.core import caching

    # CacheImpl since numba 0.61, _CacheImpl before: the list every cache implementation
    # shares (a class attribute of their base).
    impl = getattr(caching, "CacheImpl", None) or getattr(caching, "_CacheImpl")  # noqa: B009
    locator = package_locator()
    if locator not in impl._locator_classes:
        impl._locator_classes.insert(0, locator)
    install_quick_load()


_quick_load_installed = False


def install_quick_load() -> None:
    """Load rock's cached kernels without first setting numba up to compile (once).

    Before it loads any cached function, numba "refreshes" its CPU target: it imports and
    registers every lowering it has (numba.np.arraymath and the rest, and through numba's
    BLAS probe all of scipy.linalg), 0.6–0.75 s of every start measured on this machine
    (cProfile of ``rock assess``: ``BaseContext.refresh`` under ``Cache.load_overload``),
    although running machine code already compiled needs none of it. What running it needs is
    set up elsewhere: the C helpers, math functions and exception symbols when the target
    context is created (``BaseContext.__init__``, ``CPUContext.init``), and the runtime (NRT),
    which is initialised here. A kernel that is not in the cache is still compiled the usual
    way: numba's compiler refreshes the target itself before it compiles
    (``numba.core.compiler.CompilerBase.__init__``).

    Only caches located by :func:`package_locator` (rock's own files) take this path; where
    numba's internals differ from what this expects, numba's own load runs.
    """
    global _quick_load_installed
    if _quick_load_installed:
        return
    from numba.core import caching

    cache_class = getattr(caching, "Cache", None)
    original = getattr(cache_class, "load_overload", None)
    if cache_class is None or original is None:
        return
    locator = package_locator()

    def load_overload(self: Any, sig: Any, target_context: Any) -> Any:
        impl = getattr(self, "_impl", None)
        guard = getattr(self, "_guard_against_spurious_io_errors", None)
        if not isinstance(getattr(impl, "locator", None), locator) or guard is None:
            return original(self, sig, target_context)
        from numba.core.runtime import rtsys

        rtsys.initialize(target_context)
        with guard():
            return self._load_overload(sig, target_context)
        return None  # the guard swallowed an I/O error: numba compiles instead

    cache_class.load_overload = load_overload
    _quick_load_installed = True


_LOCATOR: type | None = None


def package_locator() -> type:
    """numba's cache locator for rock's own kernels: their cache files are named after the
    file's place in the package and stamped with a digest of its content, never with its
    absolute path or modification time.

    numba's own locators name the cache subfolder after the absolute folder of the source
    (a hash of ``…/site-packages/rockcli/dynamics``) and, before numba 0.61, stamp it with
    the file's modification time: a cache compiled while the package was built (setup.py)
    would then never match the installed files. Keyed on content and relative place, the
    cache compiled at build time is found by the installed package; a file edited anyway
    changes the folder (:func:`sources_digest`) and its own stamp.
    """
    global _LOCATOR
    if _LOCATOR is not None:
        return _LOCATOR
    from numba.core.caching import UserProvidedCacheLocator

    class PackageLocator(UserProvidedCacheLocator):
        """Cache files of rock's kernels: CACHE_DIR/rockcli_<subpackage>, content-stamped."""

        def __init__(self, py_func: object, py_file: str) -> None:
            super().__init__(py_func, py_file)
            from numba.core import config

            parts = Path(py_file).resolve().relative_to(PACKAGE.parent).parent.parts
            self._cache_path = os.path.join(getattr(config, "CACHE_DIR"), "_".join(parts))  # noqa: B009

        def get_source_stamp(self) -> str:
            return hashlib.sha256(Path(self._py_file).read_bytes()).hexdigest()

        @classmethod
        def from_function(cls, py_func: object, py_file: str) -> PackageLocator | None:
            try:
                Path(py_file).resolve().relative_to(PACKAGE)
            except (OSError, ValueError):
                return None  # not one of rock's files: numba's own locators
            return super().from_function(py_func, py_file)

    _LOCATOR = PackageLocator
    return PackageLocator


#: The file in the cache folder that says every kernel was compiled there, for which numba
#: and which processor (a cache of another machine is not used by numba).
MARKER = "compiled.json"


def machine_key() -> dict[str, object]:
    """What a compiled kernel is valid for: numba's version and the processor (numba's own
    key of a cached function: the target triple, CPU name and features)."""
    import numba
    from numba.core.registry import cpu_target

    return {
        "numba": numba.__version__,
        "machine": list(cpu_target.target_context.codegen().magic_tuple()),
    }


def compiled() -> bool:
    """True when the cache folder holds every kernel compiled for this numba and machine."""
    import json

    where = folder()
    if where is None:
        return False
    try:
        data = json.loads((where / MARKER).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(data, dict) and {k: data.get(k) for k in ("numba", "machine")} == (
        machine_key()
    )


def mark_compiled(seconds: float) -> None:
    """Record that every kernel is in the cache folder (and how long compiling took)."""
    import json

    where = folder()
    if where is None:
        return
    try:
        text = json.dumps({**machine_key(), "seconds": round(seconds, 1)})
        (where / MARKER).write_text(text, encoding="utf-8")
    except OSError:
        pass


def writable(folder: Path) -> bool:
    """True if `folder` exists or can be made, and a file can be written in it."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError:
        return False
    return True


def private_temp_folder(digest: str) -> Path | None:
    """``<tmp>/rock-numba-<uid>-<digest>``, made private to this user; None if impossible.

    An existing folder is used only if it is a real folder (not a link) owned by this user and
    writable by nobody else.
    """
    try:
        folder = Path(tempfile.gettempdir()) / f"rock-numba-{_user_id()}-{digest}"
        folder.mkdir(mode=PRIVATE_MODE, exist_ok=True)
        info = os.lstat(folder)
    except OSError:
        return None
    if not stat.S_ISDIR(info.st_mode):
        return None
    if hasattr(os, "getuid") and (
        info.st_uid != os.getuid() or info.st_mode & (stat.S_IWGRP | stat.S_IWOTH)
    ):
        return None
    return folder if writable(folder) else None


def _user_id() -> str:
    if hasattr(os, "getuid"):
        return str(os.getuid())
    import getpass

    try:
        return getpass.getuser()
    except (ImportError, KeyError, OSError):
        return "user"


def prune(base: Path, keep: Path) -> None:
    """Remove the package's caches of earlier sources (this install's own folder only)."""
    import shutil

    for old in base.glob("numba-*"):
        if old != keep:
            shutil.rmtree(old, ignore_errors=True)


#: Seconds every kernel takes to compile the first time, measured with an empty cache on the
#: 2-core development machine (`rock warmup`: 37–41 s; 44 s since the two-block chain's
#: specialisation of the step, against 37 s before it in the same session); what the
#: message announces.
COMPILE_ESTIMATE = 45
#: Called before the kernels compile, with COMPILE_ESTIMATE, and after, with the seconds it
#: took: the command line sets them to say so on stderr (the numeric core stays silent).
before_compile: Callable[[float], None] | None = None
after_compile: Callable[[float], None] | None = None
#: Compiles every kernel and returns the seconds it took: rockcli.kernels.warmup, registered
#: when rockcli.kernels is imported (the numeric packages do not import it: one-way imports).
compile_all: Callable[[], float] | None = None
_ready = False


def ensure_compiled() -> None:
    """Compile every kernel now, announced, unless the cache holds them for this machine.

    Called where a kernel is first used in a process (rockcli.dynamics.simulate and batch,
    rockcli.codecheck.response): without it numba compiles each kernel silently at its first
    call, for tens of seconds with nothing on the screen. Does nothing until rockcli.kernels
    has registered :data:`compile_all` (the command line and the study workers import it).
    """
    global _ready
    if _ready or compile_all is None:
        return
    _ready = True  # compile_all runs the kernels, which come back here
    if compiled():
        return
    if before_compile is not None:
        before_compile(COMPILE_ESTIMATE)
    seconds = compile_all()
    mark_compiled(seconds)
    if after_compile is not None:
        after_compile(seconds)
