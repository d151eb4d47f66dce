//! The sweep's table as CSV: a header of the columns, one line per run
//! ([`super::record::Row::csv_line`]); with `--resume`, the lines of an existing file checked
//! and copied.

use super::record::{Row, RunSettings};
use super::runner::Sweep;
use super::table::{not_this_sweep, other_columns, PartialRow, Resumed, Staged, TableWriter};
use crate::error::{AppResult as Result, FileError};
use std::io::{BufRead, BufWriter, Write};
use std::path::Path;

/// A CSV table.
pub struct CsvTable {
    staged: Staged,
    file: BufWriter<std::fs::File>,
    sweep_settings: RunSettings,
}

/// The cells of one line of the table, as [`crate::row::Cell::to_csv`] writes them: split at
/// the commas outside quotes (a quoted cell holds no line break).
fn cells(line: &str) -> Vec<&str> {
    let mut cells = Vec::new();
    let (mut start, mut quoted) = (0, false);
    for (i, c) in line.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => {
                cells.push(&line[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    cells.push(&line[start..]);
    cells
}

impl CsvTable {
    /// Start writing `target`; with `resume`, copy the rows of an existing `target` and return
    /// the runs they hold. A last row cut short (fewer cells than columns, or no line break:
    /// a process ended while writing it) is dropped and said in [`Resumed::dropped`]; any
    /// other row that is not a row of this sweep is refused.
    pub fn create(target: &Path, sweep: &Sweep, resume: bool) -> Result<(Self, Resumed)> {
        let names: Vec<String> = sweep.table_columns().into_iter().map(|c| c.0).collect();
        let width = names.len();
        let header = names.join(",");
        let staged = Staged::beside(target)?;
        let file = std::fs::File::create(&staged.tmp).map_err(|e| staged.io(e))?;
        let mut file = BufWriter::new(file);
        writeln!(file, "{header}").map_err(|e| staged.io(e))?;
        let mut resumed = Resumed::default();
        if resume && target.exists() {
            let read_err = |source| FileError::Io {
                path: target.to_path_buf(),
                source,
            };
            let mut old = std::io::BufReader::new(std::fs::File::open(target).map_err(read_err)?);
            let mut next_line = || -> Result<Option<String>> {
                let mut line = String::new();
                let read = old.read_line(&mut line).map_err(read_err)?;
                Ok((read > 0).then_some(line))
            };
            let first = next_line()?.unwrap_or_default();
            let first = first.trim_end_matches(['\n', '\r']);
            if first != header {
                let found: Vec<String> = cells(first).into_iter().map(str::to_string).collect();
                return Err(other_columns(target, &found, &names));
            }
            let fixed = sweep.names().len() + 4;
            let mut next = next_line()?;
            let mut line_no = 1;
            while let Some(raw) = next {
                line_no += 1;
                next = next_line()?;
                let line_break = raw.ends_with('\n');
                let line = raw.trim_end_matches(['\n', '\r']);
                let fields = cells(line);
                if fields.len() != width || !line_break {
                    let partial = PartialRow {
                        line: line_no,
                        columns: fields.len(),
                        expected: width,
                        line_break,
                    };
                    if next.is_none() {
                        resumed.dropped = Some(partial);
                        break;
                    }
                    return Err(not_this_sweep(
                        target,
                        format!("a malformed row before the last: {partial}"),
                    ));
                }
                let number = |i: usize| -> Result<f64> {
                    fields[i]
                        .parse()
                        .map_err(|_| not_this_sweep(target, format!("a malformed row `{line}`")))
                };
                let run = number(0)? as u64;
                let values: Vec<f64> = (1..fixed).map(number).collect::<Result<_>>()?;
                sweep.check_resumed_row(target, run, &values)?;
                if fields[fixed] != sweep.run_settings().method {
                    return Err(not_this_sweep(
                        target,
                        format!("run {run} used another method"),
                    ));
                }
                if !resumed.done.insert(run) {
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
        Ok((table, resumed))
    }
}

impl TableWriter for CsvTable {
    fn write(&mut self, rows: &[Row]) -> Result<()> {
        let mut text = String::new();
        for row in rows {
            row.write_csv_line(&self.sweep_settings, &mut text);
            text.push('\n');
        }
        self.file
            .write_all(text.as_bytes())
            .and_then(|()| self.file.flush())
            .map_err(|e| self.staged.io(e))
    }

    fn finish(self: Box<Self>) -> Result<()> {
        let CsvTable { staged, file, .. } = *self;
        let file = file.into_inner().map_err(|e| staged.io(e.into_error()))?;
        file.sync_all().map_err(|e| staged.io(e))?;
        staged.commit()
    }
}

#[cfg(test)]
mod tests {
    use super::cells;
    use crate::row::Cell;

    #[test]
    fn cells_are_split_outside_quotes_as_they_are_written() {
        let written = crate::row::csv_line(&[
            Cell::Int(Some(3)),
            Cell::Text("no quadrature: a, b \"c\"".into()),
            Cell::Float(None),
            Cell::Float(Some(0.5)),
        ]);
        assert_eq!(
            cells(&written),
            ["3", "\"no quadrature: a, b \"\"c\"\"\"", "", "0.5"]
        );
        assert_eq!(cells("1,2,3").len(), 3);
        assert_eq!(cells("").len(), 1);
    }
}
