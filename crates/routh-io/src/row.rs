//! A row of a table as named columns and typed cells, built once and written by every
//! writer: CSV ([`csv_line`]), Parquet (`sweep::parquet`), JSON ([`Cell::to_json`]) and the
//! in-memory [`crate::table::Table`] ([`Cell::to_f64`]). The rows of `routh simulate`
//! ([`crate::table::sample_cells`]) and of a sweep (`sweep::record`) are built here.

/// The type of a column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Unsigned integer (run number, step counts).
    Int,
    /// Double, null where it does not apply.
    Float,
    /// Text.
    Text,
}

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// An unsigned integer, null for a failed run.
    Int(Option<u64>),
    /// A double, null where it does not apply.
    Float(Option<f64>),
    /// Text.
    Text(String),
}

impl Cell {
    /// The cell as a JSON value (null for a missing number).
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            Cell::Int(v) => v.map_or(serde_json::Value::Null, Into::into),
            Cell::Float(v) => v
                .and_then(serde_json::Number::from_f64)
                .map_or(serde_json::Value::Null, serde_json::Value::Number),
            Cell::Text(s) => s.clone().into(),
        }
    }

    /// The cell as CSV text: numbers in the shortest form that reads back to the same f64,
    /// empty for null, text quoted when it holds a comma, a quote or a line break.
    pub fn to_csv(&self) -> String {
        let mut text = String::new();
        self.write_csv(&mut text);
        text
    }

    /// [`Cell::to_csv`] appended to `out` (no allocation but `out`'s growth: a sweep's
    /// writer formats every cell of every row through it).
    pub fn write_csv(&self, out: &mut String) {
        use std::fmt::Write;
        // Writing into a `String` cannot fail.
        let _ = match self {
            Cell::Int(Some(v)) => write!(out, "{v}"),
            Cell::Float(Some(v)) => write!(out, "{v}"),
            Cell::Int(None) | Cell::Float(None) => Ok(()),
            Cell::Text(s) if s.contains([',', '"', '\n', '\r']) => {
                out.push('"');
                for c in s.chars() {
                    match c {
                        '"' => out.push_str("\"\""),
                        '\n' | '\r' => out.push(' '),
                        c => out.push(c),
                    }
                }
                out.push('"');
                Ok(())
            }
            Cell::Text(s) => {
                out.push_str(s);
                Ok(())
            }
        };
    }

    /// The cell as a number of a [`crate::table::Table`]: NaN for null and for text (as an
    /// empty CSV cell reads back).
    pub fn to_f64(&self) -> f64 {
        match self {
            Cell::Int(v) => v.map_or(f64::NAN, |v| v as f64),
            Cell::Float(v) => v.unwrap_or(f64::NAN),
            Cell::Text(_) => f64::NAN,
        }
    }
}

/// The cells as one line of CSV (without the line break).
pub fn csv_line(cells: &[Cell]) -> String {
    let mut line = String::new();
    write_csv_line(cells, &mut line);
    line
}

/// [`csv_line`] appended to `out` (without the line break).
pub fn write_csv_line(cells: &[Cell], out: &mut String) {
    for (i, cell) in cells.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        cell.write_csv(out);
    }
}

/// A table as CSV into `path`: the header `columns`, then one line per row of `rows`, written
/// whole or not at all ([`crate::output::write_atomic`]), in chunks of about 64 KiB.
pub fn write_csv_file(
    path: &std::path::Path,
    columns: &[&str],
    rows: impl Iterator<Item = Vec<Cell>>,
) -> crate::AppResult<()> {
    crate::output::write_atomic(path, |w| {
        let io = crate::AppError::io(path);
        let mut line = columns.join(",");
        line.push('\n');
        for cells in rows {
            write_csv_line(&cells, &mut line);
            line.push('\n');
            if line.len() > 1 << 16 {
                w.write_all(line.as_bytes()).map_err(&io)?;
                line.clear();
            }
        }
        w.write_all(line.as_bytes()).map_err(&io)
    })
}
