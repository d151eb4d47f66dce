//! routh: the nonholonomic Routh sphere.
//!
//! An unbalanced, dynamically symmetric ball (I1 = I2) rolling without slipping on a
//! horizontal plane, after Bizyaev and Tsiganov, "On the Routh sphere problem". Equation
//! labels in the documentation, such as (m-eq) or (p-br), are the labels of that paper.
//!
//! Three layers. (1) The model of a rolling ball with any moments and any centre of mass
//! ([`Ball`], [`field`], [`integrals`], generic over [`scalar::Scalar`]), the integrators
//! ([`integrate`]: DOP853, RK4, one driver) and runs ([`simulate`], [`problem`]). (2) What is
//! special to the Routh sphere ([`Body`] with I1 = I2): [`quadrature`], [`steady`],
//! [`poisson`], [`audit`]. (3) Front ends: case files, tables, figures (features `io`, `plot`)
//! and the command-line tool (feature `cli`).
//!
//! ```
//! use routh::integrate::Method;
//! use routh::problem::{Problem, Status};
//! use routh::simulate::Settings;
//! use routh::state::Normalise;
//! use routh::{Ball, Model, State};
//!
//! // A Chaplygin ball: centre of mass at the geometric centre, three different moments.
//! let ball = Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 9.81)?;
//! assert_eq!(ball.model(), Model::Chaplygin);
//! let initial = State::from_omega(&ball, [0.0, 0.6, 0.8], [1.0, -2.0, 3.0], Normalise::Reject)?;
//! let settings = Settings { method: Method::Dop853, t_end: 10.0, rtol: 1e-12, atol: 1e-12,
//!                           project: false, samples: 11, ..Settings::default() };
//! let solution = Problem { ball, initial, settings, event: None }.solve()?;
//! assert_eq!(solution.status, Status::Reached);
//! assert!(solution.integrals["MM"].max_rel_drift < 1e-10);
//! # Ok::<(), routh::RouthError>(())
//! ```
#![warn(missing_docs)]
// Checks are written `!(x <= limit)` on purpose, so that a NaN fails them too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

#[cfg(feature = "io")]
pub mod animate;
pub mod ball;
pub mod batch;
pub mod body;
#[cfg(feature = "io")]
pub mod case;
pub mod diagram;
pub mod differential;
pub mod error;
pub mod field;
pub mod integrals;
pub mod integrate;
pub mod motion;
#[cfg(feature = "io")]
pub mod output;
#[cfg(feature = "plot")]
pub mod plot;
pub mod problem;
pub mod projection;
pub mod quadrature;
pub mod range;
pub mod sampling;
pub mod scalar;
pub mod simulate;
pub mod state;
pub mod steady;
#[cfg(feature = "sweep")]
pub mod sweep;
#[cfg(feature = "io")]
pub mod table;

pub use ball::{AsBall, Ball, Model};
pub use body::Body;
#[cfg(feature = "io")]
pub use error::{AppError, AppResult, FileError};
pub use error::{Result, RouthError};
pub use state::State;
pub mod audit;
pub mod poisson;
