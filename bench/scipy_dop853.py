#!/usr/bin/env python3
"""Time SciPy's DOP853 implementations against `routh simulate` on the same case, in one run.

Usage (from the repository root, after `cargo build --release`):

    python3 bench/scipy_dop853.py [--t-end 1000] [--tol 1e-12] [--repeat 3]

The default case of routh (cases/default.toml) is integrated to t_end at rtol = atol = tol by
  * routh (the release binary, `routh simulate --json`; wall time of the whole process),
  * scipy.integrate.solve_ivp(method="DOP853") (SciPy's Python implementation),
  * scipy.integrate.ode("dop853") (Hairer's Fortran code wrapped by SciPy),
with the same right-hand side (mg-eq) written in plain Python for SciPy. Each final state is
compared with a tight reference: routh at rtol = atol = 1e-15. The script prints the times,
the speed ratios, the final-state errors and the energy drift of each run.
"""
import argparse
import json
import math
import pathlib
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
    w1, w2, w3, (r1, r2, r3) = omega_of(*x)
    return x[3] * w1 + x[4] * w2 + x[5] * w3 + 2 * m * G * (r1 * x[0] + r2 * x[1] + r3 * x[2])


def routh(t_end, tol):
    out = subprocess.run(
        [str(BINARY), "simulate", "--t-end", str(t_end), "--rtol", str(tol), "--atol", str(tol), "--json"],
        check=True,
        capture_output=True,
        text=True,
    )
    return json.loads(out.stdout)


def timed(f, repeat):
    best, result = math.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = f()
        best = min(best, time.perf_counter() - start)
    return best, result


def error(x, ref):
    return max(abs(u - v) for u, v in zip(x, ref)) / max(abs(v) for v in ref)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--t-end", type=float, default=1000.0)
    p.add_argument("--tol", type=float, default=1e-12)
    p.add_argument("--repeat", type=int, default=3)
    args = p.parse_args()

    reference = routh(args.t_end, 1e-15)
    ref = reference["final_state"]["gamma"] + reference["final_state"]["M"]
    x0 = reference["initial_state"]["gamma"] + reference["initial_state"]["M"]
    e0 = energy(x0)

    t_routh, s = timed(lambda: routh(args.t_end, args.tol), max(args.repeat, 5))
    x_routh = s["final_state"]["gamma"] + s["final_state"]["M"]

    def ivp():
        return integrate.solve_ivp(field, (0.0, args.t_end), x0, method="DOP853", rtol=args.tol, atol=args.tol)

    t_ivp, sol = timed(ivp, 1)
    x_ivp = list(sol.y[:, -1])

    def hairer():
        ode = integrate.ode(field).set_integrator("dop853", rtol=args.tol, atol=args.tol, nsteps=10**8)
        ode.set_initial_value(x0, 0.0)
        return list(ode.integrate(args.t_end))

    t_ode, x_ode = timed(hairer, 1)

    print(f"default case to t = {args.t_end}, rtol = atol = {args.tol}; reference: routh at 1e-15")
    print(f"{'run':<34}{'time [s]':>12}{'routh faster by':>18}{'final-state error':>20}{'energy drift':>15}")
    rows = [
        ("routh simulate (process)", t_routh, x_routh, s["rhs_evals"]),
        ("scipy solve_ivp DOP853", t_ivp, x_ivp, sol.nfev),
        ("scipy ode('dop853') (Fortran)", t_ode, x_ode, None),
    ]
    for name, t, x, _ in rows:
        print(f"{name:<34}{t:>12.4f}{t / t_routh:>17.1f}x{error(x, ref):>20.3e}{abs(energy(x) - e0) / abs(e0):>15.3e}")
    print(f"field evaluations: routh {s['rhs_evals']}, solve_ivp {sol.nfev}")


if __name__ == "__main__":
    main()
