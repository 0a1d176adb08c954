"""Where dualmech keeps files between runs: one private directory per user.

The directory is ``$DUALMECH_CACHE_DIR`` if set, else ``$XDG_CACHE_HOME/dualmech``, else
``~/.cache/dualmech``; ``DUALMECH_CACHE_DIR=off`` turns disk caching off.  It is created
private to the user (mode 0700).  What is read back from it must be trusted (generated modules
are imported, parser tables unpickled), so :func:`read_private` reads a file only when both
the file and its directory belong to the user and nobody else may write to them, and
:func:`write_atomic` writes to a temporary name and renames it, so that a concurrent process
never reads a half-written file.

Example
-------
>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp()) / "dualmech"
>>> write_atomic(folder, "note.bin", b"tables")
True
>>> read_private(folder / "note.bin")
b'tables'
>>> read_private(folder / "missing.bin") is None
True
"""
from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

__all__ = ["ENV", "cache_dir", "read_private", "write_atomic"]

#: environment variable naming the cache directory (``off`` turns disk caching off)
ENV = "DUALMECH_CACHE_DIR"


def cache_dir() -> Path | None:
    """Where files are kept between runs (``None`` when disk caching is off)."""
    env = os.environ.get(ENV, "").strip()
    if env.lower() in ("off", "0", "none", "false"):
        return None
    if env:
        return Path(env).expanduser()
    base = os.environ.get("XDG_CACHE_HOME", "").strip()
    return (Path(base) if base else Path.home() / ".cache") / "dualmech"


def _private(st: os.stat_result) -> bool:
    """Owned by this user and writable by nobody else (always true without POSIX owners)."""
    if not hasattr(os, "geteuid"):
        return True
    return st.st_uid == os.geteuid() and not st.st_mode & (stat.S_IWGRP | stat.S_IWOTH)


def read_private(path: Path, most: int = 1 << 24) -> bytes | None:
    """The bytes of ``path`` (at most ``most``), or ``None`` when it is missing, unreadable, a
    symbolic link, or when it or its directory may be written by another user."""
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0))
    except OSError:
        return None
    with os.fdopen(fd, "rb") as fh:
        try:
            if not (_private(os.fstat(fh.fileno())) and _private(os.stat(path.parent))):
                return None
            return fh.read(most)
        except OSError:
            return None


def write_atomic(folder: Path, name: str, data: bytes) -> bool:
    """Write ``data`` to ``folder/name`` through a temporary file and a rename; ``False``
    (nothing written) when the folder cannot be made private or written."""
    try:
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
        if not _private(os.stat(folder)):
            return False
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp_")
        try:
            with os.fdopen(fd, "wb") as fh:
                fh.write(data)
            os.replace(tmp, folder / name)
        except BaseException:
            try:
                os.unlink(tmp)
            except OSError:
                pass
            raise
        return True
    except OSError:
        return False
