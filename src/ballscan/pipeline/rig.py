"""A rig's images to joint estimates: each camera's own estimate, the balls matched across cameras by time, one motion fitted to all.

:func:`estimate_rig` runs :func:`ballscan.pipeline.estimate.estimate_image`
on every camera's image, matches each ball of the reference camera with
the other cameras' balls whose crossing time falls in a window about the
crossing its motion predicts for them (:func:`match_window_s`; each camera
measured on its refined background, and a ball that no joint fit takes
measured again on the detector's, :func:`_alone_reports`,
``Recipe.rig_refined_background``), starts the joint fit from the cameras' estimates combined by their
information (:func:`combined_start`) and fits one world motion to all their
edges (:func:`ballscan.solve.joint.fit_joint`).  A ball seen by one camera
only keeps that camera's estimate and is flagged ``single_camera``; a camera
that disagrees with the others (a wrong pose, a wrong clock) is named in
``inconsistent_cameras`` and the ball flagged ``inconsistent_camera``; a
joint motion no sports ball could have is flagged as one camera's would be
(``implausible_speed``, ``implausible_range``).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..geometry.camera import LineScanCamera
from ..measure.edges import EdgeMeasurements
from ..measure.shading import shade_profile
from ..geometry.rig import Rig, RigCamera, WorldMotion, camera_params, plane_crossing, viewing_plane, world_crossing
from ..solve.constraint import Constraint
from ..solve.derived import WORLD_COVARIANCE_PARAMETERS, derive, launch_angles, world_covariance
from ..solve.joint import STATE_NAMES, JointCamera, JointResult, fit_joint
from ..solve.settings import FitSettings
from .estimate import estimate_image
from .plausibility import PlausibilityLimits
from .recipe import Recipe
from .results import BallEstimate, EstimateReport, jsonable
from .stages import unknown_gain_sigma

__all__ = [
    "RIG_FLAGS",
    "RigBall",
    "RigReport",
    "check_lines",
    "combined_start",
    "estimate_rig",
    "gain_prior",
    "match_window_s",
    "measure_group",
    "own_block",
    "own_state",
    "predicted_crossing",
    "single_camera_rig",
]

#: Flags of a rig's ball (docs/geometry.md), beside the cameras' own.
RIG_FLAGS = ("single_camera", "inconsistent_camera", "not_converged", "degenerate", "implausible_speed", "implausible_range")


@dataclass(frozen=True)
class RigBall:
    """One ball of a rig: its world motion at the reference camera's crossing, with 1-sigma and covariance.

    Attributes
    ----------
    cameras : tuple of str
        The cameras whose measurements entered.
    motion : WorldMotion or None
        World frame, rig clock (``t_ref_s`` is the crossing); None where undetermined.
    covariance : ndarray (7, 7) or None
        Of ``(t_c, x, y, z, vx, vy, vz)``.
    flags : tuple of str
        :data:`RIG_FLAGS` words.
    estimates : dict
        Each camera's own :class:`BallEstimate` by name.
    joint : JointResult or None
        The joint fit (None for a ball measured by one camera alone, without a constraint).
    """

    cameras: tuple[str, ...]
    motion: WorldMotion | None
    covariance: np.ndarray | None
    flags: tuple[str, ...] = ()
    estimates: dict[str, BallEstimate] = field(default_factory=dict, compare=False, repr=False)
    joint: JointResult | None = field(default=None, compare=False, repr=False)

    @property
    def sigmas(self) -> np.ndarray:
        return np.full(7, np.nan) if self.covariance is None else np.sqrt(np.abs(np.diag(self.covariance)))

    @property
    def t_c_s(self) -> float:
        return math.nan if self.motion is None else self.motion.t_ref_s

    @property
    def undetermined(self) -> tuple[str, ...]:
        """The joint fit's undetermined components (:data:`ballscan.solve.joint.STATE_NAMES`), () without one."""
        return () if self.joint is None else tuple(self.joint.undetermined)

    @property
    def velocity_determined(self) -> bool:
        """Whether every velocity component is determined (the speed and the angles need all three)."""
        return self.motion is not None and not set(STATE_NAMES[3:]) & set(self.undetermined)

    @property
    def t_c_determined(self) -> bool:
        """Whether the crossing time is determined (the joint fit leaves its covariance row NaN where it moves with an undetermined component)."""
        return self.motion is not None and self.covariance is not None and bool(np.isfinite(self.covariance[0, 0]))

    def direction(self) -> tuple[float, float, float, float]:
        """Elevation, its sigma, azimuth, its sigma (degrees; :func:`ballscan.solve.derived.launch_angles`); NaN where a velocity component is undetermined."""
        if not self.velocity_determined:
            return (math.nan,) * 4
        return launch_angles(np.asarray(self.motion.velocity_mps), self.covariance[4:, 4:])

    def speed(self) -> tuple[float, float]:
        """Speed and its 1-sigma (m/s, first order); NaN where a velocity component is undetermined."""
        if not self.velocity_determined:
            return math.nan, math.nan
        V = np.asarray(self.motion.velocity_mps)
        sp = float(np.linalg.norm(V))
        u = V / sp
        return sp, float(math.sqrt(max(u @ self.covariance[4:, 4:] @ u, 0.0)))

    def to_dict(self) -> dict[str, Any]:
        """The ball's JSON (docs/geometry.md, "Rig results")."""
        d: dict[str, Any] = {"frame": "world", "cameras": list(self.cameras), "flags": list(self.flags)}
        if self.motion is None:
            d.update(t_c_s=None, position_m=None, velocity_mps=None, speed_mps=None)
        else:
            m, s = self.motion, self.sigmas
            elev, elev_s, azim, azim_s = self.direction()
            sp, sp_s = self.speed()
            # an undetermined component's value is wherever the solver stopped along its flat direction
            known = np.array([name not in self.undetermined for name in STATE_NAMES])
            position = np.where(known[:3], np.asarray(m.position_m, dtype=float), np.nan)
            velocity = np.where(known[3:], np.asarray(m.velocity_mps, dtype=float), np.nan)
            t_c = m.t_ref_s if self.t_c_determined else math.nan
            d.update(
                radius_m=m.radius_m, t_c_s=t_c, position_m=position, velocity_mps=velocity, speed_mps=sp,
                t_c_sigma_s=s[0], position_sigma_m=s[1:4], velocity_sigma_mps=s[4:7], speed_sigma_mps=sp_s,
                elevation_deg=elev, elevation_sigma_deg=elev_s, azimuth_deg=azim, azimuth_sigma_deg=azim_s,
                covariance={"parameters": list(WORLD_COVARIANCE_PARAMETERS), "matrix": self.covariance},
            )
        j = self.joint
        if j is not None:
            d["per_camera"] = {c.name: {**c.to_dict(), **({} if self.t_c_determined else {"t_c_s": None})} for c in j.cameras}
            d["inconsistent_cameras"] = [c.name for c in j.cameras if not c.consistent]
            d["chi2_red"] = j.chi2_red
            d["undetermined"] = list(j.undetermined)
            if j.constraint is not None:
                d["constraint"] = {**j.constraint.describe(), "residuals_sigma": j.constraint_residuals}
        d["own"] = {name: e.to_dict() for name, e in self.estimates.items()}
        return jsonable(d)

    def to_json(self, *, own: bool = True, indent: int | None = None) -> str:
        """:meth:`to_dict` as JSON; ``own=False`` keeps of the cameras' own estimates only their ``t_c_s`` (``own_t_c_s``: one line per ball in a stream)."""
        d = self.to_dict()
        if not own:
            d["own_t_c_s"] = jsonable({n: e.t_c_s for n, e in self.estimates.items()})
            del d["own"]
        return json.dumps(d, indent=indent, allow_nan=False)


@dataclass(frozen=True)
class RigReport:
    """Every ball of one rig's images, in the order of ``t_c_s``.

    ``reports`` holds each camera's first measurement of its image (on
    its refined background with ``Recipe.rig_refined_background``); the
    estimates each ball took, a ball measured again among them, are in its
    :attr:`RigBall.estimates`.
    """

    rig: Rig
    images: tuple[str, ...]
    balls: tuple[RigBall, ...]
    reports: tuple[EstimateReport, ...] = field(default=(), compare=False, repr=False)

    def to_dict(self) -> dict[str, Any]:
        return {
            "rig": self.rig.source,
            "images": {c.name: img for c, img in zip(self.rig.cameras, self.images)},
            "balls": [b.to_dict() for b in self.balls],
        }

    def to_json(self) -> str:
        return json.dumps(self.to_dict(), indent=2, allow_nan=False)


# ----------------------------------------------------------------- the check


def check_lines(rig: Rig) -> list[str]:
    """``ballscan rig check``: each camera's viewing plane and centre, and where each pair of planes meets."""
    gravity = ", ".join(f"{v:g}" for v in rig.gravity_vector())
    out = [f"rig {rig.source}: {len(rig.cameras)} cameras, gravity ({gravity}) m/s^2, match window {rig.match_window_s:g} s"]
    planes = [viewing_plane(c.camera) for c in rig.cameras]
    for c, p in zip(rig.cameras, planes):
        clock = "unknown" if c.clock_offset_s is None else f"{c.clock_offset_s:+.6g} s"
        n, ctr, ax = p.normal, p.centre_m, p.axis
        out.append(
            f"  {c.name}: viewing plane {n[0]:+.4f} X {n[1]:+.4f} Y {n[2]:+.4f} Z = {p.offset_m:+.4f} m; "
            f"centre ({ctr[0]:+.3f}, {ctr[1]:+.3f}, {ctr[2]:+.3f}) m, optical axis ({ax[0]:+.3f}, {ax[1]:+.3f}, {ax[2]:+.3f}); clock offset {clock}"
        )
    for i in range(len(planes)):
        for j in range(i + 1, len(planes)):
            x = plane_crossing(planes[i], planes[j])
            a, b = rig.cameras[i].name, rig.cameras[j].name
            if x.parallel:
                where = "the same plane" if x.distance_m < 1e-9 else f"parallel, {x.distance_m:.4f} m apart"
                out.append(f"  {a} x {b}: {where}; optical axes {x.axes_angle_deg:.2f} deg apart")
            else:
                p0, d = x.point_m, x.direction
                out.append(
                    f"  {a} x {b}: planes {x.angle_deg:.2f} deg apart, crossing along ({d[0]:+.4f}, {d[1]:+.4f}, {d[2]:+.4f}) "
                    f"through ({p0[0]:+.4f}, {p0[1]:+.4f}, {p0[2]:+.4f}) m; optical axes {x.axes_angle_deg:.2f} deg apart"
                )
    return out


# --------------------------------------------------------------- matching


#: 1-sigma given to a camera's parameter its own image leaves undetermined (the key-point guess stands in):
#: crossing time (s), centre (m), velocity (m/s); wide enough that the other cameras decide.
_UNKNOWN_SIGMA = (1.0, 10.0, 1000.0)


def own_state(e: BallEstimate, line_period_s: float) -> tuple[np.ndarray, np.ndarray] | None:
    """A camera's own ``(t_c, y0, z0, vx, vy, vz)`` and its 6x6 covariance, with the key-point guess where the fit left a value undetermined.

    One camera leaves its depth velocity (or more) undetermined exactly
    where a second camera pins it: such a parameter takes the key-point
    guess's value (:attr:`BallEstimate.initial`), its covariance row and
    column zero and its variance :data:`_UNKNOWN_SIGMA` squared, so that a
    weighted combination leaves it to the other cameras.  The crossing time,
    if undetermined, takes the guess's (the middle of the ball's lines where
    the guess falls outside them) with the ball's time in the image as its
    sigma.  None when neither the fit nor the guess has a crossing.

    Parameters
    ----------
    e : BallEstimate
        One camera's estimate (its frame, its clock; times s, lengths m,
        velocities m/s).
    line_period_s : float
        The camera's line period (s).
    """
    g = e.initial
    def pick(key: str):
        v = getattr(e, key)
        return v if v is not None else (None if g is None else getattr(g, key))
    t_c, pos, vel = pick("t_c_s"), pick("position_m"), pick("velocity_mps")
    if t_c is None or pos is None:
        return None
    x = np.array([float(t_c), float(pos[1]), float(pos[2]), *(np.zeros(3) if vel is None else np.asarray(vel, dtype=float))])
    C = np.full((6, 6), np.nan) if e.covariance is None else np.array(e.covariance, dtype=float)
    unknown = ~np.isfinite(np.diag(C)) | np.any(~np.isfinite(C), axis=1) | ~np.isfinite(x)
    unknown[0] |= e.t_c_s is None
    unknown[1:3] |= e.position_m is None
    unknown[3:] |= e.velocity_mps is None
    x[~np.isfinite(x)] = 0.0
    C[unknown, :] = 0.0
    C[:, unknown] = 0.0
    var = np.array([_UNKNOWN_SIGMA[0]] + [_UNKNOWN_SIGMA[1]] * 2 + [_UNKNOWN_SIGMA[2]] * 3) ** 2
    if unknown[0] and e.first_line is not None and e.last_line is not None:
        # the ball's time in the image (uniform line timing) bounds its crossing there
        t_lo, t_hi = e.first_line * line_period_s, e.last_line * line_period_s
        var[0] = (t_hi - t_lo + line_period_s) ** 2
        if not t_lo <= x[0] <= t_hi:
            x[0] = 0.5 * (t_lo + t_hi)
    C[unknown, unknown] = var[unknown]
    return x, C


def _own_world(rc: RigCamera, e: BallEstimate, offset_s: float) -> tuple[np.ndarray, np.ndarray, float] | None:
    """A camera's estimate as the world state at its crossing (rig time), its 6x6 covariance at that fixed time, and the time.

    Parameters its image leaves undetermined come from :func:`own_state`
    with a wide sigma.
    """
    own = own_state(e, 1.0 / rc.camera.line_rate_hz)
    if own is None:
        return None
    x, C6 = own
    cam = rc.camera
    C7 = world_covariance(cam, C6)
    X = cam.camera_to_world(np.array([0.0, x[1], x[2]]))
    V = cam.vectors_to_world(x[3:])
    A = np.zeros((6, 7))
    A[:3, 0] = -V  # the centre at the fixed time: the crossing time's error moves it along V
    A[:3, 1:4] = np.eye(3)
    A[3:, 4:] = np.eye(3)
    C = A @ C7 @ A.T
    return np.concatenate([X, V]), C, float(x[0]) - offset_s


def match_window_s(rig: Rig, k: int, ref_state: np.ndarray, ref_cov: np.ndarray, t_ref_s: float) -> tuple[float, float]:
    """Camera ``k``'s predicted crossing (its own clock, s) of the reference ball and the half-width of the matching window (s).

    The window: the rig's ``match_window_s`` plus 5 sigma of the
    prediction (the reference ball's covariance through the crossing's
    derivative) and 5 times the camera's ``clock_sigma_s``.
    """
    rc = rig.cameras[k]
    t, _, _, J, ok = world_crossing(ref_state, rc.camera, t_ref_s, rig.gravity_vector())
    if not ok or not np.isfinite(t):
        return math.nan, 0.0
    var = float(J[0] @ ref_cov @ J[0])
    sig = math.sqrt(var) if np.isfinite(var) and var >= 0 else math.inf
    off = rc.clock_offset_s if rc.clock_known else 0.0
    return t + off, rig.match_window_s + 5.0 * sig + 5.0 * rc.clock_sigma_s


def predicted_crossing(rig: Rig, reference: BallEstimate, k: int) -> tuple[float, float]:
    """Camera ``k``'s predicted crossing (its clock, s) of a reference camera's ball and the window's half-width (s); NaN when it cannot say."""
    ref = rig.cameras[rig.reference]
    own = _own_world(ref, reference, ref.clock_offset_s)
    if own is None:
        return math.nan, 0.0
    state, cov, t = own
    return match_window_s(rig, k, state, cov, t)


def _crossing(rc: RigCamera, e: BallEstimate) -> tuple[float, float] | None:
    """A camera's crossing of one ball (its clock, s) and its 1-sigma (s): the fit's, else the key-point guess's (:func:`own_state`)."""
    own = own_state(e, 1.0 / rc.camera.line_rate_hz)
    return None if own is None else (float(own[0][0]), float(math.sqrt(own[1][0, 0])))


def _matches(rig: Rig, reports) -> list[dict[int, int]]:
    """Groups ``{camera index: ball index}``: each reference ball with the nearest unused ball in each window, then the rest alone."""
    ref = rig.reference
    used = [set() for _ in rig.cameras]
    groups: list[dict[int, int]] = []
    for i, e in enumerate(reports[ref].balls):
        group = {ref: i}
        used[ref].add(i)
        own = _own_world(rig.cameras[ref], e, rig.cameras[ref].clock_offset_s)
        if own is not None:
            state, cov, t = own
            for k in range(len(rig.cameras)):
                if k == ref:
                    continue
                t_pred, half = match_window_s(rig, k, state, cov, t)
                cands = []
                for j, b in enumerate(reports[k].balls):
                    tb = _crossing(rig.cameras[k], b)
                    if j not in used[k] and tb is not None and abs(tb[0] - t_pred) <= half + 5.0 * tb[1]:
                        cands.append((abs(tb[0] - t_pred), j))
                if cands:
                    j = min(cands)[1]
                    group[k] = j
                    used[k].add(j)
        groups.append(group)
    for k, rep in enumerate(reports):
        for j in range(len(rep.balls)):
            if j not in used[k]:
                groups.append({k: j})
    return groups


# -------------------------------------------------------------- the start


def combined_start(rig: Rig, picks: dict[int, BallEstimate], radius_m: float) -> tuple[WorldMotion, list[float]] | None:
    """The cameras' own estimates combined by their information into one world motion, and the unknown clocks' starts.

    Each camera with a known clock gives the world state at its crossing
    (its covariance at that fixed time, :func:`_own_world`); the state at
    the first one's crossing is their weighted least squares (straight
    line; gravity's few micrometres over a crossing are left to the fit).
    Each unknown clock starts at its crossing less the predicted one.
    Returns None when no camera with a known clock has an estimate.
    """
    g = rig.gravity_vector()
    rows, t_ref = [], None
    for k, e in sorted(picks.items()):
        rc = rig.cameras[k]
        if not rc.clock_known:
            continue
        own = _own_world(rc, e, rc.clock_offset_s)
        if own is None:
            continue
        if rows:
            # align an unstated crossing sign (V.x >= 0 by convention) with the first camera's
            state, C, t = own
            Rm = rc.camera.rotation_matrix
            V_alt = Rm.T @ (np.diag([-1.0, 1.0, 1.0]) @ (Rm @ state[3:]))
            if np.linalg.norm(V_alt - rows[0][0][3:]) < np.linalg.norm(state[3:] - rows[0][0][3:]):
                state = np.concatenate([state[:3], V_alt])
            own = (state, C, t)
        rows.append(own)
        t_ref = rows[0][2]
    if not rows:
        return None
    N = np.zeros((6, 6))
    b = np.zeros(6)
    for state, C, t in rows:
        dt = t - t_ref
        A = np.eye(6)
        A[:3, 3:] = np.eye(3) * dt
        # equilibrated before the pseudo-inverse (metres^2 and (m/s)^2 differ by 1e12)
        d = np.sqrt(np.where(np.diag(C) > 0, np.diag(C), 1.0))
        W = np.linalg.pinv(C / np.outer(d, d), rcond=1e-10, hermitian=True) / np.outer(d, d)
        N += A.T @ W @ A
        b += A.T @ W @ state
    x = np.linalg.lstsq(N + 1e-12 * np.trace(N) * np.eye(6), b, rcond=None)[0]
    start = WorldMotion(radius_m, t_ref, tuple(x[:3]), tuple(x[3:]), tuple(g))
    offsets = []
    for k in rig.unknown_clocks:
        tk = _crossing(rig.cameras[k], picks[k]) if k in picks else None
        if tk is not None:
            t_pred = camera_params(start.state, rig.cameras[k].camera, t_ref, g, 0.0)[0][0]
            offsets.append(float(tk[0] - t_pred))
        else:
            offsets.append(0.0)
    return start, offsets


# -------------------------------------------------------------- estimate


def _single(rig: Rig, k: int, e: BallEstimate, flags: tuple[str, ...]) -> RigBall:
    """A ball measured by camera ``k`` alone: its own estimate in the world frame."""
    rc = rig.cameras[k]
    name = rc.name
    if e.t_c_s is None or e.covariance is None or e.position_m is None or e.velocity_mps is None:
        return RigBall((name,), None, None, flags + ("degenerate",), {name: e})
    dv = derive(rc.camera, e.position_m, e.velocity_mps, e.covariance)
    off = rc.clock_offset_s if rc.clock_known else 0.0
    motion = WorldMotion(e.radius_m, float(e.t_c_s) - off, tuple(dv.world_position_m), tuple(dv.world_velocity_mps), tuple(rig.gravity_vector()))
    extra = tuple(f for f in ("not_converged", "degenerate", "implausible_speed", "implausible_range") if f in e.flags)
    return RigBall((name,), motion, dv.world_covariance, flags + extra, {name: e})


def own_block(e: BallEstimate, recipe: Recipe) -> tuple[EdgeMeasurements, FitSettings]:
    """A camera's block in the joint fit: its edges and the settings of their residuals.

    Where the camera's own fit took pixels (its final fit's path,
    :class:`ballscan.pipeline.stages.FinalFit`), the block takes them as it
    did: the pixels of the edge windows and of the ball's ends
    (``recipe.pixel_fit``, the pixel fit), or the ends' and the spread
    lines' pixels beside the matched edges (``recipe.spread_fit``).  Where
    it took edges although the pixel model describes the ball
    (:attr:`BallEstimate.pixel_limb`: a uniform ball whose sensor's column
    gains scatter, measured with window edges), the block fits those
    edges' windows' pixels in their place (``recipe.pixel_fit``): a window
    edge keeps of a short, fast ball's pixels less than they hold
    (docs/benchmarks.md, "Two cameras against one").  Otherwise the edges
    and end areas (``recipe.edge_fit``).

    A pixel block on a sensor whose column gains scatter (:func:`gain_prior`)
    takes each column's gain as a nuisance parameter with that scatter as
    its prior (``FitSettings.pixel_gain_sigma``, :mod:`ballscan.solve.gains`):
    the gains repeat on every line of a column, an error the pixels' own
    weights take as independent.

    Parameters
    ----------
    e : BallEstimate
        One camera's estimate, with its ``fitted_edges``.
    recipe : Recipe
        The estimator's recipe (its fit settings).
    """
    path = None if e.record is None else e.record.final_fit
    edges = e.fitted_edges
    gain = gain_prior(e, recipe)
    if path == "pixels":
        return edges, replace(recipe.pixel_fit, pixel_gain_sigma=gain)
    if path == "spread":
        return edges, replace(recipe.spread_fit, pixel_gain_sigma=gain)
    if e.pixel_limb is not None:
        shade = shade_profile(e.pixel_limb, edges)
        if shade is not None:
            return replace(edges, profile_shade=shade), replace(recipe.pixel_fit, pixel_gain_sigma=gain)
    return edges, recipe.edge_fit


def _with_blur(camera: LineScanCamera, e: BallEstimate) -> LineScanCamera:
    """The camera with the blur circle its estimate's edges were measured with (measured on the ball where the camera file gives none)."""
    d = None if e.record is None else e.record.defocus
    if d is None or not d.used or camera.defocus_px is not None:
        return camera
    return replace(camera, defocus_px=d.diameter_px)


def gain_prior(e: BallEstimate, recipe: Recipe) -> float:
    """The relative 1-sigma of the column gains in a camera's pixels, 0 where they count as known.

    :func:`ballscan.pipeline.stages.unknown_gain_sigma` of the camera's
    stage record (:attr:`ballscan.pipeline.stages.StageRecord.column_gain_sigma`
    and ``flat_fielded``): the prior its own fit's pixels took, if any.

    Parameters
    ----------
    e : BallEstimate
        One camera's estimate (its stage record).
    recipe : Recipe
    """
    r = e.record
    return 0.0 if r is None else unknown_gain_sigma(r.column_gain_sigma, r.flat_fielded, recipe)


def _block(e: BallEstimate, recipe: Recipe, clock_offset_s: float | None) -> tuple:
    """:class:`JointCamera`'s fields after its camera: edges, clock offset, settings, and whether its partial lines enter levelled."""
    edges, settings = own_block(e, recipe)
    levelled = bool(e.extra.get("partial_levelled", False)) and not settings.pixels
    return edges, clock_offset_s, settings, levelled


def _joint_ball(rig: Rig, group: dict[int, int], reports, radius_m: float, recipe: Recipe, constraint: Constraint | None) -> RigBall:
    return measure_group(rig, {k: reports[k].balls[j] for k, j in group.items()}, radius_m, recipe, constraint)


def measure_group(
    rig: Rig,
    picks: dict[int, BallEstimate],
    radius_m: float,
    recipe: Recipe = Recipe(),
    constraint: Constraint | None = None,
    cameras: dict[int, LineScanCamera] | None = None,
) -> RigBall:
    """One ball from the cameras' own estimates of it (by camera index): the joint fit, or one camera's estimate alone (flagged).

    The joint fit needs two cameras with fitted edges, or one and a
    constraint.  ``cameras`` gives, by camera index, the camera an
    estimate's edges were measured with where it is not the rig's (a
    stream's crop, :func:`ballscan.geometry.camera.crop_camera`).
    """
    cameras = cameras or {}
    usable = {k: e for k, e in picks.items() if _usable(rig, k, e)}
    names = {rig.cameras[k].name: e for k, e in picks.items()}
    flags: tuple[str, ...] = ("single_camera",) if len(rig.cameras) > 1 and len(usable) < 2 else ()
    start = combined_start(rig, usable, radius_m) if usable else None
    if start is None or (len(usable) < 2 and constraint is None):
        k = min(picks)
        ball = _single(rig, k, picks[k], flags)
        return replace(ball, estimates=names)
    motion0, offsets = start
    order = sorted(usable)
    cams = [
        JointCamera(rig.cameras[k].name, _with_blur(cameras.get(k, rig.cameras[k].camera), usable[k]), *_block(usable[k], recipe, rig.cameras[k].clock_offset_s))
        for k in order
    ]
    offs = [offsets[rig.unknown_clocks.index(k)] for k in order if not rig.cameras[k].clock_known]
    res = fit_joint(cams, motion0, offs, constraint=constraint)
    flags += () if res.consistent else ("inconsistent_camera",)
    flags += () if res.converged else ("not_converged",)
    flags += ("degenerate",) if res.undetermined else ()
    ball = RigBall(tuple(c.name for c in cams), res.motion, res.covariance, flags, names, res)
    return replace(ball, flags=flags + _implausible(rig, ball))


def _usable(rig: Rig, k: int, e: BallEstimate) -> bool:
    """Whether camera ``k``'s estimate ``e`` can enter a joint fit: it has fitted edges and a crossing time."""
    return e.fitted_edges is not None and _crossing(rig.cameras[k], e) is not None


def _implausible(rig: Rig, ball: RigBall, limits: PlausibilityLimits = PlausibilityLimits()) -> tuple[str, ...]:
    """The flags of :mod:`ballscan.pipeline.plausibility` that a joint ball's motion earns.

    ``implausible_speed``: faster than ``limits.max_speed_mps`` (m/s);
    ``implausible_range``: the centre farther than ``limits.max_range_m``
    (m) from every camera of ``rig``.  Each is judged only where the fit
    determines the components it needs, finite (``math.hypot`` does not
    overflow on the solver's far values).
    """
    if ball.motion is None:
        return ()
    flags: tuple[str, ...] = ()
    v = ball.motion.velocity_mps
    if ball.velocity_determined and all(map(math.isfinite, v)) and math.hypot(*v) > limits.max_speed_mps:
        flags += ("implausible_speed",)
    p = np.asarray(ball.motion.position_m, dtype=float)
    if not set(STATE_NAMES[:3]) & set(ball.undetermined) and np.all(np.isfinite(p)):
        if min(math.hypot(*rc.camera.world_to_camera(p)) for rc in rig.cameras) > limits.max_range_m:
            flags += ("implausible_range",)
    return flags


def _alone_reports(
    images: list, rig: Rig, radius_m: float, recipe: Recipe, reports: tuple[EstimateReport, ...], apart: list[dict[int, int]]
) -> tuple[EstimateReport, ...]:
    """Each camera's report with the balls that enter no joint fit measured again on the detector's background.

    With ``recipe.rig_refined_background`` every camera is measured first on
    its refined background (:func:`estimate_rig`): the joint fit's direction
    rests on each camera's measurement across its line of sight, which the
    detector's per-column level biases in proportion to the noise
    (``Recipe.refined_background``), and the depth velocity that the
    refined level moves in one camera is fixed there by the others, or by
    a known plane.  A ball whose group has fewer estimates that can join a
    fit (:func:`_usable`) than its fit needs (:func:`_joins`) keeps one
    camera's estimate, depth and all, so it is measured again with
    ``recipe`` itself.  It is taken from that second
    measurement where exactly one of its balls spans the same lines, and
    keeps the first otherwise.

    Parameters
    ----------
    images : list of path, LineImage or array
        The rig's images, in its cameras' order (read again for the second
        measurement).
    rig : Rig
    radius_m : float
        Ball radius, m.
    recipe : Recipe
    reports : tuple of EstimateReport
        Each camera's first measurement.
    apart : list of dict
        The groups (``{camera index: ball index}`` of :func:`_matches`) that
        no joint fit takes.

    Returns
    -------
    tuple of EstimateReport
        ``reports`` itself where nothing is measured again (the first
        measurement was the recipe's own, or every ball joins a fit).
    """
    if not _refines_first(recipe):
        return reports
    wanted: dict[int, set[int]] = {}
    for g in apart:
        for k, j in g.items():
            wanted.setdefault(k, set()).add(j)
    if not wanted:
        return reports
    out = list(reports)
    for k, js in wanted.items():
        again = estimate_image(images[k], rig.cameras[k].camera, radius_m, recipe=recipe).balls
        spans = [(b.first_line, b.last_line) for b in again]
        balls = list(reports[k].balls)
        for j in js:
            span = (balls[j].first_line, balls[j].last_line)
            if spans.count(span) == 1:
                balls[j] = again[spans.index(span)]
        out[k] = replace(reports[k], balls=tuple(balls))
    return tuple(out)


def _refines_first(recipe: Recipe) -> bool:
    """Whether :func:`estimate_rig` measures first on the refined background where ``recipe`` itself would not."""
    return recipe.rig_refined_background and not recipe.refined_background


def _joins(rig: Rig, group: dict[int, int], reports, constrained: bool = False) -> bool:
    """Whether a group's estimates that can enter its joint fit are enough for one: two, or one beside a known plane (``constrained``), among them one from a camera whose clock is known (the joint fit's start needs one, :func:`combined_start`)."""
    usable = [k for k, j in group.items() if _usable(rig, k, reports[k].balls[j])]
    return any(rig.cameras[k].clock_known for k in usable) and (len(usable) >= 2 or constrained)


def estimate_rig(images, rig: Rig, radius_m: float, *, recipe: Recipe = Recipe(), constraint: Constraint | None = None) -> RigReport:
    """Detect, match and jointly measure every ball of a rig's images (one per camera, the rig's order).

    Parameters
    ----------
    images : sequence of path or LineImage or array
        One image per camera of ``rig``.
    rig : Rig
    radius_m : float
        Ball radius (m).
    recipe : Recipe
        Each camera's estimator; the joint fit uses its ``edge_fit``
        settings.  With ``recipe.rig_refined_background`` every camera is
        measured on its refined background, and a ball whose joint fit
        fewer than two cameras' estimates can join (none of a camera with
        a known clock, beside a plane ``constraint``) is measured again
        with ``recipe`` itself (:func:`_alone_reports`).
    constraint : Constraint, optional
        A known plane or point (world frame), as a prior of every ball's fit.

    Returns
    -------
    RigReport
    """
    images = list(images)
    if len(images) != len(rig.cameras):
        raise ValueError(f"estimate --rig: {len(images)} images for {len(rig.cameras)} cameras ({', '.join(rig.names)}); give one per camera in the rig's order")
    if recipe.method != "fit":
        raise ValueError("estimate --rig: the joint fit needs --method fit")
    first = replace(recipe, refined_background=True) if _refines_first(recipe) else recipe
    reports = tuple(estimate_image(img, rc.camera, radius_m, recipe=first) for img, rc in zip(images, rig.cameras))
    groups = _matches(rig, reports)
    # a plane fixes the depth motion as a second camera would; a point need not (near the viewing plane)
    constrained = constraint is not None and constraint.kind == "plane"
    joins = [_joins(rig, g, reports, constrained) for g in groups]
    alone = _alone_reports(images, rig, radius_m, recipe, reports, [g for g, j in zip(groups, joins) if not j])
    balls = [_joint_ball(rig, g, reports if j else alone, radius_m, recipe, constraint) for g, j in zip(groups, joins)]
    balls.sort(key=lambda b: (math.isnan(b.t_c_s), b.t_c_s))
    return RigReport(rig, tuple(r.image for r in reports), tuple(balls), reports)


def single_camera_rig(camera: LineScanCamera, name: str = "camera") -> Rig:
    """A rig of one camera (its pose, or the identity: the world frame is then the camera's), for a constraint without a second camera."""
    if not camera.has_pose:
        camera = camera.with_pose(np.eye(3), np.zeros(3))
    g = camera.gravity_mps2
    return Rig((RigCamera(name, camera, 0.0),), g, source=camera.source)
