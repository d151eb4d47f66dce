"""The exact solution, the steady motions and the audit, against independent values:
the symmetry of the nutation, the field at a steady motion, simulations near the vertical
spin, and the JSON of the command-line tool."""

import json
import pickle
import pathlib
import subprocess

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
E3 = np.array([0.0, 0.0, 1.0])


def rotate_about_e3(x, angle):
    c, s = np.cos(angle), np.sin(angle)
    rot = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    return np.concatenate([rot @ x[:3], rot @ x[3:]])


@pytest.fixture(scope="module")
def exact():
    body, x0, _, _, _ = routh.default_case()
    return routh.ExactSolution(body, x0)


def test_exact_solution_is_periodic_up_to_the_precession(exact):
    # After one period the state is the initial one rotated about e3 by the advance; the
    # quadrature's own accuracy (~1e-12, docs/quadrature.md) bounds the residual.
    assert exact.motion == "nutation" and exact.period > 0
    t = np.linspace(-3.0, 7.0, 41)
    now, later = exact(t), exact(t + exact.period)
    rotated = np.array([rotate_about_e3(now[:, k], exact.precession_advance) for k in range(41)]).T
    assert np.max(np.abs(later - rotated)) < 1e-10
    assert exact.precession_rate == pytest.approx(exact.precession_advance / exact.period)
    # Negative control: a slightly wrong advance is far off.
    wrong = np.array([rotate_about_e3(now[:, k], exact.precession_advance + 1e-3)
                      for k in range(41)]).T
    assert np.max(np.abs(later - wrong)) > 1e-4


def test_exact_solution_fields(exact):
    body, x0 = exact.body, exact.x0
    # At t = 0 the quadrature reproduces x0 to its accuracy (the phase is found by Newton).
    np.testing.assert_allclose(exact(0.0), x0, rtol=0, atol=1e-12)
    u_min, u_max = exact.turning_points
    gamma3 = exact(np.linspace(0.0, exact.period, 2001))[2]
    # The sampled range lies within the turning points and reaches them to the sampling's
    # resolution (quadratic near a turning point: (pi / 2000)^2 of the amplitude).
    assert u_min - 1e-12 <= gamma3.min() and gamma3.max() <= u_max + 1e-12
    assert gamma3.min() - u_min < 1e-5 * (u_max - u_min)
    assert u_max - gamma3.max() < 1e-5 * (u_max - u_min)
    theta_min, theta_max = exact.theta_range
    assert theta_min == pytest.approx(np.arccos(u_max)) and theta_max == pytest.approx(np.arccos(u_min))
    ints = body.integrals(x0)
    for name in ("H1", "H3", "K"):
        assert exact.integrals[name] == pytest.approx(ints[name], rel=1e-14)
    # The integrals are constant along the exact solution (an independent evaluation).
    along = body.integrals(exact(np.linspace(0.0, 50.0, 101)))
    for name in ("H1", "H3", "H4", "K"):
        assert np.max(np.abs(along[name] - ints[name])) < 1e-10 * abs(ints[name])
    assert exact.passes_through_axis is False and exact.nodes >= 8


def test_steady_precession_is_a_relative_equilibrium():
    # At a steady precession the field is the rotation about e3 at rate precession:
    # dx/dt = precession (e3 x gamma, e3 x M). Checked in numpy from body.field.
    body, _, _, _, _ = routh.default_case()
    found = routh.steady_precessions(body, 0.6, 8.0)
    assert len(found) == 2
    for p in found:
        x = p["x"]
        rotation = np.concatenate([np.cross(E3, x[:3]), np.cross(E3, x[3:])])
        scale = np.max(np.abs(body.field(x)))
        assert np.max(np.abs(body.field(x) - p["precession"] * rotation)) < 1e-12 * scale
        # Negative control: a wrong rate.
        assert np.max(np.abs(body.field(x) - 1.01 * p["precession"] * rotation)) > 1e-4 * scale
        assert p["theta"] == 0.6 and p["spin"] == 8.0
        np.testing.assert_array_equal(x, np.concatenate([p["state"]["gamma"], p["state"]["M"]]))
        steady = routh.ExactSolution(body, x)
        assert steady.motion == "steady" and steady.period is None
        assert steady.precession_rate == pytest.approx(p["precession"], rel=1e-9)
        assert set(p["stability"]) == {"q_second_derivative", "stable_by_q",
                                       "max_real_eigenvalue", "stable_by_jacobian"}


def max_tilt(body, spin, t_end=20.0):
    """The largest tilt (rad) of a vertical spin at gamma3 = 1 tipped by 1e-3 rad."""
    gamma = np.array([np.sin(1e-3), 0.0, np.cos(1e-3)])
    x = body.state_from_omega(gamma, [0.0, 0.0, spin])
    result = routh.simulate(body, x, t_end, samples=2001)
    return np.max(np.arccos(np.clip(result.y[2], -1.0, 1.0)))


def test_routh_threshold_separates_stable_from_unstable_spins():
    # Independent of the formula: simulate the slightly tipped top above and below Routh's
    # threshold. Above it the tilt stays near 1e-3; below it the top falls over.
    body, _, _, _, _ = routh.default_case()
    threshold = routh.routh_threshold(body, 1.0)
    spin = routh.vertical_spin(body, 1.0, 1.2 * threshold)
    assert spin["threshold_spin"] == threshold and spin["centre_of_mass_above"]
    assert spin["stability"]["stable_by_q"] and spin["stability"]["stable_by_jacobian"]
    below = routh.vertical_spin(body, 1.0, 0.8 * threshold)
    assert not below["stability"]["stable_by_q"] and not below["stability"]["stable_by_jacobian"]
    assert max_tilt(body, 1.2 * threshold) < 1e-2
    assert max_tilt(body, 0.8 * threshold) > 0.5
    # The bottom-heavy pole is stable at any spin, and its threshold is 0.
    assert routh.routh_threshold(body, -1.0) == 0.0
    assert routh.vertical_spin(body, -1.0, 0.1)["stability"]["stable_by_q"]


def test_audit_matches_the_command_line_tool():
    records = routh.audit(points=3, seed=5)
    assert records and set(records[0]) == {"id", "label", "statement", "status", "residual", "note"}
    binary = ROOT / "target" / "release" / "routh"
    out = subprocess.run([str(binary), "audit", "--json", "--points", "3", "--seed", "5"],
                         check=True, capture_output=True, text=True).stdout
    cli = json.loads(out)
    assert [r["id"] for r in records] == [r["id"] for r in cli]
    assert [r["status"] for r in records] == [r["status"] for r in cli]
    for ours, theirs in zip(records, cli):
        if theirs["residual"] is None:
            assert ours["residual"] is None
        else:
            assert ours["residual"] == pytest.approx(theirs["residual"], rel=1e-12, abs=1e-300)
    assert {r["status"] for r in records} <= {"OK", "FAIL", "NOT-CHECKED", "OK-WITHIN-ANSATZ"}
    assert any(r["status"] == "OK" for r in records)


@pytest.mark.parametrize("flow, condition", [("X1", "cond"), ("X2", "cond2"), ("X1", "conformal")])
def test_hamiltonian_flows_agree_with_scipy_on_their_field(flow, condition):
    # The quadrature of a flow of the first bracket against SciPy's DOP853 on the same field
    # P dH (automatic differentiation): a second, step-by-step method. Both ~1e-10 over t = 2.
    body, x0, _, _, _ = routh.default_case()
    f = routh.HamiltonianFlow(body, x0, flow, condition=condition, alpha=1.0)
    t = np.linspace(0.0, 2.0, 21)
    ref = solve_ivp(lambda _, x: f.field(x), (0.0, 2.0), x0, method="DOP853", t_eval=t,
                    rtol=1e-12, atol=1e-12)
    assert ref.success
    assert np.max(np.abs(f(t) - ref.y)) < 1e-8
    assert np.max(np.abs(f(t[5]) - ref.y[:, 5])) < 1e-8
    # Negative control: the flow is not the motion of (mg-eq) (a different field).
    assert np.max(np.abs(f(t) - routh.ExactSolution(body, x0)(t))) > 1e-3
    copy = pickle.loads(pickle.dumps(f))
    np.testing.assert_array_equal(copy(t), f(t))
    lo, hi = f.theta_range
    assert 0.0 <= lo <= hi <= np.pi
    assert f.energy == pytest.approx(body.integrals(x0)["H1"], rel=1e-14)


def test_hamiltonian_flow_bad_arguments():
    body, x0, _, _, _ = routh.default_case()
    for kwargs, pattern in [(dict(flow="X3"), "^flow: unknown flow"),
                            (dict(flow="X1", condition="c"), "^condition: unknown condition"),
                            (dict(flow="X1", alpha=0.0), "^alpha: 0 must be finite and nonzero")]:
        with pytest.raises(ValueError, match=pattern):
            routh.HamiltonianFlow(body, x0, **kwargs)
