//! The front ends' library of routh: case files ([`case`]), tables of samples ([`table`]) and their rows ([`row`]),
//! output files written whole or not at all ([`output`]), figures ([`plot`], [`figure`]), the
//! 3D viewer ([`animate`]), the explorer page computing in the browser ([`explore`]), sweeps
//! ([`sweep`]), the report of Lyapunov exponents ([`lyapunov`]), of MEGNO and FLI
//! ([`megno`]) and charts of regimes over a parameter plane ([`chart`]), and Poincaré
//! sections ([`section`], on the surfaces of [`surface`]). The command-line tool and the Python module
//! are built on it; the model and the mathematics are the layers below (`routh-ball`,
//! `routh-sphere`).
#![warn(missing_docs)]
// Checks are written `!(x <= limit)` on purpose, so that a NaN fails them too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod animate;
pub mod case;
#[cfg(feature = "sweep")]
pub mod chart;
pub mod error;
pub mod explore;
#[cfg(feature = "plot")]
pub mod figure;
#[cfg(feature = "sweep")]
pub mod inversion;
pub mod lyapunov;
pub mod megno;
pub mod output;
#[cfg(feature = "plot")]
pub mod plot;
pub mod row;
pub mod run;
pub mod section;
pub mod surface;
#[cfg(feature = "sweep")]
pub mod sweep;
pub mod table;

pub use error::{AppError, AppResult, FileError};

pub(crate) use routh_ball::{
    ball, body, contact, integrals, motion, problem, range, simulate, state, Result,
};
pub(crate) use routh_integrate::{self as integrate, batch, sampling};
pub(crate) use routh_sphere::quadrature;
