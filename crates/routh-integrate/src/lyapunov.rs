//! Lyapunov exponents by the standard QR method (Benettin, Galgani, Giorgilli and Strelcyn,
//! Meccanica 15 (1980); Shimada and Nagashima, Prog. Theor. Phys. 61 (1979)).
//!
//! `K` tangent vectors move with the state by the variational equations
//! ([`Variational`]); every renormalisation interval `tau` they are orthonormalised,
//! `Y = Q R` (Householder QR, nalgebra), and replaced by `Q`. The `k`-th exponent is the
//! average growth rate of the `k`-th vector orthogonal to the previous ones,
//!
//! `lambda_k = lim (1 / (t - t_0)) sum ln |R_kk|`,
//!
//! summed over the renormalisations after a transient `t_0` (during which the vectors are
//! renormalised as well, so that they have turned towards the most expanding directions when
//! the averaging starts). With `K = N` this is the whole spectrum; with fewer vectors, the `K`
//! largest exponents.
//!
//! Two numbers come with the spectrum: the Kaplan–Yorke dimension
//! ([`kaplan_yorke_dimension`]) and the time average of the divergence `tr J` of the field along
//! the orbit after the transient (automatic differentiation of the same field, integrated by
//! 3-point Gauss–Legendre on each step's dense output: exact to the interpolant's order). By
//! Liouville's formula `d/dt ln det Y = tr J`, the sum of all `N` exponents equals that
//! average, so that their difference checks the tangent flow, the integration and the
//! renormalisations at once; it vanishes where the field has an invariant measure and the orbit
//! is recurrent.
//!
//! **Units.** The components of a state may have units of their own (the ball's gamma is
//! dimensionless, its M an angular momentum): the Euclidean norm and the orthogonality of the
//! QR step mix them unless the vectors are measured in the units of the run
//! ([`Field::units`], as the steppers measure their errors: [`Scales`]). So the start vectors
//! are generic in those units, and each renormalisation divides component `i` of every vector
//! by its unit `u_i`, orthonormalises, and multiplies back: the exponents of a copy of the
//! system in other units are those of the original divided by the unit of time (exponents are
//! rates), and do not depend on how the components are written.
//!
//! On a level set of integrals (the ball's `|gamma| = 1`), the projection given to
//! [`spectrum`] (after every step, as [`crate::drive`] applies it) moves the state onto the
//! level set and the tangent vectors onto its tangent space
//! ([`variational::project_tangent`](crate::variational::project_tangent)); then at most
//! `N - C` vectors (`C` the number of constraints) are independent, and the exponents are
//! those of the flow on the level set.

use crate::batch::Field;
use crate::variational::{divergence, Variational};
use crate::{
    drive, stepper, Control, Drive, IntegrateError, Method, Options, Projection, Scales, Stats,
    Stepper,
};
use nalgebra::DMatrix;
use std::convert::Infallible;

/// When the tangent vectors are renormalised and the exponents averaged: from `t = 0` to
/// `t_end`, every `interval`, averaged over `[transient, t_end]`. Valid once built
/// ([`Renormalisation::new`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Renormalisation {
    t_end: f64,
    transient: f64,
    interval: f64,
}

impl Renormalisation {
    /// The schedule from 0 to `t_end` (finite, > 0), averaging after `transient` (finite,
    /// `0 <= transient < t_end`), renormalising every `interval` (finite, > 0, at most
    /// `t_end - transient`: one renormalisation at least is averaged); the intervals are
    /// counted from 0 and from `transient`, the last of each stretch cut to end on it.
    /// [`IntegrateError::InvalidOption`] names the first value that breaks its rule.
    pub fn new(t_end: f64, transient: f64, interval: f64) -> Result<Self, IntegrateError> {
        let rules: [(&'static str, f64, bool, &'static str); 3] = [
            (
                "t_end",
                t_end,
                t_end.is_finite() && t_end > 0.0,
                "must be finite and > 0",
            ),
            (
                "transient",
                transient,
                transient.is_finite() && transient >= 0.0 && transient < t_end,
                "must be finite, >= 0 and < t_end",
            ),
            (
                "interval",
                interval,
                interval.is_finite() && interval > 0.0 && interval <= t_end - transient,
                "must be finite, > 0 and <= t_end - transient",
            ),
        ];
        for (name, value, ok, rule) in rules {
            if !ok {
                return Err(IntegrateError::InvalidOption { name, value, rule });
            }
        }
        Ok(Renormalisation {
            t_end,
            transient,
            interval,
        })
    }

    /// The final time.
    pub fn t_end(&self) -> f64 {
        self.t_end
    }

    /// The time after which the exponents are averaged.
    pub fn transient(&self) -> f64 {
        self.transient
    }

    /// The time between two renormalisations.
    pub fn interval(&self) -> f64 {
        self.interval
    }

    /// The times of the renormalisations: `k interval` up to the transient's end, then
    /// `transient + k interval` up to `t_end` (each time computed from its stretch's start,
    /// not accumulated, and each stretch's last time its end; a time within a billionth of an
    /// interval before the end is the end, so that rounding leaves no sliver of an interval).
    fn times(&self) -> impl Iterator<Item = f64> + '_ {
        let stretch = move |start: f64, end: f64| {
            (1..)
                .map(move |k| start + k as f64 * self.interval)
                .take_while(move |&t| t < end - 1e-9 * self.interval)
                .chain(std::iter::once(end))
        };
        stretch(0.0, self.transient)
            .filter(move |_| self.transient > 0.0)
            .chain(stretch(self.transient, self.t_end))
    }
}

/// The running estimates of the exponents at one renormalisation.
#[derive(Debug, Clone, PartialEq)]
pub struct Estimate {
    /// The time of the renormalisation.
    pub t: f64,
    /// The exponents averaged from the transient's end to `t`.
    pub exponents: Vec<f64>,
}

/// The result of [`spectrum`].
#[derive(Debug, Clone, PartialEq)]
pub struct Spectrum<const N: usize> {
    /// The `K` exponents, in the order of the Gram–Schmidt vectors (the largest first once the
    /// vectors have converged; not sorted).
    pub exponents: Vec<f64>,
    /// The running estimates at each renormalisation after the transient: their convergence.
    pub history: Vec<Estimate>,
    /// The Kaplan–Yorke dimension of the exponents ([`kaplan_yorke_dimension`]).
    pub kaplan_yorke_dimension: f64,
    /// The time average of the divergence of the field over `[transient, t_end]`.
    pub divergence_mean: f64,
    /// The state at `t_end`.
    pub end: [f64; N],
    /// The work of all the intervals' runs.
    pub stats: Stats,
}

/// The Kaplan–Yorke (Lyapunov) dimension `j + (lambda_1 + .. + lambda_j) / |lambda_{j+1}|` of
/// the exponents sorted in decreasing order, `j` the largest number of them whose sum is
/// `>= 0`: 0 when the largest is negative, their number when every partial sum is `>= 0`.
pub fn kaplan_yorke_dimension(exponents: &[f64]) -> f64 {
    let mut sorted = exponents.to_vec();
    sorted.sort_by(|a, b| b.total_cmp(a));
    let mut sum = 0.0;
    for (j, &lambda) in sorted.iter().enumerate() {
        if sum + lambda < 0.0 {
            return j as f64 + sum / lambda.abs();
        }
        sum += lambda;
    }
    sorted.len() as f64
}

/// `K` generic directions of `R^N` in the units `scales` (component `i` of each is a number of
/// units `1 / scales.of(i)`): the fractional parts of multiples of the golden ratio (Weyl's
/// sequence) less 1/2. Any fixed subspace of codimension `< K` (the tangent space of a level
/// set) meets their span in `K - codimension` independent directions unless by coincidence;
/// the unit vectors would not (the first three span the normal of `|gamma| = 1`).
pub(crate) fn generic_directions<const N: usize, const K: usize>(
    scales: &Scales<N>,
) -> [[f64; N]; K] {
    let golden = (5f64.sqrt() - 1.0) / 2.0;
    std::array::from_fn(|k| {
        std::array::from_fn(|i| ((((k * N + i + 1) as f64) * golden).fract() - 0.5) / scales.of(i))
    })
}

/// The tangent vectors of `z` replaced by `Q` of the Householder QR of their matrix in the
/// units `scales` (row `i` multiplied by `scales.of(i)`, and `Q`'s divided by it), and
/// `ln |R_kk|`; [`IntegrateError::DependentTangents`] at `t` when a diagonal entry is zero or
/// not finite.
fn renormalise<F: Field<N>, const N: usize, const K: usize, const M: usize>(
    system: &Variational<'_, F, N, K, M>,
    scales: &Scales<N>,
    z: &[f64; M],
    t: f64,
) -> Result<([f64; M], [f64; K]), IntegrateError> {
    let y = system.matrix(z);
    let qr = DMatrix::from_fn(N, K, |i, k| y[(i, k)] * scales.of(i)).qr();
    let (q, r) = (qr.q(), qr.r());
    let logs: [f64; K] = std::array::from_fn(|k| r[(k, k)].abs().ln());
    if logs.iter().any(|l| !l.is_finite()) {
        return Err(IntegrateError::DependentTangents { t });
    }
    let vectors = std::array::from_fn(|k| std::array::from_fn(|i| q[(i, k)] / scales.of(i)));
    Ok((system.join(&system.state(z), &vectors), logs))
}

/// The integral of `integrand(t, z)` over the last step of `run`, by 3-point Gauss–Legendre
/// on its dense output (exact for polynomials of degree 5; the error of the interpolant's
/// order beside it): the divergence here, the integrands of MEGNO in [`crate::megno`].
pub(crate) fn gauss_on_step<const M: usize>(
    run: &(impl Stepper<M> + ?Sized),
    integrand: impl Fn(f64, &[f64; M]) -> f64,
) -> f64 {
    let (a, b) = (run.t_prev(), run.t());
    let (middle, half) = ((a + b) / 2.0, (b - a) / 2.0);
    let node = (0.6f64).sqrt() * half;
    [(-node, 5.0), (0.0, 8.0), (node, 5.0)]
        .iter()
        .map(|&(x, w)| {
            let t = middle + x;
            w / 9.0 * integrand(t, &run.dense(t))
        })
        .sum::<f64>()
        * half
}

/// The `K` largest Lyapunov exponents of `field` from `y0` (all of them with `K = N`) by the
/// QR method on the schedule `schedule`, the tangent vectors starting along `K` generic
/// directions (Weyl's sequence, `generic_directions`), projected by `project` and
/// orthonormalised, all in the units of the run from `y0` ([`Field::units`]: see the
/// module's documentation).
///
/// Each interval is one run of [`crate::drive`] with the stepper of `method` (DOP853, Vern9
/// or RK4 with `steps` equal steps per interval; [`Method::Taylor`] and [`Method::Auto`] are
/// refused) and the tolerances and step limit of `opts`, on the state and the tangent vectors
/// together; `project` (on the whole variational state) after each step. `M` must be
/// `N (K + 1)` ([`Variational::new`]).
///
/// Errors: the stepper's, and [`IntegrateError::DependentTangents`] when the vectors lose
/// their independence (more vectors than the dimension of the space that `project` leaves
/// them).
pub fn spectrum<F: Field<N>, const N: usize, const K: usize, const M: usize>(
    field: &F,
    y0: &[f64; N],
    schedule: &Renormalisation,
    method: Method,
    opts: &Options,
    project: Option<Projection<'_, M>>,
) -> Result<Spectrum<N>, IntegrateError> {
    let system = Variational::<F, N, K, M>::new(field);
    let scales = Scales::of_units(&field.units(y0));
    let mut z = system.join(y0, &generic_directions(&scales));
    if let Some(p) = project {
        p(&mut z);
    }
    let mut t = 0.0;
    z = renormalise(&system, &scales, &z, t)?.0;
    let mut sums = [0.0; K];
    let mut history = Vec::new();
    let mut divergence_integral = 0.0;
    let mut stats = Stats::default();
    for t_next in schedule.times() {
        let averaged = t >= schedule.transient;
        let mut run = stepper(method, &system, t, z, t_next, opts)?;
        let run_drive = Drive {
            project,
            ..Drive::default()
        };
        let Ok(outcome) = drive::<_, Infallible, M>(
            run.as_mut(),
            &run_drive,
            &mut |_, _| Ok(()),
            &mut |_, _, run| {
                if averaged {
                    divergence_integral +=
                        gauss_on_step(run, |_, z| divergence(field, &system.state(z)));
                }
                Ok(Control::Continue)
            },
        );
        let outcome = outcome.into_result()?;
        stats.steps += outcome.stats.steps;
        stats.rejected += outcome.stats.rejected;
        stats.rhs_evals += outcome.stats.rhs_evals;
        t = t_next;
        let (renormalised, logs) = renormalise(&system, &scales, &outcome.y, t)?;
        z = renormalised;
        if averaged {
            for (sum, log) in sums.iter_mut().zip(logs) {
                *sum += log;
            }
            let elapsed = t - schedule.transient;
            history.push(Estimate {
                t,
                exponents: sums.iter().map(|s| s / elapsed).collect(),
            });
        }
    }
    let exponents = history
        .last()
        .map(|e| e.exponents.clone())
        .expect("one interval at least is averaged");
    Ok(Spectrum {
        kaplan_yorke_dimension: kaplan_yorke_dimension(&exponents),
        exponents,
        history,
        divergence_mean: divergence_integral / (schedule.t_end - schedule.transient),
        end: system.state(&z),
        stats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Scalar;
    use crate::variational::tests::{Linear, Lorenz, LORENZ};
    use nalgebra::SMatrix;
    use num_dual::DualSVec64;

    /// The Lorenz system at `rho` (`sigma`, `beta` classical) from `(1, 1, 20)`, exponents
    /// averaged over `[10, t_end]`, renormalised every 0.5, DOP853 at tolerances 1e-9.
    fn lorenz_spectrum(rho: f64, t_end: f64) -> Spectrum<3> {
        struct AtRho(f64);
        impl Field<3> for AtRho {
            fn eval<D: Scalar>(&self, y: &[D; 3]) -> [D; 3] {
                Lorenz::with_rho(self.0, y)
            }
        }
        let schedule = Renormalisation::new(t_end, 10.0, 0.5).unwrap();
        let opts = Options::new(1e-9, 1e-9).unwrap();
        let y0 = [1.0, 1.0, 20.0];
        spectrum::<_, 3, 3, 12>(&AtRho(rho), &y0, &schedule, Method::Dop853, &opts, None).unwrap()
    }

    /// The Lorenz exponents at the classical parameters, averaged over t = 10000 (0.5 s),
    /// against the published 0.9056, 0, -14.5723 (Sprott, *Chaos and Time-Series Analysis*,
    /// 2003, to four decimals). Measured: 0.9065, 1.4e-4, -14.5733; the finite-time estimates
    /// over 5000, 10000 and 20000 spread by 0.0015 around the published values, hence the
    /// tolerances 0.005 on the outer exponents and 0.002 on the zero one (whose bias decays as
    /// 1/T). Their sum equals the average divergence `-(sigma + 1 + beta)` to 1e-6 (measured
    /// 2e-8: the integration error of `ln det Y` at tolerances 1e-9), the divergence itself to
    /// round-off; the Kaplan–Yorke dimension is 2.06. Negative control: at `rho = 10` the orbit
    /// falls onto a stable equilibrium, and the largest exponent is -0.595.
    #[test]
    fn lorenz_exponents_are_the_published_ones() {
        let (sigma, _, beta) = LORENZ;
        let s = lorenz_spectrum(LORENZ.1, 10_000.0);
        let [l1, l2, l3] = [s.exponents[0], s.exponents[1], s.exponents[2]];
        assert!((l1 - 0.9056).abs() < 5e-3, "{:?}", s.exponents);
        assert!(l2.abs() < 2e-3, "{:?}", s.exponents);
        assert!((l3 + 14.5723).abs() < 5e-3, "{:?}", s.exponents);
        let divergence = -(sigma + 1.0 + beta);
        assert!((s.divergence_mean - divergence).abs() < 1e-12);
        assert!((l1 + l2 + l3 - divergence).abs() < 1e-6);
        assert!((s.kaplan_yorke_dimension - 2.062).abs() < 1e-3);
        assert_eq!(s.history.len(), 19_980);
        assert_eq!(s.history.last().unwrap().exponents, s.exponents);
        let stable = lorenz_spectrum(10.0, 1000.0);
        assert!(stable.exponents[0] < -0.5, "{:?}", stable.exponents);
        assert_eq!(stable.kaplan_yorke_dimension, 0.0);
    }

    /// On `y' = A y` the exponents are the real parts of the eigenvalues of `A` (the tangent
    /// flow is `exp(A t)` from the fixed point 0): `0.1 +- 2i` and `-0.5`, with a coupling
    /// above the diagonal. The estimates converge as `1/T` (the logarithm of the bounded
    /// factors of `exp(A t)` in the eigenbasis, divided by `T`): within 1e-3 over T = 1000
    /// (measured 1.2e-4; Vern9 at 1e-10). Their sum is `tr A` to 1e-8. Negative control: the
    /// history's first estimate, over one interval, is off by 0.17.
    #[test]
    fn linear_exponents_are_the_real_parts_of_the_eigenvalues() {
        let a = SMatrix::<f64, 3, 3>::new(0.1, -2.0, 1.0, 2.0, 0.1, 0.5, 0.0, 0.0, -0.5);
        let schedule = Renormalisation::new(1000.0, 0.0, 1.0).unwrap();
        let opts = Options::new(1e-10, 1e-10).unwrap();
        let s =
            spectrum::<_, 3, 3, 12>(&Linear(a), &[0.0; 3], &schedule, Method::Vern9, &opts, None)
                .unwrap();
        let expected = [0.1, 0.1, -0.5];
        for (l, e) in s.exponents.iter().zip(expected) {
            assert!((l - e).abs() < 1e-2, "{:?}", s.exponents);
        }
        let first = &s.history[0].exponents;
        assert!(
            first
                .iter()
                .zip(expected)
                .any(|(l, e)| (l - e).abs() > 1e-2),
            "{first:?}"
        );
        assert!((s.exponents.iter().sum::<f64>() - a.trace()).abs() < 1e-8);
        assert!((s.divergence_mean - a.trace()).abs() < 1e-12);
    }

    /// The free rigid body `m' = m x omega`, `omega = I^{-1} m` (Euler), which keeps `|m|^2`
    /// and the energy.
    struct Euler;

    const INERTIA: [f64; 3] = [1.0, 2.0, 3.0];

    impl Field<3> for Euler {
        fn eval<D: Scalar>(&self, m: &[D; 3]) -> [D; 3] {
            let w = [m[0] / INERTIA[0], m[1] / INERTIA[1], m[2] / INERTIA[2]];
            crate::scalar::cross(m, &w)
        }
    }

    fn sphere(m: &[DualSVec64<3>; 3]) -> [DualSVec64<3>; 1] {
        [m[0] * m[0] + m[1] * m[1] + m[2] * m[2]]
    }

    /// The projection hook: the free rigid body's two exponents on the sphere `|m| = const`
    /// (tangent vectors projected after each step) tend to zero (an integrable, periodic
    /// motion about the first axis: the logarithm of the bounded shear over `T`; measured
    /// +-2.6e-3 over T = 500, tolerance 0.01),
    /// and their sum is the average divergence, 0 (Euler's field is divergence-free). Three
    /// vectors on the 2-dimensional tangent space are refused as dependent (negative control
    /// of the projection: without it, the three vectors stay independent).
    #[test]
    fn projected_tangent_vectors_of_the_rigid_body() {
        let schedule = Renormalisation::new(500.0, 0.0, 1.0).unwrap();
        let opts = Options::new(1e-10, 1e-10).unwrap();
        let y0 = [1.0, 0.2, 0.1];
        let two = Variational::<_, 3, 2, 9>::new(&Euler);
        let project_two = |z: &mut [f64; 9]| two.project_vectors(z, sphere);
        let s = spectrum::<_, 3, 2, 9>(
            &Euler,
            &y0,
            &schedule,
            Method::Dop853,
            &opts,
            Some(&project_two),
        )
        .unwrap();
        assert!(
            s.exponents.iter().all(|l| l.abs() < 1e-2),
            "{:?}",
            s.exponents
        );
        assert!(s.divergence_mean.abs() < 1e-12);
        assert!((s.exponents.iter().sum::<f64>() - s.divergence_mean).abs() < 1e-8);
        let three = Variational::<_, 3, 3, 12>::new(&Euler);
        let project_three = |z: &mut [f64; 12]| three.project_vectors(z, sphere);
        let refused = spectrum::<_, 3, 3, 12>(
            &Euler,
            &y0,
            &schedule,
            Method::Dop853,
            &opts,
            Some(&project_three),
        );
        assert!(
            matches!(refused, Err(IntegrateError::DependentTangents { .. })),
            "{refused:?}"
        );
        assert!(
            spectrum::<_, 3, 3, 12>(&Euler, &y0, &schedule, Method::Dop853, &opts, None).is_ok()
        );
    }

    /// The schedule's rules, each refused by name.
    #[test]
    fn invalid_schedules_are_refused() {
        let name = |r: Result<Renormalisation, IntegrateError>| match r {
            Err(IntegrateError::InvalidOption { name, .. }) => name,
            other => panic!("{other:?}"),
        };
        assert_eq!(name(Renormalisation::new(f64::NAN, 0.0, 1.0)), "t_end");
        assert_eq!(name(Renormalisation::new(10.0, 10.0, 1.0)), "transient");
        assert_eq!(name(Renormalisation::new(10.0, -1.0, 1.0)), "transient");
        assert_eq!(name(Renormalisation::new(10.0, 0.0, -1.0)), "interval");
        assert_eq!(name(Renormalisation::new(10.0, 5.0, 6.0)), "interval");
        assert_eq!(name(Renormalisation::new(10.0, 0.0, f64::NAN)), "interval");
        assert!(Renormalisation::new(10.0, 5.0, 5.0).is_ok());
    }

    /// The renormalisation times: every interval from 0 to the transient, then from the
    /// transient to `t_end`, each stretch ending on its end; computed, not accumulated
    /// (`0.1 + 0.1 + 0.1` is not `0.3`), and no sliver of an interval left by rounding.
    #[test]
    fn renormalisation_times() {
        let times: Vec<f64> = Renormalisation::new(5.0, 2.5, 1.0)
            .unwrap()
            .times()
            .collect();
        assert_eq!(times, [1.0, 2.0, 2.5, 3.5, 4.5, 5.0]);
        let times: Vec<f64> = Renormalisation::new(0.3, 0.0, 0.1)
            .unwrap()
            .times()
            .collect();
        assert_eq!(times, [0.1, 0.2, 0.3]);
        let times: Vec<f64> = Renormalisation::new(2.0, 1.0, 1.0)
            .unwrap()
            .times()
            .collect();
        assert_eq!(times, [1.0, 2.0]);
        let above = f64::from_bits((3.0 * 0.1f64).to_bits() + 1);
        let times: Vec<f64> = Renormalisation::new(above, 0.0, 0.1)
            .unwrap()
            .times()
            .collect();
        assert_eq!(times, [0.1, 0.2, above]);
    }

    /// Kaplan–Yorke: Lorenz-like `(0.9, 0, -14.5)` gives `2 + 0.9 / 14.5`; all negative gives
    /// 0; all sums non-negative gives the number of exponents.
    #[test]
    fn kaplan_yorke_dimension_by_its_definition() {
        assert!((kaplan_yorke_dimension(&[0.0, -14.5, 0.9]) - (2.0 + 0.9 / 14.5)).abs() < 1e-15);
        assert_eq!(kaplan_yorke_dimension(&[-0.1, -1.0]), 0.0);
        assert_eq!(kaplan_yorke_dimension(&[0.1, 0.0, -0.05]), 3.0);
        assert_eq!(kaplan_yorke_dimension(&[1.0, -3.0]), 1.0 + 1.0 / 3.0);
    }
}
