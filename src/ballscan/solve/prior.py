"""A Gaussian prior on one motion parameter, or on the velocity along one direction, as one more whitened residual of a fitting problem.

A prior ``w . p ~ N(mean, sigma^2)`` on a linear combination of the
parameters ``p`` of :data:`ballscan.geometry.motion.PARAM_NAMES` adds the
residual ``(w . p - mean) / sigma`` to the least squares of Eq. (9) and the
row ``w / sigma`` to its Jacobian, so the fit's covariance holds it too
(scaled, as the data's information is, by the fit's covariance scale: a
reduced chi-square above 1 widens the prior's share alike).  Its use:
keeping what the image leaves undetermined (one camera's velocity along
its line of sight) within a stated plausible range, so that the rest is
taken where the motion is plausible instead of wherever the flat direction
led the solver.  :class:`ParameterPrior` puts it on one parameter (``w`` a
unit vector), :class:`VelocityPrior` on the velocity's component along a
direction.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from ..geometry.motion import PARAM_NAMES

__all__ = ["ParameterPrior", "Prior", "VelocityPrior", "WithPrior"]


@dataclass(frozen=True)
class ParameterPrior:
    """``name ~ N(mean, sigma^2)``, in the parameter's units (s, m or m/s).

    Attributes
    ----------
    name : str
        One of :data:`ballscan.geometry.motion.PARAM_NAMES`.
    mean : float
        The prior's centre, in the parameter's unit.
    sigma : float
        Its standard deviation, same unit; positive and finite.
    """

    name: str
    mean: float
    sigma: float

    def __post_init__(self) -> None:
        if self.name not in PARAM_NAMES:
            raise ValueError(f"ParameterPrior.name: one of {PARAM_NAMES}, got {self.name!r}")
        _check_mean_sigma("ParameterPrior", self.mean, self.sigma)

    @property
    def index(self) -> int:
        """The parameter's place in the fit's parameter vector."""
        return PARAM_NAMES.index(self.name)

    def weights(self, n_params: int) -> np.ndarray:
        """``w`` over the fit's ``n_params`` parameters: 1 at :attr:`index`."""
        w = np.zeros(n_params)
        w[self.index] = 1.0
        return w


@dataclass(frozen=True)
class VelocityPrior:
    """``v . direction ~ N(mean, sigma^2)``: the velocity's component along a unit direction, m/s.

    Attributes
    ----------
    direction : (float, float, float)
        Unit vector in the camera frame (normalised at construction; not
        zero, finite).
    mean : float
        The prior's centre, m/s.
    sigma : float
        Its standard deviation, m/s; positive and finite.
    """

    direction: tuple[float, float, float]
    mean: float
    sigma: float

    def __post_init__(self) -> None:
        d = np.asarray(self.direction, dtype=float)
        if d.shape != (3,) or not np.all(np.isfinite(d)) or not np.any(d):
            raise ValueError(f"VelocityPrior.direction: a finite non-zero 3-vector, got {self.direction!r}")
        object.__setattr__(self, "direction", tuple(float(c) for c in d / np.linalg.norm(d)))
        _check_mean_sigma("VelocityPrior", self.mean, self.sigma)

    def weights(self, n_params: int) -> np.ndarray:
        """``w`` over the fit's ``n_params`` parameters: the direction in the velocity's three."""
        w = np.zeros(n_params)
        w[3:6] = self.direction
        return w


#: either prior: what :class:`WithPrior` and the fit take
Prior = ParameterPrior | VelocityPrior


def _check_mean_sigma(owner: str, mean, sigma) -> None:
    """One precise ``ValueError`` naming ``owner``'s field where ``mean`` is not finite or ``sigma`` not finite and positive."""
    if not (_real(mean) and math.isfinite(mean)):
        raise ValueError(f"{owner}.mean: a finite number, got {mean!r}")
    if not (_real(sigma) and math.isfinite(sigma) and sigma > 0):
        raise ValueError(f"{owner}.sigma: a finite number > 0, got {sigma!r}")


def _real(v) -> bool:
    """A real number, numpy's included, that is not a bool."""
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


class WithPrior:
    """A :class:`ballscan.solve.problem.FitProblem` with the prior's residual as its last.

    The problem's own residuals keep their places, so what slices them by
    block (outlier rejection, the correlated runs) sees them unchanged.

    Parameters
    ----------
    problem : FitProblem
        Its ``residuals``, ``residuals_and_jacobian``, ``start`` and
        ``fit_bias`` (the parameters: the six of ``PARAM_NAMES``, and the
        edge bias after them when it is fitted).
    prior : ParameterPrior or VelocityPrior
    """

    def __init__(self, problem, prior: Prior) -> None:
        self.problem = problem
        self.prior = prior
        self._w = prior.weights(6 + int(problem.fit_bias))
        self._jac = self._w / prior.sigma

    def _residual(self, x: np.ndarray) -> float:
        return (float(self._w @ x) - self.prior.mean) / self.prior.sigma

    def residuals(self, x: np.ndarray) -> np.ndarray:
        """The problem's whitened residuals at ``x``, then ``(w . x - mean) / sigma``."""
        return np.append(self.problem.residuals(x), self._residual(x))

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        """Jacobian of :meth:`residuals` at ``x``: the problem's rows, then ``w / sigma``."""
        return self.residuals_and_jacobian(x)[1]

    def residuals_and_jacobian(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`residuals` and :meth:`jacobian` at ``x`` in one call (the problem's own reuse kept)."""
        r, J = self.problem.residuals_and_jacobian(x)
        return np.append(r, self._residual(x)), np.vstack([J, self._jac])

    def start(self):
        """The problem's ``start()`` with the prior's row (None where the problem has none)."""
        s = self.problem.start()
        return None if s is None else (None, np.vstack([s[1], self._jac]))
