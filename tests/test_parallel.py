"""Tests of ballscan.parallel: completion, the error policy, the warm-up hook, no worker left, Dask."""

from __future__ import annotations

import os
import time

import psutil
import pytest

from ballscan.errors import BallscanError
from ballscan.parallel import TaskExecutor, TaskResult, run_tasks

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


def _warm_up() -> None:
    _WARM["pid"] = os.getpid()
    _WARM["calls"] = _WARM.get("calls", 0) + 1


def _warm_state(x: int) -> tuple[int, int, int]:
    # slow enough that both workers of a 2-process pool get items
    time.sleep(0.05)
    return x, _WARM.get("pid", -1), _WARM.get("calls", 0)


def _children() -> list[psutil.Process]:
    return [p for p in psutil.Process().children(recursive=True) if p.is_running() and p.status() != psutil.STATUS_ZOMBIE]


@pytest.mark.parametrize("jobs", [1, 2])
def test_every_item_completes(jobs):
    out = list(run_tasks(_square, range(7), jobs=jobs))
    assert all(isinstance(r, TaskResult) and r.ok for r in out)
    assert sorted((r.item, r.value) for r in out) == [(i, i * i) for i in range(7)]


@pytest.mark.parametrize("jobs", [1, 2])
def test_a_failing_task_is_a_result_and_the_others_complete(jobs):
    out = {r.item: r for r in run_tasks(_fail_on_three, range(6), jobs=jobs)}
    assert sorted(out) == list(range(6))
    bad = out[3]
    assert not bad.ok and bad.value is None
    assert bad.error == "ValueError: three is not wanted"
    assert all(out[i].ok and out[i].value == i for i in (0, 1, 2, 4, 5))


def test_warm_up_runs_once_in_each_worker_process():
    out = [r.value for r in run_tasks(_warm_state, range(8), jobs=2, warm_up=_warm_up)]
    pids = {pid for _, pid, _ in out}
    assert -1 not in pids and os.getpid() not in pids
    # every task saw its own worker warmed up exactly once
    assert all(calls == 1 for _, _, calls in out)
    assert len(pids) <= 2


def test_warm_up_in_this_process_for_one_job():
    _WARM.clear()
    with TaskExecutor(1, warm_up=_warm_up) as ex:
        first = [r.value for r in ex.map(_warm_state, range(3))]
        second = [r.value for r in ex.map(_warm_state, range(2))]
    assert {pid for _, pid, _ in first + second} == {os.getpid()}
    assert _WARM["calls"] == 1
    _WARM.clear()


def test_no_worker_process_outlives_the_call():
    before = {p.pid for p in _children()}
    with TaskExecutor(2) as ex:
        assert sorted(r.value for r in ex.map(_square, range(4))) == [0, 1, 4, 9]
        assert len({p.pid for p in _children()} - before) >= 1
        # a second map reuses the same workers
        assert sorted(r.value for r in ex.map(_square, range(3))) == [0, 1, 4]
    assert {p.pid for p in _children()} - before == set()


def test_no_worker_process_outlives_an_error_in_the_loop():
    before = {p.pid for p in _children()}
    with pytest.raises(RuntimeError, match="stop"):
        for _ in run_tasks(_warm_state, range(20), jobs=2):
            raise RuntimeError("stop")
    assert {p.pid for p in _children()} - before == set()


@pytest.mark.parametrize("jobs", [1, 2])
def test_keyboard_interrupt_stops_everything(jobs):
    before = {p.pid for p in _children()}
    seen = []
    with pytest.raises(KeyboardInterrupt):
        for r in run_tasks(_interrupt_on_two, range(40), jobs=jobs):
            seen.append(r.item)
    assert 2 not in seen and len(seen) < 39
    assert {p.pid for p in _children()} - before == set()


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
