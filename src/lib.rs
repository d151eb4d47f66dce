//! routh: the nonholonomic Routh sphere.
//!
//! An unbalanced, dynamically symmetric ball (I1 = I2) rolling without slipping on a
//! horizontal plane, after Bizyaev and Tsiganov, "On the Routh sphere problem". Equation
//! labels in the documentation, such as (m-eq) or (p-br), are the labels of that paper.
#![warn(missing_docs)]

pub mod animate;
pub mod body;
pub mod case;
pub mod differential;
pub mod error;
pub mod field;
pub mod integrals;
pub mod integrate;
pub mod motion;
pub mod output;
pub mod plot;
pub mod projection;
pub mod range;
pub mod quadrature;
pub mod sampling;
pub mod scalar;
pub mod simulate;
pub mod state;
pub mod steady;
pub mod table;

pub use body::Body;
pub use error::{Result, RouthError};
pub use state::State;
pub mod audit;
pub mod poisson;
