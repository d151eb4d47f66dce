//! The sweep's table as Parquet (feature `parquet`, on in the `routh` binary): typed columns
//! (run and counts as unsigned 64-bit integers, numbers as doubles with nulls where they do not
//! apply, text as UTF-8 strings), Snappy-compressed, one row group per chunk of finished runs,
//! and in the file's key-value metadata the case file's text (`routh.case`), the tool's
//! version (`routh.version`) and the settings (`routh.settings`).
//!
//! Written with the `parquet` crate's own column writers, without Apache Arrow: the `arrow`
//! feature of that crate builds arrow-cast, arrow-ord and arrow-select, ten times the
//! build time of the writer alone (BENCHMARKS.md, "Parquet in the default build"), for a
//! table of three column types. pyarrow, pandas, polars and Dask read the file as before.

use super::record::{Row, RunSettings};
use super::runner::Sweep;
use super::table::{not_this_sweep, other_columns, Resumed, Staged, TableWriter};
use crate::error::{AppError, AppResult as Result, FileError};
use crate::row::{Cell, Kind};
use parquet::basic::{Compression, LogicalType, Repetition, Type as PhysicalType};
use parquet::column::writer::ColumnWriter;
use parquet::data_type::ByteArray;
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::reader::FileReader;
use parquet::file::serialized_reader::SerializedFileReader;
use parquet::file::writer::SerializedFileWriter;
use parquet::record::Field;
use parquet::schema::types::{Type, TypePtr};
use std::collections::HashSet;
use std::path::Path;
use std::sync::Arc;

/// Metadata key of the case file's text.
pub const CASE_KEY: &str = "routh.case";
/// Metadata key of the tool's version.
pub const VERSION_KEY: &str = "routh.version";
/// Metadata key of the settings (`t_end`, `rtol`, `atol`, `method`).
pub const SETTINGS_KEY: &str = "routh.settings";

/// Rows of an existing table copied per row group by `--resume`.
const RESUMED_GROUP: usize = 4096;

/// A Parquet table being written.
pub struct ParquetTable {
    staged: Staged,
    writer: Option<SerializedFileWriter<std::fs::File>>,
    columns: Vec<(String, Kind)>,
    settings: RunSettings,
}

/// Whether a column never holds a null: `run` and the text columns.
fn required(name: &str, kind: Kind) -> bool {
    name == "run" || kind == Kind::Text
}

/// The Parquet schema of the columns `columns`.
fn schema(columns: &[(String, Kind)]) -> std::result::Result<TypePtr, ParquetError> {
    let fields = columns
        .iter()
        .map(|(name, kind)| {
            let (physical, logical) = match kind {
                Kind::Int => (
                    PhysicalType::INT64,
                    Some(LogicalType::Integer {
                        bit_width: 64,
                        is_signed: false,
                    }),
                ),
                Kind::Float => (PhysicalType::DOUBLE, None),
                Kind::Text => (PhysicalType::BYTE_ARRAY, Some(LogicalType::String)),
            };
            let repetition = if required(name, *kind) {
                Repetition::REQUIRED
            } else {
                Repetition::OPTIONAL
            };
            Type::primitive_type_builder(name, physical)
                .with_repetition(repetition)
                .with_logical_type(logical)
                .build()
                .map(Arc::new)
        })
        .collect::<std::result::Result<Vec<_>, _>>()?;
    Type::group_type_builder("schema")
        .with_fields(fields)
        .build()
        .map(Arc::new)
}

fn parquet_error(path: &Path, e: impl std::fmt::Display) -> AppError {
    FileError::Table {
        origin: path.display().to_string(),
        message: format!("Parquet: {e}"),
    }
    .into()
}

fn settings_text(s: &RunSettings) -> String {
    format!(
        "t_end = {:?}, rtol = {:?}, atol = {:?}, method = {}",
        s.t_end, s.rtol, s.atol, s.method
    )
}

/// The values of one column and its definition levels (1 for a value, 0 for a null), or no
/// levels for a column that is [`required`].
fn present<T>(
    cells: impl Iterator<Item = Option<T>>,
    required: bool,
) -> (Vec<T>, Option<Vec<i16>>) {
    let mut values = Vec::new();
    let mut levels = Vec::new();
    for cell in cells {
        levels.push(i16::from(cell.is_some()));
        values.extend(cell);
    }
    (values, (!required).then_some(levels))
}

/// Write `rows` (the cells of rows of `columns`) as one row group.
fn write_group(
    writer: &mut SerializedFileWriter<std::fs::File>,
    columns: &[(String, Kind)],
    rows: &[Vec<Cell>],
) -> std::result::Result<(), ParquetError> {
    let mut group = writer.next_row_group()?;
    for (i, (name, kind)) in columns.iter().enumerate() {
        let mut column = group
            .next_column()?
            .ok_or_else(|| ParquetError::General(format!("no column `{name}` in the schema")))?;
        let required = required(name, *kind);
        let cells = rows.iter().map(|row| &row[i]);
        match column.untyped() {
            ColumnWriter::Int64ColumnWriter(w) => {
                // An unsigned 64-bit integer is stored in INT64's bits (Parquet's UINT_64).
                let (values, levels) = present(
                    cells.map(|c| match c {
                        Cell::Int(v) => v.map(|v| v as i64),
                        _ => None,
                    }),
                    required,
                );
                w.write_batch(&values, levels.as_deref(), None)?;
            }
            ColumnWriter::DoubleColumnWriter(w) => {
                let (values, levels) = present(
                    cells.map(|c| match c {
                        Cell::Float(v) => *v,
                        _ => None,
                    }),
                    required,
                );
                w.write_batch(&values, levels.as_deref(), None)?;
            }
            ColumnWriter::ByteArrayColumnWriter(w) => {
                let (values, levels) = present(
                    cells.map(|c| match c {
                        Cell::Text(s) => Some(ByteArray::from(s.as_str())),
                        _ => None,
                    }),
                    required,
                );
                w.write_batch(&values, levels.as_deref(), None)?;
            }
            _ => {
                return Err(ParquetError::General(format!(
                    "column `{name}` has an unexpected type"
                )))
            }
        }
        column.close()?;
    }
    group.close()?;
    Ok(())
}

/// The cell of `field`, a value of a column of kind `kind`; None for another type.
fn cell(field: &Field, kind: Kind) -> Option<Cell> {
    match (field, kind) {
        (Field::ULong(v), Kind::Int) => Some(Cell::Int(Some(*v))),
        (Field::Null, Kind::Int) => Some(Cell::Int(None)),
        (Field::Double(v), Kind::Float) => Some(Cell::Float(Some(*v))),
        (Field::Null, Kind::Float) => Some(Cell::Float(None)),
        (Field::Str(s), Kind::Text) => Some(Cell::Text(s.clone())),
        _ => None,
    }
}

impl ParquetTable {
    /// Start writing `target`; with `resume`, copy the rows of an existing `target` (checked
    /// to be rows of this sweep: same case text, settings, columns and design values) and
    /// return the runs they hold.
    pub fn create(target: &Path, sweep: &Sweep, resume: bool) -> Result<(Self, Resumed)> {
        let columns = sweep.table_columns();
        let settings = sweep.run_settings();
        let staged = Staged::beside(target)?;
        // No dictionary encoding: the numbers of a sweep are nearly all distinct, so hashing
        // each one into a dictionary (the crate's default) was most of the writer's time, a
        // thread beside the runs; Snappy compresses the repeated ones (settings, status).
        let props = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_dictionary_enabled(false)
            .set_key_value_metadata(Some(vec![
                KeyValue::new(CASE_KEY.into(), sweep.case_text.clone()),
                KeyValue::new(VERSION_KEY.into(), env!("CARGO_PKG_VERSION").to_string()),
                KeyValue::new(SETTINGS_KEY.into(), settings_text(&settings)),
            ]))
            .build();
        let file = std::fs::File::create(&staged.tmp).map_err(|e| staged.io(e))?;
        let mut writer = schema(&columns)
            .and_then(|schema| SerializedFileWriter::new(file, schema, Arc::new(props)))
            .map_err(|e| parquet_error(&staged.target, e))?;
        let mut done = HashSet::new();
        if resume && target.exists() {
            let file = std::fs::File::open(target).map_err(|source| FileError::Io {
                path: target.to_path_buf(),
                source,
            })?;
            let reader = SerializedFileReader::new(file).map_err(|e| parquet_error(target, e))?;
            let meta = reader.metadata().file_metadata();
            let value = |key: &str| {
                meta.key_value_metadata()
                    .and_then(|m| m.iter().find(|kv| kv.key == key))
                    .and_then(|kv| kv.value.clone())
            };
            if value(CASE_KEY).as_deref() != Some(sweep.case_text.as_str()) {
                return Err(not_this_sweep(target, "it was made from another case file"));
            }
            if value(SETTINGS_KEY) != Some(settings_text(&settings)) {
                return Err(not_this_sweep(
                    target,
                    format!(
                        "its settings are {:?}, not {}",
                        value(SETTINGS_KEY),
                        settings_text(&settings)
                    ),
                ));
            }
            let found: Vec<String> = meta
                .schema_descr()
                .columns()
                .iter()
                .map(|c| c.name().to_string())
                .collect();
            let asked: Vec<String> = columns.iter().map(|c| c.0.clone()).collect();
            if found != asked {
                return Err(other_columns(target, &found, &asked));
            }
            let d = sweep.names().len();
            let mut kept: Vec<Vec<Cell>> = Vec::new();
            for row in reader
                .get_row_iter(None)
                .map_err(|e| parquet_error(target, e))?
            {
                let row = row.map_err(|e| parquet_error(target, e))?;
                let cells: Option<Vec<Cell>> = row
                    .get_column_iter()
                    .zip(&columns)
                    .map(|((_, field), (_, kind))| cell(field, *kind))
                    .collect();
                let Some(cells) = cells else {
                    return Err(not_this_sweep(target, "its columns have other types"));
                };
                let number = |i: usize| match cells[i] {
                    Cell::Float(Some(v)) => Some(v),
                    _ => None,
                };
                let (Cell::Int(Some(run)), Some(values)) = (
                    &cells[0],
                    (1..=d + 3).map(number).collect::<Option<Vec<f64>>>(),
                ) else {
                    return Err(not_this_sweep(target, "a row without its run or settings"));
                };
                sweep.check_resumed_row(target, *run, &values)?;
                if !done.insert(*run) {
                    return Err(not_this_sweep(target, format!("run {run} appears twice")));
                }
                kept.push(cells);
                if kept.len() == RESUMED_GROUP {
                    write_group(&mut writer, &columns, &kept)
                        .map_err(|e| parquet_error(&staged.target, e))?;
                    kept.clear();
                }
            }
            if !kept.is_empty() {
                write_group(&mut writer, &columns, &kept)
                    .map_err(|e| parquet_error(&staged.target, e))?;
            }
        }
        let table = ParquetTable {
            staged,
            writer: Some(writer),
            columns,
            settings,
        };
        Ok((
            table,
            Resumed {
                done,
                dropped: None,
            },
        ))
    }
}

impl TableWriter for ParquetTable {
    fn write(&mut self, rows: &[Row]) -> Result<()> {
        let cells: Vec<Vec<Cell>> = rows.iter().map(|r| r.cells(&self.settings)).collect();
        let writer = self.writer.as_mut().expect("open until finish");
        write_group(writer, &self.columns, &cells)
            .map_err(|e| parquet_error(&self.staged.target, e))?;
        writer.flush().map_err(|e| self.staged.io(e))
    }

    fn finish(mut self: Box<Self>) -> Result<()> {
        let writer = self.writer.take().expect("open until finish");
        let file = writer
            .into_inner()
            .map_err(|e| parquet_error(&self.staged.target, e))?;
        file.sync_all().map_err(|e| self.staged.io(e))?;
        let ParquetTable { staged, .. } = *self;
        staged.commit()
    }
}
