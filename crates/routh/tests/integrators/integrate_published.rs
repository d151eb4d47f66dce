//! Tests of the integrators against published problems and reference figures.

// Published constants are quoted with all their digits.
#![allow(clippy::excessive_precision)]

use routh::integrate::{
    brent, fixed_step_solve, rk4, solve, solve_dense, Dop853, IntegrateError, Method, Options,
    Stats, Stepper, Stop,
};
use std::f64::consts::{FRAC_PI_2, PI};

/// Arenstorf orbit of the restricted three-body problem (Hairer, Nørsett,
/// Wanner, Solving ODE I, Section II.0, eq. (0.1)), as a first-order system.
fn arenstorf(_t: f64, y: &[f64; 4]) -> [f64; 4] {
    const MU: f64 = 0.012277471;
    const MUP: f64 = 1.0 - MU;
    let r1 = (y[0] + MU).powi(2) + y[1].powi(2);
    let r1 = r1 * r1.sqrt();
    let r2 = (y[0] - MUP).powi(2) + y[1].powi(2);
    let r2 = r2 * r2.sqrt();
    [
        y[2],
        y[3],
        y[0] + 2.0 * y[3] - MUP * (y[0] + MU) / r1 - MU * (y[0] - MUP) / r2,
        y[1] - 2.0 * y[2] - MUP * y[1] / r1 - MU * y[1] / r2,
    ]
}

const AREN_Y0: [f64; 4] = [0.994, 0.0, 0.0, -2.00158510637908252240537862224];
const AREN_T: f64 = 17.0652165601579625588917206249;

fn tol_opts(tol: f64) -> Options {
    Options {
        rtol: tol,
        atol: tol,
        ..Options::default()
    }
}

fn max_abs_diff<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn run_to_end<const N: usize>(
    f: &impl Fn(f64, &[f64; N]) -> [f64; N],
    t0: f64,
    y0: [f64; N],
    t1: f64,
    opts: &Options,
) -> ([f64; N], Stats) {
    let (stop, y, t, stats) = solve(f, t0, y0, t1, opts, None, None, &mut |_, _| {}).unwrap();
    assert_eq!(stop, Stop::Reached);
    assert_eq!(t, t1, "the last step lands exactly on t_end");
    (y, stats)
}

/// Step counts of Hairer's `dop853.f` (version of 2002, from
/// cpmech/hwode commit 2fb5fbe, which is the original distribution), compiled
/// with `gfortran -O2` and run on the Arenstorf orbit over one period with
/// `ITOL = 0`, `RTOL = ATOL = 10^-k`, `IOUT = 0`, stiffness test off. The
/// Fortran reports `NFCN` (which counts `f(x0)` and the `HINIT` call as 2),
/// `NSTEP` (all attempted steps), `NACCPT` and `NREJCT` (rejections of the
/// first step not counted, so `NSTEP - NACCPT - NREJCT` of them occurred
/// there). Endpoint `y(T)` as printed by the Fortran driver (E25.16).
const HAIRER_ARENSTORF: [(i32, usize, usize, usize, [f64; 4]); 6] = [
    (
        7,
        1361,
        116,
        83,
        [
            0.9940016115880793,
            0.4097708248571551e-05,
            0.6714462110871677e-03,
            -0.2001333791054284e+01,
        ],
    ),
    (
        8,
        1736,
        148,
        106,
        [
            0.9940001874524537,
            0.5160189669511581e-06,
            0.8433704326926694e-04,
            -0.2001555907717282e+01,
        ],
    ),
    (
        9,
        2184,
        186,
        136,
        [
            0.9940000133010850,
            0.4486347898269381e-07,
            0.7281362233095556e-05,
            -0.2001583034377828e+01,
        ],
    ),
    (
        10,
        2785,
        237,
        176,
        [
            0.9940000015236845,
            0.5272854179270894e-08,
            0.8553979480227514e-06,
            -0.2001584869042114e+01,
        ],
    ),
    (
        11,
        3509,
        298,
        229,
        [
            0.9939999999520527,
            -0.1581515766870684e-10,
            -0.3345545493416147e-08,
            -0.2001585113830624e+01,
        ],
    ),
    (
        12,
        4249,
        359,
        298,
        [
            0.9939999999956166,
            0.5911632294797187e-11,
            0.8503002468795984e-09,
            -0.2001585107059725e+01,
        ],
    ),
];

#[test]
fn arenstorf_matches_hairer_dop853_f() {
    for &(k, nfcn, nstep, naccpt, y_ref) in &HAIRER_ARENSTORF {
        let tol = 10f64.powi(-k);
        // The plain update of the Fortran (no compensated summation), so that the
        // arithmetic is the same operation for operation.
        let opts = Options {
            compensated: false,
            ..tol_opts(tol)
        };
        let (y, stats) = run_to_end(&arenstorf, 0.0, AREN_Y0, AREN_T, &opts);
        println!(
            "tol 1e-{k}: {stats:?}, endpoint error {:e}",
            max_abs_diff(&y, &AREN_Y0)
        );
        // Same algorithm and arithmetic order as the Fortran: identical counts.
        assert_eq!(stats.rhs_evals, nfcn, "tol 1e-{k}");
        assert_eq!(stats.steps + stats.rejected, nstep, "tol 1e-{k}");
        assert_eq!(stats.steps, naccpt, "tol 1e-{k}");
        // Identical step sequence: the endpoints agree with the Fortran's printed
        // 16 digits up to rounding; 1e-12 is far below the global errors
        // (>= 8e-10 here), so any deviation from Hairer's algorithm would show.
        assert!(max_abs_diff(&y, &y_ref) < 1e-12, "tol 1e-{k}: {y:?}");
    }
}

#[test]
fn arenstorf_returns_to_start() {
    // Global error at rtol = atol = 1e-12 over one period: the orbit is
    // sensitive (error growth ~1e3 through the close approaches), so the
    // endpoint returns to y0 within 1e-8 (Hairer's figure shows the same level).
    let (y, _) = run_to_end(&arenstorf, 0.0, AREN_Y0, AREN_T, &tol_opts(1e-12));
    let err = max_abs_diff(&y, &AREN_Y0);
    assert!(err < 1e-8, "endpoint error {err:e}");
}

/// Harmonic oscillator `x'' = -x` with `x(0) = 1, x'(0) = 0`: `x = cos t`.
fn oscillator(_t: f64, y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0]]
}

fn oscillator_exact(t: f64) -> [f64; 2] {
    [t.cos(), -t.sin()]
}

/// Observed orders `log2(e(n) / e(2n))` from errors at successive halvings.
fn observed_orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect()
}

#[test]
fn dop853_fixed_step_has_order_8() {
    // Harmonic oscillator over [0, 10] with n = 10, 20, 40, 80 equal steps: the
    // errors (7e-7 down to 3e-14) stay above round-off (~1e-15), so every
    // halving must show the order 8 within 0.3. (On y' = y cos t the error
    // constant changes sign along the interval, which blurs the ratios.)
    let exact = oscillator_exact(10.0);
    let errors: Vec<f64> = [10, 20, 40, 80]
        .iter()
        .map(|&n| {
            max_abs_diff(
                &fixed_step_solve(&oscillator, 0.0, [1.0, 0.0], 10.0, n).unwrap(),
                &exact,
            )
        })
        .collect();
    let orders = observed_orders(&errors);
    println!("DOP853 fixed-step errors {errors:?}, observed orders {orders:?}");
    for p in orders {
        assert!((p - 8.0).abs() < 0.3, "observed order {p}");
    }
}

#[test]
fn rk4_has_order_4() {
    // Harmonic oscillator over [0, 2π] with 50..400 steps: errors 1e-6..1e-10,
    // far above round-off, so the observed order is 4 within 0.1.
    let exact = oscillator_exact(2.0 * PI);
    let errors: Vec<f64> = [50, 100, 200, 400]
        .iter()
        .map(|&n| {
            let mut calls = 0;
            let (y, stats) = rk4(&oscillator, 0.0, [1.0, 0.0], 2.0 * PI, n, |_, _| calls += 1);
            assert_eq!(calls, n);
            assert_eq!(stats.rhs_evals, 4 * n);
            max_abs_diff(&y, &exact)
        })
        .collect();
    let orders = observed_orders(&errors);
    println!("RK4 errors {errors:?}, observed orders {orders:?}");
    for p in orders {
        assert!((p - 4.0).abs() < 0.1, "observed order {p}");
    }
}

#[test]
fn event_at_quarter_period_is_located_to_1e_12() {
    // x = cos t vanishes at π/2. With rtol = atol = 1e-12 the solution and the
    // 7th-order dense output are accurate to ~1e-13 there and |x'| = 1, so the
    // root is located within 1e-12 (a published crate was found 4e-8 off here).
    let opts = tol_opts(1e-12);
    let g = |_t: f64, y: &[f64; 2]| y[0];
    let mut last_t = 0.0;
    let (stop, y, t, _) = solve(
        &oscillator,
        0.0,
        [1.0, 0.0],
        10.0,
        &opts,
        None,
        Some(&g),
        &mut |t, _| last_t = t,
    )
    .unwrap();
    let Stop::Event { t: te, y: ye } = stop else {
        panic!("no event found: {stop:?}");
    };
    println!("event at t = {te:.17}, error {:e}", te - FRAC_PI_2);
    assert_eq!((te, ye), (t, y));
    assert_eq!(last_t, te, "the observer sees the event point last");
    assert!((te - FRAC_PI_2).abs() < 1e-12);
    assert!((ye[1] + 1.0).abs() < 1e-12);
}

#[test]
fn dense_output_matches_exact_solution() {
    // 2001 samples on [0, 20] (about 3 periods) at rtol = atol = 1e-10: the
    // global error of the steps grows to a few 1e-10; the interpolant adds an
    // error of the order of the local tolerance. Bound: 10 x tolerance.
    let tol = 1e-10;
    let samples: Vec<f64> = (0..=2000).map(|i| i as f64 * 0.01).collect();
    let mut worst: f64 = 0.0;
    let mut count = 0;
    let (y_end, stats) = solve_dense(
        &oscillator,
        0.0,
        [1.0, 0.0],
        20.0,
        &tol_opts(tol),
        None,
        &samples,
        &mut |t, y| {
            assert_eq!(t, samples[count]);
            count += 1;
            worst = worst.max(max_abs_diff(y, &oscillator_exact(t)));
        },
    )
    .unwrap();
    println!("dense output: worst error {worst:e}, {stats:?}");
    assert_eq!(count, samples.len());
    assert!(worst < 10.0 * tol, "worst dense error {worst:e}");
    assert!(max_abs_diff(&y_end, &oscillator_exact(20.0)) < 10.0 * tol);
}

#[test]
fn dense_output_interpolates_each_step() {
    // On every step, the interpolant reproduces both step ends to rounding
    // (1e-15) and is accurate at interior points to 10 x tolerance (1e-11).
    let opts = tol_opts(1e-12);
    let mut solver = Dop853::new(&oscillator, 0.0, [1.0, 0.0], 7.0, &opts).unwrap();
    let mut done = false;
    while !done {
        let before = solver.stats().rhs_evals;
        done = solver.step().unwrap();
        let after_step = solver.stats().rhs_evals;
        let (ta, tb) = (solver.t_prev(), solver.t());
        assert!(max_abs_diff(&solver.dense(tb), solver.y()) < 1e-15);
        assert!(max_abs_diff(&solver.dense(ta), &oscillator_exact(ta)) < 1e-11);
        for j in 1..10 {
            let s = ta + (tb - ta) * j as f64 / 10.0;
            assert!(max_abs_diff(&solver.dense(s), &oscillator_exact(s)) < 1e-11);
        }
        // The three extra dense stages are computed once per step.
        assert_eq!(solver.stats().rhs_evals, after_step + 3);
        assert!(after_step - before >= 12);
    }
    assert_eq!(solver.t(), 7.0);
}

#[test]
fn backward_integration() {
    // From 0 back to -5 at rtol = atol = 1e-12; exact (cos t, -sin t).
    // Global error over less than one period stays below 1e-11 (10 x tolerance).
    let (y, stats) = run_to_end(&oscillator, 0.0, [1.0, 0.0], -5.0, &tol_opts(1e-12));
    let err = max_abs_diff(&y, &oscillator_exact(-5.0));
    println!("backward: error {err:e}, {stats:?}");
    assert!(err < 1e-11);
    // Forward and backward integrations take mirrored steps.
    let (_, forward) = run_to_end(&oscillator, 0.0, [1.0, 0.0], 5.0, &tol_opts(1e-12));
    assert_eq!(forward, stats);
}

#[test]
fn invalid_options_are_rejected() {
    let cases: [(Options, &str); 7] = [
        (
            Options {
                rtol: f64::NAN,
                ..Options::default()
            },
            "rtol",
        ),
        (
            Options {
                rtol: 0.0,
                ..Options::default()
            },
            "rtol",
        ),
        (
            Options {
                atol: -1e-8,
                ..Options::default()
            },
            "atol",
        ),
        (
            Options {
                atol: f64::INFINITY,
                ..Options::default()
            },
            "atol",
        ),
        (
            Options {
                h_init: Some(0.0),
                ..Options::default()
            },
            "h_init (absolute value)",
        ),
        (
            Options {
                h_max: Some(f64::NAN),
                ..Options::default()
            },
            "h_max",
        ),
        (
            Options {
                max_steps: 0,
                ..Options::default()
            },
            "max_steps",
        ),
    ];
    for (opts, expected) in cases {
        match Dop853::new(&oscillator, 0.0, [1.0, 0.0], 1.0, &opts) {
            Err(IntegrateError::InvalidOption { name, .. }) => assert_eq!(name, expected),
            Err(e) => panic!("wrong error for {expected}: {e}"),
            Ok(_) => panic!("{expected} accepted"),
        }
    }
    assert!(Options::default().validate().is_ok());
    let err = solve_dense(
        &oscillator,
        0.0,
        [1.0, 0.0],
        1.0,
        &Options::default(),
        None,
        &[0.5, 0.25],
        &mut |_, _| {},
    )
    .unwrap_err();
    assert!(
        matches!(err, IntegrateError::InvalidOption { name: "samples", value, .. } if value == 0.25)
    );
    let err = Dop853::new(&oscillator, 0.0, [f64::NAN, 0.0], 1.0, &Options::default()).err();
    assert_eq!(err, Some(IntegrateError::NonFinite { t: 0.0 }));
}

#[test]
fn blow_up_is_an_error_not_a_hang() {
    // y' = y^2, y(0) = 1 has the solution 1 / (1 - t), singular at t = 1.
    let f = |_t: f64, y: &[f64; 1]| [y[0] * y[0]];
    let mut solver = Dop853::new(&f, 0.0, [1.0], 2.0, &Options::default()).unwrap();
    let err = loop {
        match solver.step() {
            Ok(false) => {}
            Ok(true) => panic!("integrated through the singularity"),
            Err(e) => break e,
        }
    };
    println!("blow-up: {err} after {:?}", solver.stats());
    match err {
        IntegrateError::StepSizeTooSmall { t, .. } | IntegrateError::NonFinite { t } => {
            assert!((t - 1.0).abs() < 1e-6, "stopped at t = {t}");
        }
        e => panic!("unexpected error {e}"),
    }
    let opts = Options {
        max_steps: 5,
        ..Options::default()
    };
    let err = solve(&f, 0.0, [1.0], 2.0, &opts, None, None, &mut |_, _| {}).unwrap_err();
    assert!(
        matches!(err, IntegrateError::TooManySteps { t, max_steps: 5 } if t > 0.0 && t < 1.0),
        "{err}"
    );
}

#[test]
fn projection_keeps_the_norm() {
    // Rotation y' = (-y1, y0) at a loose tolerance (1e-6) so that the unprojected
    // norm drifts visibly; the projection normalises after every step, so at
    // every step end |y| = 1 to rounding (1e-15).
    let rot = |_t: f64, y: &[f64; 2]| [-y[1], y[0]];
    // Counts the projections that change the state (the others call no set_state).
    let changed = std::cell::Cell::new(0usize);
    let normalise = |y: &mut [f64; 2]| {
        let before = *y;
        let r = y[0].hypot(y[1]);
        y[0] /= r;
        y[1] /= r;
        if before.map(f64::to_bits) != y.map(f64::to_bits) {
            changed.set(changed.get() + 1);
        }
    };
    let opts = tol_opts(1e-6);
    let mut worst: f64 = 0.0;
    let mut observed = 0;
    let (_, y, _, stats) = solve(
        &rot,
        0.0,
        [1.0, 0.0],
        100.0,
        &opts,
        Some(&normalise),
        None,
        &mut |_, y| {
            observed += 1;
            worst = worst.max((y[0].hypot(y[1]) - 1.0).abs());
        },
    )
    .unwrap();
    println!("projection: worst |r - 1| = {worst:e}, {stats:?}");
    assert!(worst <= 1e-15);
    assert_eq!(observed, stats.steps);
    // f(t0), HINIT, 11 per attempt, 1 FSAL per acceptance, 1 per set_state (one per
    // projection that changed the state: nearly every step here).
    assert!(
        changed.get() + 5 > stats.steps,
        "{} of {}",
        changed.get(),
        stats.steps
    );
    assert_eq!(
        stats.rhs_evals,
        2 + 11 * (stats.steps + stats.rejected) + stats.steps + changed.get()
    );
    let (y_free, _) = run_to_end(&rot, 0.0, [1.0, 0.0], 100.0, &opts);
    let drift = (y_free[0].hypot(y_free[1]) - 1.0).abs();
    println!("without projection |r - 1| = {drift:e}");
    assert!(drift > 1e-12, "the test must exercise the projection");
    assert!((y[0].hypot(y[1]) - 1.0).abs() <= 1e-15);
}

#[test]
fn brent_finds_bracketed_roots() {
    // cos has its root π/2 in [1, 2]; tol = 0 asks for full precision (2 ulp).
    let r = brent(f64::cos, 1.0, 2.0, 0.0, 100).unwrap();
    assert!((r - FRAC_PI_2).abs() <= 4.0 * f64::EPSILON);
    assert_eq!(brent(f64::cos, 2.0, 3.0, 0.0, 100), None, "no bracket");
}

#[test]
fn method_names_round_trip() {
    assert_eq!("dop853".parse::<Method>().unwrap(), Method::Dop853);
    assert!(matches!(
        "rk4".parse::<Method>().unwrap(),
        Method::Rk4 { .. }
    ));
    let m = Method::Rk4 { steps: 250 };
    assert_eq!(m.to_string().parse::<Method>().unwrap(), m);
    assert_eq!(Method::Dop853.to_string(), "dop853");
    assert!("euler".parse::<Method>().is_err());
    assert!("rk4:0".parse::<Method>().is_err());
}
