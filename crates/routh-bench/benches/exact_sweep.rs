//! Issue 14's sweep: 2,000 initial conditions (tilts over (0, pi), spins 0.1 to 30, gravity
//! on and off, centre of mass up and down, random Routh spheres; generator in
//! `tests/support/exact_sweep.rs`). Each is solved by the quadrature (`ExactSolution::new` and
//! the state at t = 10, timed) and compared with DOP853 at rtol 1e-13. Prints the refusal
//! counts, the worst agreement and the median and maximum time per case.
//!
//! `cargo bench --bench exact_sweep` (N cases: `EXACT_SWEEP_CASES=N`).

#[path = "../../routh/tests/support/exact_sweep.rs"]
mod exact_sweep;

use exact_sweep::{cases, distance, dop853, quadrature, Outcome, AGREEMENT, T};
use std::time::Instant;

fn main() {
    let n = std::env::var("EXACT_SWEEP_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000);
    let (mut times, mut worst, mut beyond) = (vec![], 0.0_f64, 0);
    let (mut separatrices, mut refused) = (vec![], vec![]);
    for case in cases(n, 14) {
        let start = Instant::now();
        let outcome = quadrature(&case);
        times.push(start.elapsed().as_secs_f64());
        match outcome {
            Outcome::Solved(state) => {
                let d = distance(&state, &dop853(&case, T));
                if d >= AGREEMENT {
                    beyond += 1;
                    println!("disagrees by {d:e}: {case:?}");
                }
                worst = worst.max(d);
            }
            Outcome::Separatrix(reason) => separatrices.push(format!("{case:?}: {reason}")),
            Outcome::Refused(reason) => refused.push(format!("{case:?}: {reason}")),
        }
    }
    times.sort_by(f64::total_cmp);
    println!(
        "{n} cases: solved {}, worst difference from DOP853 at t = {T} {worst:.1e} ({beyond} \
         above {AGREEMENT:e}); separatrix {}, other refusals {}",
        n - separatrices.len() - refused.len(),
        separatrices.len(),
        refused.len()
    );
    for r in separatrices.iter().chain(&refused) {
        println!("  refused: {r}");
    }
    println!(
        "time per case (ExactSolution::new + state at t = {T}): median {:.3} ms, 90 % {:.3} ms, \
         max {:.3} ms, total {:.2} s",
        1e3 * times[n / 2],
        1e3 * times[9 * n / 10],
        1e3 * times[n - 1],
        times.iter().sum::<f64>()
    );
}
