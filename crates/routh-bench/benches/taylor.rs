//! Cost of one Taylor step against its order (`src/integrate/taylor`): the expansion of the
//! default case's field (mg-eq) through one state to the orders 5, 10, 15, 20, 25, 30 (the
//! integrator's order is 14 at tolerance 1e-8, 20 at 1e-12, 16 at 1e-13 and 20 at 1e-16:
//! `taylor::taylor_order`). The tape's size (operations,
//! of which products, quotients and square roots) is printed beside the times, so that the
//! `O(n_ops p^2)` law can be checked: the time divided by `p^2` should settle to a constant as
//! `p` grows. Run with `cargo bench --bench taylor`; figures are recorded in BENCHMARKS.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use routh::batch::Lanes;
use routh::case::Case;
use routh::integrate::taylor::tape::Isa;
use routh::integrate::taylor::Tape;
use routh::kernels::BallKernels;
use routh::simulate::ReducedSystem;
use std::hint::black_box;
use std::time::Duration;

const ORDERS: [usize; 6] = [5, 10, 15, 20, 25, 30];

fn expansion(c: &mut Criterion) {
    let case = Case::default_case().expect("the built-in default case is valid");
    let x = case.initial.to_array();
    let sys = ReducedSystem(&case.ball);
    let tape = Tape::record(&sys, 30).expect("the reduced system records");
    println!(
        "tape of (mg-eq), default case: {} operations, {} of them products, quotients or square roots",
        tape.len(),
        tape.nonlinear_len()
    );
    let mut group = c.benchmark_group("taylor expansion (default case)");
    for p in ORDERS {
        // Recorded for order p, as the integrator records it (the layout depends on it).
        let mut tape = Tape::record(&sys, p).expect("the reduced system records");
        group.bench_with_input(BenchmarkId::from_parameter(p), &p, |b, &p| {
            b.iter(|| {
                tape.expand(0.0, black_box(&x), p);
                tape.state_coefficient(0, p)
            })
        });
    }
    group.finish();
}

/// The same expansion for 4 and 8 runs at once (a tape over [`Lanes`], as the batched Taylor
/// method of `src/batch/taylor.rs` runs it), the instruction set (AVX-512 or AVX2) chosen at
/// run time: the time per run is the time divided by the lanes.
fn expansion_in_lanes(c: &mut Criterion) {
    let case = Case::default_case().expect("the built-in default case is valid");
    let x = case.initial.to_array();
    let sys = ReducedSystem(&case.ball);
    // The instruction set each tape detects when it is recorded.
    println!("expansion in lanes: {:?}", Isa::detect());
    let mut group = c.benchmark_group("taylor expansion in lanes (default case)");
    for p in ORDERS {
        // Recorded for order p, as the integrator records it (the layout depends on it).
        let tape = Tape::record(&sys, p).expect("the reduced system records");
        let mut four: Tape<6, Lanes<4>, BallKernels> = tape.with_coefficients();
        let mut eight: Tape<6, Lanes<8>, BallKernels> = tape.with_coefficients();
        group.bench_with_input(BenchmarkId::new("4 lanes", p), &p, |b, &p| {
            let y = x.map(Lanes::splat);
            b.iter(|| {
                four.expand(Lanes::splat(0.0), black_box(&y), p);
                four.state_coefficient(0, p)
            })
        });
        group.bench_with_input(BenchmarkId::new("8 lanes", p), &p, |b, &p| {
            let y = x.map(Lanes::splat);
            b.iter(|| {
                eight.expand(Lanes::splat(0.0), black_box(&y), p);
                eight.state_coefficient(0, p)
            })
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().measurement_time(Duration::from_secs(3)).warm_up_time(Duration::from_secs(1));
    targets = expansion, expansion_in_lanes
}
criterion_main!(benches);
