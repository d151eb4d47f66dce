//! Benchmarks of the Poisson geometry (issue 4): one Jacobi-identity evaluation `[P, P]` of the
//! first bracket (p-br) at a point (one AD pass for the 36 entries and their 216 derivatives,
//! then the 20 components of the trivector), and the full claims audit at 20 points.

use criterion::{criterion_group, criterion_main, Criterion};
use routh::audit::claims::{audit, body, generic_first, Sample};
use routh::poisson::schouten::jacobi_defect;
use routh::poisson::second::{SecondAlphas, SecondBracket};
use std::hint::black_box;

fn jacobi(c: &mut Criterion) {
    let x = Sample::new(1, 1).unwrap().points(&body())[0];
    let first = generic_first(body());
    c.bench_function("jacobi [P, P] of (p-br) at a point", |b| {
        b.iter(|| jacobi_defect(black_box(&first), black_box(&x)))
    });
    let second = SecondBracket {
        body: body(),
        alphas: SecondAlphas::Printed,
    };
    c.bench_function("jacobi [P', P'] of (p-bv2) at a point", |b| {
        b.iter(|| jacobi_defect(black_box(&second), black_box(&x)))
    });
}

fn full_audit(c: &mut Criterion) {
    let sample = Sample::new(1, 20).unwrap();
    c.bench_function("full audit, 20 points per claim", |b| {
        b.iter(|| audit(black_box(&sample)))
    });
}

criterion_group!(benches, jacobi, full_audit);
criterion_main!(benches);
