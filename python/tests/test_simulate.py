"""`simulate` against independent values: SciPy's solve_ivp on `Body.field`, the exact
solution by quadrature, time reversal, and the kinematics of the motion in space.

Each tolerance is stated with its reason; each check has a negative control.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import routh


@pytest.fixture(scope="module")
def case():
    body, x0, _, _, _ = routh.default_case()
    return body, x0


def test_simulate_agrees_with_scipy_dop853(case):
    # SciPy's own DOP853 on the same field, a second implementation of the integrator: both at
    # rtol = atol = 1e-12 over t = 10 (about 10 nutations), whose global errors are ~1e-11.
    body, x0 = case
    t = np.linspace(0.0, 10.0, 101)
    ours = routh.simulate(body, x0, 10.0, t_eval=t)
    theirs = solve_ivp(lambda _, x: body.field(x, unit_tolerance=None), (0.0, 10.0), x0, method="DOP853",
                       t_eval=t, rtol=1e-12, atol=1e-12)
    assert ours.success and theirs.success
    np.testing.assert_array_equal(ours.t, t)
    assert ours.y.shape == (6, 101)
    assert np.max(np.abs(ours.y - theirs.y)) < 1e-8
    # Negative control: SciPy at a loose tolerance differs by far more than 1e-8.
    loose = solve_ivp(lambda _, x: body.field(x, unit_tolerance=None), (0.0, 10.0), x0, method="RK23",
                      t_eval=t, rtol=1e-4, atol=1e-4)
    assert np.max(np.abs(ours.y - loose.y)) > 1e-6


def test_simulate_agrees_with_the_exact_solution(case):
    # The quadrature is an independent method; at 1e-12 both agree to ~1e-10 over t = 20
    # (docs/motion.md reports 1e-10 at t = 100).
    body, x0 = case
    exact = routh.ExactSolution(body, x0)
    result = routh.simulate(body, x0, 20.0, samples=201)
    assert np.max(np.abs(result.y - exact(result.t))) < 1e-9
    # Negative control: a crude RK4 differs visibly.
    crude = routh.simulate(body, x0, 20.0, samples=201, method="rk4:400")
    assert np.max(np.abs(crude.y - exact(crude.t))) > 1e-6


def test_dense_output_reproduces_the_samples(case):
    # sol(t) re-takes the step that covers t, so it equals the run's own samples (which come
    # from the same continuous extension) to rounding: 1e-13 on values of size ~5.
    body, x0 = case
    rng = np.random.default_rng(3)
    t = np.sort(rng.uniform(0.0, 5.0, 200))
    sampled = routh.simulate(body, x0, 5.0, t_eval=t)
    dense = routh.simulate(body, x0, 5.0, dense_output=True)
    assert dense.sol.t_min == 0.0 and dense.sol.t_max == 5.0
    np.testing.assert_array_equal(dense.sol.ts, dense.t)
    assert np.max(np.abs(dense.sol(t) - sampled.y)) < 1e-13
    # Unsorted times and a single time.
    perm = rng.permutation(200)
    assert np.max(np.abs(dense.sol(t[perm]) - sampled.y[:, perm])) < 1e-13
    assert dense.sol(t[7]).shape == (6,)
    # Between the steps it is an interpolant of order 7, not the nearest step end: a
    # piecewise-constant "dense output" would be off by the motion within a step.
    nearest = dense.y[:, np.searchsorted(dense.t, t).clip(0, dense.t.size - 1)]
    assert np.max(np.abs(nearest - sampled.y)) > 1e-3
    # The dense output of RK4 is its own continuous extension, agreeing with its samples.
    rk = routh.simulate(body, x0, 5.0, method="rk4:2000", dense_output=True)
    rk_sampled = routh.simulate(body, x0, 5.0, method="rk4:2000", t_eval=t)
    assert np.max(np.abs(rk.sol(t) - rk_sampled.y)) < 1e-12


def test_backward_time_returns_to_the_start(case):
    # Time reversal: forward to t = 5, then backward from there to 0 recovers x0; the global
    # errors of the two runs (~1e-11 each) bound the difference.
    body, x0 = case
    forward = routh.simulate(body, x0, 5.0)
    back = routh.simulate(body, forward.y_final, (5.0, 0.0), dense_output=True)
    assert back.success and back.t[0] == 5.0 and back.t[-1] == 0.0
    assert np.all(np.diff(back.t) < 0)
    assert np.max(np.abs(back.y_final - x0)) < 1e-9
    # Backward from x0 equals the exact solution at negative times.
    exact = routh.ExactSolution(body, x0)
    t = np.linspace(0.0, -5.0, 11)
    past = routh.simulate(body, x0, (0.0, -5.0), t_eval=t)
    assert np.max(np.abs(past.y - exact(t))) < 1e-9
    # Negative control: the past is not the future.
    assert np.max(np.abs(past.y[:, -1] - exact(5.0))) > 1e-2


def test_named_theta_dot_events_are_the_turning_points(case):
    # theta_dot vanishes where gamma3 reaches its turning points, which the quadrature gives
    # independently (Brent's method on Q); the event states agree to 1e-9 (the run's error),
    # and the time between two maxima of theta is the nutation period.
    body, x0 = case
    exact = routh.ExactSolution(body, x0)
    u_min, u_max = exact.turning_points
    result = routh.simulate(body, x0, 10.0, events=[
        routh.Event("theta_dot", direction=-1.0),   # theta from increasing to decreasing
        routh.Event("theta_dot", direction=+1.0),
    ])
    maxima, minima = result.t_events
    assert len(maxima) >= 9 and len(minima) >= 9
    np.testing.assert_allclose(result.y_events[0][:, 2], u_min, atol=1e-9)
    np.testing.assert_allclose(result.y_events[1][:, 2], u_max, atol=1e-9)
    np.testing.assert_allclose(np.diff(maxima), exact.period, atol=1e-9)
    assert result.y_events[0].shape == (len(maxima), 6)
    # Negative control: gamma3 at arbitrary times is not at a turning point.
    assert np.max(np.abs(result.y[2] - u_min)) > 1e-3


def test_callable_event_matches_the_named_one(case):
    body, x0 = case

    def theta_dot(t, y):
        omega = body.omega(y)
        return y[1] * omega[0] - y[0] * omega[1]

    named = routh.simulate(body, x0, 5.0, events="theta_dot")
    called = routh.simulate(body, x0, 5.0, events=theta_dot)
    # The same function evaluated in Python and in Rust: the located times agree to the
    # tolerance of Brent's method (a few ulp of t).
    np.testing.assert_allclose(called.t_events[0], named.t_events[0], rtol=0, atol=1e-13)
    # SciPy's attributes on a callable: terminal and direction.
    theta_dot.terminal = True
    theta_dot.direction = -1.0
    stopped = routh.simulate(body, x0, 5.0, events=theta_dot)
    assert stopped.status == 1 and stopped.message == "A termination event occurred."
    assert len(stopped.t_events[0]) == 1 and stopped.t[-1] == stopped.t_events[0][0]
    # The first crossing with direction -1 among the named events (which count both).
    first = next(t for t, y in zip(named.t_events[0], named.y_events[0])
                 if theta_dot(t, routh.simulate(body, x0, t + 1e-3, samples=2).y[:, -1]) < 0)
    assert stopped.t_events[0][0] == pytest.approx(first, abs=1e-13)
    np.testing.assert_array_equal(stopped.y_final, stopped.y_events[0][0])


def test_terminal_count_gamma3_and_dense_output_up_to_the_event(case):
    body, x0 = case
    exact = routh.ExactSolution(body, x0)
    level = 0.5 * sum(exact.turning_points)
    result = routh.simulate(body, x0, 10.0, events=routh.Event(f"gamma3={level}", terminal=3),
                            dense_output=True, samples=1001)
    assert result.status == 1 and len(result.t_events[0]) == 3
    np.testing.assert_allclose(result.y_events[0][:, 2], level, atol=1e-12)
    assert result.t[-1] <= result.t_events[0][-1]
    assert result.sol.t_max == result.t_events[0][-1]
    assert np.max(np.abs(result.sol(result.t_events[0]) - result.y_events[0].T)) < 1e-13
    # The same crossing times from the exact solution, by bisection on gamma3(t) - level.
    for te in result.t_events[0]:
        lo, hi = te - 1e-3, te + 1e-3
        f = lambda t: exact(t)[2] - level
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if np.sign(f(mid)) == np.sign(f(lo)) else (lo, mid)
        assert abs(te - 0.5 * (lo + hi)) < 1e-9


def test_full_motion_in_space_rolls_without_slipping(case):
    # The kinematics, checked in numpy: |q| = 1, Q gamma = -e_z, the height of the centre of
    # mass R + a gamma3, and no slip: the velocity of the centre of mass (a central difference
    # of the dense output, error ~h^2 |x'''| ~ 1e-7) equals Q (r x omega).
    body, x0 = case
    result = routh.simulate(body, x0, 3.0, full=True, samples=31, dense_output=True)
    assert result.y.shape == (12, 31)
    q = result.space["q"]
    np.testing.assert_allclose(np.linalg.norm(q, axis=0), 1.0, atol=1e-12)
    # The reduced part is the reduced run (the steps differ: the error control sees all 12
    # components), to the runs' errors.
    assert np.max(np.abs(result.y[:6] - routh.simulate(body, x0, 3.0, samples=31).y)) < 1e-9

    def rotation(qv):
        w, x, y, z = qv
        return np.array([
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ])

    h = 1e-4
    worst = 0.0
    for k in range(1, 30):
        t, y = result.t[k], result.y[:, k]
        Q = rotation(q[:, k])
        np.testing.assert_allclose(Q @ y[:3], [0.0, 0.0, -1.0], atol=1e-10)
        # (r, gamma) = R |gamma|^2 + a gamma3, with |gamma|^2 - 1 of the run ~1e-13.
        assert result.space["com"][2, k] == pytest.approx(body.R + body.a * y[2], abs=1e-12)
        r = body.R * y[:3] + np.array([0.0, 0.0, body.a])
        velocity = Q @ np.cross(r, body.omega(y[:6]))
        difference = (result.sol(t + h)[10:12] - result.sol(t - h)[10:12]) / (2 * h)
        worst = max(worst, np.max(np.abs(difference - velocity[:2])))
        # The contact point is the centre of mass plus Q r.
        np.testing.assert_allclose(result.space["contact"][:, k],
                                   result.space["com"][:2, k] + (Q @ r)[:2], atol=1e-12)
    assert worst < 1e-6
    # Negative control: slipping (the velocity of the centre of mass taken as zero) is far off.
    assert np.max(np.abs(np.diff(result.space["com"][:2], axis=1))) > 1e-2


def test_drift_and_counters(case):
    body, x0 = case
    result = routh.simulate(body, x0, 10.0, samples=11)
    assert result.nfev >= 12 * result.steps and result.njev == 0 and result.nlu == 0
    assert result["rhs_evals"] == result.nfev
    np.testing.assert_array_equal(result["x"], result.y.T)
    for name, drift in result.integrals.items():
        assert drift["max_rel_drift"] < 1e-10, name
        values = body.integrals(result.y)[name]
        assert drift["final"] == values[-1]
    # Problem.solve is simulate.
    problem = routh.Problem(body, x0, 10.0)
    again = problem.solve(samples=11)
    np.testing.assert_array_equal(again.y, result.y)
    assert routh.Problem.from_case().t_span == (0.0, routh.default_case()[2])


def test_problem_from_case_keeps_the_case_integration_table(tmp_path):
    # A case's [integration] is read as every command reads it: its max_steps too (it was
    # dropped, so a Python run of a case took up to 10^7 steps where `routh simulate` took 5).
    case = tmp_path / "few_steps.toml"
    case.write_text(
        "[body]\nm = 1.0\nR = 1.0\na = 0.3\nI1 = 0.4\nI3 = 0.5\n"
        "[initial]\ngamma = [0.0, 0.0, 1.0]\nomega = [0.5, 0.2, 8.0]\n"
        "[integration]\nt_end = 10.0\nrtol = 1e-10\natol = 1e-10\nmax_steps = 5\n"
    )
    problem = routh.Problem.from_case(str(case))
    assert (problem.rtol, problem.atol, problem.t_span) == (1e-10, 1e-10, (0.0, 10.0))
    solution = problem.solve()
    assert not solution.success and "max_steps = 5" in solution.message, solution.message
    # Control: without the limit the same case reaches t_end.
    case.write_text(case.read_text().replace("max_steps = 5\n", ""))
    assert routh.Problem.from_case(str(case)).solve().success


def test_theta_event_is_the_gamma3_event(case):
    # theta = c and gamma3 = cos(c) are the same crossings (arccos is monotone).
    body, x0 = case
    c = 0.25
    by_theta = routh.simulate(body, x0, 5.0, events=f"theta={c}")
    by_gamma3 = routh.simulate(body, x0, 5.0, events=f"gamma3={np.cos(c)}")
    assert len(by_theta.t_events[0]) >= 8
    np.testing.assert_allclose(by_theta.t_events[0], by_gamma3.t_events[0], rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.arccos(by_theta.y_events[0][:, 2]), c, atol=1e-12)


def test_projection_keeps_every_reported_state_on_the_level_set(case):
    # With project=True the samples, the events and the dense output are projected: the
    # integrals stay at their initial values to rounding (1e-13) even at a loose tolerance,
    # where the unprojected run drifts by ~1e-6.
    body, x0 = case
    h0 = body.integrals(x0)
    t = np.linspace(0.0, 50.0, 333)
    runs = {p: routh.simulate(body, x0, 50.0, rtol=1e-6, atol=1e-6, project=p, dense_output=True,
                              events="theta_dot", samples=101) for p in (True, False)}

    def drift(states):
        values = body.integrals(states, unit_tolerance=None)
        return max(np.max(np.abs(values[k] - h0[k])) / abs(h0[k]) for k in ("H1", "H3", "K"))

    projected = runs[True]
    assert projected.projected
    assert drift(projected.y) < 1e-13
    assert drift(projected.sol(t)) < 1e-13
    assert drift(projected.y_events[0].T) < 1e-13
    # Negative control: without projection the same tolerance drifts.
    assert drift(runs[False].y) > 1e-9


def test_rk4_events_and_backward(case):
    # RK4 with fixed steps: events are located on its continuous extension; backward runs
    # take negative steps. 20000 steps over t = 5 (h = 2.5e-4): global error ~1e-11.
    body, x0 = case
    exact = routh.ExactSolution(body, x0)
    result = routh.simulate(body, x0, (0.0, -5.0), method="rk4:20000",
                            events=routh.Event("theta_dot", direction=-1.0))
    assert result.method == "rk4:20000" and result.steps == 20000 and result.success
    assert np.max(np.abs(result.y_final - exact(-5.0))) < 1e-9
    # As in SciPy, the direction of a crossing follows the integration: backward in time,
    # g = -d(gamma3)/dt going from + to - marks the minima of theta (gamma3 at its maximum).
    np.testing.assert_allclose(result.y_events[0][:, 2], exact.turning_points[1], atol=1e-9)
