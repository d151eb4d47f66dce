//! The sweep's table as Parquet (feature `parquet`): typed columns (run and counts as
//! UInt64, numbers as Float64 with nulls where they do not apply, text as Utf8), one row
//! group per chunk of finished runs, and in the file's key-value metadata the case file's
//! text (`routh.case`), the tool's version (`routh.version`) and the settings
//! (`routh.settings`).

use super::record::{columns, Row, RunSettings};
use super::runner::Sweep;
use super::table::{check_resumed_row, not_this_sweep, Resumed, Staged, TableWriter};
use crate::error::{AppError, AppResult as Result, FileError};
use crate::row::{Cell, Kind};
use arrow_array::{Array, ArrayRef, Float64Array, RecordBatch, StringArray, UInt64Array};
use arrow_schema::{DataType, Field, Schema, SchemaRef};
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use std::collections::HashSet;
use std::path::Path;
use std::sync::Arc;

/// Metadata key of the case file's text.
pub const CASE_KEY: &str = "routh.case";
/// Metadata key of the tool's version.
pub const VERSION_KEY: &str = "routh.version";
/// Metadata key of the settings (`t_end`, `rtol`, `atol`, `method`).
pub const SETTINGS_KEY: &str = "routh.settings";

/// A Parquet table being written.
pub struct ParquetTable {
    staged: Staged,
    writer: Option<ArrowWriter<std::fs::File>>,
    schema: SchemaRef,
    settings: RunSettings,
}

fn schema(sweep: &Sweep) -> SchemaRef {
    let fields: Vec<Field> = columns(&sweep.names())
        .into_iter()
        .map(|(name, kind)| {
            let (t, nullable) = match kind {
                Kind::Int => (DataType::UInt64, name != "run"),
                Kind::Float => (DataType::Float64, true),
                Kind::Text => (DataType::Utf8, false),
            };
            Field::new(name, t, nullable)
        })
        .collect();
    Arc::new(Schema::new(fields))
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

/// The rows as one record batch of `schema`.
fn batch(schema: &SchemaRef, rows: &[Row], settings: &RunSettings) -> Result<RecordBatch> {
    let cells: Vec<Vec<Cell>> = rows.iter().map(|r| r.cells(settings)).collect();
    let arrays: Vec<ArrayRef> = schema
        .fields()
        .iter()
        .enumerate()
        .map(|(i, field)| -> ArrayRef {
            let column = cells.iter().map(|row| &row[i]);
            match field.data_type() {
                DataType::UInt64 => Arc::new(
                    column
                        .map(|c| match c {
                            Cell::Int(v) => *v,
                            _ => None,
                        })
                        .collect::<UInt64Array>(),
                ),
                DataType::Float64 => Arc::new(
                    column
                        .map(|c| match c {
                            Cell::Float(v) => *v,
                            _ => None,
                        })
                        .collect::<Float64Array>(),
                ),
                _ => Arc::new(
                    column
                        .map(|c| match c {
                            Cell::Text(s) => Some(s.as_str()),
                            _ => None,
                        })
                        .collect::<StringArray>(),
                ),
            }
        })
        .collect();
    RecordBatch::try_new(schema.clone(), arrays).map_err(|e| {
        FileError::Table {
            origin: "sweep".into(),
            message: format!("cannot build a record batch: {e}"),
        }
        .into()
    })
}

impl ParquetTable {
    /// Start writing `target`; with `resume`, copy the rows of an existing `target` (checked
    /// to be rows of this sweep: same case text, settings, and design values) and return the
    /// runs they hold.
    pub fn create(target: &Path, sweep: &Sweep, resume: bool) -> Result<(Self, Resumed)> {
        let schema = schema(sweep);
        let settings = sweep.run_settings();
        let staged = Staged::beside(target)?;
        let props = WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_key_value_metadata(Some(vec![
                KeyValue::new(CASE_KEY.into(), sweep.case_text.clone()),
                KeyValue::new(VERSION_KEY.into(), env!("CARGO_PKG_VERSION").to_string()),
                KeyValue::new(SETTINGS_KEY.into(), settings_text(&settings)),
            ]))
            .build();
        let file = std::fs::File::create(&staged.tmp).map_err(|e| staged.io(e))?;
        let mut writer = ArrowWriter::try_new(file, schema.clone(), Some(props))
            .map_err(|e| parquet_error(&staged.target, e))?;
        let mut done = HashSet::new();
        if resume && target.exists() {
            let file = std::fs::File::open(target).map_err(|source| FileError::Io {
                path: target.to_path_buf(),
                source,
            })?;
            let builder = ParquetRecordBatchReaderBuilder::try_new(file)
                .map_err(|e| parquet_error(target, e))?;
            let meta = builder.metadata().file_metadata().key_value_metadata();
            let value = |key: &str| {
                meta.and_then(|m| m.iter().find(|kv| kv.key == key))
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
            let shape = |s: &Schema| -> Vec<(String, DataType)> {
                s.fields()
                    .iter()
                    .map(|f| (f.name().clone(), f.data_type().clone()))
                    .collect()
            };
            if shape(builder.schema()) != shape(&schema) {
                return Err(not_this_sweep(
                    target,
                    "its columns differ from this sweep's",
                ));
            }
            let reader = builder.build().map_err(|e| parquet_error(target, e))?;
            let d = sweep.names().len();
            for b in reader {
                let b = b.map_err(|e| parquet_error(target, e))?;
                let float = |i: usize| b.column(i).as_any().downcast_ref::<Float64Array>().cloned();
                let runs = b.column(0).as_any().downcast_ref::<UInt64Array>().cloned();
                let cols: Option<Vec<Float64Array>> = (1..=d + 3).map(float).collect();
                let (Some(runs), Some(cols)) = (runs, cols) else {
                    return Err(not_this_sweep(target, "its columns have other types"));
                };
                for r in 0..b.num_rows() {
                    let run = runs.value(r);
                    let values: Vec<f64> = cols.iter().map(|c| c.value(r)).collect();
                    check_resumed_row(sweep, target, run, &values)?;
                    if !done.insert(run) {
                        return Err(not_this_sweep(target, format!("run {run} appears twice")));
                    }
                }
                writer
                    .write(&b)
                    .map_err(|e| parquet_error(&staged.target, e))?;
            }
            writer
                .flush()
                .map_err(|e| parquet_error(&staged.target, e))?;
        }
        let table = ParquetTable {
            staged,
            writer: Some(writer),
            schema,
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
        let b = batch(&self.schema, rows, &self.settings)?;
        let writer = self.writer.as_mut().expect("open until finish");
        writer
            .write(&b)
            .map_err(|e| parquet_error(&self.staged.target, e))?;
        writer
            .flush()
            .map_err(|e| parquet_error(&self.staged.target, e))
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
