//! The class `Ball`: the general unbalanced ball of the library (any principal moments, the
//! centre of mass anywhere inside), its model and integrals; and [`Rolling`], a `Body` or a
//! `Ball` as `Problem` and `simulate` take it.

use crate::body::{integrals_dict, rolling_methods, PyBody};
use crate::convert::{bad_argument, python_error, vector};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use routh_core::ball::{AsBall, Ball, Model};
use routh_core::integrals::{Integrals, ALL_INTEGRAL_NAMES};
use routh_core::state::UNIT_TOLERANCE;
use routh_core::Body;

/// A ball of radius `R` and mass `m` rolling without slipping on a horizontal plane (SI units
/// or any consistent set), with principal moments `I1, I2, I3` about its centre of mass (each
/// > 0, satisfying the triangle inequalities) and its centre of mass at `com` = (x, y, z)
/// from the geometric centre in the body frame (`|com| < R`; the `Body` with offset `a` is
/// `com = (0, 0, -a)`), gravity `G >= 0`.
///
/// `model` says which integrable case it is (decided with the relative tolerance 1e-12):
/// `"routh-sphere"` (I1 = I2, centre of mass on e3: integrals H1, H2, H3, H4, K),
/// `"chaplygin"` (centre of mass at the centre: H1, H4, MM = (M, M), Mgamma = (M, gamma)) or
/// `"general"` (only the energy H1 and H4 = (gamma, gamma): not integrable). Phase-space
/// points are `x = (gamma, M)` as for `Body`. Immutable and picklable.
#[pyclass(name = "Ball", module = "routh", frozen)]
#[derive(Clone)]
pub struct PyBall {
    pub inner: Ball,
}

rolling_methods!(PyBall {
    /// `Ball(m, R, I1, I2, I3, com=(0, 0, 0), G=9.81)`; invalid parameters raise
    /// `ValueError` naming the parameter and the rule it breaks.
    #[new]
    #[pyo3(signature = (m, R, I1, I2, I3, com = None, G = 9.81))]
    #[allow(non_snake_case)]
    fn new(
        m: f64,
        R: f64,
        I1: f64,
        I2: f64,
        I3: f64,
        com: Option<&Bound<'_, PyAny>>,
        G: f64,
    ) -> PyResult<Self> {
        let com = match com {
            Some(c) => vector::<3>("com", c)?,
            None => [0.0; 3],
        };
        Ball::new(m, R, [I1, I2, I3], com, G)
            .map(|inner| PyBall { inner })
            .map_err(python_error)
    }

    /// The centre of mass relative to the geometric centre, body frame.
    #[getter]
    fn com(&self) -> (f64, f64, f64) {
        let [x, y, z] = self.inner.com();
        (x, y, z)
    }

    /// `"routh-sphere"`, `"chaplygin"` or `"general"` (see the class).
    #[getter]
    fn model(&self) -> &'static str {
        match self.inner.model() {
            Model::RouthSphere => "routh-sphere",
            Model::Chaplygin => "chaplygin",
            Model::General => "general",
        }
    }

    pub fn __repr__(&self) -> String {
        let b = &self.inner;
        let ([i1, i2, i3], [x, y, z]) = (b.inertia(), b.com());
        format!(
            "Ball(m={:?}, R={:?}, I1={:?}, I2={:?}, I3={:?}, com={:?}, G={:?})",
            b.m(),
            b.radius(),
            i1,
            i2,
            i3,
            (x, y, z),
            b.gravity()
        )
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let b = slf.get().inner;
        let ([i1, i2, i3], [x, y, z]) = (b.inertia(), b.com());
        let args = (b.m(), b.radius(), i1, i2, i3, (x, y, z), b.gravity());
        Ok((slf.get_type().into_any(), args.into_pyobject(slf.py())?))
    }

    /// The integrals of the ball's model at `x`, by name (only those the model has; see the
    /// class): H1 the energy (int-g) (twice the kinetic plus the potential energy 2 m G
    /// (r, gamma)), H4 = |gamma|^2, and H2, H3, K (Routh sphere) or MM, Mgamma (Chaplygin).
    /// Numbers for `x` of shape `(6,)`, arrays of k numbers for `(6, k)`.
    #[pyo3(signature = (x, unit_tolerance = Some(UNIT_TOLERANCE)))]
    fn integrals<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        unit_tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let ball = self.inner;
        integrals_dict(py, x, unit_tolerance, &ALL_INTEGRAL_NAMES, false, |p| {
            Integrals::at(&ball, p).all()
        })
    }
});

/// The rolling body of a `Problem`: a `Body` (the Routh sphere's parameters) or a `Ball`.
/// Both integrate the same field; the object given is kept to be returned and pickled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rolling {
    /// A `Body`.
    Body(Body),
    /// A `Ball`.
    Ball(Ball),
}

impl AsBall for Rolling {
    fn ball(&self) -> Ball {
        match self {
            Rolling::Body(b) => b.ball(),
            Rolling::Ball(b) => *b,
        }
    }
}

impl Rolling {
    /// The argument `name`: a `Body` or a `Ball` (else `ValueError` naming it).
    pub fn extract(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Self> {
        if let Ok(b) = obj.cast::<PyBody>() {
            Ok(Rolling::Body(b.get().inner))
        } else if let Ok(b) = obj.cast::<PyBall>() {
            Ok(Rolling::Ball(b.get().inner))
        } else {
            Err(bad_argument(
                name,
                format!(
                    "must be a routh.Body or a routh.Ball, not {}",
                    obj.get_type()
                ),
            ))
        }
    }

    /// The case's body: a `Body` when its centre of mass is on the e3 axis, else a `Ball`.
    pub fn of_case(case: &routh_core::case::Case, what: &'static str) -> Self {
        match case.body(what) {
            Ok(body) => Rolling::Body(body),
            Err(_) => Rolling::Ball(case.ball),
        }
    }

    /// The Python object: a `Body` or a `Ball`.
    pub fn to_object<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Rolling::Body(b) => Bound::new(py, PyBody { inner: b })?.into_any(),
            Rolling::Ball(b) => Bound::new(py, PyBall { inner: b })?.into_any(),
        })
    }

    /// As the object's `repr`.
    pub fn repr(&self) -> String {
        match self {
            Rolling::Body(b) => PyBody { inner: *b }.__repr__(),
            Rolling::Ball(b) => PyBall { inner: *b }.__repr__(),
        }
    }
}
