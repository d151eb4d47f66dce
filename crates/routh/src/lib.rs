//! routh: the nonholonomic Routh sphere.
//!
//! An unbalanced, dynamically symmetric ball (I1 = I2) rolling without slipping on a
//! horizontal plane, after Bizyaev and Tsiganov, "On the Routh sphere problem". Equation
//! labels in the documentation, such as (m-eq) or (p-br), are the labels of that paper.
//!
//! This crate gathers the workspace's layers under one name (`docs/architecture.md`), each
//! its own crate so that a wrong arrow does not compile:
//! (1) the integrators, `routh-integrate` ([`integrate`], [`batch`], [`scalar`],
//! [`differential`]), which know nothing of balls; (2) the model of a rolling ball with any
//! moments and any centre of mass, `routh-ball` ([`Ball`], [`field`], [`integrals`],
//! [`motion`], [`state`], runs: [`simulate`], [`problem`]); (3) the Routh sphere's mathematics
//! ([`Body`] with I1 = I2), `routh-sphere` ([`quadrature`], [`steady`], [`poisson`],
//! [`audit`], [`diagram`]); (4) the front ends' library, `routh-io` (features `io`, `plot`,
//! `sweep`, `parquet`: case files, tables, figures, the viewer, sweeps). The command-line tool
//! is the crate `routh-cli` (binary `routh`).
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
//! let settings = Settings::builder()
//!     .method(Method::Dop853)
//!     .t_end(10.0)
//!     .tolerances(1e-12, 1e-12)
//!     .samples(11)
//!     .build()?;
//! let solution = Problem { ball, initial, settings, event: None }.solve()?;
//! assert_eq!(solution.status, Status::Reached);
//! assert!(solution.integrals["MM"].max_rel_drift < 1e-10);
//! # Ok::<(), routh::RouthError>(())
//! ```
#![warn(missing_docs)]

pub use routh_integrate as integrate;
pub use routh_integrate::{batch, differential, sampling, scalar};

pub use routh_ball::{
    auto, ball, body, contact, error, families, field, integrals, kernels, motion, problem,
    projection, range, simulate, state, units,
};
pub use routh_ball::{AsBall, Ball, Body, Model, Point, Result, RouthError, State};

pub use routh_sphere::{audit, poisson, quadrature, steady};

/// Lyapunov exponents of a ball (`routh_ball::lyapunov`) and, with the feature `io`, their
/// report of `routh lyapunov` (`routh_io::lyapunov`).
pub mod lyapunov {
    pub use routh_ball::lyapunov::*;
    #[cfg(feature = "io")]
    pub use routh_io::lyapunov::{report, report_case, History, Report};
}

/// MEGNO and FLI of a ball (`routh_ball::megno`) and, with the feature `io`, their report of
/// `routh megno` (`routh_io::megno`) and, with `sweep`, charts of regimes (`routh_io::chart`).
pub mod megno {
    pub use routh_ball::megno::*;
    #[cfg(feature = "sweep")]
    pub use routh_io::chart;
    #[cfg(feature = "io")]
    pub use routh_io::megno::{report, report_case, History, Report};
}

/// Poincaré sections of a ball (`routh_ball::section`) and, with the feature `io`, the
/// section of a case as `routh section` reports it (`routh_io::section`).
pub mod section {
    pub use routh_ball::section::*;
    #[cfg(feature = "io")]
    pub use routh_io::section::{cells, columns, section, surface_text, write_csv, Report};
}

/// The energy-momentum diagram (`routh-sphere`), and with the feature `plot` its figures
/// (`routh-io`).
pub mod diagram {
    #[cfg(feature = "plot")]
    pub use routh_io::figure;
    pub use routh_sphere::diagram::*;
}

#[cfg(feature = "io")]
pub use routh_io::{
    animate, case, explore, output, row, run, surface, table, AppError, AppResult, FileError,
};
#[cfg(feature = "plot")]
pub use routh_io::{figure, plot};
#[cfg(feature = "sweep")]
pub use routh_io::{inversion, sweep};
