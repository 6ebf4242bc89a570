"""The command line's front: --version, bare ballscan, help without internals, presets with their radius, precision --json, a fast --help."""

from __future__ import annotations

import json
import re
import subprocess
import sys

from ballscan.cli.app import PRESET_HELP, main
from ballscan.lab.presets import PRESETS


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "ballscan", *args], capture_output=True, text=True)


def test_bare_ballscan_shows_the_overview_and_succeeds():
    res = _run()
    assert res.returncode == 0 and "Commands:" in res.stdout and "estimate" in res.stdout


def test_help_imports_no_estimator():
    code = "import sys; from ballscan.cli import main; main(['--help']); print(sorted(m for m in ('numba', 'scipy', 'matplotlib') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"


def test_help_shows_flags_as_flags_and_no_internals():
    for cmd in ("estimate", "batch", "watch", "simulate", "precision", "experiment"):
        text = _run(cmd, "--help").stdout
        assert "<bool>" not in text and "typer" not in text.lower(), cmd


def test_the_presets_help_names_every_preset_with_its_radius():
    named = dict(re.findall(r"([a-z-]+) \((?:R )?([0-9.]+) m\)", PRESET_HELP))
    assert set(named) == set(PRESETS)
    for name, preset in PRESETS.items():
        assert float(named[name]) == preset.motion.radius_m, name


def test_precision_json_gives_the_bound(tmp_path, capsys):
    from ballscan.geometry.camera import save_camera

    cam = PRESETS["tennis-serve"].camera
    path = tmp_path / "c.toml"
    save_camera(cam, path)
    args = ["precision", "--camera", str(path), "--radius", "0.0335", "--velocity", "44.5,3.9,-5.5", "--position", "0,-0.08,4.2"]
    assert main([*args, "--edge-noise", "0.05", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    (b,) = d["bounds"]
    assert b["method"] == "edges" and b["covariance"]["parameters"][0] == "t_c_s"
    assert b["velocity_sigma_mps"][0] < b["velocity_sigma_mps"][2]  # depth is the weak axis
    assert main([*args, "--edge-noise", "0.05"]) == 0
    assert f"{b['speed_sigma_mps']:12.3e}".strip() in capsys.readouterr().out
