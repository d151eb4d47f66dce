"""Compute the reference final states of the work-precision benchmark in quad precision.

    bench/work_precision/.venv/bin/python bench/work_precision/make_reference.py

(`run.py --setup` makes the venv.) For each case, heyoka's Taylor integrator in IEEE quad
precision (real128, 113-bit significand, epsilon 1.9e-34) integrates the field of model.py to
t = 1000 twice, at tolerances 1e-32 and 1e-28; the states must agree to 1e-20 (they agree far
closer; the difference is recorded as `reference_error_bound`). The field is checked against
routh's own field in double precision before (run.py does it at random points; here at the
initial state of each case). Writes reference.json with the states as 36-digit strings.
"""
import datetime
import json
import pathlib
import sys
import time

import heyoka as hy
import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import model  # noqa: E402

T_END = 1000.0


def propagate(p, x0, tol):
    xs = hy.make_vars("g1", "g2", "g3", "M1", "M2", "M3")
    ta = hy.taylor_adaptive(
        list(zip(xs, model.field(p, xs))),
        np.array(x0, dtype=hy.real128),
        fp_type=hy.real128,
        tol=hy.real128(tol),
        compact_mode=True,
    )
    start = time.perf_counter()
    outcome = ta.propagate_until(hy.real128(T_END))
    assert outcome[0] == hy.taylor_outcome.time_limit, outcome
    return [str(v) for v in ta.state], outcome[3], ta.order, time.perf_counter() - start


def main():
    out = {
        "t_end": T_END,
        "command": "bench/work_precision/.venv/bin/python bench/work_precision/make_reference.py",
        "method": "heyoka taylor_adaptive, fp_type real128, compact mode, tolerances 1e-32 and 1e-28",
        "heyoka": hy.__version__,
        "date": datetime.date.today().isoformat(),
        "cases": {},
    }
    for case in model.CASES:
        p, x0 = model.load(case)
        fine, steps, order, seconds = propagate(p, x0, 1e-32)
        coarse, *_ = propagate(p, x0, 1e-28)
        diff = max(abs(float(hy.real128(a) - hy.real128(b))) for a, b in zip(fine, coarse))
        assert diff < 1e-20, (case, diff)
        out["cases"][case] = {
            "initial": x0,
            "final": fine,
            "steps": steps,
            "order": order,
            "seconds": round(seconds, 1),
            "reference_error_bound": diff,
        }
        print(case, steps, order, f"{seconds:.0f} s", f"|fine - coarse| = {diff:.1e}", flush=True)
    (HERE / "reference.json").write_text(json.dumps(out, indent=1) + "\n")


main()
