#!/usr/bin/env bash
# Run the binary on ~220 bad or unusual inputs and tabulate the outcomes by class:
# `refused` = exit 2 with a message and no panic; `ok` = exit 0 with no NaN in its output;
# anything else (a panic, exit 101 or 134, a NaN printed with exit 0, a leftover temporary
# file) is counted as `WRONG` and makes the script fail. Class `signals`: a long run sent SIGTERM,
# counted under `refused` when it ends within a second, failing, with no temporary file. Usage: bash bench/bad_inputs.sh [BINARY]
set -uo pipefail
cd "$(dirname "$0")/.."
BIN=${1:-target/release/routh}
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
DEFAULT=cases/default.toml
declare -A REFUSED OK WRONG
wrong_total=0

# try CLASS EXPECT ARGS...: EXPECT is `refused`, `ok` or `any` (either outcome acceptable).
try() {
  local class=$1 expect=$2; shift 2
  local out err code
  out=$(timeout 60 "$BIN" "$@" 2>"$DIR/err") ; code=$?
  err=$(cat "$DIR/err")
  local verdict
  if [[ $code == 2 && -n $err && $err != *panicked* ]]; then verdict=refused
  elif [[ $code == 0 && $out != *NaN* && $out != *": null"* ]]; then verdict=ok
  else verdict=WRONG; fi
  if ls -a "$DIR" | grep -q '\.tmp-'; then verdict=WRONG; fi
  if [[ $expect != any && $verdict != "$expect" ]]; then verdict=WRONG; fi
  case $verdict in
    refused) REFUSED[$class]=$(( ${REFUSED[$class]:-0} + 1 ));;
    ok) OK[$class]=$(( ${OK[$class]:-0} + 1 ));;
    *) WRONG[$class]=$(( ${WRONG[$class]:-0} + 1 )); wrong_total=$((wrong_total + 1))
       echo "WRONG ($class, exit $code): $* :: ${err:0:200}" >&2;;
  esac
  CLASSES[$class]=1
}
declare -A CLASSES

# A case file from the default with one line replaced.
edit() { sed "s|$1|$2|" "$DEFAULT" > "$DIR/c.toml"; echo "$DIR/c.toml"; }

# Body parameters: non-finite, non-positive, |a| >= R, triangle rule, huge and tiny.
for kv in "m = 1.0|m = 0" "m = 1.0|m = -1" "m = 1.0|m = nan" "m = 1.0|m = inf" "m = 1.0|m = 1e300" \
          "R = 1.0|R = 0" "R = 1.0|R = -2" "R = 1.0|R = 1e200" "a = 0.3|a = 1.0" \
          "a = 0.3|a = -1.5" "a = 0.3|a = nan" "I1 = 0.4|I1 = 0" "I1 = 0.4|I1 = 1e300" "I3 = 0.5|I3 = 0.9" \
          "I3 = 0.5|I3 = -0.5" "G = 9.81|G = -1" "G = 9.81|G = inf" "G = 9.81|G = 1e308" "m = 1.0|m = \"one\""; do
  for cmd in simulate exact steady; do try body refused $cmd --case "$(edit "${kv%%|*}" "${kv##*|}")" --t-end 1; done
done
# A tiny mass is a valid body: simulate and exact accept it; steady accepts it (printing its
# threshold of ~4e-150 in scientific notation), or may refuse it with a message.
for cmd in simulate exact steady; do try body any $cmd --case "$(edit "m = 1.0" "m = 1e-300")"; done
# The default case in units of mass 1e-300 (the moments scaled with m) and of mass 1e300 with
# lengths 1e-100 (so that H2, of the units of an inertia squared, stays within f64): the same
# body in other units, which must be solved as the default case is (issue 33: refused before by
# the absolute range 1.6e-51 to 5.5e51 of I + m r^2; the answers, the default's after scaling
# back, are checked by crates/routh-cli/tests/suite/cli.rs and crates/routh/tests/suite/integrators.rs).
units() { sed "$1" "$DEFAULT" > "$DIR/u.toml"; echo "$DIR/u.toml"; }
for cmd in simulate exact steady; do
  try body ok $cmd --case "$(units 's|m = 1.0|m = 1e-300|; s|I1 = 0.4|I1 = 4e-301|; s|I3 = 0.5|I3 = 5e-301|')"
  try body ok $cmd --case "$(units 's|m = 1.0|m = 1e300|; s|R = 1.0|R = 1e-100|; s|a = 0.3|a = 3e-101|; s|I1 = 0.4|I1 = 4e99|; s|I3 = 0.5|I3 = 5e99|; s|G = 9.81|G = 9.81e-100|')"
done
# steady takes no --t-end: rerun the steady ones properly
for kv in "m = 1.0|m = 1e300" "a = 0.3|a = 1.0" "G = 9.81|G = -1"; do
  try body refused steady --case "$(edit "${kv%%|*}" "${kv##*|}")"
done
# Initial states: non-unit, non-finite, both or neither of omega and M, overflow.
for kv in "gamma = \[0.29552020666133955, 0.0, 0.955336489125606\]|gamma = [1, 1, 0]" \
          "gamma = \[0.29552020666133955, 0.0, 0.955336489125606\]|gamma = [0, 0, 0]" \
          "gamma = \[0.29552020666133955, 0.0, 0.955336489125606\]|gamma = [nan, 0, 1]" \
          "omega = \[0.5, 0.2, 8.0\]|omega = [0, 0, 1e200]" "omega = \[0.5, 0.2, 8.0\]|omega = [inf, 0, 1]" \
          "omega = \[0.5, 0.2, 8.0\]|M = [0, 0, 1e300]" "omega = \[0.5, 0.2, 8.0\]|" \
          "omega = \[0.5, 0.2, 8.0\]|omega = [1, 2]"; do
  for cmd in simulate exact steady; do try state refused $cmd --case "$(edit "${kv%%|*}" "${kv##*|}")"; done
done
# Case file schema: unknown keys and tables, top-level keys, malformed TOML, missing files.
for kv in "\[body\]|t_end = 5\n[body]" "\[integration\]|[extra]\nx = 1\n[integration]" "G = 9.81|G = 9.81\nmass = 2" \
          "\[initial\]|[body.sub]\n[initial]" "\[body\]|[body" "rtol = 1e-12|rtol = 1" "rtol = 1e-12|rtol = 1e-16" \
          "atol = 1e-12|atol = 0" "t_end = 100.0|t_end = -1" "t_end = 100.0|t_end = nan" "rtol = 1e-12|max_steps = 0"; do
  for cmd in simulate exact steady; do try schema refused $cmd --case "$(edit "${kv%%|*}" "${kv##*|}")"; done
done
try schema refused simulate --case /nonexistent/case.toml
try schema refused simulate --case "$DIR"
# Optional tables and keys: no [integration], no G, I2 given.
sed '/\[integration\]/,$d; /^G =/d' "$DEFAULT" > "$DIR/bare.toml"
for cmd in simulate exact steady; do try optional ok $cmd --case "$DIR/bare.toml"; done
# Options: bad numbers, sizes, limits.
for args in "--t-end nan" "--t-end -1" "--t-end inf" "--rtol 0" "--rtol 1" "--rtol 1e-20" "--atol -1" \
            "--samples 0" "--samples 1" "--samples 18446744073709551615" "--samples 100000000000" \
            "--samples -5" "--samples 1e11" "--method euler" "--method rk4:0" "--method rk4:99999999999" \
            "--max-steps 0" "--max-steps 10 --t-end 100" "--t-end 1e6 --max-steps 1000" \
            "--project --project-every 0" "--project-every 10" "--project --project-every -1" \
            "--project --project-every nan"; do
  # shellcheck disable=SC2086
  try options refused simulate $args --out "$DIR/x.csv"
done
for args in "--t nan" "--t inf" "--samples 1" "--samples 0"; do
  # shellcheck disable=SC2086
  try options refused exact $args
done
for args in "--samples 1" "--samples 18446744073709551615" "--t-end -1" "--format gif"; do
  # shellcheck disable=SC2086
  try options refused plot $args --out "$DIR/plots"
done
# Output targets: devices, pipes, symlinks, directories, missing directories, stdout.
try output ok simulate --t-end 1 --samples 3 --out /dev/null
try output ok simulate --t-end 1 --samples 3 --out -
try output ok simulate --t-end 1 --samples 3
ln -s real.csv "$DIR/link.csv"; try output ok simulate --t-end 1 --samples 3 --out "$DIR/link.csv"
[[ -L $DIR/link.csv && -f $DIR/real.csv ]] || { echo "WRONG: the symlink was replaced" >&2; wrong_total=$((wrong_total+1)); }
mkfifo "$DIR/fifo"; (cat "$DIR/fifo" > "$DIR/from-fifo" &); try output ok simulate --t-end 1 --samples 3 --out "$DIR/fifo"
try output refused simulate --t-end 1 --out "$DIR"
try output refused simulate --t-end 1 --out "$DIR/no/such/dir/x.csv"
try output refused simulate --t-end 1 --out ""
# Temporary names of long target names (255 bytes is the file system's limit of a name).
for length in 254 255; do
  name=$(printf 'x%.0s' $(seq $((length - 4)))).csv
  try output ok simulate --t-end 1 --samples 3 --out "$DIR/$name"; rm -f "$DIR/$name"
done
# Errors name the target, not its temporary file.
try output refused sweep --case cases/sweep.toml --out "$DIR/no/such/dir/x.csv"
grep -q '\.tmp-' "$DIR/err" && { echo "WRONG: the error names the temporary file: $(cat "$DIR/err")" >&2; wrong_total=$((wrong_total+1)); }
# One output stream per destination.
try output refused sweep --case cases/sweep.toml --out -
try output ok audit --points 1 --markdown -
try output ok audit --points 1 --markdown - --json
for cmd in plot animate; do try output refused $cmd --t-end 1 --samples 10 --out -; done
try output refused diagram --grid 4 --tilts 4 --out -
# --resume of a table whose last row was cut short: dropped and said.
sed 's/t_end = 100.0/t_end = 0.5/' "$DEFAULT" > "$DIR/small.toml"
printf '\n[sweep]\ntilt = { values = [0.1, 0.2, 0.3] }\n' >> "$DIR/small.toml"
"$BIN" sweep --case "$DIR/small.toml" --out "$DIR/table.csv" >/dev/null
head -3 "$DIR/table.csv" > "$DIR/cut.csv"; sed -n 4p "$DIR/table.csv" | cut -d, -f1-14 | tr -d '\n' >> "$DIR/cut.csv"
try output ok sweep --case "$DIR/small.toml" --out "$DIR/cut.csv" --resume
grep -q 'dropped the last row' "$DIR/err" || { echo "WRONG: --resume kept a cut row silently" >&2; wrong_total=$((wrong_total+1)); }
cmp -s "$DIR/cut.csv" "$DIR/table.csv" || { echo "WRONG: the resumed table differs" >&2; wrong_total=$((wrong_total+1)); }
# Sizes: bounded before any work, refused with the key, the value and the rule.
for args in "audit --points 1000000000000" "audit --points 100001" "audit --points 0" \
            "sweep --case cases/sweep.toml --threads 10000" "diagram --grid 5001" "diagram --tilts 5001" \
            "diagram --loop-points 5001" "diagram --grid 388" "plot --samples 1000001" "animate --samples 1000001"; do
  # shellcheck disable=SC2086
  try sizes refused $args
done
for sweep in "tilt = { range = [0.1, 1.0], n = 1000000000000 }" \
             "samples = 9223372036854775807\ntilt = { range = [0.1, 1.0] }" \
             "tilt = { range = [0.1, 1.0], n = 2000 }\nspin = { range = [1.0, 9.0], n = 2000 }"; do
  (cat "$DEFAULT"; printf "\n[sweep]\n$sweep\n") > "$DIR/big.toml"
  try sizes refused sweep --case "$DIR/big.toml"
done
# Signals: SIGTERM half a second into a long run ends it within a second, with a failure exit
# status and no temporary file (the sweep writes the rows done, whole, and ends with 130).
sed 's/t_end = 100.0/t_end = 1e9/' "$DEFAULT" > "$DIR/long.toml"
printf '\n[sweep]\ntilt = { values = [0.1, 0.2, 0.3, 0.4] }\n' >> "$DIR/long.toml"
signal_try() {
  local start end ms code
  "$BIN" "$@" >/dev/null 2>"$DIR/err" & local pid=$!
  sleep 0.5
  start=$(date +%s%N)
  # A run that ended before the signal tested nothing: wrong (the command must run longer).
  local sent=1
  kill -TERM $pid 2>/dev/null || sent=0
  wait $pid; code=$?; end=$(date +%s%N)
  ms=$(( (end - start) / 1000000 ))
  if [[ $sent == 1 && $code != 0 && $ms -lt 1000 ]] && ! ls -a "$DIR" | grep -q '\.tmp-'; then
    REFUSED[signals]=$(( ${REFUSED[signals]:-0} + 1 ))
  else
    WRONG[signals]=$(( ${WRONG[signals]:-0} + 1 )); wrong_total=$((wrong_total + 1))
    echo "WRONG (signals, exit $code, $ms ms): $*" >&2
  fi
  echo "signals: $1 ended $ms ms after SIGTERM (exit $code, signal sent: $sent)" >&2
}
signal_try sweep --case "$DIR/long.toml" --threads 1 --out "$DIR/long.csv"
signal_try simulate --case "$DIR/long.toml" --samples 100 --out "$DIR/long.csv"
signal_try exact --case "$DIR/long.toml" --t 1e4 --samples 10000000 --out "$DIR/long.csv"
signal_try audit --points 100000
signal_try diagram --grid 387 --tilts 5000 --loop-points 5000 --out "$DIR/figures"
# CSV files for plot and animate: empty, header only, one row, NaN, inf, ragged, text, no t,
# decreasing t, repeated column.
"$BIN" simulate --t-end 1 --samples 4 --full --out "$DIR/good.csv" >/dev/null
head -1 "$DIR/good.csv" > "$DIR/header.csv"
head -2 "$DIR/good.csv" > "$DIR/one.csv"
sed '3s/^\([^,]*\),[^,]*/\1,NaN/' "$DIR/good.csv" > "$DIR/nan.csv"
sed '3s/^\([^,]*\),[^,]*/\1,inf/' "$DIR/good.csv" > "$DIR/inf.csv"
sed '3s/$/,7/' "$DIR/good.csv" > "$DIR/ragged.csv"
sed '3s/^\([^,]*\),[^,]*/\1,abc/' "$DIR/good.csv" > "$DIR/text.csv"
sed '1s/^t,/time,/' "$DIR/good.csv" > "$DIR/no-t.csv"
(head -1 "$DIR/good.csv"; tail -n +2 "$DIR/good.csv" | sort -r -t, -k1 -g) > "$DIR/backwards.csv"
sed '1s/gamma2/gamma1/' "$DIR/good.csv" > "$DIR/repeated.csv"
: > "$DIR/empty.csv"
printf '\0\1\2garbage' > "$DIR/binary.csv"
for f in empty header one nan inf ragged text no-t backwards repeated binary; do
  try csv refused plot --csv "$DIR/$f.csv" --out "$DIR/plots"
  try csv refused animate --csv "$DIR/$f.csv" --out "$DIR/plots"
done
try csv ok plot --csv "$DIR/good.csv" --out "$DIR/plots"
try csv ok animate --csv "$DIR/good.csv" --out "$DIR/plots"

# The newer commands and the contact law (issues 35, 36, 37): sections, spectra, the explorer
# page, and case files of the sliding and the rubber ball.
for args in "--surface gamma7=0" "--surface gamma1" "--surface gamma1=nan" "--surface =0" \
            "--surface gamma1=0 --direction sideways" "--surface gamma1=0 --initial 0" \
            "--surface gamma1=0 --method taylor" "--surface gamma1=0 --t-end -1" \
            "--surface gamma1=0 --axes gamma3" "--surface gamma1=0 --rtol 1"; do
  try new refused section $args --out "$DIR/sec"
done
try new ok section --surface "gamma1 = 0" --t-end 5 --initial 3 --out "$DIR/sec" --json
for args in "--t-end 0" "--t-end nan" "--transient -1" "--interval 0" "--method taylor" "--rtol 1e-20"; do
  try new refused lyapunov $args
done
try new ok lyapunov --t-end 5 --json
try new ok explore --out "$DIR/page" --json
# A directory of figures or pages that does not exist is made, as `plot` and `animate` do.
try new ok explore --out "$DIR/no/such/dir" --json
try new ok section --surface "gamma1 = 0" --t-end 5 --initial 3 --out "$DIR/no/such/dir" --json
try new refused explore --out ""
TIPPE=cases/tippe_top.toml
tippe() { sed "s|$1|$2|" "$TIPPE" > "$DIR/t.toml"; echo "$DIR/t.toml"; }
for kv in "mu = 0.3|mu = -1" "mu = 0.3|mu = nan" "mu = 0.3|mu = inf" "law = \"sliding\"|law = \"glue\"" \
          "friction = \"viscous\"|friction = \"honey\"" "velocity = \[0.0, 0.0, 0.0\]|velocity = [0.0, 0.0, 1.0]" \
          "velocity = \[0.0, 0.0, 0.0\]|velocity = [nan, 0.0, 0.0]" "mu = 0.3|mu = 0.3\nstiffness = 2"; do
  try new refused simulate --case "$(tippe "${kv%%|*}" "${kv##*|}")" --t-end 1
done
try new ok simulate --case "$TIPPE" --t-end 1 --json
for cmd in exact steady sweep lyapunov; do try new refused $cmd --case "$TIPPE"; done
# The fast indicators and the chart of regimes (issue 36): routh megno.
for args in "--t-end 0" "--t-end nan" "--method taylor" "--method auto" "--rtol 1e-20" \
            "--x initial.tilt=0:1:4" "--x initial.tilt=0:1:4 --y initial.tilt=0:1:4 --out $DIR/chart" \
            "--x nosuch.key=0:1:4 --y initial.spin=1:2:4 --out $DIR/chart" \
            "--x initial.tilt=0:1:0 --y initial.spin=1:2:4 --out $DIR/chart" \
            "--x initial.tilt=nan:1:4 --y initial.spin=1:2:4 --out $DIR/chart"; do
  try new refused megno $args
done
try new ok megno --t-end 5 --json
try new refused megno --case "$TIPPE"
# The user events of a sweep (issue 34): the [sweep] key `events` and the option --events.
sed 's/t_end = 100.0/t_end = 1.0/' "$DEFAULT" > "$DIR/events.toml"
printf '\n[sweep]\ntilt = { values = [0.3, 0.6] }\n' >> "$DIR/events.toml"
for listed in '["omega1 = 0"]' '["gamma1 = inf"]' '["gamma1 = nan up"]' '["gamma1 = 0 sideways"]' \
              '["gamma1 = 0:up"]' '"gamma1 = 0"' '[1.0]' '[["gamma1 = 0"]]' '{ a = 1 }'; do
  (cat "$DIR/events.toml"; printf 'events = %s\n' "$listed") > "$DIR/e.toml"
  try new refused sweep --case "$DIR/e.toml" --out "$DIR/events.csv"
done
for events in "gamma1 = inf" "gamma4 = 0" "gamma1 = 0:up" "gamma1 = 0 left" "gamma1 = 0," "" \
              "$(printf 'gamma1 = 0,%.0s' $(seq 32))gamma1 = 0"; do
  try new refused sweep --case "$DIR/events.toml" --events "$events" --out "$DIR/events.csv"
done
try new refused sweep --case "$DIR/events.toml" --events "gamma1 = 0" --columns event1_count --out "$DIR/events.csv"
[[ -e $DIR/events.csv ]] && { echo "WRONG: a refused sweep wrote its table" >&2; wrong_total=$((wrong_total+1)); }
try new ok sweep --case "$DIR/events.toml" --events "gamma1 = 0,M1 = -2.5e-1 up" --out "$DIR/events.csv"
RUBBER=cases/rubber.toml
rubber() { sed "s|$1|$2|" "$RUBBER" > "$DIR/r.toml"; echo "$DIR/r.toml"; }
for kv in "omega = \[-4.0, 1.0, 3.0\]|omega = [-4.0, 1.0, 3.1]" "omega = \[-4.0, 1.0, 3.0\]|omega = [nan, 1.0, 3.0]" \
          "law = \"rubber\"|law = \"rubber\"\nmu = 0.3" "law = \"rubber\"|law = \"rubber\"\nfriction = \"viscous\"" \
          "omega = \[-4.0, 1.0, 3.0\]|omega = [-4.0, 1.0, 3.0]\nvelocity = [0.0, 0.0, 0.0]"; do
  try new refused simulate --case "$(rubber "${kv%%|*}" "${kv##*|}")" --t-end 1
done
try new refused simulate --case "$RUBBER" --t-end 1 --project
try new ok simulate --case "$RUBBER" --t-end 1 --json
for cmd in exact steady sweep lyapunov megno; do try new refused $cmd --case "$RUBBER"; done

printf '| class | tried | refused (exit 2, message) | ok (exit 0, no NaN) | wrong |\n|---|---|---|---|---|\n'
total=0
for class in body state schema optional options output csv sizes signals new; do
  r=${REFUSED[$class]:-0}; o=${OK[$class]:-0}; w=${WRONG[$class]:-0}
  total=$((total + r + o + w))
  printf '| %s | %d | %d | %d | %d |\n' "$class" $((r + o + w)) "$r" "$o" "$w"
done
printf '| all | %d | | | %d |\n' "$total" "$wrong_total"
exit $(( wrong_total > 0 ))
