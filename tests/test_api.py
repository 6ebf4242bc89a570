"""The package's front door: the README's Python example, ``estimate_image`` on arrays, paths and files, the version, a fast import."""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import ballscan
from ballscan.errors import ImageFileError
from ballscan.measure.images import as_line_image, load_image

ROOT = Path(__file__).resolve().parents[1]
SCENES = ROOT / "tests" / "data" / "scenes"


def _readme_example() -> str:
    text = (ROOT / "README.md").read_text()
    section = text[text.index("## Python API") :]
    return re.search(r"```python\n(.*?)```", section, re.S).group(1)


def test_the_readme_python_example_runs_as_written(capsys):
    exec(compile(_readme_example(), "README.md", "exec"), {})
    out = capsys.readouterr().out
    assert re.search(r"\d+\.\d\d ± \d+\.\d\d m/s, flags \[", out)


def test_every_exported_name_resolves():
    for name in ballscan.__all__:
        assert getattr(ballscan, name) is not None, name
    with pytest.raises(AttributeError, match="no attribute 'nope'"):
        ballscan.nope  # noqa: B018


def test_version_matches_the_installed_metadata():
    from importlib.metadata import version

    assert ballscan.__version__ == version("ballscan")
    out = subprocess.run([sys.executable, "-m", "ballscan", "--version"], capture_output=True, text=True, check=True).stdout
    assert out.strip() == f"ballscan {ballscan.__version__}"


def test_import_loads_neither_numba_nor_scipy():
    code = "import sys, ballscan; print(sorted(m for m in ('numba', 'scipy', 'matplotlib', 'numpy') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_the_package_is_typed():
    assert (Path(ballscan.__file__).parent / "py.typed").exists()


def _scene(name: str = "pub_tennis_serve"):
    png = SCENES / f"{name}.png"
    truth = json.loads((SCENES / f"{name}.truth.json").read_text())
    radius = (truth["balls"][0] if "balls" in truth else truth)["radius_m"]
    return png, SCENES / f"{name}.camera.toml", radius


def test_estimate_image_on_an_array_equals_the_files_result():
    png, cam, radius = _scene()
    from_file = ballscan.estimate_image(png, cam, radius)
    raw = load_image(png).data
    stored = raw.astype(np.uint16 if raw.max() > 255 else np.uint8)
    from_array = ballscan.estimate_image(stored, ballscan.load_camera(cam), radius)
    a, b = _without_times(from_file.to_dict()), _without_times(from_array.to_dict())
    assert (a.pop("image"), b.pop("image")) == (str(png), "<array>")
    assert a == b
    assert a["balls"], "the scene has a ball"


def _without_times(v):
    """``v`` without its run-time keys (``run_time_s``, ``time_*_s``), at any depth."""
    if isinstance(v, dict):
        return {k: _without_times(x) for k, x in v.items() if not (k == "run_time_s" or (k.startswith("time_") and k.endswith("_s")))}
    if isinstance(v, list):
        return [_without_times(x) for x in v]
    return v


def test_a_float_array_needs_its_bit_depth():
    data = np.full((4, 4), 100.0)
    with pytest.raises(ValueError, match="bits: give the bit depth of a float64 array"):
        as_line_image(data)
    img = as_line_image(data, bits=12)
    assert (img.bits, img.saturation_dn, img.source) == (12, 4095.0, "<array>")


@pytest.mark.parametrize(
    ("data", "bits", "match"),
    [
        (np.zeros(5), 8, "shape"),
        (np.zeros((1, 5)), 8, "at least 2 lines"),
        (np.array([[0.0, np.nan], [1.0, 2.0]]), 8, "NaN"),
        (np.array([[0.0, 300.0], [1.0, 2.0]]), 8, "outside 0..255"),
        (np.array([[0.0, -1.0], [1.0, 2.0]]), 8, "outside"),
        (np.array([["a", "b"], ["c", "d"]]), 8, "need integer or float"),
    ],
)
def test_a_bad_array_is_refused_naming_it(data, bits, match):
    with pytest.raises(ImageFileError, match=match) as info:
        as_line_image(data, bits=bits, source="mine")
    assert "mine" in str(info.value)


@pytest.mark.parametrize("bits", [0, 17, 8.0, True])
def test_bits_out_of_range_are_refused(bits):
    with pytest.raises(ValueError, match="bits"):
        as_line_image(np.zeros((3, 3), dtype=np.uint8), bits=bits)


def test_estimate_image_calls_the_warm_up_before_any_ball(monkeypatch):
    from ballscan.pipeline import estimate

    calls = []
    monkeypatch.setattr(estimate, "ensure_warm", lambda: calls.append(1))
    png, cam, radius = _scene()
    estimate.estimate_image(png, cam, radius)
    assert calls == [1]
