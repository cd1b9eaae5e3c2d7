"""The solver runs with the GIL released: another Python thread makes progress while a table
is computed; progress is reported on the calling thread; the result does not depend on the
number of worker threads; an exception from the progress callback stops the build."""

from __future__ import annotations

import _thread
import signal
import threading
import time

import polargen as pg
import pytest

GRID = dict(re=[5e5, 1e6, 2e6], mach=[0.0, 0.3], alpha="-4:10:0.5", xtr=1.0)


def test_another_thread_runs_while_a_table_is_computed():
    ticks = []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=ticker)
    thread.start()
    try:
        start = time.perf_counter()
        table = pg.table("naca2412", threads=1, **GRID)
        end = time.perf_counter()
    finally:
        stop.set()
        thread.join()
    inside = [t for t in ticks if start < t < end]
    assert end - start > 0.2, "the table should take long enough to measure"
    # With the GIL held for the whole call the ticker could not run at all.
    assert len(inside) > 50, f"{len(inside)} ticks in {end - start:.2f} s"
    assert table.converged_count > 0.9 * table.point_count


def test_progress_is_reported_on_the_calling_thread_and_threads_do_not_change_results():
    calls = []
    caller = threading.get_ident()
    one = pg.table("naca2412", threads=1, progress=lambda done, total: calls.append(
        (done, total, threading.get_ident())), **GRID)
    total = 3 * 2 * 29
    assert calls and calls[-1][:2] == (total, total)
    assert all(t == caller for _, _, t in calls)
    assert [c[0] for c in calls] == sorted(c[0] for c in calls)
    assert one == pg.table("naca2412", threads=2, **GRID)


class Bar:
    """A tqdm-like progress object."""

    def __init__(self):
        self.n, self.total = 0, None

    def update(self, n):
        self.n += n


def test_tqdm_like_progress_and_a_failing_callback():
    bar = Bar()
    pg.table("naca2412", re=[1e6], mach=[0.0, 0.2], alpha="0:4:1", progress=bar)
    assert bar.n == bar.total == 10

    def fail(done, total):
        raise RuntimeError("stop here")

    start = time.perf_counter()
    with pytest.raises(RuntimeError, match="stop here"):
        pg.table("naca2412", threads=1, progress=fail, **GRID)
    # Cancelled after the first polar rather than running all six.
    assert time.perf_counter() - start < 10


def test_ctrl_c_stops_a_table_after_the_polars_under_way():
    """A KeyboardInterrupt (raised from another thread as Ctrl-C would, once the build has
    reported its first points) stops the build: the rotor grid's 64 polars at 0.25° steps take
    about a minute on one thread, the interrupted build the time of the polar under way.

    Python installs its Ctrl-C handler only if SIGINT is not ignored when it starts, and a job
    a non-interactive shell starts with `&` has it ignored; there `interrupt_main` does nothing.
    The test installs Python's handler, as an interactive session has it."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        _interrupt_a_table()
    finally:
        signal.signal(signal.SIGINT, previous)


def _interrupt_a_table() -> None:
    running = threading.Event()
    interrupted_at = []

    def progress(done: int, total: int) -> None:
        if done > 0:
            running.set()

    def ctrl_c() -> None:
        if running.wait(60):
            interrupted_at.append(time.perf_counter())
            _thread.interrupt_main()

    threading.Thread(target=ctrl_c, daemon=True).start()
    with pytest.raises(KeyboardInterrupt):
        pg.table("naca2412", alpha="-10:20:0.25", threads=1, progress=progress)
    assert interrupted_at and time.perf_counter() - interrupted_at[0] < 10


def test_a_table_states_its_work_on_stderr_by_default_and_progress_lines_follow(capsys):
    pg.table("naca2412", re=[1e6], mach=[0.0, 0.2], alpha="0:4:1")
    err = capsys.readouterr().err
    assert err.startswith("polargen: 2 polars of NACA 2412: 10 points, under 1 s"), err
    pg.table("naca2412", re=[1e6], mach=[0.0], alpha="0:4:1", progress=None)
    assert capsys.readouterr().err == ""
    # The lines that follow the start line, at their interval (here every call).
    lines = pg.PlainProgress("grid", polars=1, threads=1, interval=0.0)
    for done in (0, 40, 80, 160):
        lines(done, 160)
    err = capsys.readouterr().err.splitlines()
    assert err[0] == "polargen: grid: 160 points, about 1 s", err
    assert err[1].startswith("polargen: 40/160 points, elapsed 0 s, about ") and err[1].endswith(" left")
    assert len(err) == 3, err
