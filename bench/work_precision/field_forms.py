"""The two forms of the field of model.py, against routh's field and in heyoka.

    bench/work_precision/.venv/bin/python bench/work_precision/field_forms.py [--repeat 5]

from the repository root, with the venv of run.py (heyoka). `model.field` is (mg-eq)
shortened by two exact identities (as routh's crates/routh-ball/src/field.rs), `model.field_literal` the same
function term by term as the paper prints it (model.py's documentation).

1. check: both forms against routh's field (`work_precision eval`, the benchmark binary of
   run.py) at 1000 random points per case with |gamma| in [0.5, 2] (the identities hold on all
   of R^6) and M up to twice the initial one: largest difference relative to the largest
   component of routh's field, which must be below 1e-13 (as run.py's check). Negative
   control: the short form with the wrong sign of its rolling term must fail it.
2. heyoka: `taylor_adaptive` on the default case at tol 1e-13 with each form: the length of
   its decomposition, the construction (compile) time, and the minimum over `--repeat` runs,
   interleaved (literal, short, literal, ...), of the CPU time (`time.process_time`) and wall
   time of `propagate_until(1000)`; the final-state error against reference.json.
"""
import argparse
import json
import pathlib
import random
import subprocess
import time

import model

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def bench_binary():
    out = subprocess.run(["cargo", "bench", "--bench", "work_precision", "--no-run", "--message-format=json"],
                         cwd=ROOT, check=True, text=True, capture_output=True).stdout
    exe = [json.loads(l).get("executable") for l in out.splitlines() if '"executable"' in l]
    return next(e for e in exe if e and "work_precision" in e)


def wrong_sign(p, x):
    """model.field with the rolling term m R a (dgamma/dt)_3 omega subtracted twice."""
    (w1, w2, w3), _ = model.omega_of(p, x)
    s = p["m"] * p["R"] * p["a"] * (x[0] * w2 - x[1] * w1)
    f = model.field(p, x)
    return f[:3] + [f[3] - 2 * s * w1, f[4] - 2 * s * w2, f[5] - 2 * s * w3]


def check(bench, case):
    rng = random.Random(2)
    p, x0 = model.load(case)
    pts = []
    for _ in range(1000):
        g = [rng.gauss(0, 1) for _ in range(3)]
        n = sum(c * c for c in g) ** 0.5 / rng.uniform(0.5, 2.0)
        pts.append([c / n for c in g] + [x0[3 + i] * rng.uniform(-2, 2) for i in range(3)])
    text = "\n".join(" ".join(repr(v) for v in x) for x in pts) + "\n"
    out = subprocess.run([bench, "eval", str(model.CASES[case])], input=text, check=True, text=True,
                         capture_output=True).stdout
    ours = [json.loads(l)["field"] for l in out.splitlines()]
    assert len(ours) == len(pts)
    worst = {}
    for name, f in (("field", model.field), ("field_literal", model.field_literal), ("wrong sign", wrong_sign)):
        worst[name] = max(max(abs(u - v) for u, v in zip(a, f(p, x))) / max(abs(v) for v in a)
                          for x, a in zip(pts, ours))
    print(f"{case}: largest relative difference from routh's field: " + ", ".join(f"{k} {v:.1e}" for k, v in worst.items()))
    assert worst["field"] < 1e-13 and worst["field_literal"] < 1e-13, worst
    assert worst["wrong sign"] > 1e-13 or p["a"] == 0.0, worst


def heyoka_forms(repeat):
    import heyoka as hy
    import numpy as np

    p, x0 = model.load("default")
    ref = json.loads((HERE / "reference.json").read_text())["cases"]["default"]["final"]
    ref = [float(v) for v in ref]
    xs = hy.make_vars("g1", "g2", "g3", "M1", "M2", "M3")
    forms = {}
    for name, f in (("field_literal", model.field_literal), ("field", model.field)):
        start = time.perf_counter()
        ta = hy.taylor_adaptive(list(zip(xs, f(p, xs))), np.array(x0), tol=1e-13)
        forms[name] = {"ta": ta, "compile_s": time.perf_counter() - start, "cpu_s": [], "wall_s": [],
                       "decomposition": len(ta.decomposition), "order": ta.order}
    for _ in range(repeat):
        for name, r in forms.items():
            ta = r["ta"]
            ta.time = 0.0
            ta.state[:] = x0
            cpu, wall = time.process_time(), time.perf_counter()
            out = ta.propagate_until(1000.0)
            r["cpu_s"].append(time.process_time() - cpu)
            r["wall_s"].append(time.perf_counter() - wall)
            r["steps"] = out[3]
            r["error"] = max(abs(u - v) for u, v in zip(ta.state, ref)) / max(abs(v) for v in ref)
    for name, r in forms.items():
        print(f"heyoka {hy.__version__}, default case, tol 1e-13, {name}: decomposition {r['decomposition']}, "
              f"order {r['order']}, compile {r['compile_s']:.2f} s, steps {r['steps']}, "
              f"propagate_until(1000) min CPU {1e3 * min(r['cpu_s']):.2f} ms, min wall {1e3 * min(r['wall_s']):.2f} ms "
              f"(of {repeat}), error {r['error']:.2e}")
    a, b = forms["field"], forms["field_literal"]
    print(f"short / literal: CPU {min(a['cpu_s']) / min(b['cpu_s']):.3f}, wall {min(a['wall_s']) / min(b['wall_s']):.3f}, "
          f"decomposition {a['decomposition']} / {b['decomposition']}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    print(subprocess.run(["uptime"], check=True, text=True, capture_output=True).stdout.strip())
    bench = bench_binary()
    for case in model.CASES:
        check(bench, case)
    heyoka_forms(args.repeat)
    print(subprocess.run(["uptime"], check=True, text=True, capture_output=True).stdout.strip())


if __name__ == "__main__":
    main()
