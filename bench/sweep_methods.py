"""The sweep's own table of methods: runs per second and error of `routh sweep` by method and
tolerance, from which `SWEEP_AUTO_TABLE` (crates/routh-io/src/sweep/runner.rs) is chosen.

    python3 bench/sweep_methods.py [--runs 1024] [--rounds 5] [--tols 1e-6,1e-8,1e-10,1e-12,1e-13]

from the repository root. The ensemble: RUNS runs of the default body (cases/sweep.toml's body
and omega1, omega2), tilt 0.2 to 1.5 x spin 3 to 7, to t = 10. For each tolerance
(rtol = atol = tol) and method (DOP853 and Taylor, both in the sweep's SIMD lanes), the whole
`routh sweep --threads 1 --columns final` process is timed (the fastest of ROUNDS rounds, the
configurations alternated in each round, so that a change of the machine's load hits them
alike), and its error is the largest over the runs of the max-norm error of the final state
(gamma, M) relative to the max norm of the reference state. The reference: Vern9 one run at a
time at rtol = atol = 2.2e-14 (the smallest tolerance accepted), checked against the Taylor
method at the same tolerance (their largest difference is printed: it bounds the reference's
own error). Prints the table of BENCHMARKS.md ("The sweep's default method").
"""
import argparse
import csv
import io
import math
import pathlib
import subprocess
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
BIN = ROOT / "target" / "release" / "routh"
STATE = ["final_gamma1", "final_gamma2", "final_gamma3", "final_M1", "final_M2", "final_M3"]


def case_text(runs):
    spins = 32 if runs % 32 == 0 else 1
    tilts = runs // spins
    base = (ROOT / "cases" / "sweep.toml").read_text().split("[sweep]")[0]
    return base + (
        "[sweep]\n"
        f"tilt = {{ range = [0.2, 1.5], n = {tilts} }}\n"
        f"spin = {{ range = [3.0, 7.0], n = {spins} }}\n"
    )


def sweep(case, method, tol, *extra):
    """The final states of the sweep, by run, and the process's wall time."""
    cmd = [str(BIN), "sweep", "--case", str(case), "--threads", "1", "--columns", "final",
           "--method", method, "--rtol", repr(tol), "--atol", repr(tol), *extra]
    start = time.perf_counter()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - start
    rows = {int(r["run"]): [float(r[c]) for c in STATE] for r in csv.DictReader(io.StringIO(out))}
    return rows, wall


def error(rows, reference):
    worst = 0.0
    for k, ref in reference.items():
        scale = max(abs(v) for v in ref)
        worst = max(worst, max(abs(a - b) for a, b in zip(rows[k], ref)) / scale)
    return worst


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=1024)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--tols", default="1e-6,1e-8,1e-10,1e-12,1e-13")
    args = ap.parse_args()
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    tols = [float(t) for t in args.tols.split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        case = pathlib.Path(tmp) / "case.toml"
        case.write_text(case_text(args.runs))
        reference, _ = sweep(case, "vern9", 2.2e-14, "--no-batch")
        check, _ = sweep(case, "taylor", 2.2e-14)
        print(f"reference: Vern9 at 2.2e-14; Taylor at 2.2e-14 differs by {error(check, reference):.1e}")
        configs = [(tol, m) for tol in tols for m in ("dop853", "taylor")]
        best = {c: math.inf for c in configs}
        errs = {}
        print(f"load before: {subprocess.run(['uptime'], capture_output=True, text=True).stdout.strip()}")
        for _ in range(args.rounds):
            for c in configs:
                rows, wall = sweep(case, c[1], c[0])
                best[c] = min(best[c], wall)
                errs[c] = error(rows, reference)
        print(f"load after: {subprocess.run(['uptime'], capture_output=True, text=True).stdout.strip()}")
    print(f"\n{args.runs} runs, `routh sweep --threads 1 --columns final`, fastest of {args.rounds}\n")
    print("| tol | method | wall | runs/s | error vs reference | error / tol |")
    print("|---|---|---|---|---|---|")
    for (tol, m) in configs:
        e = errs[(tol, m)]
        print(f"| {tol:.0e} | {m} | {best[(tol, m)]:.3f} s | {args.runs / best[(tol, m)]:,.0f} "
              f"| {e:.1e} | {e / tol:.2g} |")


if __name__ == "__main__":
    main()
