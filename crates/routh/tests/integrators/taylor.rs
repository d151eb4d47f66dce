//! The Taylor-series integrator (`src/integrate/taylor`): its tape against the `f64` field, its
//! solution against the quadrature solution (`ExactSolution`), its observed order on a problem
//! with a known solution, its dense output, events and projection through the one driver, and
//! negative controls that show each check can fail.

use routh::auto;
use routh::case::Case;
use routh::field::{vector_field_in, OmegaForm};
use routh::integrate::taylor::{
    step_exponent, step_tolerance, taylor_order, taylor_step, Tape, Var,
};
use routh::integrate::{
    drive, stepper, Control, Drive, IntegrateError, Method, OdeSystem, Options, Stepper, Stop,
    Taylor, Vern9,
};
use routh::quadrature::ExactSolution;
use routh::scalar::Scalar;
use routh::simulate::ReducedSystem;

/// Kepler's problem `q'' = -q / |q|^3`, written once over [`Scalar`] (a square root and a
/// quotient: every recurrence of the tape but the fused product is used).
fn kepler<D: Scalar>(y: &[D; 4]) -> [D; 4] {
    let r2 = y[0] * y[0] + y[1] * y[1];
    let r3 = r2 * r2.sqrt();
    [y[2], y[3], -y[0] / r3, -y[1] / r3]
}

struct Kepler;

impl OdeSystem<4> for Kepler {
    type Kernels = routh::integrate::taylor::Interpreted;

    fn rhs(&self, _t: f64, y: &[f64; 4]) -> [f64; 4] {
        kepler(y)
    }

    fn record(&self, _t: Var, y: &[Var; 4]) -> Option<[Var; 4]> {
        Some(kepler(y))
    }
}

/// Pericentre of an orbit of eccentricity `e` and semi-major axis 1 (period 2 pi).
fn kepler_start(e: f64) -> [f64; 4] {
    [1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()]
}

fn max_abs_diff<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn tolerances(tol: f64) -> Options {
    Options {
        rtol: tol,
        atol: tol,
        ..Options::default()
    }
}

fn run_to_end<const N: usize>(s: &mut dyn Stepper<N>) -> Result<[f64; N], IntegrateError> {
    while !s.step()? {}
    Ok(*s.y())
}

/// A small deterministic generator (xorshift64*), uniform in [lo, hi).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self, lo: f64, hi: f64) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let u = (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * u
    }
}

#[test]
fn tape_reproduces_the_f64_field_bit_for_bit() {
    // Order 0 of the recurrences is the f64 operation itself, recorded in the same order as
    // the generic code runs it: equality, not a tolerance. 2,000 random states per ball, on
    // balls with and without gravity, centre of mass above, below and off the axis, with huge
    // and tiny momenta and states near the poles gamma = +-e3.
    let mut rng = Uniform(0x9e37_79b9_7f4a_7c15);
    let case = Case::default_case().unwrap();
    let mut balls = vec![case.ball];
    let mut free = case.ball;
    free.gravity = 0.0;
    balls.push(free);
    let mut off_axis = case.ball;
    off_axis.com = [0.05, -0.02, -0.1];
    balls.push(off_axis);
    for ball in &balls {
        let sys = ReducedSystem(ball);
        let mut tape = Tape::record(&sys, 0).expect("the reduced system records");
        for n in 0..2000 {
            let scale = 10f64.powf(rng.next(-8.0, 8.0));
            let pole = n % 10 == 0;
            let g: [f64; 3] = if pole {
                [rng.next(-1e-9, 1e-9), rng.next(-1e-9, 1e-9), 1.0]
            } else {
                std::array::from_fn(|_| rng.next(-1.0, 1.0))
            };
            let x = [
                g[0],
                g[1],
                g[2],
                scale * rng.next(-1.0, 1.0),
                scale * rng.next(-1.0, 1.0),
                scale * rng.next(-1.0, 1.0),
            ];
            let from_tape = tape.evaluate(0.0, &x);
            // The tape records omega in the form for series (`OmegaForm::Determinant`): the
            // f64 field in that form, bit for bit.
            let direct = vector_field_in::<f64>(OmegaForm::Determinant, ball, &x);
            assert_eq!(from_tape, direct, "at {x:?}");
        }
    }
    // Negative control: a tape of another ball (gravity off) differs at a generic point.
    let x = case.initial.to_array();
    let mut other = Tape::record(&ReducedSystem(&free), 0).unwrap();
    assert_ne!(
        other.evaluate(0.0, &x),
        vector_field_in::<f64>(OmegaForm::Determinant, &case.ball, &x)
    );
}

#[test]
fn recording_folds_constants_and_shares_subexpressions() {
    // Without gravity the torque gamma x grad U is zero: folded away at record time, so the
    // tape is shorter than with gravity; products of constants never reach the tape.
    let case = Case::default_case().unwrap();
    let mut free = case.ball;
    free.gravity = 0.0;
    let with = Tape::record(&ReducedSystem(&case.ball), 0).unwrap();
    let without = Tape::record(&ReducedSystem(&free), 0).unwrap();
    println!(
        "tape: {} ops with gravity, {} without",
        with.len(),
        without.len()
    );
    assert!(without.len() < with.len());
    // Common subexpressions: y0 * y0 recorded twice is one operation.
    struct Square;
    impl OdeSystem<1> for Square {
        type Kernels = routh::integrate::taylor::Interpreted;

        fn rhs(&self, _t: f64, y: &[f64; 1]) -> [f64; 1] {
            [y[0] * y[0] + y[0] * y[0]]
        }
        fn record(&self, _t: Var, y: &[Var; 1]) -> Option<[Var; 1]> {
            Some([y[0] * y[0] + y[0] * y[0]])
        }
    }
    assert_eq!(Tape::record(&Square, 0).unwrap().len(), 2);
}

#[test]
fn agrees_with_the_quadrature_solution_at_t_100() {
    // Default case to t = 100 against ExactSolution (Gauss quadrature of the reduced
    // equations). The bound is the sum of the two methods' own error estimates, relative to
    // the size of the state (|M| ~ 4.5):
    // * the quadrature's, `accuracy.error_at(100)` (5e-12; conservative by 3..30x on the test
    //   cases of docs/quadrature.md, so the true difference is mostly the integrator's);
    // * the integrator's: every step leaves a truncation error below tol relative to the
    //   state (its last term is about e^(-u) tol, taylor_step) and a rounding error of about 2 ulp
    //   (the field's rounding, and the update, summed with compensation), added up over the
    //   steps without cancellation: steps * (tol + 2 eps).
    // At tol 1e-16 (Jorba-Zou order 20) the measured difference (9.4e-13) is within the
    // issue's 1e-12 and the bound; at tol 1e-12 it misses the bound (about 3e-11), so the
    // bound is not loose. At tol 1e-10 (the rule u = 1.5 of step_exponent) the same kind of
    // bound holds.
    let case = Case::default_case().unwrap();
    let body = case.body("").unwrap();
    let solution = ExactSolution::new(&body, &case.initial).unwrap();
    let exact = solution.state_at(100.0).to_array();
    let quadrature = solution.accuracy.error_at(100.0);
    let sys = ReducedSystem(&case.ball);
    let x0 = case.initial.to_array();
    let scale = exact.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let run = |tol: f64| {
        let mut s = Taylor::new(&sys, 0.0, x0, 100.0, &tolerances(tol)).unwrap();
        let err = max_abs_diff(&run_to_end(&mut s).unwrap(), &exact) / scale;
        let bound = quadrature + s.stats().steps as f64 * (tol + 2.0 * f64::EPSILON);
        (err, bound)
    };
    let (tight, tight_bound) = run(1e-16);
    let (loose, _) = run(1e-12);
    let (mid, mid_bound) = run(1e-10);
    println!(
        "relative error at t = 100: {tight:e} (tol 1e-16; bound {tight_bound:e}, of which \
         quadrature {quadrature:e}), {loose:e} (tol 1e-12), {mid:e} (tol 1e-10; bound \
         {mid_bound:e})"
    );
    assert!(tight <= tight_bound, "{tight:e} > {tight_bound:e}");
    assert!(mid <= mid_bound, "{mid:e} > {mid_bound:e}");
    assert!(tight <= 1e-12, "{tight:e}");
    // Negative control: the looser tolerance visibly fails the tight run's bound.
    assert!(loose > tight_bound, "{loose:e}");
}

#[test]
fn the_step_is_the_radius_of_convergence_over_e_to_the_u() {
    // y' = y^2, y(0) = y0 >= 1: y = y0 / (1 - y0 t), a pole at t = 1 / y0, Taylor coefficients
    // y0^(k+1) t^k. Relative control (rtol y0 >= atol: the scale is y0): the radius estimated
    // from the last two coefficients is (y0 / y0^(k+1))^(1/k) = 1 / y0, the distance to the
    // pole, exactly; the first step is that times e^(-u - 0.7 / (p - 1)) to a few ulp (the
    // powers and roots round), with u = 1.5 at tol >= 1e-12 and Jorba-Zou's 2 below.
    struct Square;
    impl OdeSystem<1> for Square {
        type Kernels = routh::integrate::taylor::Interpreted;

        fn rhs(&self, _t: f64, y: &[f64; 1]) -> [f64; 1] {
            [y[0] * y[0]]
        }
        fn record(&self, _t: Var, y: &[Var; 1]) -> Option<[Var; 1]> {
            Some([y[0] * y[0]])
        }
    }
    for (y0, tol, u) in [(1.0, 1e-12, 1.5), (4.0, 1e-8, 1.5), (2.5, 1e-15, 2.0)] {
        assert_eq!(step_exponent(tol), u);
        let p = taylor_order(tol);
        let expected = (-u - 0.7 / (p - 1) as f64).exp() / y0;
        let mut s = Taylor::new(&Square, 0.0, [y0], 10.0, &tolerances(tol)).unwrap();
        s.step().unwrap();
        println!(
            "y0 {y0}, tol {tol:e}: order {p}, step {} vs {expected}",
            s.h()
        );
        assert!((s.h() - expected).abs() <= 1e-14 * expected, "{}", s.h());
        assert_eq!(s.stats().rhs_evals, p);
        // The same from the pure functions the batched lanes use.
        let (eps, c) = step_tolerance(tol, tol, y0);
        assert_eq!((eps, c), (tol, y0));
        let h = taylor_step(eps, p, c, y0.powi(p as i32), y0.powi(p as i32 + 1));
        assert!((h - expected).abs() <= 1e-14 * expected, "{h}");
        // The last term (h / rho)^p is below the tolerance, by about e^(-u).
        let last = (h * y0).powi(p as i32);
        assert!(last < tol && last > 1e-3 * tol, "{last:e}");
        // Negative control: the radius is not the one of another pole.
        assert!((s.h() - expected / 2.0).abs() > 0.1 * expected);
    }
    // Absolute control below the size where rtol |y| <= atol; the orders as documented.
    assert_eq!(step_tolerance(1e-12, 1e-6, 1.0), (1e-6, 1.0));
    assert_eq!(taylor_order(1e-8), 14);
    assert_eq!(taylor_order(1e-12), 20);
    assert_eq!(taylor_order(1e-13), 16);
    assert_eq!(taylor_order(f64::EPSILON), 20);
}

#[test]
fn fixed_order_and_step_show_the_order_on_kepler() {
    // Eccentricity 0.5 over one period with 64, 128 and 256 equal steps at fixed order p: the
    // solution returns to its start, and each halving of h divides the global error by about
    // 2^p. Observed within 0.6 of p for p = 4, 6, 8 (errors between 1e-3 and 1e-12, far above
    // round-off); order p - 1 is excluded by the same bound.
    let y0 = kepler_start(0.5);
    let period = 2.0 * std::f64::consts::PI;
    for p in [4, 6, 8] {
        let errors: Vec<f64> = [64, 128, 256]
            .iter()
            .map(|&n| {
                let mut s = Taylor::fixed(&Kepler, 0.0, y0, period, p, n).unwrap();
                max_abs_diff(&run_to_end(&mut s).unwrap(), &y0)
            })
            .collect();
        let orders: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).log2()).collect();
        println!("order {p}: errors {errors:?}, observed {orders:?}");
        for q in orders {
            assert!((q - p as f64).abs() < 0.6, "order {p}: observed {q}");
        }
    }
}

#[test]
fn adaptive_steps_meet_the_tolerance_and_truncated_order_fails() {
    // Kepler e = 0.6 over three periods: the order and step (u = 1.5 down to tol 1e-12,
    // Jorba-Zou's u = 2 below: both rules are exercised) keep the global error
    // below 100 x tol for tol 1e-8 .. 1e-14 (it grows about linearly along the orbit). The
    // negative control: the same number of steps at a truncated order 4 (the steps the
    // adaptive run took at tol 1e-12, taken equal) misses 100 x tol by orders of magnitude.
    let y0 = kepler_start(0.6);
    let t_end = 6.0 * std::f64::consts::PI;
    let mut steps_at_1e12 = 0;
    for tol in [1e-8, 1e-10, 1e-12, 1e-14] {
        let mut s = Taylor::new(&Kepler, 0.0, y0, t_end, &tolerances(tol)).unwrap();
        let err = max_abs_diff(&run_to_end(&mut s).unwrap(), &y0);
        println!("tol {tol:e}: error {err:e}, {:?}", s.stats());
        assert!(err < 100.0 * tol, "tol {tol}: error {err}");
        if tol == 1e-12 {
            steps_at_1e12 = s.stats().steps;
            assert_eq!(s.stats().rhs_evals, steps_at_1e12 * taylor_order(1e-12));
        }
    }
    let mut truncated = Taylor::fixed(&Kepler, 0.0, y0, t_end, 4, steps_at_1e12).unwrap();
    let err = max_abs_diff(&run_to_end(&mut truncated).unwrap(), &y0);
    println!("order 4 with {steps_at_1e12} steps: error {err:e}");
    assert!(err > 1e4 * 1e-12, "{err:e}");
}

#[test]
fn dense_output_is_the_series_and_events_are_located_on_it() {
    // Kepler e = 0.6: inside every 7th step, the dense output against an independent method,
    // Verner 9(8) at tol 1e-14 run to the same time (agreement to 1e-10, above the global
    // error of either run over one period, 1e-12). Then an event: y = 0 at the apocentre t = pi (half a period),
    // located by the driver on the series to 1e-10.
    let y0 = kepler_start(0.6);
    let opts = tolerances(1e-13);
    let t_end = 2.0 * std::f64::consts::PI;
    let mut s = Taylor::new(&Kepler, 0.0, y0, t_end, &opts).unwrap();
    let mut worst: f64 = 0.0;
    let mut n = 0;
    while !s.step().unwrap() {
        n += 1;
        if n % 7 != 0 {
            continue;
        }
        let t = s.t_prev() + 0.37 * s.h();
        let mut fresh = Vern9::new(&Kepler, 0.0, y0, t, &tolerances(1e-14)).unwrap();
        worst = worst.max(max_abs_diff(&s.dense(t), &run_to_end(&mut fresh).unwrap()));
    }
    println!("dense output: worst error {worst:e} over {n} steps");
    assert!(worst < 1e-10, "{worst:e}");
    // Negative control: the dense output is not the step-end state.
    let mid = s.t_prev() + 0.5 * s.h();
    assert!(max_abs_diff(&s.dense(mid), s.y()) > 1e-6);

    let event = |_t: f64, y: &[f64; 4]| y[1];
    let mut s = Taylor::new(&Kepler, 0.0, y0, t_end, &opts).unwrap();
    let outcome = drive(
        &mut s,
        &Drive {
            event: Some(&event),
            ..Drive::default()
        },
        &mut |_, _| Ok::<_, IntegrateError>(()),
        &mut |_, _, _| Ok(Control::Continue),
    )
    .unwrap();
    let Stop::Event { t, y } = outcome.stop else {
        panic!("no event: {:?}", outcome.stop)
    };
    println!("event at t = {t}, y = {y:?}");
    assert!((t - std::f64::consts::PI).abs() < 1e-10, "{t}");
    assert!((y[0] + 1.6).abs() < 1e-10, "apocentre {y:?}");
}

#[test]
fn method_names_and_the_stepper_factory() {
    for (name, method) in [
        ("taylor", Method::Taylor),
        ("VERN9", Method::Vern9),
        ("auto", Method::Auto),
    ] {
        let parsed: Method = name.parse().unwrap();
        assert_eq!(parsed, method);
        assert_eq!(parsed.to_string().parse::<Method>().unwrap(), method);
    }
    assert!("taylor:3".parse::<Method>().is_err());
    // auto resolves to a concrete method, for every tolerance.
    for tol in [1e-3, 1e-6, 1e-9, 1e-12, 1e-15] {
        assert_ne!(auto::resolve(Method::Auto, tol, false), Method::Auto);
    }
    // The measured choice (AUTO_TABLE): Vern9 down to tol 5e-12, Taylor below.
    assert_eq!(auto::resolve(Method::Auto, 1e-11, false), Method::Vern9);
    assert_eq!(auto::resolve(Method::Auto, 1e-12, false), Method::Taylor);
    // With projection (AUTO_TABLE_PROJECTED): Vern9 down to tol 5e-11, Taylor below.
    assert_eq!(auto::resolve(Method::Auto, 1e-10, true), Method::Vern9);
    assert_eq!(auto::resolve(Method::Auto, 1e-11, true), Method::Taylor);
    assert_eq!(auto::resolve(Method::Auto, 1e-11, false), Method::Vern9);
    assert_eq!(auto::resolve(Method::Vern9, 1e-15, true), Method::Vern9);
    assert_eq!(auto::resolve(Method::Taylor, 1e-3, false), Method::Taylor);
    // The integrator crate has no table of its own: auto unresolved is refused, not run.
    let oscillator = |_t: f64, y: &[f64; 2]| [y[1], -y[0]];
    let err = stepper(
        Method::Auto,
        &oscillator,
        0.0,
        [1.0, 0.0],
        1.0,
        &Options::default(),
    )
    .err()
    .expect("auto names no integrator");
    assert_eq!(err, IntegrateError::UnresolvedAuto);
    // Negative control: a concrete method through the same call runs.
    assert!(stepper(
        Method::Vern9,
        &oscillator,
        0.0,
        [1.0, 0.0],
        1.0,
        &Options::default()
    )
    .is_ok());
    // A system that cannot be recorded: a clear refusal, not a wrong result.
    let closure = |_t: f64, y: &[f64; 2]| [y[1], -y[0]];
    let err = stepper(
        Method::Taylor,
        &closure,
        0.0,
        [1.0, 0.0],
        1.0,
        &Options::default(),
    )
    .err()
    .expect("a closure cannot be recorded");
    assert!(err.to_string().contains("taylor"), "{err}");
    // The same system through every method of the factory, to the same answer.
    let case = Case::default_case().unwrap();
    let sys = ReducedSystem(&case.ball);
    let x0 = case.initial.to_array();
    let ends: Vec<[f64; 6]> = [Method::Dop853, Method::Vern9, Method::Taylor, Method::Auto]
        .iter()
        .map(|&m| {
            let m = auto::resolve(m, 1e-12, false);
            let mut s = stepper(m, &sys, 0.0, x0, 10.0, &tolerances(1e-12)).unwrap();
            run_to_end(s.as_mut()).unwrap()
        })
        .collect();
    for e in &ends[1..] {
        assert!(max_abs_diff(e, &ends[0]) < 1e-9, "{e:?} vs {:?}", ends[0]);
    }
}
