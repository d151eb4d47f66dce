//! The exact solution of the Routh sphere by quadrature, compared with DOP853 at t = 50.
//!
//!     cargo run --release --example exact_solution

use routh::integrate::Method;
use routh::problem::Problem;
use routh::quadrature::ExactSolution;
use routh::simulate::Settings;
use routh::state::Normalise;
use routh::{AsBall, Body, State};

fn main() -> routh::Result<()> {
    let body = Body::default();
    let gamma = [0.3_f64.sin(), 0.0, 0.3_f64.cos()];
    let initial = State::from_omega(&body, gamma, [0.5, 0.2, 8.0], Normalise::Reject)?;
    let exact = ExactSolution::new(&body, &initial)?;
    let t = 50.0;
    let by_quadrature = exact.state_at(t);
    let settings = Settings::builder()
        .method(Method::Dop853)
        .t_end(t)
        .tolerances(1e-12, 1e-12)
        .build()?;
    let numerical = Problem {
        ball: body.ball(),
        initial,
        settings,
        event: None,
    }
    .solve()?
    .final_state;
    println!("quadrature gamma = {:?}", by_quadrature.gamma);
    println!("DOP853     gamma = {:?}", numerical.gamma);
    let difference = (0..3)
        .map(|i| (by_quadrature.gamma[i] - numerical.gamma[i]).abs())
        .fold(0.0, f64::max);
    println!("largest difference in gamma: {difference:.1e}");
    Ok(())
}
