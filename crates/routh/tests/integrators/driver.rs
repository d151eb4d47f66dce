//! The stepper abstraction and the one driver: the RK4 table's own consistency, its dense
//! output against the exact solution, the observer that stops a run, samples and events on
//! both steppers.

use routh::integrate::{
    drive, Control, Dop853, Drive, IntegrateError, Options, Rk4, Stepper, Stop, RK4_A, RK4_B,
    RK4_C, RK4_DENSE,
};
use std::f64::consts::PI;

fn oscillator(_t: f64, y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0]]
}

#[test]
fn rk4_table_is_consistent() {
    // Exact in binary floating point for these simple fractions up to one rounding: 1e-15.
    for i in 0..4 {
        let row: f64 = RK4_A[i].iter().sum();
        assert!(
            (row - RK4_C[i]).abs() < 1e-15,
            "row {i}: {row} != c = {}",
            RK4_C[i]
        );
        let at_one: f64 = RK4_DENSE[i].iter().sum();
        assert!((at_one - RK4_B[i]).abs() < 1e-15, "b_{i}(1) = {at_one}");
    }
    assert!((RK4_B.iter().sum::<f64>() - 1.0).abs() < 1e-15);
    // Negative control: a wrong weight breaks the sum.
    let mut b = RK4_B;
    b[1] += 1e-3;
    assert!((b.iter().sum::<f64>() - 1.0).abs() > 1e-4);
}

#[test]
fn rk4_dense_output_is_third_order_and_exact_at_step_ends() {
    // The continuous extension of order 3: the error of the interpolant inside a step is
    // O(h^4), so halving h divides the worst error over [0, 2 pi] by ~16 (the global error of
    // RK4 is O(h^4) too). At step ends it returns the step's own state (to round-off).
    let worst = |steps: usize| {
        let mut stepper = Rk4::new(&oscillator, 0.0, [1.0, 0.0], 2.0 * PI, steps);
        let mut worst: f64 = 0.0;
        while !stepper.step().unwrap() {
            let (ta, tb) = (stepper.t_prev(), stepper.t());
            let end = stepper.dense(tb);
            assert!(
                (end[0] - stepper.y()[0]).abs() < 1e-14,
                "dense at the step end"
            );
            for k in 1..8 {
                let t = ta + (tb - ta) * k as f64 / 8.0;
                worst = worst.max((stepper.dense(t)[0] - t.cos()).abs());
            }
        }
        worst
    };
    let (coarse, fine) = (worst(50), worst(100));
    let ratio = coarse / fine;
    assert!(
        (12.0..20.0).contains(&ratio),
        "{coarse:e} / {fine:e} = {ratio}"
    );
}

#[test]
fn the_observer_stops_a_run_between_steps() {
    let opts = Options {
        rtol: 1e-10,
        atol: 1e-10,
        ..Options::default()
    };
    let mut solver = Dop853::new(&oscillator, 0.0, [1.0, 0.0], 100.0, &opts).unwrap();
    let mut seen = 0;
    let outcome = drive::<_, IntegrateError, 2>(
        &mut solver,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| {
            seen += 1;
            Ok(if seen == 5 {
                Control::Stop
            } else {
                Control::Continue
            })
        },
    )
    .unwrap();
    assert_eq!(seen, 5);
    assert_eq!(outcome.stats.steps, 5);
    assert!(matches!(outcome.stop, Stop::Stopped { t } if t > 0.0 && t < 100.0));
    // Negative control: without the stop the run reaches t_end.
    let mut solver = Dop853::new(&oscillator, 0.0, [1.0, 0.0], 100.0, &opts).unwrap();
    let outcome = drive::<_, IntegrateError, 2>(
        &mut solver,
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| Ok(Control::Continue),
    )
    .unwrap();
    assert_eq!(outcome.stop, Stop::Reached);
    assert_eq!(outcome.t, 100.0);
}

#[test]
fn samples_and_events_work_on_both_steppers() {
    // The event y0 = 0 (cos t = 0) at t = pi/2 and the samples on [0, 1.5] against the exact
    // solution: DOP853 at 1e-12 (5e-11 for its dense output), RK4 with h = 1e-3 (error
    // h^4 ~ 1e-12, interpolant ~1e-12).
    let samples: Vec<f64> = (0..16).map(|i| 0.1 * i as f64).collect();
    let event = |_: f64, y: &[f64; 2]| y[0];
    let opts = Options {
        rtol: 1e-12,
        atol: 1e-12,
        ..Options::default()
    };
    let mut dop = Dop853::new(&oscillator, 0.0, [1.0, 0.0], 3.0, &opts).unwrap();
    let mut rk = Rk4::new(&oscillator, 0.0, [1.0, 0.0], 3.0, 3000);
    let steppers: [&mut dyn Stepper<2>; 2] = [&mut dop, &mut rk];
    for stepper in steppers {
        let mut got = Vec::new();
        let outcome = drive::<_, IntegrateError, 2>(
            stepper,
            &Drive {
                samples: &samples,
                project: None,
                event: Some(&event),
            },
            &mut |t, y| {
                got.push((t, y[0]));
                Ok(())
            },
            &mut |_, _, _| Ok(Control::Continue),
        )
        .unwrap();
        let Stop::Event { t, .. } = outcome.stop else {
            panic!("no event: {:?}", outcome.stop)
        };
        assert!((t - PI / 2.0).abs() < 1e-10, "event at {t}");
        assert_eq!(got.len(), samples.len());
        for (t, y) in got {
            assert!(
                (y - t.cos()).abs() < 5e-11,
                "sample at {t}: {y} vs {}",
                t.cos()
            );
        }
    }
}
