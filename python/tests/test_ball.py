"""The class `Ball` (the general unbalanced ball of the library) against the Rust results and
independent values: its model, its integrals conserved along `simulate`, the `Body` with
com = (0, 0, -a) giving the same trajectory bit for bit, pickling, and bad arguments.

Each tolerance is stated with its reason; each check has a negative control.
"""

import pathlib
import pickle
import subprocess
import json

import numpy as np
import pytest

import routh

ROOT = pathlib.Path(__file__).resolve().parents[2]
CHAPLYGIN = ROOT / "cases" / "chaplygin.toml"


def test_models_follow_the_parameters():
    assert routh.Ball(1.0, 1.0, 0.4, 0.4, 0.5, com=(0.0, 0.0, -0.3)).model == "routh-sphere"
    assert routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5).model == "chaplygin"
    assert routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.1, 0.0, 0.0)).model == "general"
    # The tolerance is relative (1e-12), not ==: I2 = I1 (1 + 1e-14) is still a Routh sphere,
    # I2 = I1 (1 + 1e-9) is not.
    assert routh.Ball(1.0, 1.0, 0.4, 0.4 * (1 + 1e-14), 0.5, com=(0, 0, -0.3)).model == "routh-sphere"
    assert routh.Ball(1.0, 1.0, 0.4, 0.4 * (1 + 1e-9), 0.5, com=(0, 0, -0.3)).model == "general"
    ball = routh.Ball(2.0, 1.5, 0.3, 0.4, 0.5, com=[0.1, -0.2, 0.3], G=3.0)
    assert (ball.m, ball.R, ball.I1, ball.I2, ball.I3, ball.com, ball.G) == \
        (2.0, 1.5, 0.3, 0.4, 0.5, (0.1, -0.2, 0.3), 3.0)


def test_integrals_by_model_match_numpy():
    # H1 = (M, omega) + 2 m G (r, gamma) (int-g), H4 = |gamma|^2, MM = |M|^2, Mgamma = (M, gamma),
    # computed here in numpy from Ball.omega: they agree to rounding (1e-14 relative).
    x = np.array([np.sin(0.3), 0.0, np.cos(0.3), 1.0, -0.5, 2.0])
    chaplygin = routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, G=9.81)
    ints = chaplygin.integrals(x)
    assert sorted(ints) == ["H1", "H4", "MM", "Mgamma"]
    omega = chaplygin.omega(x)
    gamma, M = x[:3], x[3:]
    assert ints["H1"] == pytest.approx(M @ omega + 2 * 9.81 * 1.0 * (1.0 * gamma @ gamma), rel=1e-14)
    assert ints["MM"] == pytest.approx(M @ M, rel=1e-14)
    assert ints["Mgamma"] == pytest.approx(M @ gamma, rel=1e-14)
    general = routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.1, 0.0, -0.2))
    assert sorted(general.integrals(x)) == ["H1", "H4"]
    # The Routh sphere as a Ball has the Body's integrals, equal to the last bit.
    body = routh.Body(1.0, 1.0, 0.3, 0.4, 0.5)
    as_ball = routh.Ball(1.0, 1.0, 0.4, 0.4, 0.5, com=(0.0, 0.0, -0.3))
    for name, value in body.integrals(x).items():
        if value is not None:
            assert as_ball.integrals(x)[name] == value, name
    # Arrays of points.
    xs = np.stack([x, x * [1, 1, 1, 2, 2, 2]], axis=1)
    assert chaplygin.integrals(xs)["MM"].shape == (2,)


def test_body_and_ball_give_identical_trajectories():
    body, x0, _, _, _ = routh.default_case()
    ball = routh.Ball(body.m, body.R, body.I1, body.I2, body.I3, com=(0.0, 0.0, -body.a), G=body.G)
    a = routh.simulate(body, x0, 5.0, samples=11, events="theta_dot")
    b = routh.simulate(ball, x0, 5.0, samples=11, events="theta_dot")
    # The same field, written once for the ball: bit for bit.
    np.testing.assert_array_equal(a.y, b.y)
    np.testing.assert_array_equal(a.t_events[0], b.t_events[0])
    assert a.nfev == b.nfev and a.integrals == b.integrals
    np.testing.assert_array_equal(ball.field(x0), body.field(x0))
    # Negative control: moving the centre of mass by 1e-6 changes the trajectory.
    moved = routh.Ball(body.m, body.R, body.I1, body.I2, body.I3, com=(1e-6, 0.0, -body.a), G=body.G)
    c = routh.simulate(moved, x0, 5.0, samples=11)
    assert np.max(np.abs(c.y - a.y)) > 1e-8


def test_chaplygin_ball_keeps_its_integrals(tmp_path):
    # The Chaplygin case of the library (cases/chaplygin.toml: com = 0, I1 != I2 != I3). Its
    # centre of mass is on the e3 axis, so load_case gives a Body (a = 0), as before; the same
    # ball as a Ball. DOP853 at 1e-12 over t = 100: the drift of its four integrals is the
    # method's truncation error, measured 1e-10 ((M, gamma); see tests/ball.rs).
    body, x0, _, rtol, atol = routh.load_case(CHAPLYGIN)
    assert isinstance(body, routh.Body)
    ball = routh.Ball(body.m, body.R, body.I1, body.I2, body.I3, G=body.G)
    assert ball.model == "chaplygin"
    # A case with the centre of mass off the axis is read as a Ball.
    off_axis = tmp_path / "off.toml"
    off_axis.write_text(CHAPLYGIN.read_text().replace("com = [0.0, 0.0, 0.0]", "com = [0.1, 0.0, 0.0]"))
    general = routh.load_case(off_axis)[0]
    assert isinstance(general, routh.Ball) and general.model == "general" and general.com == (0.1, 0.0, 0.0)
    result = routh.simulate(ball, x0, 100.0, rtol=rtol, atol=atol, samples=101)
    assert sorted(result.integrals) == ["H1", "H4", "MM", "Mgamma"]
    h0 = ball.integrals(x0)
    along = ball.integrals(result.y, unit_tolerance=None)
    for name in h0:
        drift = np.max(np.abs(along[name] - h0[name])) / abs(h0[name])
        assert drift < 3e-10, (name, drift)
        assert result.integrals[name]["max_rel_drift"] < 3e-10
    projected = routh.simulate(ball, x0, 100.0, rtol=rtol, atol=atol, samples=101, project=True)
    assert max(d["max_rel_drift"] for d in projected.integrals.values()) < 1e-12
    # The same run as the command-line tool: the same final state, bit for bit.
    binary = ROOT / "target" / "release" / "routh"
    if binary.exists():
        out = subprocess.run([str(binary), "simulate", "--case", str(CHAPLYGIN), "--t-end", "100",
                              "--json"], capture_output=True, text=True, check=True)
        final = json.loads(out.stdout)["final_state"]
        np.testing.assert_array_equal(result.y_final, final["gamma"] + final["M"])
    # Negative control: (M, M) is not conserved by a ball with an off-centre mass.
    off = routh.simulate(general, x0, 100.0, samples=101)
    mm = np.sum(off.y[3:] ** 2, axis=0)
    assert np.max(np.abs(mm - mm[0])) / mm[0] > 1e-3


def test_general_ball_conserves_energy_only():
    # A general ball (com off every axis, three moments): the energy H1 and H4 are integrals
    # (drift at 1e-12 over t = 50 below 1e-10), (M, M) is not.
    ball = routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.1, -0.05, -0.2), G=9.81)
    x0 = np.array([np.sin(0.3), 0.0, np.cos(0.3), 1.0, -0.5, 2.0])
    result = routh.simulate(ball, x0, 50.0, samples=51)
    assert sorted(result.integrals) == ["H1", "H4"]
    assert result.integrals["H1"]["max_rel_drift"] < 1e-10
    h1 = ball.integrals(result.y)["H1"]
    assert np.max(np.abs(h1 - h1[0])) / abs(h1[0]) < 1e-10
    mm = np.sum(result.y[3:] ** 2, axis=0)
    assert np.max(np.abs(mm - mm[0])) / mm[0] > 1e-4
    # Problem and pickling with a Ball.
    problem = routh.Problem(ball, x0, 5.0)
    assert isinstance(problem.body, routh.Ball) and problem.body == ball
    copy = pickle.loads(pickle.dumps(problem))
    np.testing.assert_array_equal(copy.solve(samples=3).y, problem.solve(samples=3).y)
    dense = problem.solve(dense_output=True).sol
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(dense))(1.3), dense(1.3))
    assert pickle.loads(pickle.dumps(ball)) == ball
    assert "com=(0.1, -0.05, -0.2)" in repr(ball)


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: routh.Ball(-1.0, 1.0, 0.3, 0.4, 0.5), r"\bm = -1"),
        (lambda: routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.0, 0.0, 1.5)), r"\|com\|"),
        (lambda: routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.0, float("nan"), 0.0)), r"com\[1\]"),
        (lambda: routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5, com=(0.0, 0.0)), r"com must have 3 components"),
        (lambda: routh.Ball(1.0, 1.0, 0.1, 0.1, 0.5), r"triangle inequality"),
        (lambda: routh.Ball(1.0, 1.0, 0.3, 0.4, 0.5).integrals([0, 0, 2.0, 1, 1, 1]), r"not a unit vector"),
        (lambda: routh.simulate("ball", [0, 0, 1, 0, 0, 1], 1.0), r"^body: must be a routh.Body or a routh.Ball"),
    ],
)
def test_bad_arguments_raise_value_error_naming_them(call, message):
    with pytest.raises(ValueError, match=message):
        call()
