#!/usr/bin/env bash
# A sweep of N runs (default 100,000) of the default body, a tilt x spin grid, to t = 10 at
# rtol = atol = 1e-10 on 2 threads, written as Parquet: wall time, runs per second and peak
# memory (GNU time's maximum resident set size), with `uptime` before and after (the machine
# is shared). Run it for two sizes to see that the peak memory does not grow with the number
# of runs: `bash bench/sweep_runs.sh 10000` and `bash bench/sweep_runs.sh 100000`. Further
# arguments go to `routh sweep` (e.g. `--no-batch` for the one-at-a-time integrator, or
# `--columns all` for every column, the table of the runs recorded before issue 34: the
# default columns are the final state and the integrals).
set -euo pipefail
cd "$(dirname "$0")/.."
runs="${1:-100000}"
shift || true
spins=20
tilts=$((runs / spins))
cargo build --release --quiet
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
sed '/^\[sweep\]/,$d' cases/sweep.toml > "$dir/case.toml"
cat >> "$dir/case.toml" <<TOML
[sweep]
tilt = { range = [0.2, 1.5], n = $tilts }
spin = { range = [3.0, 7.0], n = $spins }
TOML
echo "runs: $((tilts * spins)) ($tilts tilts x $spins spins); extra options: ${*:-none}"
echo "load before: $(uptime)"
/usr/bin/time -f "wall %e s, user %U s, system %S s, peak RSS %M KiB" \
    target/release/routh sweep --case "$dir/case.toml" --t-end 10 --rtol 1e-10 --atol 1e-10 \
    --threads 2 --out "$dir/sweep.parquet" "$@"
echo "load after: $(uptime)"
ls -l "$dir/sweep.parquet"
