//! The Python module `routh`: everything the Rust library `routh` computes, with numpy arrays.
//!
//! A phase-space point is the 6-vector `x = (gamma1, gamma2, gamma3, M1, M2, M3)` of the
//! library: `gamma` the unit normal of the plane pointing into it, `M` the angular momentum
//! about the contact point, both in the body frame; several points are the columns of an
//! array `(6, k)`, as in SciPy. Every formula lives in the library; this crate converts
//! arguments and results, releases the interpreter lock while the library computes, and turns
//! the library's errors into `ValueError` (bad input, naming the argument) or `RuntimeError`.
//! One file per topic: the body, the general ball, the problem and `simulate` (with the events and the
//! dense output on the library's driver, and the solution), the exact solution, the Hamiltonian flows of the first
//! bracket, the steady motions, the audit.

mod audit;
mod ball;
mod body;
mod convert;
mod dense;
mod diagram;
mod drive;
mod exact;
mod flows;
mod lyapunov;
mod problem;
mod section;
mod solution;
mod steady;
mod sweep;

use pyo3::prelude::*;

/// The nonholonomic Routh sphere: Python access to the Rust library `routh`.
#[pymodule]
fn routh(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add("MAX_VALUES", convert::MAX_VALUES)?;
    module.add_class::<body::PyBody>()?;
    module.add_class::<ball::PyBall>()?;
    module.add_class::<problem::PyProblem>()?;
    module.add_class::<problem::PyEvent>()?;
    module.add_class::<solution::Solution>()?;
    module.add_class::<dense::DenseOutput>()?;
    module.add_class::<exact::PyExact>()?;
    module.add_class::<flows::PyFlow>()?;
    module.add_function(wrap_pyfunction!(problem::simulate, module)?)?;
    module.add_function(wrap_pyfunction!(problem::default_case, module)?)?;
    module.add_function(wrap_pyfunction!(problem::load_case, module)?)?;
    module.add_function(wrap_pyfunction!(steady::vertical_spin, module)?)?;
    module.add_function(wrap_pyfunction!(steady::steady_precessions, module)?)?;
    module.add_function(wrap_pyfunction!(steady::routh_threshold, module)?)?;
    module.add_function(wrap_pyfunction!(audit::audit, module)?)?;
    module.add_function(wrap_pyfunction!(sweep::sweep, module)?)?;
    module.add_function(wrap_pyfunction!(lyapunov::lyapunov, module)?)?;
    module.add_function(wrap_pyfunction!(section::section, module)?)?;
    module.add_function(wrap_pyfunction!(diagram::diagram, module)?)?;
    module.add_function(wrap_pyfunction!(diagram::sleeping_tops, module)?)?;
    Ok(())
}
