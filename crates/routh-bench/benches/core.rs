//! Core benchmarks on the default case (`cases/default.toml`): one evaluation of the field
//! (mg-eq), independent and chained (each evaluation's input depends on the previous
//! result), one evaluation of the tracked integrals, one projection onto their level set, and one trajectory
//! to t = 1000 with DOP853 at rtol = atol = 1e-12. The trajectory's step and field-evaluation
//! counts are printed beside it, so that the time per evaluation can be read off.
//! Run with `cargo bench --bench core`; figures are recorded in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, Criterion};
use routh::case::Case;
use routh::field::vector_field;
use routh::integrals::Integrals;
use routh::integrate::Method;
use routh::projection::LevelSet;
use routh::simulate::{run, ReducedSystem, Settings};
use std::hint::black_box;
use std::time::Duration;

/// The trajectory of the benchmark: the default case to t = 1000 at rtol = atol = 1e-12.
fn trajectory_settings() -> Settings {
    Settings::builder()
        .method(Method::Dop853)
        .t_end(1000.0)
        .tolerances(1e-12, 1e-12)
        .build()
        .expect("valid settings")
}

fn default_case() -> Case {
    Case::default_case().expect("the built-in default case is valid")
}

fn field_and_integrals(c: &mut Criterion) {
    let case = default_case();
    let x = case.initial.to_array();
    c.bench_function("vector_field (default case)", |b| {
        b.iter(|| vector_field::<f64>(black_box(&case.ball), black_box(&x)))
    });
    // Each evaluation feeds the next, as the stages of a Runge-Kutta step do: this measures
    // the latency of the field rather than the throughput of independent evaluations.
    c.bench_function("vector_field chained (default case)", |b| {
        let mut y = x;
        b.iter(|| {
            let f = vector_field::<f64>(black_box(&case.ball), &y);
            for (yi, fi) in y.iter_mut().zip(f) {
                *yi += 1e-12 * fi;
            }
        })
    });
    c.bench_function("integrals H1..H4, K (default case)", |b| {
        b.iter(|| Integrals::at(black_box(&case.ball), black_box(&x)))
    });
}

fn projection(c: &mut Criterion) {
    let case = default_case();
    let x0 = case.initial.to_array();
    let level = LevelSet::through(&case.ball, &x0);
    // A state off the level set by about the local error of one step at rtol = 1e-12.
    let perturbed = x0.map(|v| v * (1.0 + 1e-12));
    c.bench_function("projection onto the level set (default case)", |b| {
        b.iter(|| {
            let mut x = black_box(perturbed);
            level.project(&mut x);
            x
        })
    });
}

fn trajectory(c: &mut Criterion) {
    let case = default_case();
    let system = ReducedSystem(&case.ball);
    let x0 = case.initial.to_array();
    let settings = trajectory_settings();
    let simulate = || {
        run(&case.ball, &system, x0, &settings, &mut |_, _| Ok(()))
            .expect("the default case integrates to t = 1000")
    };
    let summary = simulate();
    eprintln!(
        "trajectory: default case to t = {}, DOP853 at rtol = atol = {:e}: {} steps ({} rejected), {} field evaluations",
        settings.t_end(), settings.rtol(), summary.steps, summary.rejected, summary.rhs_evals
    );
    let mut group = c.benchmark_group("trajectory");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(10));
    group.bench_function("default case, t = 1000, DOP853, tol 1e-12", |b| {
        b.iter(|| black_box(simulate()))
    });
    group.finish();
}

criterion_group!(benches, field_and_integrals, projection, trajectory);
criterion_main!(benches);
