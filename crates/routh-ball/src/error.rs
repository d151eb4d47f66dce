//! Errors of the library: each variant carries the data that explains it.
//!
//! [`RouthError`]: the errors of the model and its numerics, what the library layers
//! return. The errors of files and of the front ends are `routh-io`'s (`FileError`,
//! `AppError`, which holds a [`RouthError`] or a `FileError`).
//!
//! Normal endings of a computation (end time reached, event found) are not errors; they are
//! returned as values by the modules that produce them.

/// What can go wrong in the model and its numerics: the library core (the model, the
/// integrators, the quadrature, the Poisson geometry) returns this error and no other.
#[derive(Debug, thiserror::Error)]
pub enum RouthError {
    /// A body parameter breaks a rule (non-finite, non-positive, |a| >= R, ...).
    #[error("invalid body parameter {name} = {}: {rule}", Number(*value))]
    Parameter {
        /// The parameter's name as in the paper (m, R, a, I1, I2, I3, G).
        name: &'static str,
        /// The offending value.
        value: f64,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// The principal moments of inertia violate a triangle inequality.
    #[error("principal moments of inertia violate the triangle inequality {rule}: I1 = {i1}, I2 = {i2}, I3 = {i3}")]
    Triangle {
        /// The inequality that fails, e.g. "I1 + I2 >= I3".
        rule: &'static str,
        /// I1.
        i1: f64,
        /// I2.
        i2: f64,
        /// I3.
        i3: f64,
    },
    /// A computation that needs the dynamically symmetric Routh sphere I1 = I2.
    #[error("{what} needs a dynamically symmetric body I1 = I2, but I1 = {i1} and I2 = {i2}")]
    NotSymmetric {
        /// What needs the symmetry.
        what: &'static str,
        /// I1.
        i1: f64,
        /// I2.
        i2: f64,
    },
    /// A computation that needs the centre of mass on the e3 axis (a [`crate::Body`]: the
    /// Routh sphere, its quadrature and geometry) was given a ball whose centre of mass is off it.
    #[error(
        "{what} needs the centre of mass on the e3 axis (com = (0, 0, -a)), but com = {com:?}"
    )]
    OffAxis {
        /// What needs it.
        what: &'static str,
        /// The centre of mass offset of the ball.
        com: [f64; 3],
    },
    /// A state (gamma, M) that is not a point of the phase space.
    #[error("invalid state: {0}")]
    State(String),
    /// An invalid option value (NaN or negative t_end, tolerance, sample count, ...).
    #[error("invalid option {name} = {value}: {rule}")]
    Option {
        /// The option's name as on the command line or in the case file.
        name: &'static str,
        /// The offending value, as text.
        value: String,
        /// The rule it breaks.
        rule: &'static str,
    },
    /// A formula evaluated at one of its singular points.
    #[error("{formula} is singular here: {reason}")]
    Singular {
        /// The formula, with its equation label.
        formula: &'static str,
        /// Why, with the offending value.
        reason: String,
    },
    /// The motion is on or near a separatrix (a homoclinic orbit of (mg-eq)): the nutation
    /// period diverges, so the quadrature over one period cannot be done.
    #[error("the motion is on or near a separatrix, where the nutation period diverges: {reason} (tilt between gamma3 = {u_min} and {u_max})")]
    Separatrix {
        /// Lower turning point of gamma3.
        u_min: f64,
        /// Upper turning point of gamma3.
        u_max: f64,
        /// What shows it (a double root of Q, or a series that does not converge).
        reason: String,
    },
    /// A time beyond the range where the quadrature keeps its accuracy: the phase error grows
    /// like t times the error of the period (or exponentially near an unstable equilibrium).
    #[error("t = {t:e} is beyond the range |t| <= {horizon:e} where the quadrature keeps an error below {tolerance:e}: its estimated relative error at t is {error:e} (the phase error grows like t times the error of the period)")]
    Horizon {
        /// The time asked for.
        t: f64,
        /// The largest |t| with the error below the tolerance.
        horizon: f64,
        /// The tolerance.
        tolerance: f64,
        /// The estimated relative error at t.
        error: f64,
    },
    /// A state that the quadrature cannot resolve at all: its estimated error is above the
    /// tolerance already at t = 0 (the turning points, the period or the start are
    /// conditioned beyond what f64 resolves for this state).
    #[error("the quadrature cannot resolve this state: its estimated relative error is {error:e} already at t = 0, above {tolerance:e} (its turning points, period or start are conditioned beyond what f64 resolves; integrate it with `routh simulate` instead)")]
    Unresolved {
        /// The tolerance.
        tolerance: f64,
        /// The estimated relative error at t = 0.
        error: f64,
    },
    /// A parameter or a state beyond the range of f64 for a quantity of the model.
    #[error("{cause} makes {quantity} {direction} (value {value:e})")]
    Overflow {
        /// The parameters or the state that cause it, with their values.
        cause: String,
        /// The quantity that overflows (the energy H1, the inertia I_Q, ...).
        quantity: &'static str,
        /// `overflow` or `underflow`.
        direction: &'static str,
        /// The value reached (infinite, NaN, or the offending magnitude).
        value: f64,
    },
    /// The numerical integration failed.
    #[error("integration failed: {0}")]
    Integrate(#[from] crate::integrate::IntegrateError),
}

/// A number in a message as a reader reads it: the shorter of its plain decimal (`-1`,
/// `9.81`) and its shortest round-trip form with an exponent (`1e40`, `1e-320`, where the plain
/// decimal has dozens or hundreds of digits).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Number(pub f64);

impl std::fmt::Display for Number {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let plain = self.0.to_string();
        let exponent = format!("{:?}", self.0);
        f.write_str(if exponent.len() < plain.len() {
            &exponent
        } else {
            &plain
        })
    }
}

/// Shorthand for results of this crate.
pub type Result<T> = std::result::Result<T, RouthError>;
