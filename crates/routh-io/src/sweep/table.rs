//! Writing a sweep's table as its runs finish: CSV (small sweeps) or Parquet (feature
//! `parquet`). The rows go to a temporary file beside the target, flushed chunk by chunk; the
//! temporary file is renamed over the target only when the sweep finishes or stops cleanly,
//! so the target is never half-written. With `--resume` the rows of an existing target are
//! checked against the sweep (same case, settings and design), copied, and their runs
//! skipped.

use super::record::{columns, Row};
use super::runner::Sweep;
use crate::error::{AppError, AppResult as Result, FileError, RouthError};
use std::collections::HashSet;
use std::io::{BufRead, BufWriter, Write};
use std::path::{Path, PathBuf};

/// A table being written.
pub trait TableWriter: Send {
    /// Append the rows of finished runs (made durable before returning).
    fn write(&mut self, rows: &[Row]) -> Result<()>;
    /// Close the file and move it to the target.
    fn finish(self: Box<Self>) -> Result<()>;
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
    /// A temporary path beside `target`.
    pub fn beside(target: &Path) -> Result<Self> {
        let name = target.file_name().ok_or_else(|| RouthError::Option {
            name: "out",
            value: target.display().to_string(),
            rule: "must name a file",
        })?;
        let tmp = target.with_file_name(format!(
            ".{}.tmp-{}",
            name.to_string_lossy(),
            std::process::id()
        ));
        // A signal that ends the process (a second one, after the sweep's stop) removes it.
        crate::output::register_temporary(&tmp);
        Ok(Staged {
            tmp,
            target: target.to_path_buf(),
            committed: false,
        })
    }

    /// An I/O error on the temporary file.
    pub fn io(&self, source: std::io::Error) -> AppError {
        FileError::Io {
            path: self.tmp.clone(),
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

/// Check that `values` (the swept values and settings read from row `run` of an existing
/// file) are those of run `run` of `sweep`, bit for bit.
pub fn check_resumed_row(sweep: &Sweep, path: &Path, run: u64, values: &[f64]) -> Result<()> {
    if run >= sweep.runs() {
        return Err(not_this_sweep(
            path,
            format!("run {run} is not a run of this sweep"),
        ));
    }
    let s = sweep.run_settings();
    let expected: Vec<f64> = sweep
        .design()
        .point(run)
        .into_iter()
        .chain([s.t_end, s.rtol, s.atol])
        .collect();
    if values
        .iter()
        .map(|v| v.to_bits())
        .ne(expected.iter().map(|v| v.to_bits()))
    {
        return Err(not_this_sweep(
            path,
            format!("run {run} has the values {values:?}, this sweep {expected:?} (swept quantities, t_end, rtol, atol)"),
        ));
    }
    Ok(())
}

/// A CSV table.
pub struct CsvTable {
    staged: Staged,
    file: BufWriter<std::fs::File>,
    sweep_settings: super::record::RunSettings,
}

impl CsvTable {
    /// Start writing `target`; with `resume`, copy the rows of an existing `target` and return
    /// the runs they hold.
    pub fn create(target: &Path, sweep: &Sweep, resume: bool) -> Result<(Self, HashSet<u64>)> {
        let header: Vec<String> = columns(&sweep.names()).into_iter().map(|c| c.0).collect();
        let header = header.join(",");
        let staged = Staged::beside(target)?;
        let file = std::fs::File::create(&staged.tmp).map_err(|e| staged.io(e))?;
        let mut file = BufWriter::new(file);
        writeln!(file, "{header}").map_err(|e| staged.io(e))?;
        let mut done = HashSet::new();
        if resume && target.exists() {
            let read_err = |source| FileError::Io {
                path: target.to_path_buf(),
                source,
            };
            let old = std::io::BufReader::new(std::fs::File::open(target).map_err(read_err)?);
            let mut lines = old.lines();
            let first = lines
                .next()
                .transpose()
                .map_err(read_err)?
                .unwrap_or_default();
            if first != header {
                return Err(not_this_sweep(
                    target,
                    "its columns differ from this sweep's",
                ));
            }
            let fixed = sweep.names().len() + 4;
            for line in lines {
                let line = line.map_err(read_err)?;
                let fields: Vec<&str> = line.splitn(fixed + 2, ',').collect();
                let number = |i: usize| -> Result<f64> {
                    fields
                        .get(i)
                        .and_then(|f| f.parse().ok())
                        .ok_or_else(|| not_this_sweep(target, format!("a malformed row `{line}`")))
                };
                let run = number(0)? as u64;
                let values: Vec<f64> = (1..fixed).map(number).collect::<Result<_>>()?;
                check_resumed_row(sweep, target, run, &values)?;
                if fields.get(fixed) != Some(&sweep.run_settings().method.as_str()) {
                    return Err(not_this_sweep(
                        target,
                        format!("run {run} used another method"),
                    ));
                }
                if !done.insert(run) {
                    return Err(not_this_sweep(target, format!("run {run} appears twice")));
                }
                writeln!(file, "{line}").map_err(|e| staged.io(e))?;
            }
        }
        let table = CsvTable {
            staged,
            file,
            sweep_settings: sweep.run_settings(),
        };
        Ok((table, done))
    }
}

impl TableWriter for CsvTable {
    fn write(&mut self, rows: &[Row]) -> Result<()> {
        for row in rows {
            let line = row.csv_line(&self.sweep_settings);
            writeln!(self.file, "{line}").map_err(|e| self.staged.io(e))?;
        }
        self.file.flush().map_err(|e| self.staged.io(e))
    }

    fn finish(self: Box<Self>) -> Result<()> {
        let CsvTable { staged, file, .. } = *self;
        let file = file.into_inner().map_err(|e| staged.io(e.into_error()))?;
        file.sync_all().map_err(|e| staged.io(e))?;
        staged.commit()
    }
}

/// Open the table `target` for `sweep`: CSV or Parquet by the extension. Returns the writer
/// and the runs already in the file (with `resume`).
pub fn open(
    target: &Path,
    sweep: &Sweep,
    resume: bool,
) -> Result<(Box<dyn TableWriter>, HashSet<u64>)> {
    match target.extension().and_then(|e| e.to_str()) {
        Some("csv") => {
            let (t, done) = CsvTable::create(target, sweep, resume)?;
            Ok((Box::new(t), done))
        }
        #[cfg(feature = "parquet")]
        Some("parquet") => {
            let (t, done) = super::parquet::ParquetTable::create(target, sweep, resume)?;
            Ok((Box::new(t), done))
        }
        #[cfg(not(feature = "parquet"))]
        Some("parquet") => Err(RouthError::Option {
            name: "out",
            value: target.display().to_string(),
            rule: "this build has no Parquet output: build with `cargo build --release --features parquet`, or write .csv",
        }.into()),
        _ => Err(RouthError::Option {
            name: "out",
            value: target.display().to_string(),
            rule: "must end in .parquet or .csv",
        }
        .into()),
    }
}
