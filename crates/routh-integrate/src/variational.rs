//! The variational equations of an autonomous field: the tangent flow integrated with the
//! state.
//!
//! For `y' = f(y)` in `R^N` and `K` tangent vectors `Y = (v_1 .. v_K)` (an `N x K` matrix),
//!
//! `y' = f(y)`, `Y' = J(y) Y`, with `J = df/dy` the Jacobian of the field,
//!
//! so that `Y(t) = D phi_t(y_0) Y(0)`, the derivative of the flow `phi_t` applied to the
//! vectors at the start. `J(y) Y` is not written by hand: [`Variational`] evaluates the one
//! generic field ([`Field::eval`]) on dual numbers ([`DualSVec64<K>`]) whose real parts are
//! the state and whose `K` derivative parts are the rows of `Y`, so one evaluation of the field
//! gives `f(y)` in the real parts and the directional derivatives `J v_k` in the derivative
//! parts (forward-mode automatic differentiation, exact to round-off).
//!
//! The variational system has `M = N (K + 1)` components: the state, then the `K` vectors one
//! after the other (component `N + k N + i` is `(v_k)_i`). Stable Rust cannot write `N (K + 1)`
//! as a const argument, so `M` is a parameter of its own, checked when the system is built:
//! a wrong `M` does not compile (`Variational::new`). The system is an [`OdeSystem<M>`], so
//! that every one-at-a-time method (DOP853, Vern9, RK4) integrates it through [`crate::drive`]
//! with its step control, dense output and projection; the Taylor method does not (its tape
//! records the field on [`crate::taylor::Var`], which is not a dual number), and its stepper
//! refuses the system ([`IntegrateError::Unsupported`]).
//!
//! Also here: the monodromy matrix of a periodic orbit and its Floquet multipliers
//! ([`monodromy`]), the divergence of a field ([`divergence`]) and the projection of tangent
//! vectors onto the tangent space of a level set ([`project_tangent`]).

use crate::batch::Field;
use crate::differential::{partials, seeded};
use crate::{drive, stepper, Control, Drive, IntegrateError, Method, OdeSystem, Options, RunUnits};
use nalgebra::{Complex, Const, DMatrix, SMatrix, SVector};
use num_dual::{Derivative, DualSVec64};
use std::convert::Infallible;

/// The variational system of `field` with `K` tangent vectors: `(y, v_1 .. v_K)` in
/// `R^M`, `M = N (K + 1)`, moving by `y' = f(y)`, `v_k' = J(y) v_k`.
#[derive(Debug)]
pub struct Variational<'f, F, const N: usize, const K: usize, const M: usize> {
    field: &'f F,
}

impl<F, const N: usize, const K: usize, const M: usize> Clone for Variational<'_, F, N, K, M> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<F, const N: usize, const K: usize, const M: usize> Copy for Variational<'_, F, N, K, M> {}

impl<'f, F: Field<N>, const N: usize, const K: usize, const M: usize> Variational<'f, F, N, K, M> {
    /// `M = N (K + 1)`, checked at compile time when [`Variational::new`] is instantiated.
    const DIMENSION: () = assert!(
        M == N * (K + 1),
        "the variational system of N components and K tangent vectors has M = N (K + 1) components"
    );

    /// The variational system of `field`. `M` must be `N (K + 1)`: the rotation field
    /// `y' = (-y_2, y_1)` with two tangent vectors has `M = 6`, and moves a vector as it moves
    /// the state,
    ///
    /// ```
    /// use routh_integrate::variational::Variational;
    /// use routh_integrate::OdeSystem;
    /// # struct Rotation;
    /// # impl routh_integrate::batch::Field<2> for Rotation {
    /// #     fn eval<D: routh_integrate::scalar::Scalar>(&self, y: &[D; 2]) -> [D; 2] { [-y[1], y[0]] }
    /// # }
    /// let system = Variational::<Rotation, 2, 2, 6>::new(&Rotation);
    /// let z = system.join(&[1.0, 0.0], &[[1.0, 0.0], [0.0, 1.0]]);
    /// assert_eq!(system.rhs(0.0, &z), [0.0, 1.0, 0.0, 1.0, -1.0, 0.0]);
    /// ```
    ///
    /// and any other `M` is a compile error:
    ///
    /// ```compile_fail
    /// use routh_integrate::variational::Variational;
    /// # struct Rotation;
    /// # impl routh_integrate::batch::Field<2> for Rotation {
    /// #     fn eval<D: routh_integrate::scalar::Scalar>(&self, y: &[D; 2]) -> [D; 2] { [-y[1], y[0]] }
    /// # }
    /// let wrong = Variational::<Rotation, 2, 2, 5>::new(&Rotation);
    /// ```
    pub fn new(field: &'f F) -> Self {
        let () = Self::DIMENSION;
        Variational { field }
    }

    /// The field.
    pub fn field(&self) -> &'f F {
        self.field
    }

    /// The point of the variational system at the state `y` with the tangent vectors
    /// `vectors`.
    pub fn join(&self, y: &[f64; N], vectors: &[[f64; N]; K]) -> [f64; M] {
        let mut z = [0.0; M];
        z[..N].copy_from_slice(y);
        for (k, v) in vectors.iter().enumerate() {
            z[N * (k + 1)..N * (k + 2)].copy_from_slice(v);
        }
        z
    }

    /// The point of the variational system at `y` with the tangent vectors the columns of
    /// `matrix` (`N x K`).
    pub fn join_matrix(&self, y: &[f64; N], matrix: &SMatrix<f64, N, K>) -> [f64; M] {
        self.join(y, &std::array::from_fn(|k| matrix.column(k).into()))
    }

    /// The state part `y` of a point `z` of the variational system.
    pub fn state(&self, z: &[f64; M]) -> [f64; N] {
        std::array::from_fn(|i| z[i])
    }

    /// The tangent vectors of `z`.
    pub fn vectors(&self, z: &[f64; M]) -> [[f64; N]; K] {
        std::array::from_fn(|k| std::array::from_fn(|i| z[N * (k + 1) + i]))
    }

    /// The tangent vectors of `z` as the columns of an `N x K` matrix `Y`.
    pub fn matrix(&self, z: &[f64; M]) -> SMatrix<f64, N, K> {
        SMatrix::from_fn(|i, k| z[N * (k + 1) + i])
    }

    /// Projects the tangent vectors of `z` (in place) onto the tangent space at its state of
    /// the level set of `constraints` ([`project_tangent`]); the state is left as it is.
    pub fn project_vectors<const C: usize>(
        &self,
        z: &mut [f64; M],
        constraints: impl Fn(&[DualSVec64<N>; N]) -> [DualSVec64<N>; C],
    ) {
        let (y, mut vectors) = (self.state(z), self.vectors(z));
        project_tangent(constraints, &y, &mut vectors);
        *z = self.join(&y, &vectors);
    }

    /// `f(y)` and `J(y) v_k` for the tangent vectors of `z`: one evaluation of the field on
    /// dual numbers seeded with the vectors.
    pub fn tangent_field(&self, z: &[f64; M]) -> [f64; M] {
        let seeded: [DualSVec64<K>; N] = std::array::from_fn(|i| {
            let directions = SVector::<f64, K>::from_fn(|k, _| z[N * (k + 1) + i]);
            DualSVec64::new(z[i], Derivative::some(directions))
        });
        let f = self.field.eval(&seeded);
        let mut out = [0.0; M];
        for (i, fi) in f.iter().enumerate() {
            out[i] = fi.re;
            let jv = fi.eps.unwrap_generic(Const::<K>, Const::<1>);
            for k in 0..K {
                out[N * (k + 1) + i] = jv[k];
            }
        }
        out
    }
}

impl<F: Field<N>, const N: usize, const K: usize, const M: usize> OdeSystem<M>
    for Variational<'_, F, N, K, M>
{
    type Kernels = crate::taylor::Interpreted;

    #[inline(always)]
    fn rhs(&self, _t: f64, z: &[f64; M]) -> [f64; M] {
        self.tangent_field(z)
    }

    /// The state's units as the field gives them ([`Field::units`]); a tangent vector is a
    /// displacement of the state, its component `i` measured in the unit of component `i`.
    fn units(&self, z0: &[f64; M]) -> RunUnits<M> {
        let of_state = self.field.units(&self.state(z0));
        RunUnits {
            time: of_state.time,
            components: std::array::from_fn(|j| of_state.components[j % N]),
        }
    }
}

/// The divergence `tr J(y) = sum_i df_i/dy_i` of `field` at `y`, by automatic differentiation
/// of the same code (one evaluation on dual numbers with `N` derivatives).
pub fn divergence<F: Field<N>, const N: usize>(field: &F, y: &[f64; N]) -> f64 {
    let f = field.eval(&seeded(y));
    (0..N).map(|i| partials(&f[i])[i]).sum()
}

/// Projects the vectors `vectors` (in place) onto the tangent space at `y` of the level set
/// `{c(y) = const}` of the `C` constraint functions `constraints`: `v <- v - G^T (G G^T)^{-1} G v`,
/// with `G` the `C x N` matrix of their gradients at `y` (automatic differentiation: the
/// function is evaluated once on [`seeded`] dual numbers). The orthogonal projection in the
/// coordinates as written; gradients that are linearly dependent (a singular `G G^T`) leave
/// the vectors as they are.
pub fn project_tangent<const N: usize, const C: usize>(
    constraints: impl Fn(&[DualSVec64<N>; N]) -> [DualSVec64<N>; C],
    y: &[f64; N],
    vectors: &mut [[f64; N]],
) {
    let values = constraints(&seeded(y));
    let gradients = SMatrix::<f64, C, N>::from_fn(|c, j| partials(&values[c])[j]);
    let Some(gram) = (gradients * gradients.transpose()).cholesky() else {
        return;
    };
    for v in vectors.iter_mut() {
        let vector = SVector::<f64, N>::from(*v);
        let normal = gradients.transpose() * gram.solve(&(gradients * vector));
        *v = (vector - normal).into();
    }
}

/// The monodromy matrix of a periodic orbit and its Floquet multipliers.
#[derive(Debug, Clone, PartialEq)]
pub struct Monodromy<const N: usize> {
    /// `Y(T) = D phi_T(y_0)`, from `Y(0) = I`.
    pub matrix: SMatrix<f64, N, N>,
    /// Its eigenvalues (with multiplicity, in no particular order): 1 along the orbit of an
    /// autonomous field, the others deciding the orbit's stability.
    pub multipliers: Vec<Complex<f64>>,
    /// The state at `T` (back at `y_0` on a periodic orbit, to the accuracy of the period and
    /// of the integration).
    pub end: [f64; N],
}

/// The monodromy matrix `D phi_T(y_0)` of the orbit of `field` from `y0` over the period
/// `period`, integrated by `method` (DOP853, Vern9 or RK4; [`Method::Taylor`] and
/// [`Method::Auto`] are refused) with the tolerances of `opts` on the state and the `N`
/// tangent vectors together, and its eigenvalues, the Floquet multipliers. `M` must be
/// `N (N + 1)` ([`Variational::new`]).
pub fn monodromy<F: Field<N>, const N: usize, const M: usize>(
    field: &F,
    y0: &[f64; N],
    period: f64,
    method: Method,
    opts: &Options,
) -> Result<Monodromy<N>, IntegrateError> {
    let system = Variational::<F, N, N, M>::new(field);
    let z0 = system.join_matrix(y0, &SMatrix::identity());
    let mut run = stepper(method, &system, 0.0, z0, period, opts)?;
    let Ok(outcome) = drive::<_, Infallible, M>(
        run.as_mut(),
        &Drive::default(),
        &mut |_, _| Ok(()),
        &mut |_, _, _| Ok(Control::Continue),
    );
    let z = outcome.into_result()?.y;
    let matrix = system.matrix(&z);
    let multipliers = DMatrix::from_fn(N, N, |i, j| matrix[(i, j)])
        .complex_eigenvalues()
        .iter()
        .copied()
        .collect();
    Ok(Monodromy {
        matrix,
        multipliers,
        end: system.state(&z),
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::scalar::Scalar;

    /// The Lorenz system at the classical parameters `sigma = 10, rho = 28, beta = 8/3`.
    pub(crate) struct Lorenz;

    /// `sigma`, `rho`, `beta` of [`Lorenz`].
    pub(crate) const LORENZ: (f64, f64, f64) = (10.0, 28.0, 8.0 / 3.0);

    impl Lorenz {
        /// The Lorenz field at `rho`, `sigma` and `beta` classical.
        pub(crate) fn with_rho<D: Scalar>(rho: f64, y: &[D; 3]) -> [D; 3] {
            let (sigma, _, beta) = LORENZ;
            [
                (y[1] - y[0]) * sigma,
                y[0] * (-y[2] + rho) - y[1],
                y[0] * y[1] - y[2] * beta,
            ]
        }
    }

    impl Field<3> for Lorenz {
        fn eval<D: Scalar>(&self, y: &[D; 3]) -> [D; 3] {
            Lorenz::with_rho(LORENZ.1, y)
        }
    }

    /// The linear field `y' = A y`.
    pub(crate) struct Linear<const N: usize>(pub SMatrix<f64, N, N>);

    impl<const N: usize> Field<N> for Linear<N> {
        fn eval<D: Scalar>(&self, y: &[D; N]) -> [D; N] {
            std::array::from_fn(|i| {
                (1..N).fold(y[0] * self.0[(i, 0)], |s, j| s + y[j] * self.0[(i, j)])
            })
        }
    }

    /// The attracting limit cycle `r' = r (1 - r^2)`, `theta' = 1` in Cartesian coordinates:
    /// the unit circle, of period `2 pi`, with the Floquet multipliers 1 and `exp(-2 * 2 pi)`
    /// (`d/dr (r - r^3) = -2` at `r = 1`).
    struct LimitCycle;

    impl Field<2> for LimitCycle {
        fn eval<D: Scalar>(&self, y: &[D; 2]) -> [D; 2] {
            let shrink = -(y[0] * y[0] + y[1] * y[1]) + 1.0;
            [y[0] * shrink - y[1], y[1] * shrink + y[0]]
        }
    }

    /// The flow of the state alone from `y0` to `t`, by DOP853 at `tol`.
    fn flow<F: Field<N>, const N: usize>(field: &F, y0: [f64; N], t: f64, tol: f64) -> [f64; N] {
        let plain = |_t: f64, y: &[f64; N]| field.eval(y);
        let opts = Options::new(tol, tol).unwrap();
        crate::solve(&plain, 0.0, y0, t, &opts, None, None, &mut |_, _| {})
            .unwrap()
            .1
    }

    /// `Y(T)` from `Y(0) = I`: the monodromy over `t`.
    fn fundamental<F: Field<N>, const N: usize, const M: usize>(
        field: &F,
        y0: [f64; N],
        t: f64,
        method: Method,
        tol: f64,
    ) -> SMatrix<f64, N, N> {
        monodromy::<F, N, M>(field, &y0, t, method, &Options::new(tol, tol).unwrap())
            .unwrap()
            .matrix
    }

    /// The largest entry of `a - b`, relative to the largest entry of `b` (at least 1).
    fn relative_error<const N: usize>(a: &SMatrix<f64, N, N>, b: &SMatrix<f64, N, N>) -> f64 {
        (a - b).amax() / b.amax().max(1.0)
    }

    /// On `y' = A y` the tangent flow is `exp(A t)` whatever the state: for
    /// `A = [[a, -b], [b, a]]`, `exp(A t) = e^{a t} R(b t)` in closed form, and for a 3 x 3
    /// matrix with a Jordan-like coupling nalgebra's `exp` (scaling and squaring with Pade:
    /// independent of the integrators). DOP853 and Vern9 at tolerances 1e-12 and RK4 with
    /// 4000 steps over t = 2 (global error about 1e-13 relative for RK4 with h = 5e-4 and
    /// rates of order 1) are within 1e-9 relative: the tolerances' error times the growth
    /// `e^{a t}`, with margin. Negative control: `exp(A^T t)` is far from it.
    #[test]
    fn linear_tangent_flow_is_the_matrix_exponential() {
        let (a, b, t) = (0.3, 2.0, 2.0);
        let rotation = Linear(SMatrix::<f64, 2, 2>::new(a, -b, b, a));
        let (c, s) = ((b * t).cos(), (b * t).sin());
        let exact = SMatrix::<f64, 2, 2>::new(c, -s, s, c) * (a * t).exp();
        let coupled = SMatrix::<f64, 3, 3>::new(-0.5, 1.0, 0.0, 0.0, -0.5, 2.0, 0.3, 0.0, 0.2);
        let coupled_exact = (coupled * t).exp();
        for method in [Method::Dop853, Method::Vern9, Method::Rk4 { steps: 4000 }] {
            let y = fundamental::<_, 2, 6>(&rotation, [1.0, -0.5], t, method, 1e-12);
            assert!(
                relative_error(&y, &exact) < 1e-9,
                "{method}: {y} vs {exact}"
            );
            assert!(relative_error(&y.transpose(), &exact) > 0.1, "control");
            let y = fundamental::<_, 3, 12>(&Linear(coupled), [0.1, 0.2, 0.3], t, method, 1e-12);
            assert!(relative_error(&y, &coupled_exact) < 1e-9, "{method}: {y}");
            assert!(
                relative_error(&y.transpose(), &coupled_exact) > 0.1,
                "control"
            );
        }
    }

    /// The Taylor method records the field on tape variables, not on dual numbers: its stepper
    /// refuses the variational system with an error, not a wrong answer.
    #[test]
    fn taylor_refuses_the_variational_system() {
        let system = Variational::<_, 3, 3, 12>::new(&Lorenz);
        let z0 = system.join_matrix(&[1.0, 1.0, 20.0], &SMatrix::identity());
        let refused = stepper(Method::Taylor, &system, 0.0, z0, 1.0, &Options::default());
        assert!(matches!(refused, Err(IntegrateError::Unsupported { .. })));
    }

    /// On the Lorenz system over t = 1 (the tangent vectors grow by about e^0.9 and more
    /// transiently), `Y(1)` equals the central differences of the flow,
    /// `(phi(y0 + h e_k) - phi(y0 - h e_k)) / 2h` with `h = 1e-4`: their truncation error is
    /// `h^2 |phi'''| / 6`, about 1e-8 relative here, and the integration error of the two runs
    /// (tolerance 1e-13) divided by `2h` another 1e-8 or so; 1e-6 relative leaves a margin of
    /// 50. Negative control: `Y^T` misses by order 1.
    #[test]
    fn lorenz_tangent_flow_equals_central_differences_of_the_flow() {
        let (y0, t, h) = ([1.0, 1.0, 20.0], 1.0, 1e-4);
        let tangent = fundamental::<_, 3, 12>(&Lorenz, y0, t, Method::Dop853, 1e-13);
        let differences = SMatrix::<f64, 3, 3>::from_fn(|i, k| {
            let (mut plus, mut minus) = (y0, y0);
            plus[k] += h;
            minus[k] -= h;
            (flow(&Lorenz, plus, t, 1e-13)[i] - flow(&Lorenz, minus, t, 1e-13)[i]) / (2.0 * h)
        });
        let error = relative_error(&tangent, &differences);
        assert!(error < 1e-6, "{error:e}: {tangent} vs {differences}");
        assert!(relative_error(&tangent.transpose(), &differences) > 1e-2);
    }

    /// The limit cycle's monodromy over its period `2 pi` from `(1, 0)`: the multipliers are 1
    /// (along the orbit) and `exp(-4 pi) = 3.49e-6`, to 1e-9 (DOP853 at 1e-12: the matrix
    /// entries are of order 1, their error of the order of the tolerance times the number of
    /// steps), and the orbit closes to 1e-10. Negative control: half a period does not give
    /// these multipliers (they are -1, a half turn, and `exp(-2 pi)`).
    #[test]
    fn limit_cycle_floquet_multipliers() {
        let period = 2.0 * std::f64::consts::PI;
        let opts = Options::new(1e-12, 1e-12).unwrap();
        let mono =
            monodromy::<_, 2, 6>(&LimitCycle, &[1.0, 0.0], period, Method::Dop853, &opts).unwrap();
        let mut multipliers: Vec<f64> = mono
            .multipliers
            .iter()
            .map(|m| {
                assert!(m.im.abs() < 1e-9, "{m}");
                m.re
            })
            .collect();
        multipliers.sort_by(f64::total_cmp);
        let contraction = (-2.0 * period).exp();
        assert!(
            (multipliers[0] - contraction).abs() < 1e-9,
            "{multipliers:?}"
        );
        assert!((multipliers[1] - 1.0).abs() < 1e-9, "{multipliers:?}");
        assert!((mono.end[0] - 1.0).abs() < 1e-10 && mono.end[1].abs() < 1e-10);
        let half = monodromy::<_, 2, 6>(
            &LimitCycle,
            &[1.0, 0.0],
            period / 2.0,
            Method::Dop853,
            &opts,
        )
        .unwrap();
        assert!(
            half.multipliers.iter().all(|m| (m.re - 1.0).abs() > 0.5),
            "control"
        );
    }

    /// The divergence of the Lorenz field is `-(sigma + 1 + beta)` everywhere (to round-off),
    /// and that of `y' = A y` is `tr A`.
    #[test]
    fn divergence_is_the_trace_of_the_jacobian() {
        let (sigma, _, beta) = LORENZ;
        let d = divergence(&Lorenz, &[3.0, -2.0, 17.0]);
        assert!((d + sigma + 1.0 + beta).abs() < 1e-13, "{d}");
        let a = SMatrix::<f64, 2, 2>::new(0.3, -2.0, 1.0, -0.7);
        assert!((divergence(&Linear(a), &[1.0, 2.0]) - a.trace()).abs() < 1e-15);
    }

    /// On the sphere `|y|^2 = const` of R^3, the projection removes the radial part of a
    /// vector (the result is orthogonal to `y`) and leaves a tangent vector as it is.
    /// Negative control: the vector before projection is not orthogonal.
    #[test]
    fn tangent_projection_onto_a_sphere() {
        let y = [0.6, 0.0, 0.8];
        let sphere = |x: &[DualSVec64<3>; 3]| [x[0] * x[0] + x[1] * x[1] + x[2] * x[2]];
        let radial = |v: &[f64; 3]| v.iter().zip(&y).map(|(a, b)| a * b).sum::<f64>();
        let mut vectors = [[1.0, 2.0, 3.0], [-0.8, 0.5, 0.6]];
        assert!(radial(&vectors[0]).abs() > 1.0);
        project_tangent(sphere, &y, &mut vectors);
        assert!(radial(&vectors[0]).abs() < 1e-15, "{vectors:?}");
        let tangent = [-0.8, 0.5, 0.6];
        for (p, q) in vectors[1].iter().zip(tangent) {
            assert!((p - q).abs() < 1e-15);
        }
    }
}
