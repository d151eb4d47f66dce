//! The exact solution by quadrature against step-by-step integration, on the default case:
//! the one-period precomputation, the period and the advance alone (the sweep's `quadrature`
//! columns, `ExactSolution::nutation_numbers`), the state at t = 1e6 after it, and (timed
//! once: it takes tens of seconds) DOP853 from 0 to 1e6 with the case's tolerances.

use criterion::Criterion;
use routh::case::Case;
use routh::field::vector_field;
use routh::integrate::{solve, Options};
use routh::quadrature::{ExactSolution, Motion};
use std::hint::black_box;
use std::time::Instant;

const T_LONG: f64 = 1e6;

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
