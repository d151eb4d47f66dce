//! The exact solution by quadrature against step-by-step integration, on the default case:
//! the one-period precomputation, the period and the advance alone (the sweep's `quadrature`
//! columns, `ExactSolution::nutation_numbers`), on the default case and on a sweep's grid of
//! its body (`SWEEP_TILTS` x `SWEEP_SPINS`), the state at t = 1e6 after it, and (timed once:
//! it takes tens of seconds) DOP853 from 0 to 1e6 with the case's tolerances.

use criterion::Criterion;
use routh::case::Case;
use routh::field::vector_field;
use routh::integrate::{solve, Options};
use routh::quadrature::{ExactSolution, Motion};
use routh::state::{Normalise, State};
use std::hint::black_box;
use std::time::Instant;

const T_LONG: f64 = 1e6;
/// The tilts (rad) and the spins omega3 (rad/s) of the sweep's grid: those of a `routh sweep`
/// of the default body (`cases/sweep.toml`, omega1 and omega2 as in the case), from a nearly
/// upright start to one nearly upside down, slow to fast.
const SWEEP_TILTS: [f64; 2] = [0.05, 3.0];
const SWEEP_SPINS: [f64; 2] = [0.5, 20.0];
/// Points of the grid in each direction.
const SWEEP_POINTS: usize = 10;

/// The initial states of the sweep's grid of `body`, `SWEEP_POINTS` tilts by as many spins.
fn sweep_grid(body: &routh::Body) -> Vec<State> {
    let along =
        |[lo, hi]: [f64; 2], i: usize| lo + (hi - lo) * i as f64 / (SWEEP_POINTS - 1) as f64;
    (0..SWEEP_POINTS * SWEEP_POINTS)
        .map(|k| {
            let (tilt, spin) = (
                along(SWEEP_TILTS, k / SWEEP_POINTS),
                along(SWEEP_SPINS, k % SWEEP_POINTS),
            );
            let gamma = [tilt.sin(), 0.0, tilt.cos()];
            State::from_omega(body, gamma, [0.5, 0.2, spin], Normalise::Rescale).unwrap()
        })
        .collect()
}

fn quadrature(c: &mut Criterion) {
    let case = Case::default_case().unwrap();
    let (body, x0) = (case.body("").unwrap(), case.initial);
    let exact = ExactSolution::new(&body, &x0).unwrap();
    if let Motion::Nutation(nut) = &exact.motion {
        println!(
            "default case: period {}, {} Chebyshev nodes",
            nut.period, nut.nodes
        );
    }
    let mut group = c.benchmark_group("quadrature");
    group.sample_size(50);
    group.bench_function("precompute (turning points, period, series)", |b| {
        b.iter(|| ExactSolution::new(black_box(&body), black_box(&x0)).unwrap())
    });
    // What a sweep's `quadrature` columns use: the same period and advance, bit for bit,
    // without the error estimate's second solve, the phase and the probes.
    group.bench_function("period and advance only (nutation_numbers)", |b| {
        b.iter(|| ExactSolution::nutation_numbers(black_box(&body), black_box(&x0)).unwrap())
    });
    let grid = sweep_grid(&body);
    let outcomes = grid.iter().fold([0; 3], |mut n, x| {
        n[match ExactSolution::nutation_numbers(&body, x) {
            Ok(numbers) if numbers.period.is_some() => 0,
            Ok(_) => 1,
            Err(_) => 2,
        }] += 1;
        n
    });
    println!(
        "sweep grid: {} runs, {outcomes:?} nutations, steady, refused",
        grid.len()
    );
    // The time of the whole grid: divided by its runs, the cost of a sweep's row.
    group.bench_function("nutation_numbers on the sweep grid (100 runs)", |b| {
        b.iter(|| {
            for x in &grid {
                let _ = black_box(ExactSolution::nutation_numbers(black_box(&body), x));
            }
        })
    });
    group.bench_function("state at t = 1e6", |b| {
        b.iter(|| exact.state_at(black_box(T_LONG)))
    });
    group.finish();
}

/// DOP853 from 0 to 1e6, timed once, with the distance to the quadrature at the end.
fn dop853_once() {
    let case = Case::default_case().unwrap();
    let (body, x0) = (case.body("").unwrap(), case.initial);
    let opts = Options::new(case.integration.rtol(), case.integration.atol())
        .and_then(|opts| opts.with_max_steps(usize::MAX))
        .unwrap();
    let field = |_t: f64, x: &[f64; 6]| vector_field(&body, x);
    let start = Instant::now();
    let (_, y, _, stats) = solve(
        &field,
        0.0,
        x0.to_array(),
        T_LONG,
        &opts,
        None,
        None,
        &mut |_, _| {},
    )
    .unwrap();
    let elapsed = start.elapsed();
    let exact = ExactSolution::new(&body, &x0)
        .unwrap()
        .state_at(T_LONG)
        .to_array();
    let diff = y
        .iter()
        .zip(&exact)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    println!(
        "DOP853 (rtol = {:e}, atol = {:e}) from 0 to {T_LONG:e}: {:.2} s, {} steps, {} rhs evaluations; \
         max |difference| to the quadrature at t = 1e6: {diff:.3e}",
        opts.rtol(),
        opts.atol(),
        elapsed.as_secs_f64(),
        stats.steps,
        stats.rhs_evals
    );
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    quadrature(&mut c);
    if std::env::var_os("ROUTH_BENCH_SKIP_DOP853").is_none() {
        dop853_once();
    }
    c.final_summary();
}
