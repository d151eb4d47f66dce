"""`routh.section`: the Poincaré section of a ball's motions on one energy level, as arrays,
against its own summary and the plane, and bad arguments.

Each tolerance is stated with its reason; each check has a negative control.
"""

import numpy as np
import pytest

import routh


def test_default_case_section_lies_on_the_plane_and_the_level():
    # The default case's level, 5 initial states over t = 20 (DOP853 in lanes at 1e-12): the
    # crossings of gamma1 = 0 upward lie on the plane to 1e-10 (Brent's method locates the
    # time to 2 ulp, gamma1 moves at most |omega| ~ 8.3 per unit time: about 1e-13) and the
    # arrays agree with the summary. Negative control: gamma2 is not on the plane.
    body, x0, _, rtol, atol = routh.default_case()
    r = routh.section(body, x0, "gamma1 = 0", 20.0, initial=5, rtol=rtol, atol=atol)
    k = r["crossings"]
    assert k > 20
    assert r["x"].shape == (6, k) and r["t"].shape == (k,) and r["run"].shape == (k,)
    assert r["initial_states_x"].shape == (6, r["initial_states"])
    assert np.max(np.abs(r["x"][0])) == r["max_surface_value"] <= 1e-10
    assert r["max_energy_drift"] < 1e-9
    assert set(r["run"].tolist()) <= set(range(r["initial_states"]))
    assert np.max(np.abs(r["x"][1])) > 0.1
    assert r["surface"] == "gamma1 = 0" and r["direction"] == "up"


@pytest.mark.parametrize(
    "kwargs",
    [
        {"surface": "omega1 = 0"},
        {"surface": "gamma1"},
        {"surface": "gamma1 = 0", "direction": "left"},
        {"surface": "gamma1 = 0", "initial": 0},
        {"surface": "gamma1 = 0", "method": "taylor"},
    ],
)
def test_bad_arguments_raise_value_error(kwargs):
    body, x0, *_ = routh.default_case()
    with pytest.raises(ValueError):
        routh.section(body, x0, t_end=1.0, **kwargs)
