//! The class `Body`: the ball's parameters, and the field (mg-eq), omega (om-m) and the
//! integrals (int-g), (raus-int) at phase-space points.

use crate::convert::{bad_argument, columns, python_error, states, vector};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use routh_core::integrals::{Integrals, INTEGRAL_NAMES};
use routh_core::state::{Normalise, State, UNIT_TOLERANCE};

/// The rolling ball (SI units or any consistent set): mass `m`, radius `R`, offset `a` of the
/// centre of mass (the centre of mass is at `-a e3` from the geometric centre, |a| < R),
/// principal moments `I1, I2, I3` about the centre of mass (`I2` defaults to `I1`: the Routh
/// sphere), gravity `G >= 0`.
///
/// Phase-space points are `x = (gamma1, gamma2, gamma3, M1, M2, M3)`: `gamma` the unit normal
/// of the plane pointing into it (downwards), `M` the angular momentum about the contact point,
/// both in the body frame. Several points are stacked as columns, shape `(6, k)`, as in SciPy.
/// Instances are immutable and picklable.
#[pyclass(name = "Body", module = "routh", frozen)]
#[derive(Clone)]
pub struct PyBody {
    pub inner: routh_core::Body,
}

/// Apply `f` to each checked point of `x` (`(6,)` or `(6, k)`), returning `(M,)`-shaped or
/// `(M, k)`-shaped results; the interpreter lock is released meanwhile.
pub fn map_points<'py, const M: usize>(
    py: Python<'py>,
    x: &Bound<'py, PyAny>,
    unit_tolerance: Option<f64>,
    f: impl Fn(&[f64; 6]) -> [f64; M] + Sync,
) -> PyResult<Bound<'py, PyAny>> {
    let (points, single) = checked_points(x, unit_tolerance)?;
    let out: Vec<[f64; M]> = py.detach(|| points.iter().map(&f).collect());
    columns(py, &out, single)
}

/// The integrals `names[i]` (the i-th value of `values(x)`) at the checked points of `x`, as a
/// dict of numbers or arrays; those that are not integrals (`None`) are `None` if `keep_none`,
/// else left out.
pub fn integrals_dict<'py, const K: usize>(
    py: Python<'py>,
    x: &Bound<'py, PyAny>,
    unit_tolerance: Option<f64>,
    names: &[&str; K],
    keep_none: bool,
    values: impl Fn(&[f64; 6]) -> [Option<f64>; K] + Sync,
) -> PyResult<Bound<'py, PyDict>> {
    let (points, single) = checked_points(x, unit_tolerance)?;
    let values: Vec<[Option<f64>; K]> = py.detach(|| points.iter().map(&values).collect());
    let dict = PyDict::new(py);
    for (i, name) in names.iter().enumerate() {
        let column: Option<Vec<f64>> = values.iter().map(|v| v[i]).collect();
        match (column, single) {
            (None, _) if keep_none => dict.set_item(*name, py.None())?,
            (None, _) => {}
            (Some(c), true) => dict.set_item(*name, c[0])?,
            (Some(c), false) => dict.set_item(*name, PyArray1::from_vec(py, c))?,
        }
    }
    Ok(dict)
}

/// The points of the argument `x`, each finite and, unless `unit_tolerance` is None, with
/// `||gamma| - 1| <= unit_tolerance`.
fn checked_points(
    x: &Bound<'_, PyAny>,
    unit_tolerance: Option<f64>,
) -> PyResult<(Vec<[f64; 6]>, bool)> {
    let (points, single) = states::<6>("x", x)?;
    if let Some(tol) = unit_tolerance {
        if !(tol.is_finite() && tol >= 0.0) {
            return Err(bad_argument(
                "unit_tolerance",
                format!("{tol} must be finite and >= 0"),
            ));
        }
    }
    for (j, p) in points.iter().enumerate() {
        let name = || {
            if single {
                "x".to_string()
            } else {
                format!("x[:, {j}]")
            }
        };
        if let Some(i) = p.iter().position(|v| !v.is_finite()) {
            return Err(bad_argument(
                &name(),
                format!("component {i} = {} is not finite", p[i]),
            ));
        }
        let norm = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        if let Some(tol) = unit_tolerance.filter(|&tol| (norm - 1.0).abs() > tol) {
            return Err(bad_argument(
                &name(),
                format!(
                    "gamma = {:?} is not a unit vector: |gamma| - 1 = {:.3e} exceeds \
                     unit_tolerance = {tol:e} (pass a looser unit_tolerance, or None, to evaluate \
                     off the sphere, e.g. at the stages of another integrator)",
                    [p[0], p[1], p[2]],
                    norm - 1.0
                ),
            ));
        }
    }
    Ok((points, single))
}

/// The `#[pymethods]` of a rolling ball's class (`Body`, `Ball`; a class has one such block):
/// the class's own methods `{ ... }`, then those both share, written once: the getters m, R,
/// I1, I2, I3, G (of the ball, [`AsBall`](routh_core::ball::AsBall)), equality, `field` and
/// `omega`.
macro_rules! rolling_methods {
    ($class:ident { $($own:tt)* }) => {
        #[pymethods]
        impl $class {
            $($own)*

            /// Mass m.
            #[getter]
            fn m(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).m()
            }

            /// Radius R.
            #[getter(R)]
            fn radius(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).radius()
            }

            /// Principal moment I1 about the centre of mass.
            #[getter(I1)]
            fn i1(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).inertia()[0]
            }

            /// Principal moment I2 about the centre of mass.
            #[getter(I2)]
            fn i2(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).inertia()[1]
            }

            /// Principal moment I3 about the centre of mass (the symmetry axis e3 of a `Body`).
            #[getter(I3)]
            fn i3(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).inertia()[2]
            }

            /// Gravitational acceleration G.
            #[getter(G)]
            fn gravity(&self) -> f64 {
                routh_core::ball::AsBall::ball(&self.inner).gravity()
            }

            fn __eq__(&self, other: &Self) -> bool {
                self.inner == other.inner
            }

            /// The vector field (mg-eq) `dx/dt` at `x` (shape `(6,)` or `(6, k)`; result the same
            /// shape), in units of x per unit time. `x` must be finite with `||gamma| - 1|` at most
            /// `unit_tolerance` (default 1e-12, as a state of the library; `None`: not checked; the
            /// field is defined off the sphere, and another integrator's stages need a looser value
            /// such as 1e-3): `ValueError` naming the column otherwise.
            #[pyo3(signature = (x, unit_tolerance = Some(routh_core::state::UNIT_TOLERANCE)))]
            fn field<'py>(
                &self,
                py: Python<'py>,
                x: &Bound<'py, PyAny>,
                unit_tolerance: Option<f64>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let inner = self.inner;
                $crate::body::map_points(py, x, unit_tolerance, |p| {
                    routh_core::field::vector_field(&inner, p)
                })
            }

            /// The angular velocity `omega = I_Q^{-1} M` of (om-m) at `x` (rad per unit time, body
            /// frame), shape `(3,)` or `(3, k)`; `unit_tolerance` as in `field`.
            #[pyo3(signature = (x, unit_tolerance = Some(routh_core::state::UNIT_TOLERANCE)))]
            fn omega<'py>(
                &self,
                py: Python<'py>,
                x: &Bound<'py, PyAny>,
                unit_tolerance: Option<f64>,
            ) -> PyResult<Bound<'py, PyAny>> {
                let inner = self.inner;
                $crate::body::map_points(py, x, unit_tolerance, |p| {
                    routh_core::state::Point::from_array(p).omega(&inner)
                })
            }
        }
    };
}
pub(crate) use rolling_methods;

rolling_methods!(PyBody {
    /// `Body(m, R, a, I1, I3, G=9.81, I2=None)`; invalid parameters raise `ValueError`
    /// naming the parameter and the rule it breaks.
    #[new]
    #[pyo3(signature = (m, R, a, I1, I3, G = 9.81, I2 = None))]
    #[allow(non_snake_case)]
    fn new(m: f64, R: f64, a: f64, I1: f64, I3: f64, G: f64, I2: Option<f64>) -> PyResult<Self> {
        routh_core::Body::new(m, R, a, I1, I2.unwrap_or(I1), I3, G)
            .map(|inner| PyBody { inner })
            .map_err(python_error)
    }

    /// Offset a of the centre of mass (the centre of mass is at `-a e3`).
    #[getter]
    fn a(&self) -> f64 {
        self.inner.a()
    }

    /// Whether the body is the Routh sphere (I1 = I2): the exact solution, the steady motions
    /// and Jellett's and Routh's integrals need it.
    #[getter]
    fn is_symmetric(&self) -> bool {
        self.inner.is_symmetric()
    }

    pub fn __repr__(&self) -> String {
        let b = &self.inner;
        format!(
            "Body(m={:?}, R={:?}, a={:?}, I1={:?}, I3={:?}, G={:?}, I2={:?})",
            b.m(), b.radius(), b.a(), b.i1(), b.i3(), b.gravity(), b.i2()
        )
    }

    /// Pickling: the constructor and its arguments.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let b = slf.get().inner;
        let args = (b.m(), b.radius(), b.a(), b.i1(), b.i3(), b.gravity(), b.i2());
        Ok((slf.get_type().into_any(), args.into_pyobject(slf.py())?))
    }

    /// The integrals at `x` as a dict `{H1, H2, H3, H4, K}`: energy H1 (int-g, twice the
    /// kinetic plus potential energy), the quadratic integral H2, Jellett's H3 = (M, r),
    /// H4 = |gamma|^2 and Routh's K (raus-int). H3 and K are `None` unless I1 = I2; H2 is
    /// `M^2 - m r^2 H1` for I1 != I2 without gravity and `None` for I1 != I2 with gravity.
    /// For `x` of shape `(6, k)` each value is an array of k numbers; `unit_tolerance` as in
    /// `field`.
    #[pyo3(signature = (x, unit_tolerance = Some(UNIT_TOLERANCE)))]
    fn integrals<'py>(
        &self,
        py: Python<'py>,
        x: &Bound<'py, PyAny>,
        unit_tolerance: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let body = self.inner;
        integrals_dict(py, x, unit_tolerance, &INTEGRAL_NAMES, true, |p| {
            Integrals::at(&body, p).values()
        })
    }

    /// The phase-space point `(gamma, M)` with `M = I_Q omega` (om-m), as a numpy 6-vector;
    /// `omega` in rad per unit time, body frame. `gamma` must be a unit vector (`ValueError`
    /// otherwise) unless `normalize=True`, which rescales it.
    #[pyo3(signature = (gamma, omega, normalize = false))]
    fn state_from_omega<'py>(
        &self,
        py: Python<'py>,
        gamma: &Bound<'py, PyAny>,
        omega: &Bound<'py, PyAny>,
        normalize: bool,
    ) -> PyResult<Bound<'py, PyArray1<f64>>> {
        let gamma = vector::<3>("gamma", gamma)?;
        let omega = vector::<3>("omega", omega)?;
        let normalise = if normalize {
            Normalise::Rescale
        } else {
            Normalise::Reject
        };
        let state = State::from_omega(&self.inner, gamma, omega, normalise)
            .map_err(|e| bad_argument("gamma/omega", e))?;
        Ok(PyArray1::from_slice(py, &state.to_array()))
    }
});
