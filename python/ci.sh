#!/usr/bin/env bash
# CI for the Python bindings: a fresh virtual environment under target/; the wheel built the way
# `pip install ./python` builds it on a fresh machine (maturin as the PEP 517 backend, in an
# isolated build environment) and installed from the file; the pytest suite; the example script
# of python/examples run to its figure. Exits non-zero on any failure, including pytest's exit
# code 5 ("no tests collected").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="$root/target/python-venv"
wheels="$root/target/wheels"
# The bindings' own target directory: their dependencies (numpy's, pyo3's) take other features
# than the command-line tool's, so that nothing of target/release would be shared, and .ci/run
# builds the tool's release binary there at the same time (each build holds its directory).
build="$root/target/python"
command -v python3 >/dev/null || { echo "python3 not found: CPython >= 3.9 is required" >&2; exit 1; }
command -v cargo >/dev/null || { echo "cargo not found: the machine's Rust toolchain is required" >&2; exit 1; }
python3 --version
cargo --version
# The bindings' Rust code is a crate of its own, outside the main crate's `cargo clippy`: linted
# here, warnings as errors, and its formatting checked (where the toolchain has the two
# components; a toolchain without them is said, not failed).
if cargo fmt --version >/dev/null 2>&1 && cargo clippy --version >/dev/null 2>&1; then
    cargo fmt --manifest-path "$root/python/Cargo.toml" --check
    CARGO_TARGET_DIR="$build" cargo clippy --manifest-path "$root/python/Cargo.toml" --release --all-targets -- -D warnings
else
    echo "rustfmt or clippy not installed: the bindings' lint is skipped" >&2
fi
rm -rf "$venv"
python3 -m venv "$venv"
pip() { "$venv/bin/pip" --disable-pip-version-check "$@"; }
# Test and example dependencies: SciPy is the independent integrator of the tests, matplotlib
# draws the example's figure, mypy checks the type stub.
pip install --quiet pytest numpy scipy matplotlib mypy pyarrow pandas "dask[distributed]"
# The wheel: `pip wheel` runs the build backend declared in python/pyproject.toml (maturin,
# fetched into an isolated environment), exactly as `pip install ./python` does.
rm -rf "$wheels"
CARGO_TARGET_DIR="$build" "$venv/bin/pip" --disable-pip-version-check wheel --no-deps --wheel-dir "$wheels" "$root/python"
wheel=$(ls "$wheels"/routh-*.whl)
echo "built $wheel"
pip install --force-reinstall --no-deps "$wheel"
# The stub and the marker of a typed package are in the wheel.
"$venv/bin/python" - "$wheel" <<'PY'
import sys, zipfile
names = zipfile.ZipFile(sys.argv[1]).namelist()
for wanted in ("routh/__init__.pyi", "routh/py.typed"):
    if wanted not in names:
        sys.exit(f"{wanted} missing from the wheel: {names}")
print("wheel holds", ", ".join(n for n in names if n.startswith("routh/")))
PY
# The stub agrees with the module (mypy's stubtest: every name, signature and default), and
# the example type-checks against it.
(cd "$root/target" && "$venv/bin/python" -m mypy.stubtest routh --allowlist "$root/python/stubtest-allowlist.txt")
"$venv/bin/python" -m mypy --ignore-missing-imports "$root/python/examples/nutation.py"
# The audit test compares with the command-line tool's JSON; the sweep test reads its Parquet
# output back (the binary's default feature `parquet`).
(cd "$root" && cargo build --release --bin routh)
status=0
(cd "$root" && "$venv/bin/python" -m pytest -p no:cacheprovider -q python/tests) || status=$?
if [ "$status" -eq 5 ]; then
    echo "pytest collected no tests: failing" >&2
    exit 1
fi
if [ "$status" -ne 0 ]; then
    exit "$status"
fi
# The example script, run as a script (its cells in order), writes its figure.
figure="$root/target/python-example.png"
rm -f "$figure"
(cd "$root/python/examples" && ROUTH_EXAMPLE_FIGURE="$figure" "$venv/bin/python" nutation.py)
test -s "$figure" || { echo "the example wrote no figure" >&2; exit 1; }
echo "example figure: $figure"
