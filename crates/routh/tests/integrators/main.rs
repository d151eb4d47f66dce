//! The integrators of routh-integrate on the Routh sphere and on published problems: DOP853 and Vern9 against Hairer's and Verner's results, the Taylor method, the SIMD lanes bitwise their one-at-a-time runs, the one driver.
//!
//! One test binary of several modules (issue 32: few binaries, each named after what it proves).

mod batch;
mod driver;
mod integrate_published;
mod taylor;
mod vern9;
