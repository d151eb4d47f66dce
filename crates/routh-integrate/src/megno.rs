//! Fast indicators of chaos along one orbit: MEGNO and FLI.
//!
//! One tangent vector `v` moves with the state by the variational equations
//! ([`Variational`], its `J v` by automatic differentiation of the one field). With
//! `g(t) = (v . v') / (v . v) = d/dt ln |v|`, the Mean Exponential Growth factor of Nearby
//! Orbits (Cincotta and Simó, Astron. Astrophys. Suppl. 147 (2000), eqs. (9) and (11)) is
//!
//! `Y(t) = (2 / t) int_0^t s g(s) ds`, and its mean `<Y>(t) = (1 / t) int_0^t Y(s) ds`.
//!
//! Where `|v|` grows linearly (a quasi-periodic orbit on a torus: the shear between
//! neighbouring tori) `<Y> -> 2`; where it stays bounded (a stable periodic orbit, an
//! isochronous centre) `<Y> -> 0`; where it grows as `e^{lambda t}` (chaos) `<Y>` grows as
//! `lambda t / 2`. The weight `s` of the integral damps the start, so `<Y>` separates the
//! regimes in times where the largest Lyapunov exponent has not converged. The Fast Lyapunov
//! Indicator (Froeschlé, Lega and Gonczi, Celest. Mech. Dyn. Astron. 67 (1997)) is
//! `FLI(t) = sup_{s <= t} ln |v(s)|` from `|v(0)| = 1`: about `ln t` on a torus, `lambda t`
//! in chaos.
//!
//! **The integrals by quadrature.** Exchanging the order of the two integrals,
//! `int_0^t Y(s) ds = 2 int_0^t s g(s) ln(t / s) ds`, so with `t_e` the final time,
//!
//! `I(t) = int_0^t s g ds`, `L(t) = int_0^t s ln(s / t_e) g ds`:
//! `Y(t) = 2 I(t) / t`, `<Y>(t) = 2 (I(t) ln(t / t_e) - L(t)) / t`,
//!
//! two plain integrals, accumulated by 3-point Gauss–Legendre on each step's dense output
//! (as the divergence of [`crate::lyapunov`]; `g` at a node is one evaluation of the tangent
//! field there). They are not extra components of the ODE: those would enter the step
//! control's error norm (with units of their own, and growing as `t^2`), so that the steps of
//! the state and its vector would no longer be those of the variational system alone; here
//! they are, and the quadrature's error is of the interpolant's order. `ln(s / t_e)` is
//! dimensionless, so the indicators of a copy of the system in other units of time are the
//! same numbers.
//!
//! **Renormalisation.** `g` is invariant under `v -> c v`, so the vector is divided by its
//! length whenever that leaves `[2^-16, 2^16]` (at a step end, after the projection given;
//! the logarithms of the factors are summed for the FLI): in a chaotic run it would overflow
//! otherwise. The lengths are measured in the units of the run ([`Field::units`],
//! [`Scales`]), as the Lyapunov exponents are.

use crate::batch::Field;
use crate::lyapunov::{gauss_on_step, generic_directions};
use crate::variational::Variational;
use crate::{
    drive, positive, stepper, Control, Drive, IntegrateError, Method, Options, Projection, Scales,
    Stats,
};
use std::cell::Cell;
use std::convert::Infallible;

/// The most entries of [`Megno::history`]: one at the first step end at or after each
/// `k t_end / HISTORY`, `k = 1 .. HISTORY` (one for several times a step passes together).
pub const HISTORY: usize = 100;

/// The tangent vector is renormalised when its length in the units of the run leaves
/// `[1 / RENORMALISE, RENORMALISE]`.
const RENORMALISE: f64 = 65536.0;

/// The indicators at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Indicators {
    /// The time (a step end).
    pub t: f64,
    /// MEGNO `Y(t)`.
    pub megno: f64,
    /// Its mean `<Y>(t)`.
    pub mean_megno: f64,
    /// `FLI(t) = sup_{s <= t} ln |v(s)|`.
    pub fli: f64,
}

/// The result of [`megno`].
#[derive(Debug, Clone, PartialEq)]
pub struct Megno<const N: usize> {
    /// The indicators at `t_end`.
    pub last: Indicators,
    /// The indicators at up to [`HISTORY`] times up to `t_end`: their convergence.
    pub history: Vec<Indicators>,
    /// The state at `t_end`.
    pub end: [f64; N],
    /// The work of the run.
    pub stats: Stats,
}

/// `|v|` in the units `scales`.
fn length<const N: usize>(scales: &Scales<N>, v: &[f64]) -> f64 {
    v.iter()
        .enumerate()
        .map(|(i, x)| (x * scales.of(i)).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// `g = (v . J v) / (v . v)` at the point `z` of `system`, in the units `scales`.
fn growth_rate<F: Field<N>, const N: usize, const M: usize>(
    system: &Variational<'_, F, N, 1, M>,
    scales: &Scales<N>,
    z: &[f64; M],
) -> f64 {
    let jv = system.tangent_field(z);
    let (mut dot, mut square) = (0.0, 0.0);
    for i in 0..N {
        let s2 = scales.of(i).powi(2);
        dot += z[N + i] * jv[N + i] * s2;
        square += z[N + i] * z[N + i] * s2;
    }
    dot / square
}

/// MEGNO, its mean and the FLI of the orbit of `field` from `y0` over `[0, t_end]` (see the
/// module's documentation), the tangent vector starting along a generic direction of unit
/// length in the units of the run.
///
/// One run of [`crate::drive`] with the stepper of `method` (DOP853, Vern9, or RK4 with its
/// `steps` over the whole run; [`Method::Taylor`] and [`Method::Auto`] are refused) and the
/// tolerances and step limit of `opts`, on the state and the vector together; `project` (on
/// the whole variational state: the state onto a level set, the vector onto its tangent
/// space) at `t = 0` and after each step. `M` must be `2 N` ([`Variational::new`]).
///
/// Errors: `t_end` not finite and > 0 ([`IntegrateError::InvalidOption`]); the stepper's;
/// [`IntegrateError::DependentTangents`] at 0 when the projection leaves no tangent vector.
pub fn megno<F: Field<N>, const N: usize, const M: usize>(
    field: &F,
    y0: &[f64; N],
    t_end: f64,
    method: Method,
    opts: &Options,
    project: Option<Projection<'_, M>>,
) -> Result<Megno<N>, IntegrateError> {
    let t_end = positive("t_end", t_end)?;
    let system = Variational::<F, N, 1, M>::new(field);
    let scales = Scales::of_units(&field.units(y0));
    let mut z = system.join(y0, &generic_directions::<N, 1>(&scales));
    if let Some(p) = project {
        p(&mut z);
    }
    let start = length(&scales, &z[N..]);
    if !(start.is_finite() && start > 0.0) {
        return Err(IntegrateError::DependentTangents { t: 0.0 });
    }
    z[N..].iter_mut().for_each(|x| *x /= start);
    let log_scale = Cell::new(0.0);
    let renormalised = |z: &mut [f64; M]| {
        if let Some(p) = project {
            p(z);
        }
        let l = length(&scales, &z[N..]);
        if !(1.0 / RENORMALISE..=RENORMALISE).contains(&l) {
            z[N..].iter_mut().for_each(|x| *x /= l);
            log_scale.set(log_scale.get() + l.ln());
        }
    };
    let (mut weighted, mut logarithmic, mut fli) = (0.0, 0.0, 0.0f64);
    let (mut history, mut passed) = (Vec::with_capacity(HISTORY), 0);
    let indicators = |t: f64, weighted: f64, logarithmic: f64, fli: f64| Indicators {
        t,
        megno: 2.0 * weighted / t,
        mean_megno: 2.0 * (weighted * (t / t_end).ln() - logarithmic) / t,
        fli,
    };
    let mut run = stepper(method, &system, 0.0, z, t_end, opts)?;
    let run_drive = Drive {
        project: Some(&renormalised),
        ..Drive::default()
    };
    let Ok(outcome) = drive::<_, Infallible, M>(
        run.as_mut(),
        &run_drive,
        &mut |_, _| Ok(()),
        &mut |t, z, run| {
            let g = |s: f64, z: &[f64; M]| growth_rate(&system, &scales, z) * s;
            weighted += gauss_on_step(run, g);
            logarithmic += gauss_on_step(run, |s, z| g(s, z) * (s / t_end).ln());
            fli = fli.max(log_scale.get() + length(&scales, &z[N..]).ln());
            let marks = (t / t_end * HISTORY as f64).floor() as usize;
            if marks > passed {
                history.push(indicators(t, weighted, logarithmic, fli));
                passed = marks;
            }
            Ok(Control::Continue)
        },
    );
    let outcome = outcome.into_result()?;
    Ok(Megno {
        last: indicators(outcome.t, weighted, logarithmic, fli),
        history,
        end: system.state(&outcome.y),
        stats: outcome.stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Scalar;

    /// The Hénon–Heiles system (Hénon and Heiles, Astron. J. 69 (1964)),
    /// `H = (p_x^2 + p_y^2) / 2 + (x^2 + y^2) / 2 + x^2 y - y^3 / 3`, state `(x, y, p_x, p_y)`,
    /// its field divided by `slow` (the same motion in a unit of time `slow` times longer).
    struct HenonHeiles {
        slow: f64,
    }

    impl Field<4> for HenonHeiles {
        fn eval<D: Scalar>(&self, s: &[D; 4]) -> [D; 4] {
            let (x, y, px, py) = (s[0], s[1], s[2], s[3]);
            let slow = 1.0 / self.slow;
            [
                px * slow,
                py * slow,
                -(x + x * y * 2.0) * slow,
                -(y + x * x - y * y) * slow,
            ]
        }
    }

    /// The state `(x, y, p_x, p_y)` of energy `h` at `x = 0`, `y`, `p_y` given, `p_x >= 0`.
    fn on_level(h: f64, y: f64, py: f64) -> [f64; 4] {
        let potential = y * y / 2.0 - y * y * y / 3.0;
        [0.0, y, (2.0 * (h - potential) - py * py).sqrt(), py]
    }

    fn megno_of<F: Field<N>, const N: usize, const M: usize>(
        field: &F,
        y0: &[f64; N],
        t_end: f64,
    ) -> Megno<N> {
        let opts = Options::new(1e-12, 1e-12).unwrap();
        megno::<F, N, M>(field, y0, t_end, Method::Dop853, &opts, None).unwrap()
    }

    /// The start of heyoka's event benchmark (issue 36): `(v_x, v_y, x, y) =
    /// (-0.2525875586263492, -0.2178423952983717, 0, 0.2587703282931232)`, energy 1/12, on a
    /// torus.
    const REGULAR: [f64; 4] = [
        0.0,
        0.2587703282931232,
        -0.2525875586263492,
        -0.2178423952983717,
    ];

    /// A regular orbit has `<Y> -> 2`: where `|v| = a + b t` exactly,
    /// `Y(t) = 2 - 2 (a / b) ln(1 + b t / a) / t`, a deficit decaying as `ln t / t`. Measured
    /// on heyoka's start: `<Y>` = 1.889 at t = 1000 and 1.986 at t = 10,000 (the deficit falls
    /// by 8, as `ln t / t` says), hence the tolerance 0.05 at t = 10,000. The chaotic orbits of
    /// energy 1/6 from `x = 0, y = 0, p_y = 0` and `x = 0, y = -0.2, p_y = 0` (in the chaotic
    /// sea that covers most of that level) have `<Y>` = 52 and 65 at t = 1000, far above the
    /// 5 of the test, and `<Y> ~ lambda t / 2`: `2 <Y> / t` and `FLI / t` are within 10 % of
    /// the largest Lyapunov exponent by the QR method over the same time (measured: lambda
    /// 0.1027 and 0.1379, `2 <Y> / t` 0.1041 and 0.1305, `FLI / t` 0.1009 and 0.1430:
    /// finite-time estimates, which differ by a few per cent). The regular orbit's FLI is of
    /// order `ln t` (5.4 at t = 1000, below 10), the chaotic ones' of order `lambda t`: the
    /// negative control each of the other.
    #[test]
    fn henon_heiles_regular_and_chaotic_orbits() {
        let hh = HenonHeiles { slow: 1.0 };
        let regular = megno_of::<_, 4, 8>(&hh, &REGULAR, 10_000.0);
        assert!(
            (regular.last.mean_megno - 2.0).abs() < 0.05,
            "{:?}",
            regular.last
        );
        let at_1000 = megno_of::<_, 4, 8>(&hh, &REGULAR, 1000.0);
        assert!(at_1000.last.fli < 10.0, "{:?}", at_1000.last);
        let schedule = crate::lyapunov::Renormalisation::new(1000.0, 0.0, 1.0).unwrap();
        let opts = Options::new(1e-12, 1e-12).unwrap();
        for y in [0.0, -0.2] {
            let y0 = on_level(1.0 / 6.0, y, 0.0);
            let chaotic = megno_of::<_, 4, 8>(&hh, &y0, 1000.0);
            let c = chaotic.last;
            assert!(c.mean_megno > 5.0, "{c:?}");
            let lambda = crate::lyapunov::spectrum::<_, 4, 1, 8>(
                &hh,
                &y0,
                &schedule,
                Method::Dop853,
                &opts,
                None,
            )
            .unwrap()
            .exponents[0];
            let (by_megno, by_fli) = (2.0 * c.mean_megno / c.t, c.fli / c.t);
            let message = format!("{c:?}: lambda {lambda}, 2<Y>/t {by_megno}, FLI/t {by_fli}");
            assert!((by_megno / lambda - 1.0).abs() < 0.1, "{message}");
            assert!((by_fli / lambda - 1.0).abs() < 0.1, "{message}");
            assert!(c.fli > 10.0 * at_1000.last.fli, "{message}");
        }
    }

    /// The linear centre `x' = p`, `p' = -omega^2 x` at `omega = 2`: every orbit is periodic
    /// with one period (isochronous), so `|v|` oscillates boundedly, `int s g = t ln |v(t)| -
    /// int ln |v|` is `O(t)`, `Y` oscillates about 0 and `<Y> -> 0` as `1 / t`: below 0.01 at
    /// t = 1000 (measured -0.0012). At `omega = 1` the tangent flow is a rotation, `|v|` is
    /// constant and every indicator is 0 exactly. Negative control: the anharmonic
    /// `p' = -x - x^3`, whose period depends on the amplitude (shear), has `<Y>` near 2
    /// (1.888 at t = 1000: within 0.15, the deficit `ln t / t` of a torus).
    #[test]
    fn linear_centre_tends_to_zero_and_anharmonic_to_two() {
        struct Oscillator {
            omega: f64,
            cubic: f64,
        }
        impl Field<2> for Oscillator {
            fn eval<D: Scalar>(&self, s: &[D; 2]) -> [D; 2] {
                [
                    s[1],
                    -(s[0] * (self.omega * self.omega) + s[0] * s[0] * s[0] * self.cubic),
                ]
            }
        }
        let centre = |omega: f64, cubic: f64| {
            megno_of::<_, 2, 4>(&Oscillator { omega, cubic }, &[1.0, 0.0], 1000.0).last
        };
        let linear = centre(2.0, 0.0);
        assert!(linear.mean_megno.abs() < 0.01, "{linear:?}");
        let rotation = centre(1.0, 0.0);
        assert_eq!(
            (rotation.megno, rotation.mean_megno, rotation.fli),
            (0.0, 0.0, 0.0)
        );
        let anharmonic = centre(1.0, 1.0);
        assert!((anharmonic.mean_megno - 2.0).abs() < 0.15, "{anharmonic:?}");
    }

    /// The indicators are dimensionless: the same motion in a unit of time 8 times longer or
    /// 1024 times shorter (the field divided by the factor, the time multiplied: powers of two,
    /// so that the steps are the same up to rounding) gives `Y`, `<Y>` and the FLI at the same
    /// dimensionless time within 1e-8 relative (measured 2.5e-9: the tolerances' error of
    /// two runs). Negative control: the original at a time 8 times longer differs by 1e-2.
    #[test]
    fn indicators_do_not_depend_on_the_unit_of_time() {
        let original = megno_of::<_, 4, 8>(&HenonHeiles { slow: 1.0 }, &REGULAR, 1000.0).last;
        for slow in [8.0, 1.0 / 1024.0] {
            let copy = megno_of::<_, 4, 8>(&HenonHeiles { slow }, &REGULAR, 1000.0 * slow).last;
            for (a, b) in [
                (copy.megno, original.megno),
                (copy.mean_megno, original.mean_megno),
                (copy.fli, original.fli),
            ] {
                assert!((a / b - 1.0).abs() < 1e-8, "{copy:?} vs {original:?}");
            }
        }
        let longer = megno_of::<_, 4, 8>(&HenonHeiles { slow: 1.0 }, &REGULAR, 8000.0).last;
        assert!(
            (longer.mean_megno - original.mean_megno).abs() > 1e-2,
            "{longer:?}"
        );
    }

    /// The history: up to [`HISTORY`] entries at increasing times, the last at `t_end` equal
    /// to the result; a non-positive `t_end` refused by name.
    #[test]
    fn history_and_refusals() {
        let m = megno_of::<_, 4, 8>(&HenonHeiles { slow: 1.0 }, &REGULAR, 100.0);
        assert!(m.history.len() <= HISTORY && m.history.len() > HISTORY / 2);
        assert!(m.history.windows(2).all(|w| w[0].t < w[1].t));
        assert_eq!(*m.history.last().unwrap(), m.last);
        let opts = Options::default();
        let refused = megno::<_, 4, 8>(
            &HenonHeiles { slow: 1.0 },
            &REGULAR,
            0.0,
            Method::Dop853,
            &opts,
            None,
        );
        assert!(
            matches!(
                refused,
                Err(IntegrateError::InvalidOption { name: "t_end", .. })
            ),
            "{refused:?}"
        );
    }
}
