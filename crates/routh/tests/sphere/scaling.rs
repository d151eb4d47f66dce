//! Issue 33, item 7: answers that do not depend on the units. Random Routh spheres (masses
//! from 1e-30 to 1e30, radii from 1e-10 to 1e10, time scales from 1e-4 to 1e4; moments from
//! slender, I3 = 1e-3 I1, to flat, I3 = 2 I1, the triangle inequality's limit; both signs of
//! a, a = 0 among them; gravity or none) and random motions (vertical spins around Routh's
//! threshold, steady precessions from 1e-4 of the axis to the plane, states near the axis
//! and near the separatrices of the unstable relative equilibria). Each answer of `steady`,
//! `diagram` and `simulate` is compared with the answer to its own copy in other units
//! (dimensionless numbers equal, or the same refusal) and with an independent method: the
//! verdict of `steady` with a DOP853 run of a perturbed state, the diagram's type and tori
//! with `steady` and with the reduced equation along a DOP853 run, `simulate` with Vern9 and
//! the conserved integrals. A wrong answer given with success fails; a refusal does not, if
//! the copy is refused alike.
//!
//! proptest with a fixed seed and a few cases each (the file runs in seconds); set
//! `PROPTEST_CASES` for a longer run (docs/reliability.md).

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use routh::body::Body;
use routh::diagram::{torus_count, vertical_spin_at, RelativeEquilibrium, StabilityType, Value};
use routh::field::vector_field;
use routh::integrals::jellett;
use routh::integrate::{solve, Method, Options};
use routh::quadrature::Reduction;
use routh::simulate::{run, ReducedSystem, Settings};
use routh::state::{Normalise, Point, State};
use routh::steady::{
    routh_threshold, steady_precessions, vertical_spin, Decision, CURVATURE_EPSILONS,
};
use routh::units::{scaled_body, scaled_state, Units};
use std::f64::consts::PI;

/// The seed of every property here: CI runs the same cases each time.
const SEED: u64 = 33;

/// A fixed seed, no persistence of failures, and `cases` cases unless `PROPTEST_CASES` says
/// how many (the longer run of docs/reliability.md).
fn config(cases: u32) -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(cases);
    ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(SEED),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// A Routh sphere in its own units (m = R = 1): `a` in (-0.95, 0.95) or 0, `I1` from 0.01
/// to 2, `I3 / I1` from 1e-3 (slender) to 2 (flat), `G` from 0.1 to 30 or none.
fn unit_body() -> impl Strategy<Value = Body> {
    (
        prop_oneof![4 => -0.95f64..0.95, 1 => Just(0.0)],
        -2.0f64..0.3,
        -3.0f64..2f64.log10(),
        prop_oneof![3 => 0.1f64..30.0, 1 => Just(0.0)],
    )
        .prop_map(|(a, i1, ratio, g)| {
            let i1 = 10f64.powf(i1);
            let i3 = (i1 * 10f64.powf(ratio)).min(2.0 * i1);
            Body::new(1.0, 1.0, a, i1, i1, i3, g).unwrap()
        })
}

/// Factors of mass, length and time, `[k, l, s]`, with `k` from 1e-30 to 1e30, `l` from
/// 1e-10 to 1e10, `s` from 1e-4 to 1e4 (log-uniform).
fn units() -> impl Strategy<Value = [f64; 3]> {
    (-30.0f64..30.0, -10.0f64..10.0, -4.0f64..4.0)
        .prop_map(|(k, l, s)| [10f64.powf(k), 10f64.powf(l), 10f64.powf(s)])
}

/// One motion in two systems of units: the body and a state in each.
#[derive(Debug, Clone)]
struct Copies {
    /// The body in its own units (m = R = 1).
    unit: Body,
    /// The factors of the first copy, `[k, l, s]`.
    first: [f64; 3],
    /// The factors of the second copy.
    second: [f64; 3],
}

impl Copies {
    fn body(&self, which: [f64; 3]) -> Body {
        scaled_body(&self.unit, which).unwrap()
    }
}

fn copies() -> impl Strategy<Value = Copies> {
    (unit_body(), units(), units()).prop_map(|(unit, first, second)| Copies {
        unit,
        first,
        second,
    })
}

/// The spin rate, in the body's own units, of a motion of `body` (m = R = 1): a multiple
/// `f` of Routh's threshold at the pole of the centre of mass, where there is one, of the
/// rate of the fall `sqrt(G)`, or of 1 without gravity. `f` near 1 (within 1e-8 to 1e-2 of
/// it, either side), around it (0.5 to 2) or anywhere from 0.05 to 5.
fn spin_factor() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-8.0f64..-2.0, prop::bool::ANY)
            .prop_map(|(e, up)| 1.0 + if up { 1.0 } else { -1.0 } * 10f64.powf(e)),
        0.5f64..2.0,
        0.05f64..5.0,
    ]
}

/// The rate that `spin_factor` multiplies for `body` (m = R = 1).
fn spin_scale(body: &Body) -> f64 {
    let pole = if body.a() >= 0.0 { 1.0 } else { -1.0 };
    let threshold = routh_threshold(body, pole);
    if threshold > 0.0 {
        threshold
    } else {
        body.gravity().sqrt().max(1.0)
    }
}

/// Whether `copy` (a number of a scaled copy in its units, divided by its unit `unit`) and
/// `original` (divided by its unit `unit0`) are equal within `relative` of the original or
/// `absolute` (in the original's dimensionless units).
fn same(copy: f64, unit: f64, original: f64, unit0: f64, relative: f64, absolute: f64) -> bool {
    let (c, o) = (copy / unit, original / unit0);
    (c - o).abs() <= relative * o.abs() + absolute
}

/// The relative tolerance of numbers computed in the units of the motion from two copies
/// that are equal to a few ulp: the computations are continuous in their inputs, with
/// condition numbers well below 1e5 away from the thresholds (which `q_accuracy` and
/// `omega_t_accuracy` cover).
const SAME: f64 = 1e-9;

/// Whether the verdict of `steady` and the diagram's type of the same motion do not
/// contradict each other: elliptic is stable, focus-focus and hyperbolic are unstable;
/// degenerate and undecided decide nothing, nor does an undecided verdict.
fn agree(kind: StabilityType, decision: Decision) -> bool {
    match (kind, decision) {
        (StabilityType::Degenerate | StabilityType::Undecided, _) | (_, Decision::Undecided) => {
            true
        }
        (StabilityType::Elliptic, d) => d == Decision::Stable,
        (StabilityType::FocusFocus | StabilityType::Hyperbolic, d) => d == Decision::Unstable,
    }
}

/// The largest angle between gamma and the initial gamma `g0` along a DOP853 run of the
/// dimensionless `body` from `x0` over `[0, t_end]`, rotated back by `precession t` about e3
/// (the steady precession's own rotation); rtol = 1e-12, atol = 1e-14 (the state is of order
/// one in these units). `None` if the run fails.
fn largest_departure(body: &Body, x0: [f64; 6], t_end: f64, precession: f64) -> Option<f64> {
    let opts = Options::new(1e-12, 1e-14)
        .unwrap()
        .with_max_steps(200_000)
        .ok()?;
    let field = |_t: f64, x: &[f64; 6]| vector_field(body, x);
    let g0 = [x0[0], x0[1], x0[2]];
    let mut largest = 0.0_f64;
    let mut observe = |t: f64, y: &[f64; 6]| {
        let (s, c) = (-precession * t).sin_cos();
        let g = [c * y[0] - s * y[1], s * y[0] + c * y[1], y[2]];
        let cross = [
            g[1] * g0[2] - g[2] * g0[1],
            g[2] * g0[0] - g[0] * g0[2],
            g[0] * g0[1] - g[1] * g0[0],
        ];
        let dot = g[0] * g0[0] + g[1] * g0[1] + g[2] * g0[2];
        let angle = (cross[0].hypot(cross[1]).hypot(cross[2])).atan2(dot);
        largest = largest.max(angle);
    };
    solve(&field, 0.0, x0, t_end, &opts, None, None, &mut observe).ok()?;
    Some(largest)
}

/// `state` tilted by `angle` about e1 (gamma only: M kept), in the dimensionless units.
fn tilted(body: &Body, state: &State, angle: f64) -> State {
    let (s, c) = angle.sin_cos();
    let g = state.gamma();
    State::from_omega(
        body,
        [g[0], c * g[1] - s * g[2], s * g[1] + c * g[2]],
        state.omega(body),
        Normalise::Rescale,
    )
    .unwrap()
}

proptest! {
    #![proptest_config(config(24))]

    /// Vertical spins: the copies in other units have the same verdict, threshold, Q'' and
    /// largest real part (converted, `SAME` relative plus their round-off: `q_accuracy`, and a
    /// tenth of the eigenvalues' tolerance, below which the real part is the scatter of the
    /// integrals' Jordan blocks), or the same refusal; the diagram's type of the same spin is
    /// the same in both and agrees with the verdict. Independently, DOP853 from the spin
    /// tilted by 1e-7: an unstable verdict (spin at most 0.99 of the threshold, so that the
    /// growth rate is at least about 0.1 of the rate of the motion) sees the tilt grow 100-fold
    /// within `ln(1e4)` growth times; a stable one (at least 1.01 of the threshold, or no
    /// threshold) sees it stay below 1e3 times the initial tilt over 50 time units of the
    /// motion (the nutation of a stable spin has an amplitude of the initial tilt times the
    /// ratio of its frequencies, below 30 at 1.01 of the threshold).
    #[test]
    fn vertical_spins_in_other_units_and_under_dop853(c in copies(), f in spin_factor(), above in prop::bool::ANY) {
        let w = f * spin_scale(&c.unit);
        let pole = if (c.unit.a() >= 0.0) == above { 1.0 } else { -1.0 };
        let (b1, b2) = (c.body(c.first), c.body(c.second));
        let (w1, w2) = (w / c.first[2], w / c.second[2]);
        let context = format!("{c:?} w = {w} pole {pole}");
        let (v1, v2) = match (vertical_spin(&b1, pole, w1), vertical_spin(&b2, pole, w2)) {
            (Ok(v1), Ok(v2)) => (v1, v2),
            (Err(e1), Err(e2)) => {
                let rule = |e: &routh::RouthError| e.to_string().split(':').next_back().unwrap_or_default().to_string();
                prop_assert_eq!(rule(&e1), rule(&e2), "{}", context);
                return Ok(());
            }
            (r1, r2) => {
                prop_assert!(false, "{context}: one refused, one accepted: {r1:?} {r2:?}");
                unreachable!()
            }
        };
        let (t1, t2) = (c.first[2], c.second[2]);
        prop_assert_eq!(v1.verdict.decision, v2.verdict.decision, "{}", context);
        prop_assert_eq!(v1.no_threshold, v2.no_threshold);
        prop_assert!(same(v1.threshold_spin, 1.0 / t1, v2.threshold_spin, 1.0 / t2, 1e-12, 0.0));
        let q = |v: &routh::steady::VerticalSpin, t: f64| v.stability.q_second_derivative * t * t;
        let accuracy = v2.verdict.q_accuracy * t2 * t2;
        prop_assert!(same(q(&v1, t1), 1.0, q(&v2, t2), 1.0, SAME, accuracy), "{context}: {v1:?} {v2:?}");
        let tolerance = v2.verdict.eigenvalue_tolerance * t2;
        prop_assert!(same(v1.stability.max_real_eigenvalue, 1.0 / t1, v2.stability.max_real_eigenvalue, 1.0 / t2, 1e-8, 0.1 * tolerance), "{context}");
        // The diagram's type of the same spin, in both units, and against the verdict.
        let kind = |b: &Body, v: &routh::steady::VerticalSpin| {
            vertical_spin_at(b, pole, jellett(b, &v.state.to_array())).map(|r| r.stability)
        };
        let (k1, k2) = (kind(&b1, &v1), kind(&b2, &v2));
        prop_assert_eq!(k1.as_ref().ok(), k2.as_ref().ok(), "{}", context);
        if let Ok(k) = k1 {
            prop_assert!(agree(k, v1.verdict.decision), "{context}: {k:?} {v1:?}");
        }
        // Independently: DOP853 from the tilted spin, in the units of the motion.
        let units = Units::of(&b1, &v1.state.omega(&b1));
        let (body, state) = (units.body(&b1).unwrap(), units.state(&v1.state).unwrap());
        let tilt = 1e-7;
        let start = tilted(&body, &state, tilt).to_array();
        // Routh's criterion: below the centre of mass, or without gravity, stable at every
        // spin; else unstable below the threshold, stable above.
        let relative = v1.routh_threshold.map(|wc| w1.abs() / wc);
        match (v1.verdict.decision, relative) {
            (Decision::Unstable, None) => prop_assert!(false, "{context}: unstable without a threshold: {v1:?}"),
            (Decision::Unstable, Some(r)) => {
                prop_assert!(r < 1.0, "{context}: unstable above the threshold: {v1:?}");
                if r <= 0.99 {
                    let growth = v1.stability.max_real_eigenvalue * units.time();
                    let far = largest_departure(&body, start, 1e4f64.ln() / growth, 0.0);
                    prop_assert!(far.is_none_or(|a| a > 100.0 * tilt), "{context}: {far:?}, growth {growth}");
                }
            }
            (Decision::Stable, r) => {
                prop_assert!(r.is_none_or(|r| r > 1.0), "{context}: stable below the threshold: {v1:?}");
                if r.is_none_or(|r| r >= 1.01) {
                    let far = largest_departure(&body, start, 50.0, 0.0);
                    prop_assert!(far.is_none_or(|a| a < 1e3 * tilt), "{context}: {far:?}");
                }
            }
            _ => {}
        }
    }
}

/// A tilt theta in (0, pi): within 1e-4 to 1e-2 of either pole (near the axis) or anywhere.
fn tilt() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-4.0f64..-2.0).prop_map(|e| 10f64.powf(e)),
        (-4.0f64..-2.0).prop_map(|e| PI - 10f64.powf(e)),
        0.01f64..PI - 0.01,
    ]
}

proptest! {
    #![proptest_config(config(24))]

    /// Steady precessions: the copies in other units have as many, with the same verdicts,
    /// omega_t and precession rates (converted, `SAME` relative plus twice `omega_t_accuracy`,
    /// the round-off of the root; over sin theta for the rates) and Q'' (plus the two copies'
    /// `q_accuracy`), or the same refusal. The diagram's relative equilibrium through the same state has a
    /// type that agrees with the verdict, the same in both copies, and its value of the
    /// integrals is critical for the count of tori (a double root of Q) away from a fold. Independently,
    /// DOP853 from the steady state keeps gamma on the rotation `precession t` about e3 to
    /// 1e-7 over 10 time units of the motion (an equilibrium of the rotating frame: a
    /// departure grows from the run's error of 1e-12 at most by `e^(10 growth T)`, and the
    /// unstable ones are run only while that stays below 1e3).
    #[test]
    fn steady_precessions_in_other_units_and_under_dop853(c in copies(), f in spin_factor(), sign in prop::bool::ANY, theta in tilt()) {
        let w = if sign { f } else { -f } * spin_scale(&c.unit);
        let (b1, b2) = (c.body(c.first), c.body(c.second));
        let (t1, t2) = (c.first[2], c.second[2]);
        let context = format!("{c:?} w = {w} theta = {theta}");
        let (l1, l2) = match (steady_precessions(&b1, theta, w / t1), steady_precessions(&b2, theta, w / t2)) {
            (Ok(l1), Ok(l2)) => (l1, l2),
            (Err(e1), Err(e2)) => {
                let rule = |e: &routh::RouthError| e.to_string().split(':').next_back().unwrap_or_default().to_string();
                prop_assert_eq!(rule(&e1), rule(&e2), "{}", context);
                return Ok(());
            }
            (r1, r2) => {
                prop_assert!(false, "{context}: one refused, one accepted: {r1:?} {r2:?}");
                unreachable!()
            }
        };
        prop_assert_eq!(l1.len(), l2.len(), "{}: {:?} {:?}", context, l1, l2);
        for (p1, p2) in l1.iter().zip(&l2) {
            prop_assert_eq!(p1.verdict.decision, p2.verdict.decision, "{}: {:?} {:?}", context, p1, p2);
            let slack = 2.0 * p2.omega_t_accuracy * t2;
            prop_assert!(same(p1.omega_t, 1.0 / t1, p2.omega_t, 1.0 / t2, SAME, slack), "{context}: {p1:?} {p2:?}");
            let rate_slack = slack / theta.sin();
            prop_assert!(same(p1.precession, 1.0 / t1, p2.precession, 1.0 / t2, SAME, rate_slack), "{context}");
            prop_assert!(same(p1.axis_precession, 1.0 / t1, p2.axis_precession, 1.0 / t2, SAME, rate_slack), "{context}");
            let accuracy = p1.verdict.q_accuracy * t1 * t1 + p2.verdict.q_accuracy * t2 * t2;
            prop_assert!(same(p1.stability.q_second_derivative * t1 * t1, 1.0, p2.stability.q_second_derivative * t2 * t2, 1.0, SAME, accuracy), "{context}: {p1:?} {p2:?}");
            // The diagram's relative equilibrium through the same state, in both units.
            let kinds: Vec<Option<StabilityType>> = [(&b1, p1), (&b2, p2)]
                .iter()
                .map(|(b, p)| RelativeEquilibrium::new(b, theta, p.state, p.precession).ok().map(|r| r.stability))
                .collect();
            prop_assert_eq!(kinds[0], kinds[1], "{}: {:?}", context, p1);
            if let Some(k) = kinds[0] {
                prop_assert!(agree(k, p1.verdict.decision), "{context}: {k:?} {p1:?}");
            }
            // Within 1e-6 (relative to the scale of its terms) of a fold, where Q'' vanishes,
            // the minimum beside the double root is closer than the count's sampling of the
            // tilt resolves (its documented limit, `CRITICAL_POINT_SAMPLES`).
            let curvature_scale = Reduction::of_state(&b1, &p1.state).unwrap().q_curvature_scale(theta.cos());
            let fold = p1.stability.q_second_derivative.abs() < 1e-6 * curvature_scale;
            if let (false, Ok(count)) = (fold, torus_count(&b1, Value::of_state(&b1, &p1.state))) {
                prop_assert!(count.critical, "{context}: the value of {p1:?} is regular: {count:?}");
            }
            // Independently: DOP853 in the units of the motion.
            let units = Units::of(&b1, &p1.state.omega(&b1));
            let body = units.body(&b1).unwrap();
            let growth = p1.stability.max_real_eigenvalue.max(0.0) * units.time();
            let horizon = if growth > 0.0 { (1e3f64.ln() / growth).min(10.0) } else { 10.0 };
            let far = largest_departure(&body, units.state(&p1.state).unwrap().to_array(), horizon, p1.precession * units.time());
            prop_assert!(far.is_none_or(|a| a < 1e-7), "{context}: {far:?} {p1:?}");
        }
    }
}

/// A state of the body (m = R = 1), chosen where answers are hard to get right.
#[derive(Debug, Clone, Copy)]
enum Start {
    /// Tilt theta, `omega = (wt, wn, w3)` (along the horizontal part of gamma, across it,
    /// along e3) in units of the body's spin scale.
    Anywhere(f64, [f64; 3]),
    /// The vertical spin at the pole of the centre of mass at `f` times the spin scale,
    /// tilted by `angle`: near the axis, near Routh's threshold (f near 1) and, below it, on
    /// the separatrix of the focus-focus spin.
    NearSpin(f64, f64),
}

impl Start {
    fn state(self, body: &Body) -> State {
        let scale = spin_scale(body);
        match self {
            Start::Anywhere(theta, [wt, wn, w3]) => {
                let (s, u) = theta.sin_cos();
                let omega = [scale * wt, scale * wn, scale * w3];
                State::from_omega(body, [s, 0.0, u], omega, Normalise::Reject).unwrap()
            }
            Start::NearSpin(f, angle) => {
                let pole = if body.a() >= 0.0 { 1.0 } else { -1.0 };
                let spin = State::from_omega(
                    body,
                    [0.0, 0.0, pole],
                    [0.0, 0.0, f * scale],
                    Normalise::Reject,
                )
                .unwrap();
                tilted(body, &spin, angle)
            }
        }
    }
}

fn start() -> impl Strategy<Value = Start> {
    prop_oneof![
        (tilt(), prop::array::uniform3(-2.0f64..2.0)).prop_map(|(t, w)| Start::Anywhere(t, w)),
        (spin_factor(), -6.0f64..-2.0).prop_map(|(f, e)| Start::NearSpin(f, 10f64.powf(e))),
    ]
}

/// The state `start` of `c`'s body in the copy with factors `which`, with that body.
fn copy_of(c: &Copies, start: Start, which: [f64; 3]) -> (Body, State) {
    (
        c.body(which),
        scaled_state(&start.state(&c.unit), which).unwrap(),
    )
}

proptest! {
    #![proptest_config(config(24))]

    /// The diagram's count of tori: the copies in other units get the same answer (critical
    /// or not, and at a regular value the same intervals of gamma3 to 1e-9 plus the round-off
    /// of each turning point, that of Q over its slope: dimensionless roots of Q, continuous
    /// in the copies' few ulp of difference away from a double root;
    /// at a critical value an interval within the round-off of a double root may or may not
    /// be listed, and counts nothing), or the same refusal. Independently, the state's own gamma3 lies in one of
    /// the intervals (Q(gamma3) = (dgamma3/dt)^2 >= 0), and a DOP853 run of 5 time units of
    /// the motion stays in it (to 1e-6: the run's error of about 1e-10 in gamma3, and the
    /// turning points' conditioning of sqrt(eps) near a double root).
    #[test]
    fn tori_in_other_units_and_along_dop853(c in copies(), start in start()) {
        let (b1, x1) = copy_of(&c, start, c.first);
        let (b2, x2) = copy_of(&c, start, c.second);
        let context = format!("{c:?} {start:?}");
        let (n1, n2) = match (torus_count(&b1, Value::of_state(&b1, &x1)), torus_count(&b2, Value::of_state(&b2, &x2))) {
            (Ok(n1), Ok(n2)) => (n1, n2),
            (Err(e1), Err(e2)) => {
                let rule = |e: &routh::RouthError| e.to_string().split(':').next_back().unwrap_or_default().to_string();
                prop_assert_eq!(rule(&e1), rule(&e2), "{}", context);
                return Ok(());
            }
            (r1, r2) => {
                prop_assert!(false, "{context}: one refused, one accepted: {r1:?} {r2:?}");
                unreachable!()
            }
        };
        prop_assert_eq!(n1.critical, n2.critical, "{}: {:?} {:?}", context, n1, n2);
        if n1.critical {
            return Ok(());
        }
        prop_assert_eq!(n1.intervals.len(), n2.intervals.len(), "{}: {:?} {:?}", context, n1, n2);
        let units = Units::of(&b1, &x1.omega(&b1));
        let body = units.body(&b1).unwrap();
        let red = Value::of_state(&body, &units.state(&x1).unwrap()).reduction(&body).unwrap();
        // The round-off of a turning point: that of Q (its terms' and one ulp of u's, as the
        // count's own test of a double root) over the slope there.
        let accuracy = |u: f64| {
            let noise = 1e3 * f64::EPSILON * (red.q_scale(u) + u.abs() * red.q_slope_scale(u));
            noise / red.q_derivatives(u).1.abs()
        };
        for (i1, i2) in n1.intervals.iter().zip(&n2.intervals) {
            for (a, b) in [(i1.0, i2.0), (i1.1, i2.1)] {
                prop_assert!((a - b).abs() <= 1e-9 + accuracy(a), "{context}: {n1:?} {n2:?}: {a} {b} accuracy {}", accuracy(a));
            }
        }
        let u0 = x1.gamma()[2];
        let slack = 1e-6;
        let Some(&(low, high)) = n1.intervals.iter().find(|(a, b)| *a - slack <= u0 && u0 <= *b + slack) else {
            prop_assert!(false, "{context}: gamma3 = {u0} in none of {n1:?}");
            unreachable!()
        };
        let opts = Options::new(1e-12, 1e-14).unwrap();
        let field = |_t: f64, x: &[f64; 6]| vector_field(&body, x);
        let mut outside = None;
        let mut observe = |t: f64, y: &[f64; 6]| {
            if !(low - slack..=high + slack).contains(&y[2]) && outside.is_none() {
                outside = Some((t, y[2]));
            }
        };
        if solve(&field, 0.0, units.state(&x1).unwrap().to_array(), 5.0, &opts, None, None, &mut observe).is_ok() {
            prop_assert!(outside.is_none(), "{context}: left [{low}, {high}] at {outside:?}");
        }
    }
}

/// The relative tolerance of the `simulate` runs.
const RTOL: f64 = 1e-11;

/// `simulate` (DOP853, or `method`) of `body` from `state` over `t_end`, with an absolute
/// tolerance of `1e-3 RTOL` in the units of the motion's angular momentum, at most
/// `1e-3 RTOL` (so that the relative tolerance rules every component of order one in those
/// units, whether atol applies to the angular momentum only, in its unit, or to every
/// component as it is). The final state in the units of the motion, or `None` if refused.
fn simulated(body: &Body, state: &State, t_end: f64, method: Method) -> Option<[f64; 6]> {
    let units = Units::of(body, &state.omega(body));
    let atol = 1e-3 * RTOL * units.momentum().min(1.0);
    let settings = Settings::builder()
        .method(method)
        .t_end(t_end)
        .tolerances(RTOL, atol)
        .build()
        .ok()?;
    let summary = run(
        body,
        &ReducedSystem(body),
        state.to_array(),
        &settings,
        &mut |_, _| Ok(()),
    )
    .ok()?;
    Some(units.point(&summary.final_state).to_array())
}

proptest! {
    #![proptest_config(config(16))]

    /// `simulate` over 3 time units of the motion: the copies in other units end at the same
    /// dimensionless state, and Vern9 (an independent integrator) at the same as DOP853, to
    /// 1e-6 (each run's global error is about RTOL = 1e-11 per step over a few hundred steps,
    /// amplified near a separatrix by at most e^(3 lambda T), lambda T below 4 for these
    /// bodies: 1e5 RTOL leaves a margin over 1e-9 e^(...)), or both refused. The runs near the
    /// separatrices and the threshold start within 1e-6 to 1e-2 of the relative equilibria.
    #[test]
    fn simulate_in_other_units_and_with_vern9(c in copies(), start in start()) {
        let (b1, x1) = copy_of(&c, start, c.first);
        let (b2, x2) = copy_of(&c, start, c.second);
        let context = format!("{c:?} {start:?}");
        let t = Units::of(&b1, &x1.omega(&b1)).time();
        let t_copy = Units::of(&b2, &x2.omega(&b2)).time();
        let y1 = simulated(&b1, &x1, 3.0 * t, Method::Dop853);
        let y2 = simulated(&b2, &x2, 3.0 * t_copy, Method::Dop853);
        let close = |a: &[f64; 6], b: &[f64; 6]| a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-6);
        match (y1, y2) {
            (Some(y1), Some(y2)) => {
                prop_assert!(close(&y1, &y2), "{context}: {y1:?} {y2:?}");
                if let Some(y3) = simulated(&b1, &x1, 3.0 * t, Method::Vern9) {
                    prop_assert!(close(&y1, &y3), "{context}: DOP853 {y1:?} Vern9 {y3:?}");
                }
            }
            (None, None) => {}
            (y1, y2) => prop_assert!(false, "{context}: one refused: {y1:?} {y2:?}"),
        }
    }
}

/// Issue 33 (found by `steady_precessions_in_other_units_and_under_dop853`): within 0.01 of a
/// pole, Q'' of a steady precession changed between copies of one motion in other units (time
/// scaled by 3, 0.1, 20) by up to 4.1e-12, 25 times its stated accuracy `q_accuracy` = 1.6e-13
/// (then the round-off of the terms of Q'' alone). The cause: the state fixes omega only to the
/// conditioning of I_Q, 7.5e-12 for this slender body (I3 = 6.6e-5), and the spin omega3
/// recovered from each copy's M was off by +2.7e-12 to -5.3e-12 relative, which moves Q''
/// by 0.35e-12 per 1e-12 here; the accuracy now holds that propagation
/// (`steady::curvature_accuracy`): 2.7e-12. Tolerance: the sum of the two copies' accuracies
/// (each Q'' is within its own of the Q'' of the exact state), plus 1e-12 relative for the
/// conversion. Measured: 2.6e-12, 1.8e-12, 4.1e-12 (s = 3, 0.1, 20; at s = 20 the roots omega_t
/// differ by 1.1e-12 too, within twice their accuracy, which moves Q'' by 1.3e-12 more), against
/// 5.4e-12; copies scaled by powers of two give the same Q'' to the bit. Negative control: the
/// accuracy of the round-off of the terms alone (`CURVATURE_EPSILONS` eps of their scale) is
/// exceeded by the s = 20 copy.
#[test]
fn q_second_derivative_near_a_pole_within_its_accuracy() {
    let unit = Body::new(
        1.0,
        1.0,
        -0.4837943090849918,
        0.030719115264210707,
        0.030719115264210707,
        6.591246236632951e-5,
        0.1,
    )
    .unwrap();
    let (w, theta) = (-0.4429463049674229, PI - 0.01);
    let answer = |s: f64| {
        let body = scaled_body(&unit, [1.0, 1.0, s]).unwrap();
        let p = steady_precessions(&body, theta, w / s).unwrap()[1];
        (
            p.stability.q_second_derivative * s * s,
            p.verdict.q_accuracy * s * s,
        )
    };
    let (q2, accuracy) = answer(1.0);
    let mut worst = 0.0_f64;
    for s in [3.0, 0.1, 20.004370193423576] {
        let (copy, copy_accuracy) = answer(s);
        let tolerance = accuracy + copy_accuracy + 1e-12 * q2.abs();
        assert!(
            (copy - q2).abs() <= tolerance,
            "s = {s}: {copy:e} vs {q2:e} (accuracies {accuracy:e}, {copy_accuracy:e})"
        );
        worst = worst.max((copy - q2).abs());
    }
    for s in [2.0, 0.125, 1024.0] {
        assert_eq!(answer(s).0, q2, "s = {s}");
    }
    // Negative control: the round-off of the terms alone, as before, does not hold the copies.
    let p = steady_precessions(&unit, theta, w).unwrap()[1];
    let scale = Reduction::of_state(&unit, &p.state)
        .unwrap()
        .q_curvature_scale(theta.cos());
    let terms_alone = 2.0 * CURVATURE_EPSILONS * f64::EPSILON * scale + 1e-12 * q2.abs();
    assert!(worst > terms_alone, "{worst:e} <= {terms_alone:e}");
}

/// Negative controls of the comparisons above: a copy's number left unconverted is not the
/// original's; contradicting verdicts and types do not agree; DOP853 from a vertical spin of
/// the default body at half its threshold, tilted by 1e-7, leaves it (the instability the
/// unstable verdicts are checked by), and at twice the threshold stays near it.
#[test]
fn the_comparisons_can_fail() {
    let body = Body::default();
    let w = routh_threshold(&body, 1.0);
    let copy = scaled_body(&body, [1e6, 1e-3, 10.0]).unwrap();
    let (v, c) = (
        vertical_spin(&body, 1.0, 0.5 * w).unwrap(),
        vertical_spin(&copy, 1.0, 0.05 * w).unwrap(),
    );
    let q2 = v.stability.q_second_derivative;
    assert!(same(
        c.stability.q_second_derivative,
        0.01,
        q2,
        1.0,
        SAME,
        v.verdict.q_accuracy
    ));
    assert!(!same(
        c.stability.q_second_derivative,
        1.0,
        q2,
        1.0,
        SAME,
        v.verdict.q_accuracy
    ));
    assert!(!agree(StabilityType::Elliptic, Decision::Unstable));
    assert!(!agree(StabilityType::FocusFocus, Decision::Stable));
    for (f, grows) in [(0.5, true), (2.0, false)] {
        let spin = vertical_spin(&body, 1.0, f * w).unwrap();
        let units = Units::of(&body, &spin.state.omega(&body));
        let scaled = units.body(&body).unwrap();
        let start = tilted(&scaled, &units.state(&spin.state).unwrap(), 1e-7).to_array();
        let far = largest_departure(&scaled, start, 50.0, 0.0).unwrap();
        assert_eq!(far > 1e3 * 1e-7, grows, "f = {f}: {far}");
    }
}

/// Issue 33, last item: the default body in units of mass 2^997 and length 2^-332 (and in the
/// decimal units 1e300, 1e-100), accepted since the inertia about the contact point is
/// inverted in the body's own unit: Routh's threshold, in which `G a A` is of the size of a
/// length to the fourth (1e-400 there), is computed with the lengths in the unit R rounded to a
/// power of two, and is the default's: to the bit for powers of two, within 4 eps for the
/// decimal factors (each parameter rounded once, the formula a few correctly rounded
/// operations). Negative control: the lift of the formula in the problem's lengths (the one
/// before) underflows to 0, the threshold 0 that `routh steady` printed.
#[test]
fn routh_threshold_of_a_body_in_units_of_length_1e_minus_100() {
    let body = Body::default();
    let w = routh_threshold(&body, 1.0);
    for (factors, tolerance) in [
        ([2f64.powi(997), 2f64.powi(-332), 1.0], 0.0),
        ([1e300, 1e-100, 1.0], 4.0 * f64::EPSILON),
    ] {
        let copy = scaled_body(&body, factors).unwrap();
        let wc = routh_threshold(&copy, 1.0);
        assert!((wc - w).abs() <= tolerance * w, "{factors:?}: {wc} {w}");
        let mu = Units::with_rate(&copy, 0.0).mass();
        let n = copy.m() / mu;
        let l = copy.radius() + copy.a();
        let lift = 4.0 * copy.gravity() * copy.a() * (copy.i1() / mu + n * l * l) * n;
        assert_eq!(lift, 0.0, "{factors:?}");
    }
}

/// The default case (`cases/default.toml`) and its copy in other units with the factors
/// `[k, l, s]` (mass, length, time), each with its time factor.
fn default_case_and_copy(factors: [f64; 3]) -> [(Body, [f64; 6], f64); 2] {
    let body = Body::new(1.0, 1.0, 0.3, 0.4, 0.4, 0.5, 9.81).unwrap();
    let gamma = [0.3f64.sin(), 0.0, 0.3f64.cos()];
    let state = State::from_omega(&body, gamma, [0.5, 0.2, 8.0], Normalise::Reject).unwrap();
    let copy = scaled_body(&body, factors).unwrap();
    let copy_state = scaled_state(&state, factors).unwrap();
    [
        (body, state.to_array(), 1.0),
        (copy, copy_state.to_array(), factors[2]),
    ]
}

/// The five exponents over t = 100 time units of the motion (the default schedule of `routh
/// lyapunov`: transient 10, 100 renormalisations) of the default case and of its copy with
/// `factors` (over `100 s`), the copy's multiplied by its time factor `s`.
fn spectra_of_copies(factors: [f64; 3]) -> [Vec<f64>; 2] {
    use routh::lyapunov::{lyapunov_spectrum, LyapunovSettings};
    default_case_and_copy(factors).map(|(body, x, s)| {
        let run = Settings::builder().t_end(100.0 * s).build().unwrap();
        let settings = LyapunovSettings::new(run, None, None).unwrap();
        let spectrum = lyapunov_spectrum(&body, &x, &settings).unwrap();
        spectrum.exponents.into_iter().map(|l| l * s).collect()
    })
}

/// The largest difference between the sums of the first k exponents of `a` and `b`, over k,
/// each divided by k.
fn partial_sums_apart(a: &[f64], b: &[f64]) -> f64 {
    let (mut sa, mut sb, mut worst) = (0.0, 0.0, 0.0f64);
    for (k, (x, y)) in a.iter().zip(b).enumerate() {
        sa += x;
        sb += y;
        worst = worst.max((sa - sb).abs() / (k + 1) as f64);
    }
    worst
}

/// Exponents are rates: the spectrum of a copy of the default case in other units, times the
/// copy's time factor, is the original's.
///
/// A copy by powers of two (`[2^40, 1, 2^-10]`: the units of the run, powers of two
/// themselves, scale exactly) takes the same steps (4336 each) and gives the same exponents
/// to 1e-4 relative to the largest (measured 6e-6: the copies' states differ by the rounding
/// of omega into M). The copy `[1e12, 1, 1e-3]` measures M in a unit rounded to a power of
/// two from 1e15 times the original's, so the two QR norms differ by a factor `kappa` of at
/// most sqrt(2) on M: a change of norm changes a k-dimensional volume by at most `kappa^k`,
/// and the sum of the first k finite-time exponents by at most `k ln(kappa) / (T - t_0)` at
/// each end of the averaging: `ln 2 / 90 = 7.7e-3` per exponent over the span 90 (measured at
/// most 5.8e-4, for k = 3).
///
/// Negative control (issue 36's units bug, not kept as code): before the QR step was done in
/// the run's units, the Euclidean norm of the components as written, the copy
/// `[1e12, 1, 1e-3]` gave the largest exponent 0.556 / 1e3 against the original's 0.0229:
/// 0.53 apart, 70 times this test's bound.
#[test]
fn lyapunov_spectrum_of_a_copy_in_other_units_is_the_original_over_the_time_factor() {
    let [original, binary] = spectra_of_copies([2f64.powi(40), 1.0, 2f64.powi(-10)]);
    let largest = original.iter().fold(0.0f64, |m, l| m.max(l.abs()));
    let exact = original
        .iter()
        .zip(&binary)
        .map(|(l, c)| (l - c).abs())
        .fold(0.0, f64::max);
    let [_, decimal] = spectra_of_copies([1e12, 1.0, 1e-3]);
    let norm_bound = 2f64.ln() / 90.0;
    eprintln!(
        "Lyapunov: {original:?}; copy by powers of two {:e} of the largest; decimal copy \
         {decimal:?}, partial sums apart {:e} (bound {norm_bound:e})",
        exact / largest,
        partial_sums_apart(&original, &decimal)
    );
    assert!(exact <= 1e-4 * largest, "{original:?} {binary:?}");
    assert!(partial_sums_apart(&original, &decimal) <= norm_bound);
}

/// The Poincaré section `gamma1 = 0` (upward) of the default case's energy level (20 initial
/// states over t = 100, DOP853 in lanes at 1e-12) and of its copy in other units over
/// t = 0.1: the same number of crossings, at times in the ratio 1e-3 and with the same
/// dimensionless state (gamma equal, M over the unit of angular momentum equal) to 1e-8
/// (the copies differ by round-off, grown over 100 time units of a quasi-periodic motion:
/// measured 1.3e-11). Each crossing lies on the plane to 1e-10 relative to the component's
/// unit (gamma: 1; measured 1.2e-13), and on the energy level to 1e-9 relative (DOP853 at
/// 1e-12 over t = 100: measured 8.6e-11).
/// Negative control: the copy's M, not divided by its unit, is off by the factor 1e15.
#[test]
fn section_of_a_copy_in_other_units_is_the_same_section() {
    use routh::integrate::Direction;
    use routh::problem::Plane;
    use routh::section::{ball_section, energy_family};
    let plane = Plane::new(0, 0.0).unwrap();
    let sections: Vec<_> = default_case_and_copy([1e12, 1.0, 1e-3])
        .iter()
        .map(|(body, x, s)| {
            let starts = energy_family(body, x, 20).unwrap();
            let settings = Settings::builder().t_end(100.0 * s).build().unwrap();
            let section =
                ball_section(body, &starts, &settings, &plane, Direction::Rising).unwrap();
            let unit = Units::of(body, &Point::from_array(x).omega(body)).momentum();
            (section, unit, *s)
        })
        .collect();
    let (original, unit, _) = &sections[0];
    let (copy, copy_unit, s) = &sections[1];
    assert!(original.points.len() >= 100, "{}", original.points.len());
    assert_eq!(original.points.len(), copy.points.len());
    let mut apart = 0.0f64;
    let mut unscaled = 0.0f64;
    for (p, q) in original.points.iter().zip(&copy.points) {
        assert_eq!(p.run, q.run);
        apart = apart.max((p.t - q.t / s).abs() / 100.0);
        for i in 0..6 {
            let (u, v) = if i < 3 {
                (1.0, 1.0)
            } else {
                (*unit, *copy_unit)
            };
            apart = apart.max((p.y[i] / u - q.y[i] / v).abs());
            unscaled = unscaled.max((p.y[i] - q.y[i]).abs());
        }
    }
    eprintln!(
        "section: {} crossings, copies apart {apart:e}, on the plane {:e} {:e}, energy drift {:e} {:e}",
        original.points.len(),
        original.max_surface_value / original.surface_unit,
        copy.max_surface_value / copy.surface_unit,
        original.max_energy_drift,
        copy.max_energy_drift
    );
    assert!(apart < 1e-8);
    assert!(unscaled > 1.0);
    for section in [original, copy] {
        assert!(section.max_surface_value <= 1e-10 * section.surface_unit);
        assert!(section.max_energy_drift < 1e-9);
    }
}
