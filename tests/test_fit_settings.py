"""FitSettings is checked at construction: one precise ValueError naming the field."""

from __future__ import annotations

import pytest

from ballscan.solve.settings import FitSettings


def test_defaults_are_valid():
    FitSettings()


@pytest.mark.parametrize(
    "field, value",
    [
        ("edge_jacobian", "analytical"),  # a typo of a choice
        ("pixel_jacobian", "FD"),
        ("pixel_groups", "ends"),
        ("loss", "cauchy"),
        ("solver", "lm"),
        ("pixels", 1),  # a bool field given an int
        ("n_nodes", 0),  # an integer below its least value
        ("max_nfev", 2.5),  # an integer field given a float
        ("max_reject_rounds", -1),
        ("edge_floor_px", -0.1),  # a negative size
        ("max_spread_px", float("nan")),
        ("f_scale", 0.0),  # must be positive
        ("partial_shift_p", 1.0),  # a probability in (0, 1)
        ("reject_sigma", "3"),  # a number field given a string
        ("jacobian_reach", True),  # a number field given a bool
    ],
)
def test_a_bad_value_names_its_field(field, value):
    with pytest.raises(ValueError, match=rf"^FitSettings\.{field}: "):
        FitSettings(**{field: value})


def test_good_values_of_each_kind_pass():
    st = FitSettings(edge_jacobian="fd", loss="huber", pixels=True, n_nodes=4, edge_floor_px=0, reject_sigma=0.0, partial_shift_p=0.05)
    assert st.edge_jacobian == "fd" and st.n_nodes == 4
