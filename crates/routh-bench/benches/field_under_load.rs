//! The field evaluation timed so that other processes on the machine barely disturb it: the
//! minimum, 10th percentile and median over 20000 batches of 1000 evaluations (about 20 us a
//! batch, shorter than a scheduler time slice, so most batches run uninterrupted). Criterion
//! (`benches/core.rs`) reports wall time per sample, which other processes inflate.
//! Run with `cargo bench --bench field_under_load`.

use routh::case::Case;
use routh::field::vector_field;
use std::hint::black_box;
use std::time::Instant;

const BATCHES: usize = 20_000;
const PER_BATCH: u32 = 1000;

/// Nanoseconds per evaluation of each batch, sorted.
fn batch_times(mut batch: impl FnMut()) -> Vec<f64> {
    let mut ns: Vec<f64> = (0..BATCHES)
        .map(|_| {
            let start = Instant::now();
            batch();
            start.elapsed().as_secs_f64() * 1e9 / f64::from(PER_BATCH)
        })
        .collect();
    ns.sort_by(f64::total_cmp);
    ns
}

fn report(name: &str, ns: &[f64]) {
    println!(
        "{name:<40} min {:6.2} ns   p10 {:6.2} ns   median {:6.2} ns",
        ns[0],
        ns[ns.len() / 10],
        ns[ns.len() / 2]
    );
}

fn main() {
    let case = Case::default_case().expect("the built-in default case is valid");
    let body = case.body("").unwrap();
    let x = case.initial.to_array();
    let independent = batch_times(|| {
        for _ in 0..PER_BATCH {
            black_box(vector_field::<f64>(black_box(&body), black_box(&x)));
        }
    });
    report("vector_field (default case)", &independent);
    // Each evaluation feeds the next, as the stages of a Runge-Kutta step do.
    let chained = batch_times(|| {
        let mut y = x;
        for _ in 0..PER_BATCH {
            let f = vector_field::<f64>(black_box(&body), &y);
            for (yi, fi) in y.iter_mut().zip(f) {
                *yi += 1e-12 * fi;
            }
        }
        black_box(y);
    });
    report("vector_field chained (default case)", &chained);
}
