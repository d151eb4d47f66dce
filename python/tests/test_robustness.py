"""Bad arguments raise ValueError naming them (never a crash of the interpreter), objects
pickle (so multiprocessing and Dask work), the interpreter lock is released while the library
computes, and Ctrl-C interrupts a long integration."""

import _thread
import multiprocessing
import pickle
import threading
import time

import numpy as np
import pytest

import routh

BODY, X0, _, _, _ = routh.default_case()
NAN = float("nan")


def test_value_errors_name_the_argument():
    bad_gamma = np.array(X0)
    bad_gamma[:3] *= 2.0
    with_nan = np.array(X0)
    with_nan[4] = NAN
    cases = [
        (lambda: BODY.field(bad_gamma), r"^x: gamma = .* is not a unit vector"),
        (lambda: BODY.field(with_nan), r"^x: component 4 = NaN is not finite"),
        (lambda: BODY.field(np.zeros((3, 4))), r"x must have shape \(6,\) or \(6, k\)"),
        (lambda: BODY.field(np.stack([X0, bad_gamma], axis=1)), r"^x\[:, 1\]: gamma"),
        (lambda: BODY.field("abc"), r"^x: not an array of real numbers"),
        (lambda: BODY.omega(X0, unit_tolerance=-1.0), r"unit_tolerance"),
        (lambda: BODY.integrals(bad_gamma), r"not a unit vector"),
        (lambda: routh.simulate(BODY, with_nan, 1.0), r"^x0: invalid state: M .* non-finite"),
        (lambda: routh.simulate(BODY, bad_gamma, 1.0), r"^x0: invalid state: gamma"),
        (lambda: routh.simulate(BODY, X0, 1.0, samples=10**11), r"^samples: 100000000000 is too large"),
        (lambda: routh.simulate(BODY, X0, 1.0, samples=1), r"samples = 1"),
        (lambda: routh.simulate(BODY, X0, NAN), r"^t_span: value NaN"),
        (lambda: routh.simulate(BODY, X0, (0.0, 1.0), t_end=1.0), r"t_span"),
        (lambda: routh.simulate(BODY, X0, 1.0, rtol=NAN), r"rtol = NaN"),
        (lambda: routh.simulate(BODY, X0, 1.0, t_eval=[0.0, 2.0]), r"^t_eval: t_eval\[1\] = 2"),
        (lambda: routh.simulate(BODY, X0, 1.0, t_eval=[0.5, 0.2]), r"^t_eval: must be strictly monotone"),
        (lambda: routh.simulate(BODY, X0, 1.0, t_eval=[[0.1]]), r"t_eval must be a number or a 1-D"),
        (lambda: routh.simulate(BODY, X0, 1.0, t_eval=[0.1], samples=3), r"either t_eval or samples"),
        (lambda: routh.simulate(BODY, X0, 1.0, events="theta_dotty"), r"^events: unknown named event"),
        (lambda: routh.simulate(BODY, X0, 1.0, events="gamma3=x"), r"^events: .* not a finite number"),
        (lambda: routh.simulate(BODY, X0, 1.0, events=lambda t, y: "no"), r"event 0 did not return a number"),
        (lambda: routh.Event("theta_dot", direction=NAN), r"^direction: NaN is not finite"),
        (lambda: routh.Event("theta_dot", terminal=-1), r"^terminal: must be a bool or a count"),
        (lambda: routh.Event(3.0), r"an event is a name or a callable"),
        (lambda: routh.simulate(BODY, X0, 1.0, dense_output=True).sol(2.0), r"^t: 2 lies outside"),
        (lambda: routh.ExactSolution(routh.Body(1.0, 1.0, 0.3, 0.4, 0.5, I2=0.45), X0), r"I1 = I2"),
        (lambda: routh.ExactSolution(BODY, X0)(np.array([0.0, NAN])), r"^t: value NaN at flat index 1"),
        (lambda: routh.audit(points=0), r"^points: 0 must lie in"),
        (lambda: routh.audit(points=10**11), r"^points: 100000000000 must lie in"),
        (lambda: routh.vertical_spin(BODY, 0.5, 1.0), r"pole = 0.5"),
        (lambda: routh.routh_threshold(BODY, 0.0), r"pole = 0"),
        (lambda: routh.steady_precessions(BODY, 0.0, 1.0), r"theta = 0"),
        (lambda: routh.Body(NAN, 1.0, 0.3, 0.4, 0.5), r"invalid body parameter m = NaN"),
        (lambda: routh.Problem(BODY, X0[:5], 1.0), r"x0 must have 6 components, but it has 5"),
        (lambda: routh.Problem(BODY, np.zeros((2, 3)), 1.0), r"x0 must be a vector of 6 numbers"),
        (lambda: routh.Problem(BODY, X0, 1.0, method="euler"), r"unknown integration method"),
    ]
    for call, pattern in cases:
        with pytest.raises(ValueError, match=pattern):
            call()


def test_valid_arguments_pass():
    # Negative control of the test above: the same calls with good arguments.
    BODY.field(X0)
    BODY.field(np.stack([X0, X0], axis=1))
    routh.simulate(BODY, X0, 1.0, samples=3, events="gamma3=0.96")
    routh.simulate(BODY, X0, 1.0, t_eval=[0.2, 0.5])
    routh.Event("theta_dot", terminal=2, direction=-1)
    routh.audit(points=1)
    assert routh.routh_threshold(BODY, 1.0) > 0


def test_an_exception_in_an_event_function_propagates():
    def broken(t, y):
        raise ZeroDivisionError("from the event")

    with pytest.raises(ZeroDivisionError, match="from the event"):
        routh.simulate(BODY, X0, 1.0, events=broken)


def event_gamma3(t, y):
    return y[2] - 0.97


def same(a, b):
    for name in ("t", "y", "nfev", "status", "message", "t_span", "y0", "y_final"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name))
    for ta, tb in zip(a.t_events, b.t_events):
        np.testing.assert_array_equal(ta, tb)
    assert a.integrals == b.integrals


def test_pickle_round_trips():
    for obj in (BODY, routh.Problem(BODY, X0, (0.0, -2.0), rtol=1e-9, project=True, full=True),
                routh.Event("gamma3=0.5", terminal=2, direction=-1.0), routh.Event(event_gamma3)):
        copy = pickle.loads(pickle.dumps(obj))
        assert type(copy) is type(obj) and repr(copy) == repr(obj)
    assert pickle.loads(pickle.dumps(BODY)) == BODY
    result = routh.simulate(BODY, X0, 3.0, dense_output=True, events=[event_gamma3, "theta_dot"])
    copy = pickle.loads(pickle.dumps(result))
    same(result, copy)
    t = np.linspace(0.0, 3.0, 17)
    np.testing.assert_array_equal(copy.sol(t), result.sol(t))
    full = routh.simulate(BODY, X0, 1.0, full=True, samples=3, project=True, dense_output=True)
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(full)).sol(0.3), full.sol(0.3))
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(full)).space["q"], full.space["q"])
    exact = routh.ExactSolution(BODY, X0)
    np.testing.assert_array_equal(pickle.loads(pickle.dumps(exact))(t), exact(t))
    # Negative control: a different problem does not compare equal.
    with pytest.raises(AssertionError):
        same(result, routh.simulate(BODY, X0, 3.1, dense_output=True, events=[event_gamma3, "theta_dot"]))


def solve_tilt(problem):
    return problem.solve(samples=5, events=event_gamma3)


def test_multiprocessing_pool_gives_the_serial_results():
    problems = []
    for tilt in np.linspace(0.1, 0.5, 4):
        gamma = [np.sin(tilt), 0.0, np.cos(tilt)]
        problems.append(routh.Problem(BODY, BODY.state_from_omega(gamma, [0.5, 0.2, 8.0]), 2.0))
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        parallel = pool.map(solve_tilt, problems)
    for p, q in zip(problems, parallel):
        same(solve_tilt(p), q)


def longest_pause(call):
    """Run `call` while a Python thread ticks every millisecond; return the longest pause of
    the ticks during the call (as a fraction of the call's duration), the tick count and the
    duration. A call that holds the interpreter lock stops the ticks for its whole length."""
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(0.001)

    thread = threading.Thread(target=tick)
    thread.start()
    time.sleep(0.05)
    start = time.perf_counter()
    call()
    end = time.perf_counter()
    stop.set()
    thread.join()
    inside = [t for t in ticks if start <= t <= end]
    return np.diff([start] + inside + [end]).max() / (end - start), len(inside), end - start


def test_the_interpreter_lock_is_released_while_integrating():
    # simulate to t = 1e4 (~0.3 s): the ticking thread keeps running, its longest pause is a
    # small part of the call (even on a loaded machine).
    pause, count, duration = longest_pause(lambda: routh.simulate(BODY, X0, 10000.0))
    assert duration > 0.1 and count > 10 and pause < 0.5, (pause, count, duration)
    # Negative control: sorting floats holds the lock in C for the whole call.
    data = np.random.default_rng(1).random(2_000_000).tolist()
    pause, _, duration = longest_pause(lambda: sorted(data))
    assert duration > 0.1 and pause > 0.9, (pause, duration)


def test_ctrl_c_interrupts_a_long_integration():
    # SIGINT from a timer thread (as Ctrl-C) 0.3 s into a run that would take minutes
    # (t = 1e6 at 1e-12: ~4e7 steps, ~6 minutes): KeyboardInterrupt within seconds (0.3 ms
    # unloaded; 5 s leaves room for a loaded machine).
    # Python's own Ctrl-C handler, also when this process was started with SIGINT ignored
    # (a job started with `&` by a shell without job control).
    import signal

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            routh.simulate(BODY, X0, 1e6)
    finally:
        signal.signal(signal.SIGINT, previous)
    elapsed = time.perf_counter() - start
    timer.cancel()
    assert elapsed < 5.0, elapsed


def test_a_real_sigint_stops_a_python_process():
    # The signal a terminal sends on Ctrl-C, to a separate interpreter that runs a long
    # integration: it ends with KeyboardInterrupt within seconds (else it would run ~6 minutes).
    import os
    import signal
    import subprocess
    import sys

    code = ("import routh, signal, sys\n"
            "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
            "b, x, *_ = routh.default_case()\n"
            "print('running', flush=True)\n"
            "routh.simulate(b, x, 1e6)\n")
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "running"
    time.sleep(0.3)
    start = time.perf_counter()
    os.kill(proc.pid, signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=10)
    finally:
        proc.kill()
    assert time.perf_counter() - start < 5.0
    assert proc.returncode != 0 and "KeyboardInterrupt" in err, err
