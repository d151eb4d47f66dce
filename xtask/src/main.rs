//! Tasks of the routh workspace, run as `cargo xtask <task>` (an alias in `.cargo/config.toml`).
//!
//! * `kernels`: writes `crates/routh-ball/src/kernels.rs`, the generated Taylor kernels of
//!   the model families (`routh_ball::families`), from the tapes recorded through the one
//!   generic field. The test `kernels::generated_kernels_are_up_to_date` of the library's
//!   suite (`cargo test -p routh --test suite kernels::`) fails while the checked-in file
//!   differs from what this writes.
//! * `explorer [--check]`: builds `crates/routh-wasm` for `wasm32-unknown-unknown` (profile
//!   `wasm`) and writes it to `assets/explorer/routh_wasm.wasm`, which `routh explore` inlines
//!   in its page (`routh_io::explore`); with `--check`, fails (exit 1) while the committed file
//!   differs from the fresh build (`.ci/run`). The paths of the workspace and of Cargo's
//!   registry are remapped in the build, so that the bytes do not depend on where they are;
//!   they do depend on the Rust toolchain (a new rustc: run `cargo xtask explorer` again).

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

/// The WebAssembly of the explorer, from the workspace's root (`routh_io::explore::WASM_PATH`).
const EXPLORER_WASM: &str = "assets/explorer/routh_wasm.wasm";

/// Build `routh-wasm` for the browser and return the bytes of the module.
fn build_explorer(root: &Path) -> Result<Vec<u8>, String> {
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")))
        .ok_or("neither CARGO_HOME nor HOME is set")?;
    let flags = [
        format!("--remap-path-prefix={}=/routh", root.display()),
        format!("--remap-path-prefix={}=/cargo", cargo_home.display()),
    ]
    .join("\x1f");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let target_dir = root.join("target/explorer");
    let status = Command::new(cargo)
        .current_dir(root)
        .env("CARGO_ENCODED_RUSTFLAGS", flags)
        .args([
            "build",
            "--package",
            "routh-wasm",
            "--target",
            "wasm32-unknown-unknown",
        ])
        .args(["--profile", "wasm", "--target-dir"])
        .arg(&target_dir)
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if !status.success() {
        return Err(format!("cargo build of routh-wasm failed ({status})"));
    }
    let built = target_dir.join("wasm32-unknown-unknown/wasm/routh_wasm.wasm");
    std::fs::read(&built).map_err(|e| format!("cannot read {}: {e}", built.display()))
}

/// `cargo xtask explorer [--check]`.
fn explorer(check: bool) -> Result<(), String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .ok_or("xtask has no parent directory")?;
    let wasm = build_explorer(root)?;
    let path = root.join(EXPLORER_WASM);
    if check {
        let committed =
            std::fs::read(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
        if committed != wasm {
            return Err(format!(
                "{} ({} bytes) differs from a fresh build of crates/routh-wasm ({} bytes): run \
                 `cargo xtask explorer` and commit it",
                path.display(),
                committed.len(),
                wasm.len()
            ));
        }
        eprintln!("{} is current ({} bytes)", path.display(), wasm.len());
        return Ok(());
    }
    std::fs::write(&path, &wasm).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    eprintln!("wrote {} ({} bytes)", path.display(), wasm.len());
    Ok(())
}

fn main() -> ExitCode {
    let task = std::env::args().nth(1);
    match task.as_deref() {
        Some("kernels") => {
            let path = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("../crates/routh-ball")
                .join(routh_ball::families::KERNELS);
            match std::fs::write(&path, routh_ball::families::kernels_source()) {
                Ok(()) => {
                    eprintln!("wrote {}", path.display());
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("cannot write {}: {e}", path.display());
                    ExitCode::from(2)
                }
            }
        }
        Some("explorer") => {
            let check = match std::env::args().nth(2).as_deref() {
                None => false,
                Some("--check") => true,
                Some(other) => {
                    eprintln!("cargo xtask explorer: unknown option `{other}` (only --check)");
                    return ExitCode::from(2);
                }
            };
            match explorer(check) {
                Ok(()) => ExitCode::SUCCESS,
                Err(e) => {
                    eprintln!("cargo xtask explorer: {e}");
                    ExitCode::from(if check { 1 } else { 2 })
                }
            }
        }
        _ => {
            eprintln!(
                "usage: cargo xtask kernels            (writes the generated Taylor kernels)\n       \
                 cargo xtask explorer [--check]  (builds the explorer's WebAssembly)"
            );
            ExitCode::from(2)
        }
    }
}
