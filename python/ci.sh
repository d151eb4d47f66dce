#!/usr/bin/env bash
# CI for the Python bindings: a fresh virtual environment under target/, maturin, a release
# build of the extension installed into it, then the pytest suite. Exits non-zero on any
# failure, including pytest's exit code 5 ("no tests collected").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/target/python-venv"
command -v python3 >/dev/null || { echo "python3 not found: CPython >= 3.9 is required" >&2; exit 1; }
command -v cargo >/dev/null || { echo "cargo not found: the machine's Rust toolchain is required" >&2; exit 1; }
python3 --version
cargo --version
rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check maturin pytest numpy pyarrow pandas "dask[distributed]"
"$venv/bin/maturin" --version
# maturin develop installs into the environment named by VIRTUAL_ENV.
(cd "$root/python" && VIRTUAL_ENV="$venv" PATH="$venv/bin:$PATH" "$venv/bin/maturin" develop --release)
status=0
(cd "$root" && "$venv/bin/python" -m pytest -p no:cacheprovider -q python/tests) || status=$?
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests: failing" >&2
    exit 1
fi
exit "$status"
