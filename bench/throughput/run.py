"""Throughput of many runs: trajectories per second per core, ours against heyoka and NumPy.

    python3 bench/throughput/run.py [--runs 1024] [--repeat 10] [--tols 1e-12,1e-8]

from the repository root. The ensemble: RUNS runs of the default body, omega = (0.5, 0.2, 8),
tilts spread evenly over (0.05, 1.5), to t = 10 (the initial states come from routh:
`batch_throughput states N`). On one core, in one interleaved run, for each tolerance:
* routh one at a time: DOP853, one run after the other (the sweep's `--no-batch` loop);
* routh lanes4, lanes8: the batched DOP853 (crates/routh-integrate/src/batch) with 4 and 8 lanes;
* routh taylor: our Taylor method (crates/routh-integrate/src/taylor), one run after the other;
* routh taylor4, taylor8: the batched Taylor method (crates/routh-integrate/src/batch/taylor.rs) with 4 and 8 lanes,
  the instruction set (AVX-512 or AVX2) chosen at run time; each lane bitwise the one-at-a-time
  Taylor run (Jorba-Zou's order and step with u = 1.5 from tol 1e-12 up: taylor::step_exponent);
* routh sweep, routh sweep --columns all: the whole `routh sweep` process (one thread, the
  default method, the runs' tilts given as the `[sweep]` table's values, the CSV table
  written to a pipe and read back for the final states), with the default columns (final
  state, integrals and their drift) and with every column (also the turning points by events
  and the nutation by quadrature): what a user's sweep costs, not the lanes alone (the
  fastest of 2 x REPEAT processes: a whole process is noisier than a loop inside one);
* heyoka ensemble: `ensemble_propagate_until` with one worker thread (a copy of the
  integrator per run, as heyoka does it);
* heyoka batch: `taylor_adaptive_batch` with heyoka's recommended SIMD width (or
  --heyoka-simd), the runs fed
  batch by batch, timed in --heyoka-processes fresh processes (default 4) and the fastest kept:
  its speed is one of two (at 1e-12 about 26,000 or 36,000 runs/s here), fixed for the life
  of a process, which one by chance;
* NumPy RK4: classical RK4 on all runs at once (arrays of RUNS), with the fixed number of steps
  that reaches the error of our DOP853 at that tolerance (found from the h^4 law, then checked).
Each time is the minimum of REPEAT runs (RK4: one run), heyoka's compilation excluded. The error
of each is the largest over the runs of the max-norm error of the final state relative to the
max norm of the reference state, the reference being routh's Vern9 at rtol = atol = 1e-15
(checked against heyoka at tol = 1e-15). The field of heyoka and NumPy is bench/work_precision's
model.field, the one Python definition (checked there against ours). The venv is the one of
bench/work_precision/run.py (heyoka, NumPy from PyPI), created the same way if missing.
Then, for the comparison at equal error, our lanes8 alone at tighter tolerances
(--equal-error-tols). Writes results.json beside this file and prints the table of BENCHMARKS.md.
"""
import argparse
import csv
import io
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(ROOT / "bench" / "work_precision"))
import model  # noqa: E402
import run as work_precision  # noqa: E402

T_END = 10.0


def setup():
    """The venv of the work-precision benchmark, and our benchmark binary."""
    venv = work_precision.VENV
    if not (venv / "bin" / "python").exists():
        work_precision.sh(sys.executable, "-m", "venv", str(venv))
        work_precision.sh(str(venv / "bin" / "pip"), "install", "--quiet", "heyoka", "scipy", "sympy", "numpy")
    out = work_precision.sh("cargo", "bench", "--bench", "batch_throughput", "--no-run",
                            "--message-format=json", cwd=ROOT, capture_output=True).stdout
    exe = [json.loads(line).get("executable") for line in out.splitlines() if '"executable"' in line]
    return next(e for e in exe if e and "batch_throughput" in e)


def routh(bench, mode, tol, states, repeat):
    text = "\n".join(" ".join(repr(v) for v in x) for x in states) + "\n"
    r = json.loads(subprocess.run([bench, mode, repr(tol), repr(T_END), str(repeat)], input=text,
                                  capture_output=True, text=True, check=True).stdout)
    if "error" in r:
        raise RuntimeError(r["error"])
    return r["time_s"], r["finals"], {"steps": r["steps"], "rhs_evals": r["rhs_evals"]}


def sweep(states, tol, repeat, columns):
    """The whole `routh sweep` of the runs of `states` (their tilts as the sweep's values), on one
    thread with the default method: the fastest of `repeat` processes and its final states."""
    tilts = [math.atan2(x[0], x[2]) for x in states]
    base = (ROOT / "cases" / "default.toml").read_text()
    text = base.split("[integration]")[0] + "[sweep]\ntilt = { values = [" + ", ".join(
        repr(t) for t in tilts) + "] }\n"
    binary = ROOT / "target" / "release" / "routh"
    with tempfile.TemporaryDirectory() as tmp:
        case = pathlib.Path(tmp) / "case.toml"
        case.write_text(text)
        cmd = [str(binary), "sweep", "--case", str(case), "--threads", "1", "--t-end", repr(T_END),
               "--rtol", repr(tol), "--atol", repr(tol), "--columns", columns]
        best, out = float("inf"), ""
        for _ in range(repeat):
            start = time.perf_counter()
            out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
            best = min(best, time.perf_counter() - start)
    rows = list(csv.DictReader(io.StringIO(out)))
    names = ["final_gamma1", "final_gamma2", "final_gamma3", "final_M1", "final_M2", "final_M3"]
    finals = [[float(r[n]) for n in names] for r in sorted(rows, key=lambda r: int(r["run"]))]
    return best, finals, {"ran": rows[0]["method"], "columns": columns}


def error(finals, reference):
    return max(work_precision.rel_error(x, ref) for x, ref in zip(finals, reference))


def uptime():
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=1024)
    # The best of 10: heyoka's batch mode has a slow tail (at 1e-12, the best of 3 ranged from
    # 23,000 to 45,000 runs/s between runs, the best of 10 reached 51,500); ours are steady.
    ap.add_argument("--repeat", type=int, default=10)
    ap.add_argument("--tols", default="1e-12,1e-8")
    # heyoka's batch mode runs at one of two speeds, fixed for the life of a process (at 1e-12
    # about 26,000 or 36,000 runs/s here, every integrator made in that process alike, on either
    # core): it is timed in this many fresh processes and the fastest is kept.
    ap.add_argument("--heyoka-processes", type=int, default=4)
    ap.add_argument("--heyoka-batch-only", type=float, default=None, help=argparse.SUPPRESS)
    # heyoka's batch size: its recommended SIMD width by default (4 with AVX2, 8 with AVX-512);
    # on the AVX2 Zen 3 of 2026-11-27 a batch of 8 (two registers, as our taylor8) was slower.
    ap.add_argument("--heyoka-simd", type=int, default=None,
                    help="heyoka's batch size (default: hy.recommended_simd_size())")
    ap.add_argument("--equal-error-tols", default="1e-10,1e-13,1e-14,1e-15",
                    help="our lanes8 alone at these tolerances, for the comparison at equal error")
    args = ap.parse_args()
    bench = setup()
    work_precision.sh("cargo", "build", "--release", "--quiet", cwd=ROOT)
    venv = work_precision.VENV
    if pathlib.Path(sys.prefix).resolve() != venv.resolve():
        os.execv(str(venv / "bin" / "python"), [str(venv / "bin" / "python"), __file__] + sys.argv[1:])
    import heyoka as hy
    import numpy as np

    load_before = uptime()
    states = [[float(v) for v in line.split()] for line in
              subprocess.run([bench, "states", str(args.runs)], capture_output=True, text=True,
                             check=True).stdout.splitlines()]
    p, _ = model.load("default")
    x0 = np.array(states).T.copy()  # (6, runs)
    xs = hy.make_vars("g1", "g2", "g3", "M1", "M2", "M3")
    field = list(zip(xs, model.field(p, xs)))
    simd = args.heyoka_simd or hy.recommended_simd_size()
    n_batches = -(-args.runs // simd)
    padded = np.concatenate([x0, np.repeat(x0[:, -1:], n_batches * simd - args.runs, axis=1)], axis=1)

    def heyoka_ensemble(tol, repeat):
        ta = hy.taylor_adaptive(field, x0[:, 0].copy(), tol=tol)

        def gen(ta_copy, i):
            ta_copy.time = 0.0
            ta_copy.state[:] = x0[:, i]
            return ta_copy

        best, out = float("inf"), None
        for _ in range(repeat):
            start = time.perf_counter()
            out = hy.ensemble_propagate_until(ta, T_END, args.runs, gen, max_workers=1)
            best = min(best, time.perf_counter() - start)
        return best, [list(r[0].state) for r in out], {"steps": sum(int(r[4]) for r in out),
                                                        "order": ta.order}

    def heyoka_batch(tol, repeat):
        ta = hy.taylor_adaptive_batch(field, padded[:, :simd].copy(), tol=tol)
        best, finals = float("inf"), None
        for _ in range(repeat):
            finals = np.empty_like(padded)
            start = time.perf_counter()
            for b in range(n_batches):
                ta.set_time(0.0)
                ta.state[:] = padded[:, b * simd:(b + 1) * simd]
                ta.propagate_until(T_END)
                finals[:, b * simd:(b + 1) * simd] = ta.state
            best = min(best, time.perf_counter() - start)
        return best, finals[:, :args.runs].T.tolist(), {"simd": simd, "order": ta.order}

    if args.heyoka_batch_only is not None:
        # A child of heyoka_batch_in_processes: one timing, as JSON on stdout.
        t, finals, extra = heyoka_batch(args.heyoka_batch_only, args.repeat)
        print(json.dumps({"time_s": t, "finals": finals, **extra}))
        return

    def heyoka_batch_in_processes(tol):
        """heyoka_batch in --heyoka-processes fresh processes: the fastest, with every rate."""
        runs = []
        for _ in range(args.heyoka_processes):
            out = subprocess.run([str(venv / "bin" / "python"), __file__, "--runs", str(args.runs),
                                  "--repeat", str(args.repeat), "--heyoka-batch-only", repr(tol),
                                  "--heyoka-simd", str(simd)],
                                 capture_output=True, text=True, check=True).stdout
            runs.append(json.loads(out.splitlines()[-1]))
        best = min(runs, key=lambda r: r["time_s"])
        extra = {k: v for k, v in best.items() if k not in ("time_s", "finals")}
        return best["time_s"], best["finals"], {
            **extra, "per_s_of_each_process": [args.runs / r["time_s"] for r in runs]}

    _, reference, _ = routh(bench, "vern9", 1e-15, states, 1)

    def rk4(steps):
        h = T_END / steps
        x = [row.copy() for row in x0]
        for _ in range(steps):
            k1 = model.field(p, x)
            k2 = model.field(p, [x[i] + 0.5 * h * k1[i] for i in range(6)])
            k3 = model.field(p, [x[i] + 0.5 * h * k2[i] for i in range(6)])
            k4 = model.field(p, [x[i] + h * k3[i] for i in range(6)])
            x = [x[i] + (h / 6.0) * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]) for i in range(6)]
        return np.array(x).T.tolist()

    def numpy_rk4(target):
        """The fewest steps (from the h^4 law, then checked) whose error is at most `target`."""
        steps = 500
        err = error(rk4(steps), reference)
        while err > target:
            steps = int(steps * 1.05 * (err / target) ** 0.25) + 1
            start = time.perf_counter()
            finals = rk4(steps)
            elapsed = time.perf_counter() - start
            err = error(finals, reference)
        return elapsed, finals, {"steps": steps}

    check = error(heyoka_ensemble(1e-15, 1)[1], reference)
    results = {"runs": args.runs, "t_end": T_END, "repeat": args.repeat, "load_before": load_before,
               "versions": {"heyoka": hy.__version__, "numpy": np.__version__},
               "reference": "routh vern9 1e-15", "heyoka_1e-15_vs_reference": check, "rows": []}
    print(f"reference: routh Vern9 at 1e-15; heyoka at 1e-15 differs from it by {check:.1e}", flush=True)
    for tol in [float(t) for t in args.tols.split(",")]:
        rows = []
        ours = [("routh one at a time", "one"), ("routh lanes4", "lanes4"), ("routh lanes8", "lanes8"),
                ("routh taylor", "taylor"), ("routh taylor4", "taylor4"), ("routh taylor8", "taylor8")]
        for name, f in [(name, lambda mode=mode: routh(bench, mode, tol, states, args.repeat))
                        for name, mode in ours] + [
                        ("routh sweep", lambda: sweep(states, tol, 2 * args.repeat, "final,integrals")),
                        ("routh sweep --columns all", lambda: sweep(states, tol, 2 * args.repeat, "all")),
                        # The batch mode before the ensemble: after the ensemble (heyoka's
                        # thread pool, even with one worker) the batch mode measured at
                        # 23,000 to 35,000 runs/s at 1e-12 instead of its 45,000 alone.
                        ("heyoka batch", lambda: heyoka_batch_in_processes(tol)),
                        ("heyoka ensemble", lambda: heyoka_ensemble(tol, args.repeat))]:
            t, finals, extra = f()
            rows.append({"method": name, "tol": tol, "time_s": t, "per_s": args.runs / t,
                         "error": error(finals, reference), **extra})
            print(f"tol {tol:.0e} {name:20} {t:8.3f} s {args.runs / t:10.0f} runs/s  "
                  f"error {rows[-1]['error']:.1e}", flush=True)
        target = rows[0]["error"]
        t, finals, extra = numpy_rk4(target)
        rows.append({"method": "NumPy RK4", "tol": tol, "time_s": t, "per_s": args.runs / t,
                     "error": error(finals, reference), **extra})
        print(f"tol {tol:.0e} {'NumPy RK4':20} {t:8.3f} s {args.runs / t:10.0f} runs/s  "
              f"error {rows[-1]['error']:.1e} ({extra['steps']} steps)", flush=True)
        results["rows"] += rows
    # At equal error: our lanes at tighter tolerances, to set beside heyoka's errors above.
    for tol in [float(t) for t in args.equal_error_tols.split(",") if t]:
        t, finals, extra = routh(bench, "lanes8", tol, states, args.repeat)
        results["rows"].append({"method": "routh lanes8 (equal error)", "tol": tol, "time_s": t,
                                "per_s": args.runs / t, "error": error(finals, reference), **extra})
        print(f"tol {tol:.0e} {'routh lanes8':20} {t:8.3f} s {args.runs / t:10.0f} runs/s  "
              f"error {results['rows'][-1]['error']:.1e}", flush=True)
    results["load_after"] = uptime()
    (HERE / "results.json").write_text(json.dumps(results, indent=1) + "\n")
    print(f"load before: {load_before}\nload after:  {results['load_after']}")
    print("| tol | method | runs/s per core | error vs 1e-15 reference | lanes8 / this | taylor8 / this |")
    print("|---|---|---|---|---|---|")
    for tol in sorted({r["tol"] for r in results["rows"]}, reverse=True):
        rows = [r for r in results["rows"] if r["tol"] == tol]

        def rate(method):
            return next((r["per_s"] for r in rows if r["method"] == method), float("nan"))

        for r in rows:
            note = f" ({r['steps']} steps)" if r["method"] == "NumPy RK4" else ""
            ratios = [rate(m) / r["per_s"] for m in ["routh lanes8", "routh taylor8"]]
            print(f"| {tol:.0e} | {r['method']}{note} | {r['per_s']:.0f} | {r['error']:.1e} | "
                  + " | ".join("-" if x != x else f"{x:.2f}" for x in ratios) + " |")
    # At equal error: at the same tolerance our Taylor lanes reach an error at or below heyoka's
    # batch mode's (for tol >= 1e-12 they take fewer, longer steps of higher order than
    # heyoka's Jorba-Zou rules: taylor::step_exponent), so the ratio of the rates at the same
    # tolerance is a comparison at equal error or in heyoka's favour; each line says which.
    print("\nAt equal error (the same tolerance): ours / heyoka batch")
    for tol in [float(t) for t in args.tols.split(",")]:
        rows = {r["method"]: r for r in results["rows"] if r["tol"] == tol}
        hy_row = rows["heyoka batch"]
        for ours in ["routh taylor4", "routh taylor8"]:
            r = rows[ours]
            side = "at most heyoka's" if r["error"] <= hy_row["error"] * 1.05 else "ABOVE heyoka's: not equal"
            print(f"tol {tol:.0e}: {ours} {r['per_s']:.0f} runs/s (error {r['error']:.1e}, {side}), heyoka "
                  f"batch {hy_row['per_s']:.0f} runs/s (error {hy_row['error']:.1e}): "
                  f"{r['per_s'] / hy_row['per_s']:.2f}x")


if __name__ == "__main__":
    main()
