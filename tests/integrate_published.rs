//! Tests of the integrators against published problems and reference figures.

// Published constants are quoted with all their digits.
#![allow(clippy::excessive_precision)]

use routh::integrate::{solve, Options, Stats, Stop};

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
        let (y, stats) = run_to_end(&arenstorf, 0.0, AREN_Y0, AREN_T, &tol_opts(tol));
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
