"""Checks of command-line options shared by several commands."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import typer

if TYPE_CHECKING:
    from ..pipeline.recipe import Recipe

__all__ = ["check_radius_option", "recipe_from_options"]


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


def recipe_from_options(path: Path | None, **flags: object) -> "Recipe":
    """The recipe of ``--recipe FILE`` (the default recipe without one) with the flags given on the command line applied.

    Parameters
    ----------
    path : Path or None
        The recipe file (:func:`ballscan.pipeline.recipe.load_recipe`).
    **flags
        Recipe fields from their command-line flags; ``None`` where the flag
        was not given, which leaves the file's value.

    Raises
    ------
    RecipeFileError
        The file cannot be read or holds a bad setting.
    ValueError
        A flag's value is not a valid setting (naming the field).
    """
    from dataclasses import replace

    from ..pipeline.recipe import Recipe, load_recipe

    base = load_recipe(path) if path is not None else Recipe()
    return replace(base, **{k: v for k, v in flags.items() if v is not None})
