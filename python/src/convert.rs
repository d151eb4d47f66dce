//! Conversions between Python objects and the library's values: errors, arrays of numbers
//! read with their shape checked and named, states stacked along the last axis, and
//! serialisable records as dicts.

use numpy::{AllowTypeChange, PyArray1, PyArrayLikeDyn, PyArrayMethods, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use routh_core::state::{Normalise, State};
use routh_core::{AppError, FileError, RouthError};
use serde::Serialize;

/// The Python exception for a library error: the integration or a figure failing at run time
/// is a `RuntimeError`, a file that cannot be accessed an `OSError`, everything else (parameters,
/// states, options, case files) a `ValueError`.
pub fn python_error(e: impl Into<AppError>) -> PyErr {
    let e = e.into();
    let message = e.to_string();
    match e {
        AppError::Model(RouthError::Integrate(_)) | AppError::File(FileError::Plot { .. }) => {
            PyRuntimeError::new_err(message)
        }
        AppError::File(FileError::Io { .. }) => PyOSError::new_err(message),
        AppError::Model(
            RouthError::Parameter { .. }
            | RouthError::Triangle { .. }
            | RouthError::NotSymmetric { .. }
            | RouthError::OffAxis { .. }
            | RouthError::Horizon { .. }
            | RouthError::Unresolved { .. }
            | RouthError::Overflow { .. }
            | RouthError::State(_)
            | RouthError::Option { .. }
            | RouthError::Singular { .. }
            | RouthError::Separatrix { .. },
        )
        | AppError::File(FileError::Case { .. } | FileError::Table { .. }) => {
            PyValueError::new_err(message)
        }
    }
}

/// A `ValueError` for the argument `name`.
pub fn bad_argument(name: &str, message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(format!("{name}: {message}"))
}

/// Most numbers one call may return (2^27 doubles, 1 GiB): a larger request is refused with a
/// `ValueError` before anything is allocated, instead of aborting the interpreter when the
/// allocation fails.
pub const MAX_VALUES: usize = 1 << 27;

/// Refuse a result of `count` items of `width` numbers each beyond [`MAX_VALUES`].
pub fn check_size(name: &str, count: u128, width: usize) -> PyResult<()> {
    let values = count.saturating_mul(width as u128);
    if values > MAX_VALUES as u128 {
        return Err(bad_argument(
            name,
            format!(
                "{count} is too large: the result would hold {values} numbers, more than the \
                 {MAX_VALUES} (1 GiB) one call may return; split the request"
            ),
        ));
    }
    Ok(())
}

/// An array of numbers with its shape: any sequence or numpy array of real numbers.
pub struct Numbers {
    /// The shape, as numpy reports it.
    pub shape: Vec<usize>,
    /// The values in C order.
    pub values: Vec<f64>,
}

impl Numbers {
    /// Read `obj` (a number, sequence or numpy array of real numbers) for the argument `name`.
    pub fn read(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Self> {
        let array: PyArrayLikeDyn<'_, f64, AllowTypeChange> = obj
            .extract()
            .map_err(|e| bad_argument(name, format!("not an array of real numbers ({e})")))?;
        Ok(Numbers {
            shape: array.shape().to_vec(),
            values: array.as_array().iter().copied().collect(),
        })
    }

    fn shape_text(&self) -> String {
        match self.shape.as_slice() {
            [n] => format!("({n},)"),
            dims => format!(
                "({})",
                dims.iter()
                    .map(usize::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        }
    }

    /// Every value finite, or a `ValueError` naming the argument and the first bad index.
    pub fn finite(self, name: &str) -> PyResult<Self> {
        if let Some(i) = self.values.iter().position(|v| !v.is_finite()) {
            return Err(bad_argument(
                name,
                format!("value {} at flat index {i} is not finite", self.values[i]),
            ));
        }
        Ok(self)
    }
}

/// A vector of exactly `N` numbers for the argument `name`.
pub fn vector<const N: usize>(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<[f64; N]> {
    let numbers = Numbers::read(name, obj)?;
    match numbers.shape.as_slice() {
        [n] if *n == N => Ok(std::array::from_fn(|i| numbers.values[i])),
        [n] => Err(PyValueError::new_err(format!(
            "{name} must have {N} components, but it has {n}"
        ))),
        _ => Err(PyValueError::new_err(format!(
            "{name} must be a vector of {N} numbers, but its shape is {}",
            numbers.shape_text()
        ))),
    }
}

/// States stacked along the last axis, as SciPy does: shape `(N,)` (one state) or `(N, k)`.
/// Returns the states and whether a single vector was given.
pub fn states<const N: usize>(
    name: &str,
    obj: &Bound<'_, PyAny>,
) -> PyResult<(Vec<[f64; N]>, bool)> {
    let numbers = Numbers::read(name, obj)?;
    match numbers.shape.as_slice() {
        [n] if *n == N => Ok((vec![std::array::from_fn(|i| numbers.values[i])], true)),
        [rows, k] if *rows == N => Ok((
            (0..*k)
                .map(|j| std::array::from_fn(|i| numbers.values[i * k + j]))
                .collect(),
            false,
        )),
        [n] => Err(PyValueError::new_err(format!(
            "{name} must have {N} components, but it has {n}"
        ))),
        _ => Err(PyValueError::new_err(format!(
            "{name} must have shape ({N},) or ({N}, k) (states are columns, as in SciPy), but \
             its shape is {}",
            numbers.shape_text()
        ))),
    }
}

/// A phase-space point `(gamma, M)` checked as the library checks states: finite, |gamma| = 1.
pub fn phase_point(name: &str, x: &[f64; 6]) -> PyResult<State> {
    State::of_array(x, Normalise::Reject).map_err(|e| bad_argument(name, e))
}

/// Times: a number or a 1-D array, all finite. Returns them and whether a number was given.
pub fn times(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<(Vec<f64>, bool)> {
    let numbers = Numbers::read(name, obj)?.finite(name)?;
    match numbers.shape.len() {
        0 => Ok((numbers.values, true)),
        1 => Ok((numbers.values, false)),
        _ => Err(PyValueError::new_err(format!(
            "{name} must be a number or a 1-D array, but its shape is {}",
            numbers.shape_text()
        ))),
    }
}

/// States as a numpy array with the states in columns: `(N,)` for a single one, else `(N, k)`.
pub fn columns<'py, const N: usize>(
    py: Python<'py>,
    rows: &[[f64; N]],
    single: bool,
) -> PyResult<Bound<'py, PyAny>> {
    if single {
        return Ok(PyArray1::from_slice(py, &rows[0]).into_any());
    }
    let k = rows.len();
    let flat: Vec<f64> = (0..N)
        .flat_map(|i| rows.iter().map(move |r| r[i]))
        .collect();
    Ok(PyArray1::from_vec(py, flat).reshape([N, k])?.into_any())
}

/// A serialisable record of the library (the JSON of the command-line tool) as Python
/// objects: maps become dicts, sequences lists, numbers floats or ints, `null` `None`.
pub fn record<'py>(py: Python<'py>, value: &impl Serialize) -> PyResult<Bound<'py, PyAny>> {
    let json = serde_json::to_value(value).map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    json_to_python(py, &json)
}

fn json_to_python<'py>(py: Python<'py>, value: &serde_json::Value) -> PyResult<Bound<'py, PyAny>> {
    use serde_json::Value;
    Ok(match value {
        Value::Null => py.None().into_bound(py),
        Value::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        Value::Number(n) => match (n.as_i64(), n.as_f64()) {
            (Some(i), _) => i.into_pyobject(py)?.into_any(),
            (None, Some(f)) => f.into_pyobject(py)?.into_any(),
            (None, None) => return Err(PyRuntimeError::new_err(format!("number {n}"))),
        },
        Value::String(s) => s.into_pyobject(py)?.into_any(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(json_to_python(py, item)?)?;
            }
            list.into_any()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (key, item) in map {
                dict.set_item(key, json_to_python(py, item)?)?;
            }
            dict.into_any()
        }
    })
}
