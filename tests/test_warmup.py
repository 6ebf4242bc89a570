"""Loading the compiled kernels: what the disk cache holds, the compile message, and the CLI's warm-up."""

from __future__ import annotations

import gc
import importlib.util
import subprocess
import sys
import textwrap

from ballscan import compiled
from ballscan.pipeline import warmup

KERNEL_SOURCE = textwrap.dedent(
    """
    from ballscan.compiled import jit

    @jit()
    def twice(x):
        return 2.0 * x

    @jit(inline="always")
    def _helper(x):
        return x

    def warm_up():
        twice(1.0)
    """
)


def _load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod
    spec.loader.exec_module(mod)
    return mod


def test_a_new_kernel_is_not_cached_until_compiled_and_then_is_in_a_new_process(tmp_path):
    src = tmp_path / "fresh_kernels.py"
    src.write_text(KERNEL_SOURCE)
    mod = _load(src, "fresh_kernels")
    kernels = compiled.KERNELS["fresh_kernels"]
    assert [k.py_func.__name__ for k in kernels] == ["twice"]  # the inline helper has no code of its own
    assert compiled.is_cached(mod.twice) is False
    done = warmup.warm_up(("fresh_kernels",), show=False)
    assert (done.kernels, done.compiled) == (1, 1)
    assert compiled.is_cached(mod.twice) is True
    code = f"import sys; sys.path.insert(0, {str(tmp_path)!r}); import fresh_kernels; from ballscan.compiled import is_cached; print(is_cached(fresh_kernels.twice))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "True"


def test_the_compile_message_names_the_cache_and_counts_the_modules(tmp_path, capsys):
    src = tmp_path / "shown_kernels.py"
    src.write_text(KERNEL_SOURCE)
    _load(src, "shown_kernels")
    warmup.warm_up(("shown_kernels",))  # show=None: shown because a kernel must compile
    err = capsys.readouterr().err
    assert "compiling 1 numerical kernels (first run after an install only" in err
    assert str(tmp_path) in err and "[1/1] shown_kernels" in err and "kernels ready" in err
    warmup.warm_up(("shown_kernels",))
    assert capsys.readouterr().err == ""  # nothing left to compile: silent


def test_the_estimators_kernels_load_silently_once_compiled(capsys):
    warmup.warm_up(show=False)  # compiled by now, whatever ran before
    capsys.readouterr()
    done = warmup.warm_up()
    assert done.kernels >= 40 and done.compiled == 0
    assert capsys.readouterr().err == ""
    warmup.ensure_warm()


def test_the_warm_up_command_reports_the_kernels_and_the_cache():
    res = subprocess.run([sys.executable, "-m", "ballscan", "warm-up"], capture_output=True, text=True, check=True)
    assert "kernels ready" in res.stdout and "cache:" in res.stdout


PAUSE_SOURCE = textwrap.dedent(
    """
    import gc
    from ballscan.compiled import jit

    SEEN = []

    @jit()
    def thrice(x):
        return 3.0 * x

    def warm_up():
        SEEN.append(gc.isenabled())
        thrice(1.0)
    """
)


def test_the_collector_pauses_while_cached_kernels_load_not_while_they_compile(tmp_path):
    src = tmp_path / "paused_kernels.py"
    src.write_text(PAUSE_SOURCE)
    mod = _load(src, "paused_kernels")
    assert gc.isenabled()
    assert warmup.warm_up(("paused_kernels",), show=False).compiled == 1
    code = (
        f"import sys; sys.path.insert(0, {str(tmp_path)!r}); import paused_kernels as m; "
        "from ballscan.pipeline import warmup; import gc; "
        "d = warmup.warm_up(('paused_kernels',), show=False); print(d.compiled, m.SEEN, gc.isenabled())"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split(maxsplit=1)
    assert mod.SEEN == [True]  # compiling: the collector ran
    assert out == ["0", "[False] True\n"]  # loaded from the cache: paused, then running again
    assert gc.isenabled()
