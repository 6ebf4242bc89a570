"""ballscan: a ball's 3-D position and velocity from images of calibrated line-scan cameras.

The small public API (``docs/architecture.md`` follows one image through
the stages behind it)::

    import ballscan

    camera = ballscan.load_camera("serve.camera.toml")
    report = ballscan.estimate_image("serve.png", camera, radius_m=0.0335)
    for ball in report.balls:
        print(ball.speed_mps, ball.speed_sigma_mps, ball.flags)

``estimate_image`` also takes a numpy array of the camera's digital numbers
(``bits=`` for a float or 12-bit array).  The names below load on first use,
so ``import ballscan`` stays fast.

The package follows the measurement chain: ``geometry`` (camera, motion) ->
``model`` (silhouette, renderer) -> ``measure`` (images, detection, edges,
flat field, shading) -> ``solve`` (initial guess, the paper's refinement,
the fit, bounds) -> ``pipeline`` (the estimator, results, reports) ->
``stream`` (engine, sources, batch) -> ``lab`` (presets, simulation,
experiments) -> ``cli``.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING

#: Public name -> the module that defines it.
_EXPORTS = {
    "LineScanCamera": "ballscan.geometry.camera",
    "load_camera": "ballscan.geometry.camera",
    "save_camera": "ballscan.geometry.camera",
    "BallMotion": "ballscan.geometry.motion",
    "LineImage": "ballscan.measure.images",
    "load_image": "ballscan.measure.images",
    "Recipe": "ballscan.pipeline.recipe",
    "estimate_image": "ballscan.pipeline.estimate",
    "BallEstimate": "ballscan.pipeline.results",
    "EstimateReport": "ballscan.pipeline.results",
    "plot_estimates": "ballscan.pipeline.plot",
    "warm_up": "ballscan.pipeline.warmup",
    "render": "ballscan.model.render",
    "Appearance": "ballscan.model.render",
    "SensorNoise": "ballscan.model.render",
    "get_preset": "ballscan.lab.presets",
    "edge_crlb": "ballscan.solve.precision",
    "pixel_crlb": "ballscan.solve.precision",
    "sensor_crlb": "ballscan.solve.precision",
    "image_crlb": "ballscan.solve.precision",
    "PrecisionBound": "ballscan.solve.precision",
    "BallscanError": "ballscan.errors",
}

__all__ = ["__version__", *sorted(_EXPORTS)]


def _version() -> str:
    """The installed distribution's version (importlib.metadata takes tens of milliseconds to import: read on first use)."""
    from importlib import metadata

    try:
        return metadata.version("ballscan")
    except metadata.PackageNotFoundError:  # run from a source tree without installing
        return "0+unknown"


def __getattr__(name: str):
    if name == "__version__":
        globals()["__version__"] = value = _version()
        return value
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'ballscan' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value  # later lookups skip this function
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS) | {"__version__"})


if TYPE_CHECKING:  # what static checkers and IDEs see
    __version__: str
    from .errors import BallscanError
    from .geometry.camera import LineScanCamera, load_camera, save_camera
    from .geometry.motion import BallMotion
    from .lab.presets import get_preset
    from .measure.images import LineImage, load_image
    from .model.render import Appearance, SensorNoise, render
    from .pipeline.estimate import estimate_image
    from .pipeline.plot import plot_estimates
    from .pipeline.recipe import Recipe
    from .pipeline.results import BallEstimate, EstimateReport
    from .pipeline.warmup import warm_up
    from .solve.precision import PrecisionBound, edge_crlb, image_crlb, pixel_crlb, sensor_crlb
