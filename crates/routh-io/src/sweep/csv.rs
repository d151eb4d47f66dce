//! The sweep's table as CSV: a header of the columns, one line per run
//! ([`super::record::Row::csv_line`]); with `--resume`, the lines of an existing file checked
//! and copied.

use super::record::{columns, Row, RunSettings};
use super::runner::Sweep;
use super::table::{check_resumed_row, not_this_sweep, Staged, TableWriter};
use crate::error::{AppResult as Result, FileError};
use std::collections::HashSet;
use std::io::{BufRead, BufWriter, Write};
use std::path::Path;

/// A CSV table.
pub struct CsvTable {
    staged: Staged,
    file: BufWriter<std::fs::File>,
    sweep_settings: RunSettings,
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
