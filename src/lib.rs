//! routh: the nonholonomic Routh sphere.
#![warn(missing_docs)]

pub mod integrate;
