"""Grading under an OS-enforced wall-clock and memory ceiling: :class:`GradingPool`.

Every answer is graded in a worker process.  Before grading, the worker lowers its own
address-space limit (``RLIMIT_AS``) to its current size plus ``memory_mb``; the parent waits
``seconds`` for the verdict and otherwise kills the worker (``SIGKILL``) and starts a fresh
one.  On an idle machine that is ``seconds`` of wall time; on a loaded one, where a worker
may wait for a core, the answer is stopped once it has used ``seconds`` of CPU time or
``GRACE * seconds`` of wall time, whichever comes first.  An answer that overruns either ceiling gets an ``invalid`` grade whose
summary starts ``too costly to grade:`` and names the costliest sub-expression of the answer
where it can; other answers are unaffected.  Loading a problem (its models, sampled points and
feedback targets) happens in the worker before the clock starts and is cached there, so workers
stay warm.

:func:`grade_bounded` grades one answer the same way: in a forked child of this process when
the process is single-threaded (the problem is loaded here first, so repeated calls stay
warm and no interpreter is started), else through a shared pool.

Example
-------
>>> with GradingPool(1, seconds=5.0) as pool:
...     g = pool.grade("simple_pendulum", "a*theta'' + g*sin(theta) = 0")
>>> g.status
'right'
>>> grade_bounded("simple_pendulum", "a*theta'' - g*sin(theta) = 0", seconds=5.0).status
'wrong'
"""
from __future__ import annotations

import atexit
import os
import pickle
import queue
import select
import signal
import sys
import threading
import time
from dataclasses import replace

from dualmech.grade.parser import LIMITS, Limits
from dualmech.grade.result import Grade

__all__ = ["GradingPool", "grade_bounded", "too_costly", "LOAD_SECONDS", "GRACE"]

#: Wall-clock allowance for loading a problem into a worker (not counted against an answer).
LOAD_SECONDS = 300.0
#: On a loaded machine an answer may take up to GRACE times its ceiling in wall time, as long
#: as it has not used the ceiling in CPU time (see :func:`_wait`).
GRACE = 5.0

_PRELOAD = ["dualmech.grade.api", "dualmech.grade.cost"]


# -- inside a worker ------------------------------------------------------------------------
def _address_space() -> int | None:
    """Bytes of virtual memory this process maps now (Linux), else ``None``."""
    try:
        with open("/proc/self/statm") as fh:
            return int(fh.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError, AttributeError):
        return None


def _limit_memory(memory_mb: int):
    """Lower the soft ``RLIMIT_AS`` to the current size plus ``memory_mb``; return a restorer."""
    try:
        import resource
    except ImportError:   # not a POSIX system: the wall clock is the only ceiling
        return lambda: None
    base = _address_space()
    if base is None:
        return lambda: None
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    want = base + memory_mb * 2 ** 20
    if hard != resource.RLIM_INFINITY:
        want = min(want, hard)
    resource.setrlimit(resource.RLIMIT_AS, (want, hard))
    return lambda: resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _load(problem: str, quantity, about, limits: Limits, loaded: set):
    """The warm grader of ``problem``: models, points, feedback targets and what the
    ``quantity`` asked needs, built now (the printed answers only when it is one of them)."""
    from dualmech.grade.api import Grader
    # a spec with its own grader (the web app's per-student numbers, web/numbers.py)
    grader = problem.grader(limits) if hasattr(problem, "grader") else \
        Grader.of(problem, limits=limits)
    key = (problem, quantity, about, limits)
    if key not in loaded:
        from dualmech.grade.batch import warm_targets
        ctx = grader.context   # a problem whose models cannot be built fails here
        try:
            warm_targets(ctx)
            # the quantity's own targets (reference forms, feedback) are built lazily
            grader.grade("0", quantity, about)
        except Exception:
            pass
        from dualmech.grade.stored_contexts import save
        try:
            save(ctx)   # the next run of this problem starts from here (see .stored)
        except Exception:   # noqa: BLE001 - a cache that cannot be written changes nothing
            pass
        loaded.add(key)
    return grader


def _invalid(problem, quantity, answer, summary: str) -> Grade:
    shown = answer if isinstance(answer, str) else repr(answer)
    return Grade(str(problem), quantity or "auto", "", shown[:1000], "invalid", summary)


def _grade_here(grader, problem, answer, quantity, about, memory_mb) -> tuple[Grade, bool]:
    """Grade with the memory ceiling lowered for just this answer; ``(grade, healthy)``,
    ``healthy`` false when the ceiling was hit mid-computation (caches may then hold a
    half-built entry)."""
    restore = _limit_memory(memory_mb)
    try:
        result = grader.grade(answer, quantity, about)
    except MemoryError:
        result = None
    finally:
        restore()
    if result is None:
        return too_costly(problem, answer, quantity, f"more than {memory_mb} MB"), False
    return result, True


def _serve(conn) -> None:
    """A worker: load, say ``start``, grade under the ceiling, send the grade; repeat."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)   # the parent decides when workers stop
    loaded: set = set()
    while True:
        try:
            job = conn.recv()
        except (EOFError, OSError):
            return
        if job is None:
            return
        problem, answer, quantity, about, limits, memory_mb = job
        try:
            grader = _load(problem, quantity, about, limits, loaded)
        except Exception as exc:
            from dualmech.grade.parser import AnswerError
            text = str(exc) if isinstance(exc, AnswerError) else \
                f"could not load problem {problem!r}: {type(exc).__name__}: {exc}"
            conn.send(("done", _invalid(problem, quantity, answer, text)))
            continue
        conn.send(("start",))
        result, healthy = _grade_here(grader, problem, answer, quantity, about, memory_mb)
        conn.send(("done", result, healthy))
        if not healthy:
            return   # caches may hold a half-built entry: the parent starts a fresh worker


# -- naming the culprit -----------------------------------------------------------------------
def too_costly(problem, answer, quantity, ceiling: str, limits: Limits = LIMITS) -> Grade:
    """The ``invalid`` grade of an answer that overran ``ceiling`` (e.g. ``"1 s"``)."""
    culprit = ""
    try:
        from dualmech.grade.cost import costliest
        culprit = costliest(answer, limits)
    except Exception:   # naming the culprit is a courtesy; the verdict stands without it
        culprit = ""
    what = f"`{culprit}`" if culprit else "this answer"
    summary = (f"too costly to grade: {what} needs more than {ceiling} to evaluate; "
               "simplify it (smaller multiples of angles, lower powers, fewer nested "
               "functions) and submit again.")
    return _invalid(problem, quantity, answer, summary)


# -- the parent side --------------------------------------------------------------------------
def _context():
    """The start method of the workers: a forkserver where it can be started without the
    current directory on its ``sys.path`` (Python 3.11+), else ``spawn``.

    A worker must import the dualmech this process imported, never a ``dualmech/`` folder that
    happens to sit in the current directory (a source tree, with a plain install: every answer
    would be "invalid").  A spawned worker takes this process's ``sys.path`` before it imports
    anything; the forkserver (Python < 3.12) imports its preloaded modules with the current
    directory first on its path, so it is started in safe-path mode (see :func:`_forkserver`).
    """
    import multiprocessing   # here: one answer graded in a forked child needs no pool
    methods = multiprocessing.get_all_start_methods()
    if "forkserver" in methods and sys.version_info >= (3, 11):
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload(_PRELOAD)
        return ctx
    return multiprocessing.get_context("spawn")


_SAFE_PATH_LOCK = threading.Lock()


def _forkserver() -> None:
    """Start the forkserver, if it is not running, with ``PYTHONSAFEPATH=1`` (Python's ``-P``):
    no current directory on the server's ``sys.path`` when it imports :data:`_PRELOAD`, so the
    workers it forks hold the installed dualmech (an editable install's too: that is found
    through site-packages, not the current directory)."""
    from multiprocessing import forkserver
    with _SAFE_PATH_LOCK:
        before = os.environ.get("PYTHONSAFEPATH")
        os.environ["PYTHONSAFEPATH"] = "1"
        try:
            forkserver.ensure_running()
        finally:
            if before is None:
                del os.environ["PYTHONSAFEPATH"]
            else:
                os.environ["PYTHONSAFEPATH"] = before


class _Worker:
    """One worker process and the parent's end of its pipe."""

    def __init__(self, mp):
        if mp.get_start_method() == "forkserver":
            _forkserver()   # (again, if it died: a restart must not take the current directory)
        self.conn, child = mp.Pipe()
        self.proc = mp.Process(target=_serve, args=(child,), daemon=True,
                               name="dualmech-grader")
        self.proc.start()
        child.close()

    def kill(self) -> None:
        try:
            os.kill(self.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, TypeError, OSError):
            pass
        self.proc.join(5)
        self.conn.close()

    def stop(self) -> None:
        try:
            self.conn.send(None)
        except (OSError, ValueError):
            pass
        self.proc.join(2)
        if self.proc.is_alive():
            self.kill()
        else:
            self.conn.close()


class GradingPool:
    """Worker processes that grade answers under an OS-enforced wall-clock and memory ceiling.

    ``workers`` processes (default: every core) each grade one answer at a time; ``seconds``
    is the wall-clock ceiling per answer, ``memory_mb`` the memory it may use above the
    worker's size when it starts, ``limits`` the parser's bounds (its ``seconds``, the
    grader's own cooperative deadline, is lowered to stay inside the ceiling).
    """

    def __init__(self, workers: int | None = None, *, seconds: float = 1.0,
                 memory_mb: int = 256, limits: Limits = LIMITS):
        if seconds <= 0 or memory_mb <= 0:
            raise ValueError("seconds and memory_mb must be positive.")
        self.seconds = float(seconds)
        self.memory_mb = int(memory_mb)
        self.limits = replace(limits, seconds=min(limits.seconds, 0.8 * self.seconds))
        self.workers = max(1, workers or os.cpu_count() or 1)
        self._mp = _context()
        self._jobs: queue.SimpleQueue = queue.SimpleQueue()
        self._lock = threading.Lock()
        self._closed = False
        self._threads = [threading.Thread(target=self._dispatch, daemon=True,
                                          name=f"dualmech-grading-{i}")
                         for i in range(self.workers)]
        for t in self._threads:
            t.start()

    # public API
    def submit(self, problem: str, answer: str, quantity: str | None = None,
               about: str | None = None) -> concurrent.futures.Future:
        """Queue an answer; the future resolves to a :class:`~.result.Grade`, never raises.

        Thread-safe.
        """
        import concurrent.futures
        future: concurrent.futures.Future = concurrent.futures.Future()
        with self._lock:
            if self._closed:
                raise RuntimeError("this GradingPool is closed.")
            self._jobs.put((future, (problem, answer, quantity, about)))
        return future

    def grade(self, problem: str, answer: str, quantity: str | None = None,
              about: str | None = None) -> Grade:
        """Grade one answer and wait for the verdict."""
        return self.submit(problem, answer, quantity, about).result()

    def close(self) -> None:
        """Stop the workers once the queued answers are graded."""
        with self._lock:
            if self._closed:
                return
            self._closed = True
            for _ in self._threads:
                self._jobs.put(None)
        for t in self._threads:
            t.join()

    def __enter__(self) -> "GradingPool":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    # one thread per worker
    def _dispatch(self) -> None:
        worker = None
        try:
            while True:
                job = self._jobs.get()
                if job is None:
                    return
                future, args = job
                if not future.set_running_or_notify_cancel():
                    continue
                try:
                    worker, result = self._run(worker, *args)
                except BaseException as exc:  # the pool itself failed: still a Grade
                    worker = _discard(worker)
                    result = _invalid(args[0], args[2], args[1],
                                      f"could not grade this answer: the grading process "
                                      f"failed ({type(exc).__name__}: {exc}); try again.")
                future.set_result(result)
        finally:
            if worker is not None:
                worker.stop()

    def _run(self, worker, problem, answer, quantity, about):
        if worker is None or not worker.proc.is_alive():
            _discard(worker)
            worker = _Worker(self._mp)
        try:
            worker.conn.send((problem, answer, quantity, about, self.limits, self.memory_mb))
            message = _receive(worker, LOAD_SECONDS)
            if message is None:
                return _discard(worker), _invalid(problem, quantity, answer,
                                                  f"could not load problem {problem!r} "
                                                  f"within {LOAD_SECONDS:g} s.")
            if message[0] == "done":
                return worker, message[1]
            message = _receive(worker, self.seconds)
        except (OSError, EOFError, pickle.PickleError):
            message = None
        if message is None or message[0] != "done":
            return _discard(worker), too_costly(problem, answer, quantity,
                                                f"{self.seconds:g} s or {self.memory_mb} MB",
                                                self.limits)
        # a refusal by the cost model left the worker as it was: keep it warm
        healthy = message[2] if len(message) > 2 else True
        if not healthy or not worker.proc.is_alive():
            worker = _discard(worker)
        return worker, message[1]


def _cpu_seconds(pid: int) -> float | None:
    """CPU seconds (user + system) process ``pid`` has used (Linux), else ``None``."""
    try:
        with open(f"/proc/{pid}/stat") as fh:
            fields = fh.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, ValueError, IndexError, AttributeError):
        return None


def _wait(ready, pid: int, seconds: float) -> bool:
    """Wait until ``ready(timeout)`` is true; ``False`` once the answer has had ``seconds``.

    The ceiling is ``seconds`` of wall time on an idle machine.  On a loaded one, where a
    worker may wait for a core, the answer is stopped once it has used ``seconds`` of CPU
    time or :data:`GRACE` times ``seconds`` of wall time, whichever comes first, so that an
    ordinary answer is not called too costly because other work held the processor.
    """
    start, cpu0 = time.monotonic(), _cpu_seconds(pid)
    hard = start + GRACE * seconds
    deadline = start + seconds
    while True:
        now = time.monotonic()
        if ready(max(0.0, min(deadline, hard) - now)):
            return True
        now = time.monotonic()
        if now >= hard or cpu0 is None:
            return False
        cpu = _cpu_seconds(pid)
        if cpu is None or cpu - cpu0 >= seconds:
            return False
        deadline = now + max(0.01, seconds - (cpu - cpu0))


def _receive(worker: _Worker, seconds: float):
    """The worker's next message within ``seconds`` (see :func:`_wait`), else ``None`` (the
    caller kills the worker)."""
    try:
        if _wait(worker.conn.poll, worker.proc.pid, seconds):
            return worker.conn.recv()
    except (EOFError, OSError):
        return None
    return None


def _discard(worker) -> None:
    if worker is not None:
        worker.kill()
    return None


# -- one answer -------------------------------------------------------------------------------
_SHARED: dict = {}
_SHARED_LOCK = threading.Lock()


def _shared_pool(seconds: float, memory_mb: int) -> GradingPool:
    with _SHARED_LOCK:
        key = (seconds, memory_mb)
        if key not in _SHARED:
            _SHARED[key] = GradingPool(seconds=seconds, memory_mb=memory_mb)
            if len(_SHARED) == 1:
                atexit.register(_close_shared)
        return _SHARED[key]


def _close_shared() -> None:
    for pool in list(_SHARED.values()):
        pool.close()
    _SHARED.clear()


def grade_bounded(problem: str, answer: str, quantity: str | None = None, *,
                  about: str | None = None, seconds: float = 1.0,
                  memory_mb: int = 256) -> Grade:
    """Grade one answer under a ``seconds`` wall-clock and ``memory_mb`` memory ceiling.

    In a single-threaded process on a system with ``fork`` the problem is loaded here and the
    answer graded in a forked child; otherwise a shared :class:`GradingPool` grades it.
    """
    if hasattr(os, "fork") and threading.active_count() == 1 and sys.platform != "darwin":
        return _grade_forked(problem, answer, quantity, about, seconds, memory_mb)
    return _shared_pool(seconds, memory_mb).grade(problem, answer, quantity, about)


_LOADED: set = set()


def _grade_forked(problem, answer, quantity, about, seconds, memory_mb) -> Grade:
    limits = replace(LIMITS, seconds=min(LIMITS.seconds, 0.8 * seconds))
    try:
        grader = _load(problem, quantity, about, limits, _LOADED)
    except Exception as exc:
        from dualmech.grade.parser import AnswerError
        return _invalid(problem, quantity, answer, str(exc) if isinstance(exc, AnswerError)
                        else f"could not load problem {problem!r}: {type(exc).__name__}: {exc}")
    sys.stdout.flush()
    sys.stderr.flush()
    from dualmech.startup import freeze
    freeze()
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:   # the child: grade, write the pickled grade, leave without cleanup
        code = 0
        try:
            os.close(read)
            result, _ = _grade_here(grader, problem, answer, quantity, about, memory_mb)
            data = pickle.dumps(result)
            view = memoryview(data)
            while view:
                view = view[os.write(write, view):]
        except BaseException:
            code = 1
        finally:
            os._exit(code)
    os.close(write)
    chunks, end = [], True
    try:
        while True:
            if not _wait(lambda t: bool(select.select([read], [], [], t)[0]), pid, seconds):
                break
            chunk = os.read(read, 1 << 16)
            if not chunk:
                end = None
                break
            chunks.append(chunk)
    finally:
        os.close(read)
        if end is not None:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        os.waitpid(pid, 0)
    if end is None and chunks:
        try:
            return pickle.loads(b"".join(chunks))
        except Exception:
            pass
    return too_costly(problem, answer, quantity, f"{seconds:g} s or {memory_mb} MB", limits)
