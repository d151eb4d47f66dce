//! Lyapunov exponents of a rolling ball: the QR method of the integrator layer
//! ([`crate::integrate::lyapunov::spectrum`]) on the reduced field (mg-eq)
//! ([`ReducedSystem`], written once over `Scalar`, so that its tangent flow comes by automatic
//! differentiation of the same code), on the level set of the geometric integral
//! `H4 = (gamma, gamma) = 1`.
//!
//! After each step the state is projected onto the level set of the integrals of the ball's
//! model ([`LevelSet`]: H4, H1 and, for the Routh sphere and the Chaplygin ball, their two
//! others), and the [`EXPONENTS`] = 5 tangent vectors onto the tangent space of `H4 = const`
//! (the gradient of H4 by automatic differentiation,
//! [`project_tangent`](crate::integrate::variational::project_tangent)). The exponents are
//! those of the flow on the 5-dimensional `|gamma| = 1`; the sixth exponent of `R^6`, across
//! the spheres `|gamma| = const`, is zero (H4 is an integral of the tangent flow too).
//!
//! **The divergence check.** The sum of the five exponents is the time average of the
//! divergence of (mg-eq) along the orbit: the divergence on `R^6` equals that on the sphere,
//! because the flow stretches no normal direction (`n^T J n = 0` for `n = (gamma, 0)`: the
//! `gamma` part of the field is `gamma x omega`, orthogonal to `gamma` whatever its
//! derivative). Where the model has an invariant measure with density `rho` (the Routh sphere,
//! `rho = 1/g`, (rho); Chaplygin's ball), `div X = -X(ln rho)`, so the average divergence over
//! `[t_0, t_1]` is `(ln rho(x(t_0)) - ln rho(x(t_1))) / (t_1 - t_0)`: it tends to 0 as
//! `1 / T` along any orbit on which `rho` stays bounded, and so does the sum of the exponents.

use crate::ball::AsBall;
use crate::error::{Number, Result, RouthError};
use crate::integrals::geometric;
use crate::integrate::lyapunov::{spectrum, Renormalisation, Spectrum};
use crate::integrate::variational::Variational;
use crate::integrate::{IntegrateError, Method, Options};
use crate::projection::LevelSet;
use crate::simulate::{reduced, ReducedSystem, Settings};

/// The number of exponents of a ball: the dimension of the level set `|gamma| = 1`.
pub const EXPONENTS: usize = 5;

/// The dimension of the variational system: the state and [`EXPONENTS`] tangent vectors.
const VARIATIONAL: usize = 6 * (EXPONENTS + 1);

/// The transient of the default schedule, as a fraction of `t_end`: the tangent vectors turn
/// towards the directions that grow fastest before the averaging starts, which removes most of
/// the `ln T / T` bias of an integrable motion (the default case over t = 100: the largest
/// exponent 0.026 instead of 0.061).
pub const DEFAULT_TRANSIENT_FRACTION: f64 = 0.1;

/// The renormalisations of the default schedule over the averaging span `t_end - transient`
/// (the default case: every 0.9, a few spin periods).
pub const DEFAULT_RENORMALISATIONS: f64 = 100.0;

/// The settings of a spectrum: the integration's ([`Settings`]: method, `t_end`, tolerances,
/// step limit; its samples and projection are not used, the run always projects) and the
/// renormalisation schedule ([`Renormalisation`]: transient, interval). Valid once built
/// ([`LyapunovSettings::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LyapunovSettings {
    integration: Settings,
    schedule: Renormalisation,
}

impl LyapunovSettings {
    /// The settings of a spectrum over `[0, integration.t_end()]` averaged after `transient`
    /// (default: [`DEFAULT_TRANSIENT_FRACTION`] of `t_end`), renormalised every `interval`
    /// (default: the averaging span over [`DEFAULT_RENORMALISATIONS`]). Refused, naming the
    /// option ([`RouthError::Option`]): a method other than DOP853, Vern9 or RK4
    /// ([`tangent_method`]), and the rules of
    /// [`Renormalisation::new`] (`t_end > 0`, `0 <= transient < t_end`,
    /// `0 < interval <= t_end - transient`).
    pub fn new(
        integration: Settings,
        transient: Option<f64>,
        interval: Option<f64>,
    ) -> Result<Self> {
        let t_end = integration.t_end();
        let transient = transient.unwrap_or(DEFAULT_TRANSIENT_FRACTION * t_end);
        let interval = interval.unwrap_or((t_end - transient) / DEFAULT_RENORMALISATIONS);
        tangent_method(integration.method())?;
        let schedule = Renormalisation::new(t_end, transient, interval).map_err(|e| match e {
            IntegrateError::InvalidOption { name, value, rule } => RouthError::Option {
                name,
                value: Number(value).to_string(),
                rule,
            },
            other => RouthError::Integrate(other),
        })?;
        Ok(LyapunovSettings {
            integration,
            schedule,
        })
    }

    /// The integration's settings.
    pub fn integration(&self) -> &Settings {
        &self.integration
    }

    /// The renormalisation schedule.
    pub fn schedule(&self) -> &Renormalisation {
        &self.schedule
    }
}

/// `Ok` for a method that integrates the tangent flow (DOP853, Vern9, RK4); the Taylor method
/// (which records the field, not its tangent flow) and `auto` (which would pick it at tight
/// tolerances) refused, naming the option ([`RouthError::Option`]).
pub fn tangent_method(method: Method) -> Result<()> {
    if matches!(method, Method::Dop853 | Method::Vern9 | Method::Rk4 { .. }) {
        return Ok(());
    }
    Err(RouthError::Option {
        name: "method",
        value: method.to_string(),
        rule: "must be dop853, vern9 or rk4 for the tangent flow (Lyapunov exponents, MEGNO; \
               the Taylor method does not integrate it)",
    })
}

/// The projection of a point `z` of the variational system `system` of a ball: its state onto
/// the level set `level` of the model's integrals, its tangent vectors onto the tangent space
/// of `H4 = (gamma, gamma)` there.
pub(crate) fn onto_level_set<'s, B: AsBall, const K: usize, const M: usize>(
    system: &'s Variational<'s, ReducedSystem<'s, B>, 6, K, M>,
    level: &'s LevelSet,
) -> impl Fn(&mut [f64; M]) + 's {
    move |z: &mut [f64; M]| {
        let mut x = reduced(z);
        level.project(&mut x);
        *z = system.join(&x, &system.vectors(z));
        system.project_vectors(z, |x| [geometric(x)]);
    }
}

/// The [`EXPONENTS`] Lyapunov exponents of the motion of `body` from `x0 = (gamma, M)`, on
/// the level set of its integrals through `x0` (see the module's documentation), with the
/// settings `settings`. Each renormalisation interval is one run of the chosen method (RK4:
/// its `steps` per interval) with the settings' tolerances and step limit.
pub fn lyapunov_spectrum(
    body: &impl AsBall,
    x0: &[f64; 6],
    settings: &LyapunovSettings,
) -> Result<Spectrum<6>> {
    let field = ReducedSystem(body);
    let level = LevelSet::through(body, x0);
    let system = Variational::<_, 6, EXPONENTS, VARIATIONAL>::new(&field);
    let project = onto_level_set(&system, &level);
    let run = settings.integration;
    let opts = Options::new(run.rtol(), run.atol())?.with_max_steps(run.max_steps())?;
    Ok(spectrum::<_, 6, EXPONENTS, VARIATIONAL>(
        &field,
        x0,
        &settings.schedule,
        run.method(),
        &opts,
        Some(&project),
    )?)
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::ball::Ball;
    use crate::body::Body;
    use crate::integrals::{chaplygin_density, measure_density};
    use crate::state::{Normalise, State};

    /// The default case's Routh sphere and state (`cases/default.toml`).
    pub(crate) fn routh_sphere() -> (Body, [f64; 6]) {
        let gamma = [0.3f64.sin(), 0.0, 0.3f64.cos()];
        let body = Body::default();
        let x = State::from_omega(&body, gamma, [0.5, 0.2, 8.0], Normalise::Reject).unwrap();
        (body, x.to_array())
    }

    /// The Chaplygin ball and state of `cases/chaplygin.toml`.
    pub(crate) fn chaplygin_ball() -> (Ball, [f64; 6]) {
        let gamma = [0.3f64.sin(), 0.0, 0.3f64.cos()];
        let ball = Ball::new(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 0.0).unwrap();
        let x = State::from_omega(&ball, gamma, [1.5, -2.0, 3.0], Normalise::Reject).unwrap();
        (ball, x.to_array())
    }

    /// DOP853 at the default tolerances (1e-12) to `t_end`, with the schedule given or the
    /// default one.
    fn settings(t_end: f64, transient: Option<f64>, interval: Option<f64>) -> LyapunovSettings {
        let run = Settings::builder().t_end(t_end).build().unwrap();
        LyapunovSettings::new(run, transient, interval).unwrap()
    }

    fn largest(s: &Spectrum<6>) -> f64 {
        s.exponents.iter().fold(0.0f64, |m, l| m.max(l.abs()))
    }

    /// The integrable balls have every exponent zero: their motion is quasi-periodic, the
    /// tangent vectors grow at most linearly (the shear between neighbouring tori), so the
    /// estimates tend to zero as `ln T / T`. At the default time t = 100 with the default
    /// schedule (transient 10, renormalised every 0.9), every exponent is below 0.05 in
    /// absolute value (measured: the Routh sphere 0.026, the Chaplygin ball 0.036); at
    /// t = 1000 without transient below 0.01 (measured 0.0084 and 0.0083: `ln T / T` gives a
    /// factor 6.7 from 100 to 1000, measured 7.3 and 7.2). Negative control: at t = 100 without
    /// the transient, the largest is 0.061 and 0.060, above 0.05: the check can fail, and the
    /// transient is what brings it under.
    #[test]
    fn integrable_balls_have_zero_exponents() {
        let (body, x) = routh_sphere();
        let (ball, y) = chaplygin_ball();
        let routh = lyapunov_spectrum(&body, &x, &settings(100.0, None, None)).unwrap();
        let chaplygin = lyapunov_spectrum(&ball, &y, &settings(100.0, None, None)).unwrap();
        assert_eq!(routh.exponents.len(), EXPONENTS);
        assert!(largest(&routh) < 0.05, "{:?}", routh.exponents);
        assert!(largest(&chaplygin) < 0.05, "{:?}", chaplygin.exponents);
        let long = settings(1000.0, Some(0.0), Some(1.0));
        let routh_long = lyapunov_spectrum(&body, &x, &long).unwrap();
        let chaplygin_long = lyapunov_spectrum(&ball, &y, &long).unwrap();
        assert!(largest(&routh_long) < 0.01, "{:?}", routh_long.exponents);
        assert!(
            largest(&chaplygin_long) < 0.01,
            "{:?}",
            chaplygin_long.exponents
        );
        let no_transient = settings(100.0, Some(0.0), Some(1.0));
        let routh_short = lyapunov_spectrum(&body, &x, &no_transient).unwrap();
        let chaplygin_short = lyapunov_spectrum(&ball, &y, &no_transient).unwrap();
        assert!(largest(&routh_short) > 0.05, "{:?}", routh_short.exponents);
        assert!(
            largest(&chaplygin_short) > 0.05,
            "{:?}",
            chaplygin_short.exponents
        );
    }

    /// The sum of the five exponents is the average divergence of (mg-eq) (to 1e-10; measured
    /// 5.2e-14 and 3.1e-12 over t = 100 at tolerances 1e-12), and the average divergence is
    /// that of the invariant measure, `(ln rho(x_0) - ln rho(x(T))) / T` with `rho = 1/g`
    /// (rho) for the Routh sphere and Chaplygin's density for his ball (to 1e-11: both are
    /// computed from the same orbit, the divergence by Gauss–Legendre on each step, the
    /// density at the ends; measured 8e-15 and 1e-13). It is not zero at finite T (5.2e-5
    /// and -4.2e-4 over t = 100: a bounded oscillation of `ln rho` over `T`), which is the
    /// negative control: the opposite sign misses by twice that.
    #[test]
    fn sum_of_exponents_is_the_divergence_of_the_invariant_measure() {
        let (body, x) = routh_sphere();
        let (ball, y) = chaplygin_ball();
        let run = settings(100.0, Some(0.0), Some(1.0));
        let routh = lyapunov_spectrum(&body, &x, &run).unwrap();
        let chaplygin = lyapunov_spectrum(&ball, &y, &run).unwrap();
        let checks = [
            (
                &routh,
                measure_density(&body, &x),
                measure_density(&body, &routh.end),
            ),
            (
                &chaplygin,
                chaplygin_density(&ball, &y),
                chaplygin_density(&ball, &chaplygin.end),
            ),
        ];
        for (s, rho_start, rho_end) in checks {
            let sum: f64 = s.exponents.iter().sum();
            assert!(
                (sum - s.divergence_mean).abs() < 1e-10,
                "{sum} {}",
                s.divergence_mean
            );
            let by_measure = (rho_start.ln() - rho_end.ln()) / 100.0;
            assert!(
                (s.divergence_mean - by_measure).abs() < 1e-11,
                "{by_measure}"
            );
            assert!((s.divergence_mean + by_measure).abs() > 1e-5, "control");
        }
    }

    /// The Taylor method and `auto` are refused by name, and so is each rule of the schedule.
    #[test]
    fn invalid_settings_are_refused_by_name() {
        let refused = |method: Method, transient: Option<f64>, interval: Option<f64>| {
            let run = Settings::builder().method(method).build().unwrap();
            match LyapunovSettings::new(run, transient, interval) {
                Err(RouthError::Option { name, .. }) => name,
                other => panic!("{other:?}"),
            }
        };
        assert_eq!(refused(Method::Taylor, None, None), "method");
        assert_eq!(refused(Method::Auto, None, None), "method");
        assert_eq!(refused(Method::Dop853, None, Some(-1.0)), "interval");
        assert_eq!(refused(Method::Dop853, None, Some(f64::NAN)), "interval");
        assert_eq!(refused(Method::Dop853, None, Some(95.0)), "interval");
        assert_eq!(refused(Method::Dop853, Some(100.0), None), "transient");
        let defaults = settings(100.0, None, None);
        assert_eq!(defaults.schedule().transient(), 10.0);
        assert_eq!(defaults.schedule().interval(), 0.9);
    }
}
