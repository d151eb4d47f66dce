//! A trajectory of the default Routh sphere: integrate (mg-eq) with DOP853 and print the tilt
//! gamma3 and the drift of the integrals.
//!
//!     cargo run --release --example trajectory

use routh::integrate::Method;
use routh::problem::Problem;
use routh::simulate::Settings;
use routh::state::Normalise;
use routh::{AsBall, Body, State};

fn main() -> routh::Result<()> {
    let body = Body::default();
    let gamma = [0.3_f64.sin(), 0.0, 0.3_f64.cos()];
    let initial = State::from_omega(&body, gamma, [0.5, 0.2, 8.0], Normalise::Reject)?;
    let problem = Problem {
        ball: body.ball(),
        initial,
        settings: Settings::builder()
            .method(Method::Dop853)
            .t_end(20.0)
            .tolerances(1e-12, 1e-12)
            .samples(11)
            .build()?,
        event: None,
    };
    let solution = problem.solve()?;
    for sample in &solution.samples {
        println!(
            "t = {:5.1}  gamma3 = {:+.12}",
            sample.t, sample.state.gamma[2]
        );
    }
    for (name, drift) in &solution.integrals {
        println!("{name}: max relative drift {:.1e}", drift.max_rel_drift);
    }
    println!(
        "{} steps, {} field evaluations",
        solution.stats.steps, solution.stats.rhs_evals
    );
    Ok(())
}
