//! Chaplygin's ball (centre of mass at the centre, three different moments): its integrals
//! (M, M), (M, gamma) and the energy along a DOP853 run, and the dense solution at any time.
//!
//!     cargo run --release --example chaplygin_ball

use routh::integrate::Method;
use routh::problem::Problem;
use routh::simulate::Settings;
use routh::state::Normalise;
use routh::{Ball, State};

fn main() -> routh::Result<()> {
    let ball = Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 0.0)?;
    println!("model: {:?}", ball.model());
    let gamma = [0.3_f64.sin(), 0.0, 0.3_f64.cos()];
    let initial = State::from_omega(&ball, gamma, [1.5, -2.0, 3.0], Normalise::Reject)?;
    let problem = Problem {
        ball,
        initial,
        settings: Settings::builder()
            .method(Method::Dop853)
            .t_end(100.0)
            .tolerances(1e-12, 1e-12)
            .build()?,
        event: None,
    };
    let (solution, dense) = problem.solve_dense()?;
    for (name, drift) in &solution.integrals {
        println!("{name}: max relative drift {:.1e}", drift.max_rel_drift);
    }
    for t in [0.0, 12.345, 67.89, 100.0] {
        let x = dense.at(t)?;
        println!(
            "t = {t:7.3}: gamma = ({:+.6}, {:+.6}, {:+.6})",
            x[0], x[1], x[2]
        );
    }
    Ok(())
}
