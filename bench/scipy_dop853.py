#!/usr/bin/env python3
"""Time SciPy's DOP853 implementations against `routh simulate` on the same case, in one run.

Usage (from the repository root, after `cargo build --release`):

    python3 bench/scipy_dop853.py [--t-end 1000] [--tol 1e-12] [--repeat 3]

The default case of routh (cases/default.toml) is integrated to t_end at rtol = atol = tol by
  * routh (the release binary, `routh simulate --json`), timed twice: the wall time of the whole
    process (start-up, case parsing, JSON output included) and the in-process wall time of the
    integration that the binary reports as `elapsed_s`,
  * scipy.integrate.solve_ivp(method="DOP853") (SciPy's Python implementation),
  * scipy.integrate.ode("dop853") (Hairer's dop853; SciPy 1.17 ships it translated to C),
with the same right-hand side (mg-eq) written in plain Python for SciPy. Every time is the
median of `--repeat` runs, as wall time and as CPU time (user + system of the process; the
CPU time is less disturbed by other processes competing for the cores). Each final state is compared with a tight reference: routh at
rtol = atol = 1e-15. The script prints the times, the speed ratios (SciPy time / routh time),
the final-state errors and the relative drifts of the energy H1 and of the quadratic integral
H2 of (raus-int) at t_end, and their maximum over the accepted steps.
"""
import argparse
import json
import math
import pathlib
import resource
import statistics
import subprocess
import time

from scipy import integrate

ROOT = pathlib.Path(__file__).resolve().parent.parent
BINARY = ROOT / "target" / "release" / "routh"

# cases/default.toml
m, R, a, I1, I2, I3, G = 1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81


def omega_of(g1, g2, g3, M1, M2, M3):
    """omega = I_Q^{-1} M, with I_Q = I + m r^2 E - m r r^T (om-m), by Sherman-Morrison."""
    r1, r2, r3 = R * g1, R * g2, R * g3 + a
    mr2 = m * (r1 * r1 + r2 * r2 + r3 * r3)
    i1, i2, i3 = 1.0 / (I1 + mr2), 1.0 / (I2 + mr2), 1.0 / (I3 + mr2)
    ar1, ar2, ar3 = r1 * i1, r2 * i2, r3 * i3
    am1, am2, am3 = M1 * i1, M2 * i2, M3 * i3
    c = m * (r1 * am1 + r2 * am2 + r3 * am3) / (1.0 - m * (r1 * ar1 + r2 * ar2 + r3 * ar3))
    return am1 + ar1 * c, am2 + ar2 * c, am3 + ar3 * c, (r1, r2, r3)


def field(t, x):
    """(mg-eq) with U = m G (r, gamma): the same field as routh::field::vector_field."""
    g1, g2, g3, M1, M2, M3 = x
    w1, w2, w3, (r1, r2, r3) = omega_of(g1, g2, g3, M1, M2, M3)
    gd1, gd2, gd3 = g2 * w3 - g3 * w2, g3 * w1 - g1 * w3, g1 * w2 - g2 * w1
    rd1, rd2, rd3 = R * gd1, R * gd2, R * gd3
    c1, c2, c3 = w2 * r3 - w3 * r2, w3 * r1 - w1 * r3, w1 * r2 - w2 * r1
    k = m * G
    u1, u2, u3 = 2 * R * k * g1, 2 * R * k * g2, 2 * R * k * g3 + a * k
    return [
        gd1,
        gd2,
        gd3,
        M2 * w3 - M3 * w2 + m * (rd2 * c3 - rd3 * c2) + g2 * u3 - g3 * u2,
        M3 * w1 - M1 * w3 + m * (rd3 * c1 - rd1 * c3) + g3 * u1 - g1 * u3,
        M1 * w2 - M2 * w1 + m * (rd1 * c2 - rd2 * c1) + g1 * u2 - g2 * u1,
    ]


def energy(x):
    """H1 = (M, omega) + 2U of (int-g)."""
    w1, w2, w3, (r1, r2, r3) = omega_of(*x)
    return x[3] * w1 + x[4] * w2 + x[5] * w3 + 2 * m * G * (r1 * x[0] + r2 * x[1] + r3 * x[2])


def quadratic(x):
    """H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2 (after raus-int), K = g omega3, H3 = (M, r)."""
    g1, g2, g3, M1, M2, M3 = x
    w3, (r1, r2, r3) = omega_of(*x)[2:]
    g = math.sqrt(I1 * I3 + I1 * m * R * R * (g1 * g1 + g2 * g2) + I3 * m * r3 * r3)
    k = g * w3
    h3 = M1 * r1 + M2 * r2 + M3 * r3
    return I1 * energy(x) + (I3 - I1) / I1 * k * k - m / I1 * h3 * h3


def routh(t_end, tol):
    out = subprocess.run(
        [str(BINARY), "simulate", "--t-end", str(t_end), "--rtol", str(tol), "--atol", str(tol), "--json"],
        check=True,
        capture_output=True,
        text=True,
    )
    return json.loads(out.stdout)


def time_routh(t_end, tol, repeat):
    """Median whole-process wall time, CPU time (user + system) and in-process wall time
    (`elapsed_s`) of `repeat` runs of routh, and the last summary."""
    wall, cpu, inprocess, summary = [], [], [], None
    for _ in range(repeat):
        usage = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        summary = routh(t_end, tol)
        wall.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append(after.ru_utime + after.ru_stime - usage.ru_utime - usage.ru_stime)
        inprocess.append(summary["elapsed_s"])
    return statistics.median(wall), statistics.median(cpu), statistics.median(inprocess), summary


def timed(f, repeat):
    """Median wall time and CPU time of `repeat` calls of f, and the last result."""
    wall, cpu, result = [], [], None
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.process_time()
        result = f()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return statistics.median(wall), statistics.median(cpu), result


def error(x, ref):
    """Max-norm error relative to the max norm of the reference."""
    return max(abs(u - v) for u, v in zip(x, ref)) / max(abs(v) for v in ref)


def drift(h, x0, xs):
    """Relative drift |h(x) - h(x0)| / |h(x0)| at the last state and its maximum over xs."""
    h0 = h(x0)
    d = [abs(h(x) - h0) / abs(h0) for x in xs]
    return d[-1], max(d)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--t-end", type=float, default=1000.0)
    p.add_argument("--tol", type=float, default=1e-12)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args()

    reference = routh(args.t_end, 1e-15)
    ref = reference["final_state"]["gamma"] + reference["final_state"]["M"]
    x0 = reference["initial_state"]["gamma"] + reference["initial_state"]["M"]

    t_process, cpu_process, t_inprocess, s = time_routh(args.t_end, args.tol, max(args.repeat, 5))
    x_routh = s["final_state"]["gamma"] + s["final_state"]["M"]

    def ivp():
        return integrate.solve_ivp(field, (0.0, args.t_end), x0, method="DOP853", rtol=args.tol, atol=args.tol)

    t_ivp, cpu_ivp, sol = timed(ivp, args.repeat)
    ivp_states = [list(sol.y[:, j]) for j in range(sol.y.shape[1])]

    def hairer(solout=None):
        ode = integrate.ode(field).set_integrator("dop853", rtol=args.tol, atol=args.tol, nsteps=10**8)
        if solout is not None:
            ode.set_solout(solout)
        ode.set_initial_value(x0, 0.0)
        return list(ode.integrate(args.t_end))

    t_ode, cpu_ode, _ = timed(hairer, args.repeat)
    # The accepted steps of ode("dop853"), from one more (untimed) run with a solout callback.
    ode_states = []
    hairer(lambda t, y: ode_states.append(list(y)))

    print(f"default case to t = {args.t_end}, rtol = atol = {args.tol}; reference: routh at 1e-15; "
          f"median of {args.repeat} runs (routh: {max(args.repeat, 5)})")
    print(f"{'run':<33}{'wall [s]':>9}{'cpu [s]':>9}{'wall/in-proc':>13}{'wall/process':>13}{'cpu/cpu':>9}"
          f"{'final error':>12}{'H1 drift end':>13}{'H2 drift end':>13}{'H2 drift max':>13}")
    rows = [
        ("routh simulate (in-process)", t_inprocess, None, [x_routh]),
        ("routh simulate (whole process)", t_process, cpu_process, [x_routh]),
        ("scipy solve_ivp DOP853", t_ivp, cpu_ivp, ivp_states),
        ("scipy ode('dop853') (Hairer, C)", t_ode, cpu_ode, ode_states),
    ]
    for name, t, cpu, xs in rows:
        h1_end, _ = drift(energy, x0, xs)
        h2_end, h2_max = drift(quadratic, x0, xs)
        h2_max_text = f"{h2_max:>13.3e}" if len(xs) > 1 else f"{s['integrals']['H2']['max_rel_drift']:>12.3e}*"
        cpu_text = f"{cpu:>9.4f}{cpu / cpu_process:>8.1f}x" if cpu is not None else f"{'-':>9}{'-':>9}"
        print(f"{name:<33}{t:>9.4f}{cpu_text[:9]}{t / t_inprocess:>12.1f}x{t / t_process:>12.1f}x{cpu_text[9:]}"
              f"{error(xs[-1], ref):>12.3e}{h1_end:>13.3e}{h2_end:>13.3e}{h2_max_text}")
    print("* routh's own max_rel_drift of H2 over its accepted steps (simulate --json)")
    print(f"field evaluations: routh {s['rhs_evals']} ({s['steps']} steps), "
          f"solve_ivp {sol.nfev} ({sol.y.shape[1] - 1} steps), ode('dop853') {len(ode_states) - 1} steps")
    print(f"routh in-process time per field evaluation: {1e9 * t_inprocess / s['rhs_evals']:.1f} ns")


if __name__ == "__main__":
    main()
