"""Checks of command-line options shared by several commands."""

from __future__ import annotations

import sys

import typer

__all__ = ["check_radius_option"]


def check_radius_option(radius_m: float) -> float:
    """``--radius`` checked before any work: positive, computable, and warned about when no ball has it.

    Parameters
    ----------
    radius_m : float
        The ball's radius as typed, metres.

    Returns
    -------
    float
        The radius, metres.

    Raises
    ------
    typer.BadParameter
        Not positive.
    ValueError
        Outside the range the estimator can compute with (the message says
        the unit is metres).
    """
    from ..pipeline.plausibility import check_radius, radius_problem

    if not radius_m > 0:
        raise typer.BadParameter(f"must be positive, got {radius_m}", param_hint="--radius")
    radius_m = check_radius(radius_m)
    problem = radius_problem(radius_m)
    if problem is not None:  # its balls are flagged implausible_radius too
        print(f"ballscan: warning: --radius: {problem}", file=sys.stderr)
    return radius_m
