"""ballscan: a ball's 3-D position and velocity from images of calibrated line-scan cameras.

The package follows the measurement chain (``docs/architecture.md``):
``geometry`` (camera, motion) -> ``model`` (silhouette, renderer) ->
``measure`` (images, detection, edges, flat field, shading) -> ``solve``
(initial guess, the paper's refinement, the fit, bounds) -> ``pipeline``
(the estimator, results, reports) -> ``stream`` (engine, sources, batch) ->
``lab`` (presets, simulation, experiments) -> ``cli``.
"""

__version__ = "0.1.0"
