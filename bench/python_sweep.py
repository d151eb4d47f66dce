"""The same sweep from the command line, from Python and from Dask: runs per second of each.

    target/python-venv/bin/python bench/python_sweep.py [--runs 20000] [--rounds 3]

from the repository root, in the virtual environment of python/ci.sh (routh, pyarrow and
dask[distributed] installed; `bash python/ci.sh` makes it). The ensemble: RUNS runs of the
default body (cases/sweep.toml's body and omega1, omega2), tilt 0.2 to 1.5 x spin 3 to 7, to
t = 10 at rtol = atol = 1e-10, the default method and columns, on the machine's 2 cores:

* `routh sweep --threads 2 --out FILE.parquet` (the release binary), the whole process;
* `routh.sweep(text=..., threads=2)`: the pyarrow Table of every run;
* Dask: a LocalCluster of 2 worker processes of one thread each (started before the clock),
  the sweep cut into 8 chunks `routh.sweep(text=..., start=, stop=, threads=1)`, the tables
  concatenated.

Each figure is the fastest of ROUNDS rounds, the three alternated in each round. The tables of
Python and Dask are checked equal to each other (the CLI's equality with them is tested in
python/tests/test_sweep_dask.py).
"""
import argparse
import pathlib
import subprocess
import tempfile
import time

import pyarrow as pa

import routh

ROOT = pathlib.Path(__file__).resolve().parents[1]
BINARY = ROOT / "target" / "release" / "routh"
CHUNKS = 8


def case_text(runs):
    spins = 20
    base = (ROOT / "cases" / "sweep.toml").read_text().split("[sweep]")[0]
    return base + (
        "[sweep]\n"
        f"tilt = {{ range = [0.2, 1.5], n = {runs // spins} }}\n"
        f"spin = {{ range = [3.0, 7.0], n = {spins} }}\n"
    )


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=20000)
    ap.add_argument("--rounds", type=int, default=3)
    args = ap.parse_args()
    from dask.distributed import Client, LocalCluster

    text = case_text(args.runs)
    runs = args.runs // 20 * 20
    settings = dict(t_end=10.0, rtol=1e-10, atol=1e-10)
    bounds = [runs * i // CHUNKS for i in range(CHUNKS + 1)]
    best = {"routh sweep (CLI)": float("inf"), "routh.sweep (Python)": float("inf"),
            "Dask, 2 workers": float("inf")}
    with tempfile.TemporaryDirectory() as tmp, \
            LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, \
            Client(cluster) as client:
        case = pathlib.Path(tmp) / "case.toml"
        case.write_text(text)
        out = pathlib.Path(tmp) / "runs.parquet"
        cli = [str(BINARY), "sweep", "--case", str(case), "--threads", "2", "--t-end", "10",
               "--rtol", "1e-10", "--atol", "1e-10", "--out", str(out)]
        print(f"load before: {subprocess.run(['uptime'], capture_output=True, text=True).stdout.strip()}")
        for _ in range(args.rounds):
            start = time.perf_counter()
            subprocess.run(cli, check=True, capture_output=True)
            best["routh sweep (CLI)"] = min(best["routh sweep (CLI)"], time.perf_counter() - start)
            start = time.perf_counter()
            table = routh.sweep(text=text, threads=2, **settings)
            best["routh.sweep (Python)"] = min(best["routh.sweep (Python)"], time.perf_counter() - start)
            start = time.perf_counter()
            parts = [client.submit(routh.sweep, text=text, start=a, stop=b, threads=1, pure=False,
                                   **settings) for a, b in zip(bounds, bounds[1:])]
            chunked = pa.concat_tables(client.gather(parts))
            best["Dask, 2 workers"] = min(best["Dask, 2 workers"], time.perf_counter() - start)
            assert table.num_rows == runs and chunked.num_rows == runs
            assert table.equals(chunked), "Python and Dask differ"
        print(f"load after: {subprocess.run(['uptime'], capture_output=True, text=True).stdout.strip()}")
    print(f"\n{runs} runs, fastest of {args.rounds}\n")
    print("| path | wall | runs/s | / CLI |")
    print("|---|---|---|---|")
    cli_time = best["routh sweep (CLI)"]
    for name, t in best.items():
        print(f"| {name} | {t:.3f} s | {runs / t:,.0f} | {cli_time / t:.2f} |")


if __name__ == "__main__":
    main()
