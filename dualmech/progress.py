"""Progress for long commands, and a standard output that survives a closed pipe.

:func:`progress` shows a bar on a terminal and, when standard error is *not* a terminal (a log
file, CI, ``2> log``), one plain line per item -- so a piped ``dualmech report`` is never silent
for half a minute.  :class:`GuardedStdout` makes ``dualmech ... | head -1`` finish its work (the
files it writes) and keep its exit status, discarding the output nobody reads any more.

Example
-------
>>> import io
>>> err = io.StringIO()
>>> for name in progress(["a", "b"], "checking", stream=err, label=str):
...     pass
>>> print(err.getvalue().strip())
checking 1/2: a
checking 2/2: b
checking: 2 problems done in 0.0 s
"""
from __future__ import annotations

import io
import os
import sys
import time
from typing import Callable, Iterable, Iterator, TypeVar

__all__ = ["progress", "GuardedStdout"]

T = TypeVar("T")


def is_tty(stream) -> bool:
    """Is ``stream`` a terminal (where a progress bar redraws in place)?  A pipe or a log file
    gets no bar: its carriage returns would pile up into one long line."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def progress(items: Iterable[T], what: str, *, unit: str = "problem",
             label: Callable[[T], str] | None = None, stream=None,
             quiet: bool = False) -> Iterator[T]:
    """``items``, reporting progress on ``stream`` (default ``sys.stderr``).

    A terminal gets a tqdm bar (when there are several items); anything else gets one line
    ``"<what> i/n: <label(item)>"`` per item as it starts, flushed at once.  One item, or
    ``quiet``, shows nothing.
    """
    items = list(items)
    stream = sys.stderr if stream is None else stream
    if quiet or len(items) < 2:
        yield from items
        return
    if is_tty(stream):
        from tqdm import tqdm
        yield from tqdm(items, desc=what, unit=unit, file=stream, leave=False)
        return
    start = time.perf_counter()
    n = len(items)
    for i, item in enumerate(items, 1):
        name = label(item) if label is not None else getattr(item, "name", str(item))
        print(f"{what} {i}/{n}: {name}", file=stream, flush=True)
        yield item
    print(f"{what}: {n} {unit}s done in {time.perf_counter() - start:.1f} s", file=stream,
          flush=True)


class GuardedStdout(io.TextIOBase):
    """A text stream over ``stream`` that, once the reader has gone (``BrokenPipeError``),
    sends the rest to ``os.devnull`` instead of raising; ``closed_early`` says it happened.

    The conventional handling of a closed pipe (the Python documentation's: point the file
    descriptor at ``/dev/null`` so that no flush raises again), kept inside the command so
    that it finishes and exits with its own status.
    """

    def __init__(self, stream):
        super().__init__()
        self._stream = stream
        self.closed_early = False

    def _discard(self) -> None:
        self.closed_early = True
        devnull = os.open(os.devnull, os.O_WRONLY)
        try:
            os.dup2(devnull, self._stream.fileno())
        finally:
            os.close(devnull)

    def write(self, text: str) -> int:
        if not self.closed_early:
            try:
                return self._stream.write(text)
            except BrokenPipeError:
                self._discard()
        return len(text)

    def flush(self) -> None:
        try:
            self._stream.flush()
        except BrokenPipeError:
            self._discard()
            try:
                self._stream.flush()
            except (BrokenPipeError, ValueError):
                pass

    def isatty(self) -> bool:
        return is_tty(self._stream)

    def fileno(self) -> int:
        return self._stream.fileno()

    @property
    def encoding(self):
        return getattr(self._stream, "encoding", "utf-8")

    def writable(self) -> bool:
        return True
