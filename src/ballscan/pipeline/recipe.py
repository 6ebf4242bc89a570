"""The estimator's strategy: which refinement, which passes, and their thresholds.

A :class:`Recipe` is everything :func:`ballscan.pipeline.estimate.estimate_image`
chooses on its own; ``Recipe()`` is the estimator's default.  It is frozen
and checked when it is built, so that a recipe handed to a stream engine or
to worker processes is valid before the first ball arrives.
:func:`load_recipe` reads one from a file (docs/geometry.md's recipe file,
or a result's ``recipe`` key).
"""

from __future__ import annotations

import difflib
import json
import math
import numbers
import tomllib
from dataclasses import dataclass, fields, is_dataclass, replace
from pathlib import Path
from typing import Any, Literal, Mapping, get_args

from ..errors import RecipeFileError
from ..inputs import read_small_text
from ..solve.settings import FitSettings

__all__ = ["METHODS", "SHADING_STARTS", "Method", "ShadingStart", "Recipe", "load_recipe"]

Method = Literal["fit", "paper"]
ShadingStart = Literal["guess", "loose_fit"]

METHODS: tuple[str, ...] = get_args(Method)
SHADING_STARTS: tuple[str, ...] = get_args(ShadingStart)

_BOOLS = ("shading", "pixels", "matched", "flat_field", "refined_background", "rig_refined_background", "refit_law", "limb_envelope", "defocus")
#: integer fields and their smallest allowed value
_INTS = {
    "flat_field_min_columns": 0,
    "long_ball_min_lines": 0,
    "spread_min_lines": 0,
    "background_guard_lines": 0,
    "background_guard_px": 0,
    "background_min_lines": 1,
}
#: non-negative real fields
_REALS = (
    "matched_max_gain_sigma", "matched_max_prnu", "uniform_max_light", "uniform_max_level_rel_sigma", "max_lateral_px", "background_window_sigma",
    "defocus_min_px", "defocus_min_sigmas",
)
_FITS = ("loose_fit", "pixel_fit", "spread_fit", "edge_fit")


@dataclass(frozen=True)
class Recipe:
    """How :func:`ballscan.pipeline.estimate.estimate_image` measures a ball.

    Attributes
    ----------
    method : {"fit", "paper"}
        ``"fit"``: sub-pixel edges fitted by weighted least squares with
        uncertainties; ``"paper"``: the paper's gradient-image matching with
        Powell's method.  The other fields concern ``"fit"`` only.
    shading : bool
        The fit's second, shading-aware pass: the edges measured again with
        the profile of the ball's fitted Lambertian shading, and fitted again.
    pixels : bool
        Fit the pixels of the ball's edge windows and ends in the final fit
        where the ball is uniform and its image does not move along the
        sensor during the exposure (untextured balls, continuous exposure).
    matched : bool
        Measure the narrow edges of uniform balls by fitting the shading
        model's profile to their windows (a flat-fielded sensor).
    flat_field : bool
        Where the ball's interior shows column-gain scatter (PRNU), the
        matched edges on the image with the measured gains divided out, on
        long balls.
    shading_start : {"guess", "loose_fit"}
        The motion the shading law and the limb model are built at: the
        key-point guess (a loose fit where the guess is degenerate), or
        always the loose fit of the model-free edges.
    level_samples : (int, int)
        Samples over the exposure and across the pixel's height of the
        ends' mean brightness (:meth:`ballscan.measure.shading.LimbProfile.line_levels`).
    refined_background : bool
        Measure every ball's edges on its columns' background measured away
        from the balls (:func:`ballscan.pipeline.background.refine_background`);
        otherwise only long balls' matched edges are.  On independent
        renders it removes most of ``vx``'s bias (the detector's level takes
        in a shaded ball's faint limb) and leaves the depth velocity's error
        as it is; off by default while the balls it changes beyond that
        (an overlapping pair's non-converged fit it reports, single balls
        of the tests) are open (docs/benchmarks.md).
    rig_refined_background : bool
        In a rig (:func:`ballscan.pipeline.rig.estimate_rig`), measure every
        camera on its refined background, as ``refined_background`` does,
        and a ball that fewer than two cameras' estimates can join (none,
        beside a known plane; among them none of a camera with a known
        clock) again as this recipe says (it keeps one
        camera's depth).  The joint fit's direction rests on each camera's
        measurement across its line of sight, which the detector's level
        biases in proportion to the noise; the single camera's depth
        velocity, which the refined level moves, is fixed there by the
        other camera or the plane (docs/benchmarks.md, "Rigs: each
        camera on the refined background", "A constraint beside one
        camera: its refined background").
    refit_law : bool
        On the window edges' path, fit the shading law and the limb model
        again at the fitted motion, and the motion once more from there.
    matched_max_gain_sigma : float
        Largest relative column-gain scatter of the ball's interior
        (:func:`ballscan.measure.flatfield.column_gains`) at which the sensor
        counts as flat-fielded and the matched edges are measured on the
        image as it is: beyond, their sigmas come out too small.
    matched_max_prnu : float
        Largest relative column-gain scatter of the ball's interior at which
        a uniform ball beyond ``matched_max_gain_sigma`` that the
        flat-fielded matched edges do not take (too short, too few columns,
        ``flat_field`` off, or the flat-fielded edges not found) takes
        matched edges on the image as it is, each edge's sigma widened by
        its pixel's unknown gain error (that scatter, repeated on every line
        whose edge sits in the pixel), and the final fit of the ends' and
        the spread lines' pixels with the column gains as nuisance
        parameters; a ball within 3 lines of another keeps its window edges.
        Beyond, and at 0 (the default), the window edges.  On uniform balls
        it trades the estimator's time (about 2x a ball) for accuracy
        (docs/benchmarks.md, "Uniform balls on a sensor whose column gains
        scatter").
    flat_field_min_columns : int
        Fewest measured columns for the flat-fielded matched edges: fewer
        columns give gains too uncertain to divide out.
    long_ball_min_lines : int
        Fewest lines with both edges for a ball's matched edges to be
        measured on its refined background, and for the flat-fielded
        matched edges: a column's gain or level error repeats on every line
        whose edge sits in it, so it matters on long balls; on short balls
        the window edges' sigmas are the honest ones.
    spread_min_lines : int
        Fewest lines with both edges for the spread-pixel final fit after
        matched edges: on fewer lines its speed errors exceed its sigmas.
    uniform_max_light : float
        Largest fitted directional light, as a fraction of the contrast, of
        a ball the pixel model (one brightness per end times the shading
        law) describes: the pixel fit's and the matched edges' condition.
    uniform_max_level_rel_sigma : float
        Largest relative scatter of the lines' brightness about the shading
        law for the same condition (texture or a steep limb biases the
        pixel model).
    max_lateral_px : float
        Largest motion of the ball's image along the sensor during the
        exposure (pixels) for the same condition: the pixel model takes each
        chord at one mean time of the exposure.
    background_guard_lines, background_guard_px : int
        The balls' neighbourhood left out of their columns' refined
        background: this many lines and pixels around each region's mask
        (its partly covered pixels fall below the detection threshold).
    background_min_lines : int
        Fewest remaining lines for a column's refined level; columns with
        fewer keep the detector's level.
    background_window_sigma : float
        Half-width, in noise sigmas, of the window about a column's level
        whose values the refined level averages (the detector's mode seeking).
    loose_fit : FitSettings
        The loose fit of the model-free edges that replaces a degenerate
        key-point guess as the shading pass's start: no outlier rounds and a
        coarse cost tolerance, as the shading model needs the motion only
        roughly.
    pixel_fit : FitSettings
        The final fit with ``pixels``; its ``pixels`` must be True.
    spread_fit : FitSettings
        The final fit after matched edges: the pixels of the ball's ends and
        of the lines whose edges spread over ``pixel_min_spread_px`` in place
        of their edges (sharp lines keep their matched edges).  Enough
        exposure nodes that the pixel coverage is smooth in the parameters,
        and windows wide enough that each end's free brightness is measured
        on the ball's interior.  Its ``pixels`` must be True.
    edge_fit : FitSettings
        The final fit of the edges (and end areas) where no pixel fit is used.
    limb_envelope : bool
        Leave out the model-free edges that lie inwards of the outer
        envelope of the ball's edges (dark texture at the limb,
        :func:`ballscan.solve.envelope.inward_edges`), found about a loose
        fit of them all.
    defocus : bool
        Where the camera file gives no ``defocus_px``, measure the lens's
        blur circle on the ball's sharp edges
        (:func:`ballscan.measure.defocus.estimate_defocus`) and let the
        shading pass's limb model carry it.
    defocus_min_px, defocus_min_sigmas : float
        A measured blur circle is taken only from this diameter (pixels)
        and this many of its scatter's sigmas on (``Defocus.noise_px``).
    """

    method: Method = "fit"
    shading: bool = True
    pixels: bool = False
    matched: bool = True
    flat_field: bool = True
    shading_start: ShadingStart = "guess"
    level_samples: tuple[int, int] = (3, 2)
    refined_background: bool = False
    rig_refined_background: bool = True
    refit_law: bool = False
    matched_max_gain_sigma: float = 0.0015
    matched_max_prnu: float = 0.0
    flat_field_min_columns: int = 64
    long_ball_min_lines: int = 250
    spread_min_lines: int = 20
    uniform_max_light: float = 0.05
    uniform_max_level_rel_sigma: float = 0.02
    max_lateral_px: float = 0.3
    background_guard_lines: int = 3
    background_guard_px: int = 3
    background_min_lines: int = 8
    background_window_sigma: float = 4.5
    loose_fit: FitSettings = FitSettings(max_reject_rounds=0, cost_tol=1e-3)
    pixel_fit: FitSettings = FitSettings(pixels=True)
    spread_fit: FitSettings = FitSettings(pixels=True, pixel_min_spread_px=0.3, pixel_nodes=32, pixel_window_px=20.0)
    edge_fit: FitSettings = FitSettings()
    limb_envelope: bool = True
    defocus: bool = True
    defocus_min_px: float = 1.0
    defocus_min_sigmas: float = 5.0

    def changes(self) -> dict:
        """The fields that differ from ``Recipe()`` (the results' ``recipe`` key: empty for the default)."""
        return changes(self, Recipe())

    @classmethod
    def from_changes(cls, values: Mapping[str, Any]) -> "Recipe":
        """The recipe that differs from ``Recipe()`` by ``values``, the inverse of :meth:`changes`.

        ``values`` has a recipe's field names as keys (a result's ``recipe``
        key, or a recipe file's table); a fit's settings (``loose_fit``,
        ``pixel_fit``, ``spread_fit``, ``edge_fit``) are a table of their
        own changes.  Lists stand for tuples.

        Raises
        ------
        ValueError
            Naming the first unknown field or value out of range.
        """
        default = cls()
        known = {f.name for f in fields(cls)}
        out: dict[str, Any] = {}
        for name, value in values.items():
            if name not in known:
                close = difflib.get_close_matches(str(name), sorted(known), n=1)
                hint = f"did you mean {close[0]!r}?" if close else "docs/geometry.md lists them"
                raise ValueError(f"{name}: not a recipe setting ({hint})")
            if name in _FITS:
                if not isinstance(value, Mapping):
                    raise ValueError(f"{name}: expected a table of FitSettings changes, got {value!r}")
                value = _replace_checked(getattr(default, name), value, name)
            out[name] = _tuples(value)
        return replace(default, **out)

    def __post_init__(self) -> None:
        def bad(name: str, why: str) -> ValueError:
            return ValueError(f"{name}: {why}, got {getattr(self, name)!r}")

        if self.method not in METHODS:
            raise bad("method", f"expected one of {METHODS}")
        if self.shading_start not in SHADING_STARTS:
            raise bad("shading_start", f"expected one of {SHADING_STARTS}")
        for name in _BOOLS:
            if not isinstance(getattr(self, name), bool):
                raise bad(name, "expected True or False")
        ls = self.level_samples
        if not isinstance(ls, (tuple, list)) or len(ls) != 2 or not all(_is_int(k) and k >= 1 for k in ls):
            raise bad("level_samples", "expected two positive integers")
        object.__setattr__(self, "level_samples", (int(ls[0]), int(ls[1])))
        for name, low in _INTS.items():
            v = getattr(self, name)
            if not (_is_int(v) and v >= low):
                raise bad(name, f"expected an integer >= {low}")
        for name in _REALS:
            v = getattr(self, name)
            if not (isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(v) and v >= 0):
                raise bad(name, "expected a finite number >= 0")
        if not self.background_window_sigma > 0:
            raise bad("background_window_sigma", "expected a positive number")
        for name in _FITS:
            if not isinstance(getattr(self, name), FitSettings):
                raise bad(name, "expected a FitSettings")
        for name in ("pixel_fit", "spread_fit"):
            if not getattr(self, name).pixels:
                raise bad(name, "expected FitSettings with pixels=True")


def changes(value, default) -> dict:
    """The fields of a frozen settings dataclass ``value`` that differ from ``default``, nested settings as their own changes (JSON-ready)."""
    out = {}
    for f in fields(value):
        a, b = getattr(value, f.name), getattr(default, f.name)
        if a == b:
            continue
        out[f.name] = changes(a, b) if is_dataclass(a) and is_dataclass(b) else (list(a) if isinstance(a, tuple) else a)
    return out


def _replace_checked(settings: FitSettings, values: Mapping[str, Any], where: str) -> FitSettings:
    """``settings`` with ``values`` changed; an unknown field is a ``ValueError`` naming ``where``."""
    known = {f.name for f in fields(settings)}
    for name in values:
        if name not in known:
            raise ValueError(f"{where}.{name}: not a FitSettings field")
    try:
        return replace(settings, **{k: _tuples(v) for k, v in values.items()})
    except ValueError as exc:
        raise ValueError(f"{where}.{str(exc).removeprefix('FitSettings.')}") from None


def _tuples(value: Any) -> Any:
    """Lists (TOML's and JSON's arrays) as the tuples a frozen settings class holds."""
    return tuple(_tuples(v) for v in value) if isinstance(value, list) else value


def load_recipe(path: str | Path) -> Recipe:
    """Read a recipe file: a TOML table, or JSON (a bare table, or a result file's ``recipe`` key).

    The keys are :class:`Recipe`'s fields that differ from the default, as
    the results' ``recipe`` key gives them (:meth:`Recipe.from_changes`);
    an empty file is the default recipe.  A result's ``recipe`` holds the
    differences from the defaults of the version that wrote it (its
    ``ballscan_version``): another version's defaults fill in the rest.

    Raises
    ------
    RecipeFileError
        With a one-line message naming the file: not found, unreadable,
        not valid TOML or JSON, an unknown setting or a value out of range.
    """
    path = Path(path)
    text = read_small_text(path, MAX_RECIPE_FILE_BYTES, "recipe", RecipeFileError)
    kind = "JSON" if path.suffix.lower() == ".json" else "TOML"
    try:
        table = json.loads(text) if kind == "JSON" else tomllib.loads(text)
    except RecursionError:
        raise RecipeFileError(str(path), "not a recipe file (arrays or tables nested too deeply to read)") from None
    except ValueError as exc:  # the decoders' errors, and integers beyond Python's digit limit
        raise RecipeFileError(str(path), f"not valid {kind} ({exc})") from None
    if kind == "JSON" and isinstance(table, dict) and "balls" in table:
        if "recipe" not in table:
            raise RecipeFileError(str(path), "a result without a 'recipe' key (a rig's result has none): give a recipe file")
        table = table["recipe"]
    if not isinstance(table, dict):
        raise RecipeFileError(str(path), f"expected a table of recipe settings, got {type(table).__name__}")
    try:
        return Recipe.from_changes(table)
    except (ValueError, TypeError) as exc:
        raise RecipeFileError(str(path), str(exc)) from None


#: the largest recipe file read (bytes): a recipe is a few dozen settings
MAX_RECIPE_FILE_BYTES = 1 << 20


def _is_int(v: object) -> bool:
    return isinstance(v, numbers.Integral) and not isinstance(v, bool)
