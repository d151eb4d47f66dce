"""Tables of the work-precision benchmark from results.json (markdown, for BENCHMARKS.md).

    python3 bench/work_precision/table.py

For each case and each error level 1e-5 .. 1e-11 the time each method needs to reach that
error: on the method's (time, error) points sorted by tolerance, the first pair of neighbours
whose errors bracket the level, interpolated linearly in log(time) against log(error); "-" if
no run reached the level. Then the ratios of the fastest of ours to heyoka and to dop853.f
(below 1: ours is faster), the error floor (smallest error of any tolerance) and the energy
drift at tol 1e-12.
"""
import json
import math
import pathlib

HERE = pathlib.Path(__file__).resolve().parent
LEVELS = [10.0 ** -k for k in range(5, 12)]
PLAIN = ["routh dop853", "routh vern9", "routh taylor"]
PROJECTED = [n + " +proj/10" for n in PLAIN]
OURS = PLAIN + PROJECTED
PEERS = ["heyoka", "dop853.f", "scipy DOP853"]


def time_at(points, level):
    """Interpolated time to reach `level` on points (tol, time, error) sorted by decreasing tol."""
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if e0 >= level >= e1 and e0 > e1:
            s = (math.log(e0) - math.log(level)) / (math.log(e0) - math.log(e1))
            return math.exp(math.log(t0) + s * (math.log(t1) - math.log(t0)))
    if points and points[0][1] <= level:
        return points[0][0]
    return None


def main():
    res = json.loads((HERE / "results.json").read_text())
    m = res["machine"]
    print(f"load average at start {m['loadavg_start'][0]:.1f}, at end {m['loadavg_end'][0]:.1f}; "
          f"{m['nproc']} cores; heyoka {res['versions']['heyoka']}, SciPy {res['versions']['scipy']}, "
          f"{res['versions']['gfortran']}; minimum of {res['repeat']} runs\n")
    if "uptime_start" in m:
        print(f"`uptime` before: `{m['uptime_start']}`; after: `{m['uptime_end']}`\n")
    for case, data in res["cases"].items():
        rows = data["rows"]
        methods = [n for n in OURS + PEERS if any(r["method"] == n for r in rows)]
        pts = {n: [(r["time_s"], r["error"]) for r in sorted((r for r in rows if r["method"] == n), key=lambda r: -r["tol"])]
               for n in methods}
        print(f"#### {case} (field check: peers' right-hand sides within {data['field_check_max_rel']:.1e} of ours)\n")
        print("| error | " + " | ".join(f"{n} [ms]" for n in methods)
              + " | best of ours / heyoka | best of ours / dop853.f | best without projection / heyoka |")
        print("|---" * (len(methods) + 4) + "|")
        for level in LEVELS:
            t = {n: time_at(pts[n], level) for n in methods}
            def best_of(names):
                times = [t[n] for n in names if t.get(n) is not None]
                return min(times) if times else None
            def ratio(names, peer):
                best = best_of(names)
                return f"{best / t[peer]:.2f}" if best and t.get(peer) else "-"
            cells = [f"{t[n] * 1e3:.1f}" if t[n] is not None else "-" for n in methods]
            print(f"| {level:.0e} | " + " | ".join(cells) + f" | {ratio(OURS, 'heyoka')} | "
                  f"{ratio(OURS, 'dop853.f')} | {ratio(PLAIN, 'heyoka')} |")
        floors = {n: min(e for _, e in pts[n]) for n in methods}
        drift = {r["method"]: r["energy_drift"] for r in rows if r["tol"] == 1e-12}
        print("\n| | " + " | ".join(methods) + " |")
        print("|---" * (len(methods) + 1) + "|")
        print("| error floor (smallest error, tol 1e-4 .. 1e-15) | " + " | ".join(f"{floors[n]:.1e}" for n in methods) + " |")
        print("| energy drift at tol 1e-12 | " + " | ".join(f"{drift[n]:.1e}" if n in drift else "-" for n in methods) + " |")
        plain = [(r["method"], r["tol"], r["error"]) for r in rows if r["method"].endswith("plain sum")]
        if plain:
            comp = {(r["method"], r["tol"]): r["error"] for r in rows}
            print("\n| tol | " + " | ".join(f"{n}: compensated / plain sum" for n in PLAIN) + " |")
            print("|---" * (len(PLAIN) + 1) + "|")
            for tol in sorted({t for _, t, _ in plain}, reverse=True):
                cells = [f"{comp[(n, tol)]:.2e} / {comp[(n + ' plain sum', tol)]:.2e}"
                         if (n + ' plain sum', tol) in comp else "-" for n in PLAIN]
                print(f"| {tol:.0e} | " + " | ".join(cells) + " |")
        print()


main()
