//! The command-line options of an integration that every command integrating a case takes
//! (`simulate`, `sweep`, `lyapunov`, `section`), and the parser of `--method` (whose default
//! each command declares for itself).

use routh::case::{Case, Overrides};
use routh::integrate::Method;
use routh::simulate::Settings;
use routh::AppResult as Result;

/// `--t-end`, `--rtol`, `--atol` and `--max-steps`: each overrides the case's
/// `[integration]` ([`Overrides`]).
#[derive(clap::Args, Debug)]
pub struct Integration {
    /// Final time (default: the case's t_end).
    #[arg(long, allow_hyphen_values = true)]
    pub t_end: Option<f64>,
    /// Relative tolerance (default: the case's rtol).
    #[arg(long, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance, in the motion's units (gamma dimensionless, M in units of m R^2 / T: see the README); at least 1e-150 (default: the case's atol).
    #[arg(long, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// The most steps of one run, rejected ones included (RK4: its step count; `lyapunov`:
    /// of each renormalisation interval's run); default: the case's `max_steps`, else
    /// 10000000. A run that needs more fails (in `sweep`: a row with that reason).
    #[arg(long)]
    pub max_steps: Option<usize>,
}

impl Integration {
    /// These options with the integrator `method`, as overrides of a case.
    pub fn overrides(&self, method: Method) -> Overrides {
        Overrides {
            method: Some(method),
            t_end: self.t_end,
            rtol: self.rtol,
            atol: self.atol,
            max_steps: self.max_steps,
        }
    }

    /// The settings of `case` with these options and the integrator `method`, unprojected and
    /// without samples (the runs of `lyapunov` and `section`), validated as they are built.
    pub fn settings(&self, method: Method, case: &Case) -> Result<Settings> {
        Ok(self.overrides(method).applied_to(case).build()?)
    }
}

/// The integrator named by `--method`.
pub fn parse_method(s: &str) -> std::result::Result<Method, String> {
    s.parse()
        .map_err(|e: routh::integrate::ParseMethodError| e.to_string())
}
