//! Tasks of the routh workspace, run as `cargo xtask <task>` (an alias in `.cargo/config.toml`).
//!
//! * `kernels`: writes `crates/routh-ball/src/kernels.rs`, the generated Taylor kernels of
//!   the model families (`routh_ball::families`), from the tapes recorded through the one
//!   generic field. The test `kernels::generated_kernels_are_up_to_date` of the library's
//!   suite (`cargo test -p routh --test suite kernels::`) fails while the checked-in file
//!   differs from what this writes.

use std::path::Path;
use std::process::ExitCode;

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
        _ => {
            eprintln!("usage: cargo xtask kernels   (writes the generated Taylor kernels)");
            ExitCode::from(2)
        }
    }
}
