"""Tests of ballscan.parallel: completion, the error policy, the warm-up hook, no worker left, Dask."""

from __future__ import annotations

import gc
import json
import os
import subprocess
import sys
import time

import psutil
import pytest

from ballscan.errors import BallscanError, interrupt_behind
from ballscan.parallel import TaskExecutor, TaskResult, collector_paused, run_tasks

#: Set by the warm-up hook in the process it runs in.
_WARM: dict[str, int] = {}


def _square(x: int) -> int:
    return x * x


def _fail_on_three(x: int) -> int:
    if x == 3:
        raise ValueError("three is\nnot wanted")
    return x


def _interrupt_on_two(x: int) -> int:
    if x == 2:
        raise KeyboardInterrupt
    time.sleep(0.05)
    return x


def _interrupt_through_a_kernel_on_two(x: int) -> int:
    if x == 2:
        # what a compiled kernel's return raises when a signal handler raised
        # meanwhile: the handler's exception is the SystemError's cause
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as stop:
            raise SystemError("CPUDispatcher(<function kernel>) returned a result with an exception set") from stop
    return x


def _warm_up() -> None:
    _WARM["pid"] = os.getpid()
    _WARM["calls"] = _WARM.get("calls", 0) + 1


def _warm_state(x: int) -> tuple[int, int, int, int]:
    # slow enough that both workers of a 2-process pool get items
    time.sleep(0.05)
    return x, _WARM.get("pid", -1), _WARM.get("calls", 0), os.getpid()


def _pid(_: int) -> int:
    return os.getpid()


def _children() -> list[psutil.Process]:
    """This process's live descendants; one that exits while listed is none."""
    found = []
    for p in psutil.Process().children(recursive=True):
        try:
            if p.status() != psutil.STATUS_ZOMBIE:
                found.append(p)
        except psutil.NoSuchProcess:
            continue
    return found


@pytest.mark.parametrize("jobs", [1, 2])
def test_every_item_completes(jobs, cheap_workers):
    out = list(run_tasks(_square, range(7), jobs=jobs))
    assert all(isinstance(r, TaskResult) and r.ok for r in out)
    assert sorted((r.item, r.value) for r in out) == [(i, i * i) for i in range(7)]


@pytest.mark.parametrize("jobs", [1, 2])
def test_a_failing_task_is_a_result_and_the_others_complete(jobs, cheap_workers):
    out = {r.item: r for r in run_tasks(_fail_on_three, range(6), jobs=jobs)}
    assert sorted(out) == list(range(6))
    bad = out[3]
    assert not bad.ok and bad.value is None
    assert bad.error == "ValueError: three is not wanted"
    assert all(out[i].ok and out[i].value == i for i in (0, 1, 2, 4, 5))


@pytest.fixture
def cheap_workers(monkeypatch):
    """Worker start-up taken as free: the workers start after the first item whichever way they start (a suite may run threads, which rules out the fork)."""
    monkeypatch.setattr("ballscan.parallel.FORK_START_S", 0.0)
    monkeypatch.setattr("ballscan.parallel.SPAWN_START_S", 0.0)


def test_every_task_runs_warm_and_workers_share_the_work(cheap_workers):
    _WARM.clear()
    with TaskExecutor(2, warm_up=_warm_up) as ex:
        out = [r.value for r in ex.map(_warm_state, range(16))]
        method = ex.start_method
    # every task saw its process warmed up exactly once
    assert all(calls == 1 for _, _, calls, _ in out)
    assert len({pid for *_, pid in out} - {os.getpid()}) >= 1  # the work was shared with worker processes
    if method == "fork":
        # forked workers inherit this process's warm-up: it ran here, once
        assert {warm for _, warm, _, _ in out} == {os.getpid()}
    else:
        assert method == "loky"
    _WARM.clear()


def test_too_little_work_stays_in_this_process():
    before = {p.pid for p in _children()}
    with TaskExecutor(2) as ex:
        pids = [r.value for r in ex.map(_pid, range(20))]
        assert ex.start_method is None
        assert {p.pid for p in _children()} - before == set()
    assert set(pids) == {os.getpid()}


def test_warm_up_in_this_process_for_one_job():
    _WARM.clear()
    with TaskExecutor(1, warm_up=_warm_up) as ex:
        first = [r.value for r in ex.map(_warm_state, range(3))]
        second = [r.value for r in ex.map(_warm_state, range(2))]
    assert {pid for _, pid, _, _ in first + second} == {os.getpid()}
    assert _WARM["calls"] == 1
    _WARM.clear()


def test_no_worker_process_outlives_the_call(cheap_workers):
    before = {p.pid for p in _children()}
    with TaskExecutor(2) as ex:
        assert sorted(r.value[0] for r in ex.map(_warm_state, range(16))) == list(range(16))
        workers = {p.pid for p in _children()} - before
        assert len(workers) >= 1
        # a second map, however small, goes to the same workers
        assert {r.value for r in ex.map(_pid, range(3))} <= workers
    assert {p.pid for p in _children()} - before == set()


def test_no_worker_process_outlives_an_error_in_the_loop(cheap_workers):
    before = {p.pid for p in _children()}
    with pytest.raises(RuntimeError, match="stop"):
        for _ in run_tasks(_warm_state, range(20), jobs=2):
            raise RuntimeError("stop")
    assert {p.pid for p in _children()} - before == set()


@pytest.mark.parametrize("jobs", [1, 2])
def test_keyboard_interrupt_stops_everything(jobs, cheap_workers):
    before = {p.pid for p in _children()}
    seen = []
    with pytest.raises(KeyboardInterrupt):
        for r in run_tasks(_interrupt_on_two, range(40), jobs=jobs):
            seen.append(r.item)
    assert 2 not in seen and len(seen) < 39
    assert {p.pid for p in _children()} - before == set()


def test_an_interrupt_behind_an_error_stops_everything_instead_of_failing_the_item():
    seen = []
    with pytest.raises(KeyboardInterrupt):
        for r in run_tasks(_interrupt_through_a_kernel_on_two, range(10), jobs=1):
            seen.append(r.item)
    assert seen == [0, 1]


def test_interrupt_behind_follows_causes_and_contexts_and_stops_on_a_cycle():
    stop = KeyboardInterrupt()
    caused = SystemError("x")
    caused.__cause__ = stop
    assert interrupt_behind(caused) is stop
    outer = ValueError("y")
    outer.__context__ = caused
    assert interrupt_behind(outer) is stop
    a, b = ValueError("a"), ValueError("b")
    a.__context__, b.__context__ = b, a
    assert interrupt_behind(a) is None
    assert interrupt_behind(ValueError("plain")) is None


def test_jobs_is_validated():
    with pytest.raises(ValueError, match="jobs"):
        TaskExecutor(0)


def test_dask_local_cluster():
    distributed = pytest.importorskip("distributed")
    _WARM.clear()
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        out = {r.item: r for r in run_tasks(_fail_on_three, range(5), scheduler=cluster.scheduler_address, warm_up=_warm_up)}
    assert sorted(out) == list(range(5))
    assert out[3].error == "ValueError: three is not wanted"
    assert [out[i].value for i in (0, 1, 2, 4)] == [0, 1, 2, 4]
    # the in-process worker ran the hook once
    assert _WARM["calls"] == 1
    _WARM.clear()


def test_dask_unreachable_scheduler_is_one_line_error(monkeypatch):
    pytest.importorskip("distributed")
    monkeypatch.setattr("ballscan.parallel.DASK_CONNECT_TIMEOUT_S", 1.0)
    with pytest.raises(BallscanError, match="cannot connect"):
        list(run_tasks(_square, [1], scheduler="tcp://127.0.0.1:1"))


# ---------------------------------------------------------------- workers forked from a warm process
FORKED = r"""
import json, os, sys, time
import numpy, scipy.linalg  # their BLAS thread pools start here, at the parent's size
sys.path.insert(0, {tests!r})
import test_parallel as T
from ballscan.parallel import TaskExecutor

def state(x):
    from threadpoolctl import threadpool_info
    time.sleep(0.05)
    return T._WARM.get("pid", -1), T._WARM.get("calls", 0), os.getpid(), max(i["num_threads"] for i in threadpool_info())

with TaskExecutor(2, warm_up=T._warm_up) as ex:
    out = [r.value for r in ex.map(state, range(10))]
    print(json.dumps({{"method": ex.start_method, "parent": os.getpid(), "out": out}}), flush=True)
    if {hang}:
        list(ex.map(time.sleep, [30.0] * 4))
"""


def _forked(hang: bool) -> subprocess.Popen:
    code = FORKED.format(tests=os.path.dirname(__file__), hang=hang)
    return subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def test_forked_workers_start_warm_with_one_thread_and_end_with_the_block():
    p = _forked(hang=False)
    out, err = p.communicate(timeout=60)
    assert p.returncode == 0, err
    d = json.loads(out)
    assert d["method"] == "fork"
    assert {(warm, calls) for warm, calls, _, _ in d["out"]} == {(d["parent"], 1)}  # the warm-up ran once, in the parent
    assert len({pid for _, _, pid, _ in d["out"]} - {d["parent"]}) >= 1
    assert {n for _, _, pid, n in d["out"] if pid != d["parent"]} == {1}  # one BLAS/OpenMP thread in the workers


def test_forked_workers_end_when_their_parent_is_killed():
    p = _forked(hang=True)
    d = json.loads(p.stdout.readline())
    assert d["method"] == "fork"
    parent = psutil.Process(p.pid)
    t0 = time.monotonic()
    workers = []
    while time.monotonic() - t0 < 30 and len(workers) < 2:
        workers = parent.children()
        time.sleep(0.02)
    assert len(workers) == 2
    p.kill()
    p.communicate(timeout=60)
    assert psutil.wait_procs(workers, timeout=10.0)[1] == []  # PARENT_POLL_S, not the 30 s sleeps


# ---------------------------------------------------------------- the garbage collector
def _freeze_count(_: int) -> tuple[int, int]:
    time.sleep(0.02)
    return gc.get_freeze_count(), os.getpid()


def test_workers_keep_what_they_loaded_out_of_the_collector_and_this_process_does_not(cheap_workers):
    before = gc.get_freeze_count()
    with TaskExecutor(2, warm_up=_warm_up) as ex:
        out = [r.value for r in ex.map(_freeze_count, range(12))]
    assert gc.get_freeze_count() == before  # this process may be a user's: nothing frozen here
    in_workers = [n for n, pid in out if pid != os.getpid()]
    assert in_workers and all(n > 0 for n in in_workers)
    _WARM.clear()


@pytest.mark.parametrize("enabled", [True, False])
def test_the_collector_is_paused_within_the_block_and_restored_after(enabled):
    was = gc.isenabled()
    try:
        gc.enable() if enabled else gc.disable()
        with collector_paused():
            assert not gc.isenabled()
        assert gc.isenabled() == enabled
        with pytest.raises(ValueError), collector_paused():
            raise ValueError("out of the block")
        assert gc.isenabled() == enabled
    finally:
        gc.enable() if was else gc.disable()


# ---------------------------------------------------------------- memory reuse
REUSE = r"""
import resource, sys, numpy as np
from ballscan.parallel import reuse_freed_memory
ok = reuse_freed_memory() if sys.argv[1] == "1" else None
faults = []
for rep in range(4):
    f0 = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    arrays = [np.ones(1 << 18) for _ in range(20)]  # an image's working arrays: 20 x 2 MB
    del arrays
    faults.append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - f0)
print(ok, max(faults[1:]))
"""


@pytest.mark.skipif("glibc" not in " ".join(__import__("platform").libc_ver()), reason="glibc's allocator")
def test_the_next_images_arrays_reuse_freed_memory_instead_of_fresh_pages():
    def run(flag: str) -> tuple[str, int]:
        ok, faults = subprocess.run([sys.executable, "-c", REUSE, flag], capture_output=True, text=True, check=True).stdout.split()
        return ok, int(faults)

    ok, faults = run("1")
    assert ok == "True" and faults < 1000  # 40 MB kept: touched again without a fault
    ok, faults = run("0")
    assert ok == "None" and faults > 5000  # glibc's default: given back and zero-filled again (10 240 pages)


def test_before_workers_runs_here_once_before_they_start_and_not_without_them(cheap_workers):
    calls: list[int] = []
    before = {p.pid for p in _children()}
    with TaskExecutor(2, before_workers=lambda: calls.append(len({p.pid for p in _children()} - before))) as ex:
        assert sorted(r.value for r in ex.map(_square, range(8))) == [i * i for i in range(8)]
        list(ex.map(_square, range(4)))  # the same workers
    assert calls == [0]  # once, with no worker of this executor running yet
    calls.clear()
    with TaskExecutor(1, before_workers=lambda: calls.append(1)) as ex:
        list(ex.map(_square, range(8)))
    assert calls == []
