"""What a user reads off an estimate: the full covariance, the speed across the optical axis, direction angles and the world frame, each with its 1-sigma.

Every quantity here is a function of the fitted parameters ``theta = (t_c,
y0, z0, vx, vy, vz)`` (the dynamic sphere of Eq. (8), camera frame; the
centre at ``t_c`` is ``(0, y0, z0)``) and its 6x6 covariance, propagated to
first order (``J C J^T``), but the direction angles' sigmas, integrated
over the velocity's whole covariance (:func:`direction_sigmas`).  The speed
itself, with its bias correction, is
:func:`ballscan.solve.uncertainty.propagate`'s.

One line-scan camera measures ``vx`` and the velocity across its line of
sight well and the velocity along it poorly: on the optical axis
(``y0 = 0``) these are ``vy`` and ``vz``, and the speed across the optical
axis, ``|(vx, vy)|``, is typically hundreds of times more precise than the
total speed, with the depth angle's sigma correspondingly wide.  Where the
component along the line of sight is undetermined, :class:`Transverse`
holds what remains.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..geometry.camera import LineScanCamera

__all__ = [
    "COVARIANCE_PARAMETERS", "GH_NODES", "GH_WEIGHTS", "WORLD_COVARIANCE_PARAMETERS", "Derived", "Transverse", "derive", "derive_transverse",
    "direction_jacobian", "psi_y", "direction_sigmas", "launch_angles", "world_covariance",
]

#: The order of :attr:`BallEstimate.covariance`'s rows and columns (seconds, metres, m/s).
COVARIANCE_PARAMETERS = ("t_c_s", "y0_m", "z0_m", "vx_mps", "vy_mps", "vz_mps")
#: The order of the world frame's 7x7 covariance: the crossing time, the centre at it and the velocity.
WORLD_COVARIANCE_PARAMETERS = ("t_c_s", "x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps")
#: Gauss-Hermite nodes and weights (24, of a standard normal) along the velocity covariance's weakest
#: direction, where a quantity's error is not linear in the velocity's (the speed's, the angles').
GH_NODES, GH_WEIGHTS = np.polynomial.hermite_e.hermegauss(24)
GH_WEIGHTS = GH_WEIGHTS / GH_WEIGHTS.sum()
#: Gauss-Hermite nodes per eigen-direction of the angles' product grid (:func:`direction_sigmas`).
ANGLE_NODES = 10
#: A direction angle's sigma is at least its largest change over the velocity's ellipse of this many
#: sigmas, over as many (:func:`direction_sigmas`); the ellipse's boundary is sampled at REACH_NODES points.
REACH_SIGMAS = 3.0
REACH_NODES = 256
_PHI = np.linspace(0.0, 2.0 * math.pi, REACH_NODES, endpoint=False)
_CIRCLE = np.stack([np.cos(_PHI), np.sin(_PHI)])
_CIRCLE.flags.writeable = False


def _product_grid(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``ANGLE_NODES ** n`` points (rows) and weights of the standard normal's Gauss-Hermite product grid in ``n`` dimensions."""
    x, w = np.polynomial.hermite_e.hermegauss(ANGLE_NODES)
    points = np.stack([g.ravel() for g in np.meshgrid(*([x] * n), indexing="ij")], axis=1)
    weights = np.prod(np.meshgrid(*([w / w.sum()] * n), indexing="ij"), axis=0).ravel()
    return points, weights


# made once: (vx, vy) and (vx, vy, vz)
_GRIDS = {n: _product_grid(n) for n in (2, 3)}
for _a in (GH_NODES, GH_WEIGHTS, *_GRIDS[2], *_GRIDS[3]):
    _a.flags.writeable = False


@dataclass(frozen=True)
class Derived:
    """Quantities derived from one estimate and their 1-sigma (NaN where the covariance does not say).

    Attributes
    ----------
    speed_transverse_mps, speed_transverse_sigma_mps : float
        ``|(vx, vy)|``, the speed across the optical axis (in the plane of the
        sensor line and the crossing direction), m/s; for a
        :class:`Transverse` estimate ``|(vx, v_across)|``, across the line of
        sight.
    direction_deg, direction_sigma_deg : ndarray (2,)
        ``psi_y = atan2(vy, vx)`` (towards the sensor's ``+y``) and
        ``psi_z = atan2(vz, vx)`` (towards the depth ``+z``), degrees.
    speed_direction_correlation : ndarray (2,)
        Correlation of the speed (linearised, ``|V|``) with ``psi_y`` and
        ``psi_z`` (linearised too).
    world_position_m, world_velocity_mps : ndarray (3,) or None
        The centre at ``t_c`` and the velocity in the world frame (a camera
        with a pose), metres and m/s.
    world_position_sigma_m, world_velocity_sigma_mps : ndarray (3,) or None
    world_covariance : ndarray (7, 7) or None
        Of :data:`WORLD_COVARIANCE_PARAMETERS`.
    elevation_deg, elevation_sigma_deg : float or None
        World frame: the angle of the velocity above the world ``X-Y`` plane
        (``atan2(VZ, |(VX, VY)|)``; the launch angle where world ``Z`` is up).
    azimuth_deg, azimuth_sigma_deg : float or None
        World frame: ``atan2(VY, VX)``, from world ``X`` towards world ``Y``.
    """

    speed_transverse_mps: float
    speed_transverse_sigma_mps: float
    direction_deg: np.ndarray
    direction_sigma_deg: np.ndarray
    speed_direction_correlation: np.ndarray
    world_position_m: np.ndarray | None = None
    world_position_sigma_m: np.ndarray | None = None
    world_velocity_mps: np.ndarray | None = None
    world_velocity_sigma_mps: np.ndarray | None = None
    world_covariance: np.ndarray | None = None
    elevation_deg: float | None = None
    elevation_sigma_deg: float | None = None
    azimuth_deg: float | None = None
    azimuth_sigma_deg: float | None = None


@dataclass(frozen=True)
class Transverse:
    """The velocity across one camera's line of sight, where its component along the line of sight is undetermined.

    The ball's centre at ``t_c`` is ``(0, y0, z0)``: the camera sees it
    along ``(0, y0, z0) / r`` and across it, in the viewing plane, along
    ``axis = (0, z0, -y0) / r`` (``r = |(y0, z0)|``).  The image fixes
    ``vx`` and the velocity along ``axis`` (the centre's angular rate times
    ``r``); the component along the line of sight only changes the ball's
    size, which one camera sees weakly.  On the optical axis ``axis`` is
    ``(0, 1, 0)`` and the pair is ``(vx, vy)``.

    Attributes
    ----------
    velocity_mps : (float, float)
        ``(vx, v_across)``: along the camera's ``x`` and along ``axis``, m/s.
    axis : (float, float, float)
        Unit vector of ``v_across``, camera frame.
    covariance : ndarray (2, 2)
        Of ``velocity_mps``, m^2/s^2.
    psi_y_deg, psi_y_sigma_deg : float
        ``atan2(vy, vx)`` and its 1-sigma, degrees; off the optical axis
        ``vy`` holds part of the undetermined component, within the range
        the fit allowed it (NaN where no fit bounded it).
    source : {"prior", "unconstrained"}
        The fit that gave them (:func:`ballscan.pipeline.estimate.estimate_region`).
    """

    velocity_mps: tuple[float, float]
    axis: tuple[float, float, float]
    covariance: np.ndarray = field(repr=False, compare=False)
    psi_y_deg: float
    psi_y_sigma_deg: float
    source: str

    def __post_init__(self) -> None:
        object.__setattr__(self, "velocity_mps", tuple(float(v) for v in self.velocity_mps))
        object.__setattr__(self, "axis", tuple(float(v) for v in self.axis))
        cov = np.array(self.covariance, dtype=float).reshape(2, 2)
        cov.flags.writeable = False
        object.__setattr__(self, "covariance", cov)
        unit = len(self.axis) == 3 and abs(math.hypot(*self.axis) - 1.0) <= 1e-9 and self.axis[0] == 0.0
        if len(self.velocity_mps) != 2 or not np.all(np.isfinite(self.velocity_mps)) or not unit:
            raise ValueError(f"Transverse: (vx, v_across) and a unit axis in the viewing plane, finite, got {self.velocity_mps!r}, {self.axis!r}")
        if self.source not in ("prior", "unconstrained"):
            raise ValueError(f"Transverse.source: 'prior' or 'unconstrained', got {self.source!r}")


def psi_y(vx: float, vy: float, C: np.ndarray) -> tuple[float, float]:
    """``psi_y = atan2(vy, vx)`` and its 1-sigma (as :func:`direction_sigmas` gives it), degrees.

    Parameters
    ----------
    vx, vy : float
        Camera frame, m/s.
    C : ndarray (2, 2)
        Their covariance, m^2/s^2 (NaN gives a NaN sigma).
    """
    sigma = _angle_sigmas(np.array([vx, vy], dtype=float), np.asarray(C, dtype=float), ((0, 1),))[0]
    return math.degrees(math.atan2(vy, vx)), math.degrees(sigma)


def _linear_sigma(g: np.ndarray, C: np.ndarray) -> float:
    """``sqrt(g C g)``, NaN where it is not a finite non-negative number."""
    var = float(g @ C @ g)
    return math.sqrt(var) if math.isfinite(var) and var >= 0 else math.nan


def _sigmas(C: np.ndarray) -> np.ndarray:
    d = np.diag(C).astype(float)
    return np.where(d >= 0, np.sqrt(np.abs(d)), np.nan)


def _speed_across(vx: float, vy: float, C: np.ndarray) -> tuple[float, float]:
    """``|(vx, vy)|`` (m/s) and its 1-sigma from the ``vx``, ``vy`` covariance block ``C``."""
    vt = math.hypot(vx, vy)
    g = np.array([vx, vy]) / vt if vt > 0 else np.full(2, np.nan)
    return vt, _linear_sigma(g, C)


def _angle_jacobian(a: float, b: float) -> np.ndarray:
    """d atan2(b, a) / d(a, b), radians per unit."""
    den = a * a + b * b
    return np.array([-b / den, a / den]) if den > 0 else np.full(2, np.nan)


def direction_sigmas(V: np.ndarray, Cv: np.ndarray) -> np.ndarray:
    """1-sigma (2,) of ``psi_y = atan2(vy, vx)`` and ``psi_z = atan2(vz, vx)``, radians, for a velocity ``V`` of covariance ``Cv`` (m/s).

    The angles' RMS distance to the reported ones over the velocities the
    measurement allows (``V ~ N(V, Cv)``, a Gauss-Hermite product grid),
    as the speed's error is along its weakest direction
    (:func:`ballscan.solve.uncertainty.propagate`), and at least a third of
    the angle's largest change over the velocity's 3-sigma ellipse
    (:func:`_angle_reach`).  Where the weakest direction's sigma (chiefly
    ``vz``'s) is comparable with ``vx`` an angle saturates towards +-90
    degrees: its linear sigma shrinks with ``vx / vz`` while the true angle
    may lie anywhere down to 0, and even the RMS, dominated by the
    velocities near ``V``, puts a truth 3 sigmas out in ``vz`` 5-10 of its
    sigmas out in the angle.  The reach keeps a velocity within 3 sigma an
    angle within 3 sigma.  For small sigmas all agree with the linear
    propagation.  NaN where ``Cv`` is not finite.
    """
    return _angle_sigmas(np.asarray(V, dtype=float), np.asarray(Cv, dtype=float), ((0, 1), (0, 2)))


def _angle_sigmas(V: np.ndarray, Cv: np.ndarray, pairs) -> np.ndarray:
    """1-sigma of the angles ``atan2(V[b], V[a])`` for ``(a, b)`` in ``pairs`` (:func:`direction_sigmas`), radians."""
    return np.maximum(_angle_rms(V, Cv, pairs), _angle_reach(V, Cv, pairs) / REACH_SIGMAS)


def _angle_reach(V: np.ndarray, Cv: np.ndarray, pairs) -> np.ndarray:
    """Largest change of each angle ``atan2(V[b], V[a])`` over the boundary of the velocity's :data:`REACH_SIGMAS` ellipse, radians.

    The angle depends on ``(V[a], V[b])`` alone, so the ellipsoid's
    projection, the marginal covariance's ellipse, holds every value it
    takes; its extremes lie on the boundary (at the tangents from the
    origin, or anywhere, up to pi, where the ellipse holds the origin),
    sampled at :data:`REACH_NODES` points.  NaN where ``Cv`` is not finite.
    """
    if not np.all(np.isfinite(Cv)):
        return np.full(len(pairs), np.nan)
    out = []
    for a, b in pairs:
        lam, Q = np.linalg.eigh(Cv[np.ix_((a, b), (a, b))])
        edge = V[[a, b]][:, None] + REACH_SIGMAS * (Q * np.sqrt(np.maximum(lam, 0.0))) @ _CIRCLE
        d = np.arctan2(edge[1], edge[0]) - math.atan2(V[b], V[a])
        out.append(np.abs((d + math.pi) % (2.0 * math.pi) - math.pi).max())
    return np.array(out)


def _angle_rms(V: np.ndarray, Cv: np.ndarray, pairs) -> np.ndarray:
    """RMS errors of the angles ``atan2(V[b], V[a])`` for ``(a, b)`` in ``pairs`` (see :func:`direction_sigmas`), radians.

    A Gauss-Hermite product grid (:data:`ANGLE_NODES` per eigen-direction of
    ``Cv``) over the whole normal distribution: no direction is singled out,
    so the result is continuous where two eigenvalues cross.
    """
    if not np.all(np.isfinite(Cv)):
        return np.full(len(pairs), np.nan)
    lam, Q = np.linalg.eigh(Cv)
    scale = Q * np.sqrt(np.maximum(lam, 0.0))  # columns: one sigma along each eigen-direction
    points, weights = _GRIDS[V.size]
    pts = V[None, :] + points @ scale.T
    d = np.stack([np.arctan2(pts[:, b], pts[:, a]) - math.atan2(V[b], V[a]) for a, b in pairs], axis=1)
    d = (d + math.pi) % (2.0 * math.pi) - math.pi  # wrapped to [-pi, pi)
    return np.sqrt(weights @ (d * d))


def direction_jacobian(V: np.ndarray) -> np.ndarray:
    """d (psi_y, psi_z) / d V (2, 3), radians per (m/s)."""
    J = np.zeros((2, 3))
    J[0, [0, 1]] = _angle_jacobian(V[0], V[1])
    J[1, [0, 2]] = _angle_jacobian(V[0], V[2])
    return J


def world_covariance(camera: LineScanCamera, covariance: np.ndarray) -> np.ndarray:
    """The 7x7 covariance of (t_c, world centre, world velocity) from the camera frame's 6x6.

    The world centre is ``R^T ((0, y0, z0) - T)`` and the world velocity
    ``R^T V`` (``X_cam = R X_world + T``, geometry.md's pose).
    """
    Rt = camera.rotation_matrix.T
    J = np.zeros((7, 6))
    J[0, 0] = 1.0
    J[1:4, 1:3] = Rt[:, 1:3]
    J[4:7, 3:6] = Rt
    return J @ covariance @ J.T


def launch_angles(Vw: np.ndarray, Cvw: np.ndarray) -> tuple[float, float, float, float]:
    """Elevation ``atan2(VZ, |(VX, VY)|)`` and azimuth ``atan2(VY, VX)`` of a world velocity ``Vw`` (m/s) and their sigmas from its 3x3 covariance ``Cvw``, degrees."""
    h = math.hypot(Vw[0], Vw[1])
    elevation = math.atan2(Vw[2], h)
    azimuth = math.atan2(Vw[1], Vw[0])
    je = np.zeros(3)
    if h > 0:
        # d atan2(VZ, h) with dh/dVX = VX / h, dh/dVY = VY / h
        dh_dz = _angle_jacobian(h, Vw[2])
        je[:2] = dh_dz[0] * Vw[:2] / h
        je[2] = dh_dz[1]
    else:
        je[:] = np.nan
    ja = np.zeros(3)
    ja[:2] = _angle_jacobian(Vw[0], Vw[1])
    deg = math.degrees
    return deg(elevation), deg(_linear_sigma(je, Cvw)), deg(azimuth), deg(_linear_sigma(ja, Cvw))


def derive(camera: LineScanCamera | None, position_m, velocity_mps, covariance: np.ndarray | None) -> Derived:
    """:class:`Derived` of one estimate (``covariance``: 6x6 of :data:`COVARIANCE_PARAMETERS`, or None for no sigmas).

    Parameters
    ----------
    camera : LineScanCamera or None
        Its pose, if any, gives the world frame.
    position_m : (3,) array-like
        The centre at ``t_c`` (camera frame), metres.
    velocity_mps : (3,) array-like
        The velocity (camera frame), m/s.
    covariance : ndarray (6, 6) or None
    """
    V = np.asarray(velocity_mps, dtype=float)
    C = np.full((6, 6), np.nan) if covariance is None else np.asarray(covariance, dtype=float)
    Cv = C[3:, 3:]
    vt, vt_sigma = _speed_across(V[0], V[1], Cv[:2, :2])
    Jd = direction_jacobian(V)
    Cd = Jd @ Cv @ Jd.T
    speed = float(np.linalg.norm(V))
    g = V / speed if speed > 0 else np.full(3, np.nan)
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = (Jd @ Cv @ g) / (np.sqrt(np.diag(Cd)) * _linear_sigma(g, Cv))
    out = dict(
        speed_transverse_mps=vt,
        speed_transverse_sigma_mps=vt_sigma,
        direction_deg=np.degrees([math.atan2(V[1], V[0]), math.atan2(V[2], V[0])]),
        direction_sigma_deg=np.degrees(direction_sigmas(V, Cv)),
        speed_direction_correlation=np.clip(corr, -1.0, 1.0),
    )
    if camera is not None and camera.has_pose:
        Cw = world_covariance(camera, C)
        Vw = camera.vectors_to_world(V)
        elev, elev_s, azim, azim_s = launch_angles(Vw, Cw[4:, 4:])
        out.update(
            world_position_m=camera.camera_to_world(np.asarray(position_m, dtype=float)),
            world_position_sigma_m=_sigmas(Cw[1:4, 1:4]),
            world_velocity_mps=Vw,
            world_velocity_sigma_mps=_sigmas(Cw[4:, 4:]),
            world_covariance=Cw,
            elevation_deg=elev,
            elevation_sigma_deg=elev_s,
            azimuth_deg=azim,
            azimuth_sigma_deg=azim_s,
        )
    return Derived(**out)


def derive_transverse(transverse: Transverse) -> Derived:
    """What the velocity across the line of sight gives, where its component along it is undetermined.

    The speed across the line of sight ``|(vx, v_across)|`` (a lower bound
    of the speed) with its sigma, and ``psi_y`` as the fit bounded it
    (:class:`Transverse`); ``psi_z``, the correlations with the speed and
    the world frame (which need the whole velocity) are NaN or None.

    Parameters
    ----------
    transverse : Transverse
        The velocity across the line of sight (m/s) and its covariance.

    Returns
    -------
    Derived
    """
    vt, vt_sigma = _speed_across(*transverse.velocity_mps, transverse.covariance)
    return Derived(
        speed_transverse_mps=vt,
        speed_transverse_sigma_mps=vt_sigma,
        direction_deg=np.array([transverse.psi_y_deg, math.nan]),
        direction_sigma_deg=np.array([transverse.psi_y_sigma_deg, math.nan]),
        speed_direction_correlation=np.full(2, math.nan),
    )
