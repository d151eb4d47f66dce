//! Writing a sweep's table as its runs finish, whatever the format: the writer's trait, the
//! temporary file beside the target and the checks of a resumed row, shared by the CSV
//! ([`super::csv`]) and Parquet (`super::parquet`) writers. The rows go to a temporary file
//! beside the target, flushed chunk by chunk; the temporary file is renamed over the target
//! only when the sweep finishes or stops cleanly, so the target is never half-written. With
//! `--resume` the rows of an existing target are checked against the sweep (same case,
//! settings and design), copied, and their runs skipped.

use super::record::Row;
use crate::error::{AppError, AppResult as Result, FileError};
use std::collections::HashSet;
use std::path::{Path, PathBuf};

/// A table being written.
pub trait TableWriter: Send {
    /// Append the rows of finished runs (made durable before returning).
    fn write(&mut self, rows: &[Row]) -> Result<()>;
    /// Close the file and move it to the target.
    fn finish(self: Box<Self>) -> Result<()>;
}

/// What `--resume` found in an existing table.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Resumed {
    /// The runs whose rows were kept (and are not run again).
    pub done: HashSet<u64>,
    /// The last row, cut short (a process ended while writing it), dropped: its run is run
    /// again.
    pub dropped: Option<PartialRow>,
}

/// A last row cut short, dropped by `--resume`.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct PartialRow {
    /// Its line in the file (the header is line 1).
    pub line: u64,
    /// The columns it holds.
    pub columns: usize,
    /// The columns of a row.
    pub expected: usize,
    /// Whether it ends with a line break (every complete row does).
    pub line_break: bool,
}

impl std::fmt::Display for PartialRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "line {} holds {} of {} columns{}",
            self.line,
            self.columns,
            self.expected,
            if self.line_break {
                ""
            } else {
                " and no line break"
            }
        )
    }
}

/// A temporary file beside `target`, removed unless committed.
pub struct Staged {
    /// The temporary file.
    pub tmp: PathBuf,
    /// The target.
    pub target: PathBuf,
    committed: bool,
}

impl Staged {
    /// A temporary path beside `target` ([`crate::output`]'s temporary name).
    pub fn beside(target: &Path) -> Result<Self> {
        let tmp = crate::output::temporary_beside(target, "out")?;
        // A signal that ends the process (a second one, after the sweep's stop) removes it.
        crate::output::register_temporary(&tmp);
        Ok(Staged {
            tmp,
            target: target.to_path_buf(),
            committed: false,
        })
    }

    /// An I/O error on the temporary file, named by the target (the file the user asked
    /// for; the temporary is an implementation detail).
    pub fn io(&self, source: std::io::Error) -> AppError {
        FileError::Io {
            path: self.target.clone(),
            source,
        }
        .into()
    }

    /// Rename the temporary file over the target.
    pub fn commit(mut self) -> Result<()> {
        std::fs::rename(&self.tmp, &self.target).map_err(|e| self.io(e))?;
        self.committed = true;
        Ok(())
    }
}

impl Drop for Staged {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_file(&self.tmp);
        }
        crate::output::unregister_temporary(&self.tmp);
    }
}

/// The error for a file that is not a stopped run of this sweep.
pub fn not_this_sweep(path: &Path, why: impl std::fmt::Display) -> AppError {
    FileError::Table {
        origin: path.display().to_string(),
        message: format!("cannot resume: {why}; remove the file or choose another --out"),
    }
    .into()
}

/// The error for a file whose columns `found` are not the columns `asked` of this sweep,
/// naming those in one and not in the other (the columns are chosen by `--columns` or the
/// `[sweep]` key `columns`, so a file is resumed with the columns it was written with).
pub fn other_columns(path: &Path, found: &[String], asked: &[String]) -> AppError {
    let missing = |from: &[String], of: &[String]| -> String {
        let names: Vec<&str> = from
            .iter()
            .filter(|n| !of.contains(n))
            .map(String::as_str)
            .collect();
        if names.is_empty() {
            "none".into()
        } else {
            names.join(", ")
        }
    };
    not_this_sweep(
        path,
        format!(
            "its columns are not those asked for (the file's only: {}; asked for only: {}): \
             resume with the columns it was written with (--columns, or `columns` in [sweep])",
            missing(found, asked),
            missing(asked, found)
        ),
    )
}
