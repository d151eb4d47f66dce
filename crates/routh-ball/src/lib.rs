//! The model of a ball rolling without slipping on a horizontal plane: any moments of inertia
//! and any centre of mass ([`Ball`]), the Routh sphere with I1 = I2 and the centre of mass on
//! the symmetry axis ([`Body`]), the reduced equations of motion (m-eq), (mg-eq) written once
//! generic over [`Scalar`](routh_integrate::scalar::Scalar) ([`field`]), the integrals and the
//! invariant measure ([`integrals`]), the motion in space ([`motion`]), the validated states
//! ([`state`]), the projection onto the level set of the integrals ([`projection`]) and runs
//! of the integrators of `routh-integrate` on it ([`simulate`], [`problem`]; the method that
//! `auto` runs: [`auto`]), its Lyapunov exponents ([`lyapunov`]), MEGNO and FLI
//! ([`megno`]) and Poincaré sections ([`section`]); the same ball on other contacts with the
//! plane ([`contact`]: the sliding ball with viscous friction, the tippe top).
//!
//! Equation labels, such as (m-eq), are those of Bizyaev and Tsiganov, "On the Routh sphere
//! problem".
#![warn(missing_docs)]
// Checks are written `!(x <= limit)` on purpose, so that a NaN fails them too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod auto;
pub mod ball;
pub mod body;
pub mod contact;
pub mod error;
pub mod families;
pub mod field;
pub mod integrals;
#[rustfmt::skip]
pub mod kernels;
pub mod lyapunov;
pub mod megno;
pub mod motion;
pub mod problem;
pub mod projection;
pub mod range;
pub mod section;
pub mod simulate;
pub mod state;
pub mod units;

pub(crate) use routh_integrate::{self as integrate, batch, differential, scalar};

pub use ball::{AsBall, Ball, Model};
pub use body::Body;
pub use error::{Result, RouthError};
pub use state::{Point, State};
