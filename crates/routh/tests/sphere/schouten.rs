//! The Schouten bracket against known cases: the Lie-Poisson bivector of e*(3) is Poisson, a
//! hand-made non-Poisson bivector gives the trivector derived by hand, and the bracket is
//! symmetric and bilinear on bivectors.

use routh::audit::claims::{body, generic_first, Sample};
use routh::poisson::lie_poisson::LiePoisson;
use routh::poisson::schouten::{jacobi_defect, schouten, TRIPLES};
use routh::poisson::{Bivector, Jet, Matrix6};
use routh::scalar::{lift, Real};

fn points() -> Vec<[f64; 6]> {
    Sample {
        seed: 11,
        count: 10,
    }
    .points(&body())
}

#[test]
fn lie_poisson_bivector_of_e3_is_poisson() {
    // The entries are linear, so [P0, P0] is a sum of a few products of O(1) numbers: exact up
    // to one rounding each, 1e-14 absolute is far above that.
    for x in points() {
        let jet = Jet::at(&LiePoisson, &x);
        let t = schouten(&jet, &jet);
        assert!(
            t.iter().all(|v| v.abs() < 1e-14),
            "[P0, P0] = {t:?} at {x:?}"
        );
    }
}

/// `{x1, x2} = x4`, `{x3, x4} = 1` (1-based), all other brackets of coordinates zero.
///
/// By hand: the only non-zero derivative is `d P^{12} / dx4 = 1`, and the only bracket with x4
/// is `P^{34} = 1`, so the Jacobiator `J^{ijk} = sum_cyc sum_l P^{il} d_l P^{jk}` has the single
/// non-zero term `P^{34} d_4 P^{12} = 1` in the component (1, 2, 3):
/// `{x3, {x1, x2}} = {x3, x4} = 1`. Hence `[P, P]^{123} = 2 J^{123} = 2` and the other 19
/// components vanish, at every point.
struct NotPoisson;

impl Bivector for NotPoisson {
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
        let mut p = [[lift::<D>(0.0); 6]; 6];
        p[0][1] = x[3];
        p[1][0] = -x[3];
        p[2][3] = lift(1.0);
        p[3][2] = lift(-1.0);
        p
    }
}

#[test]
fn a_non_poisson_bivector_gives_the_trivector_derived_by_hand() {
    for x in points() {
        let jet = Jet::at(&NotPoisson, &x);
        for (t, [i, j, k]) in schouten(&jet, &jet).iter().zip(TRIPLES) {
            let expected = if [i, j, k] == [0, 1, 2] { 2.0 } else { 0.0 };
            assert_eq!(*t, expected, "[P, P]^{{{i}{j}{k}}} at {x:?}");
        }
        assert!(jacobi_defect(&NotPoisson, &x) > 0.1);
    }
}

#[test]
fn twenty_distinct_triples() {
    let mut t = TRIPLES.to_vec();
    t.dedup();
    assert_eq!(t.len(), 20);
    assert!(TRIPLES.iter().all(|[i, j, k]| i < j && j < k && *k < 6));
}

/// `P0 + P` of the first bracket, for the bilinearity test.
struct Sum;

impl Bivector for Sum {
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
        let a = LiePoisson.entries(x);
        let b = generic_first(body()).entries(x);
        std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
    }
}

#[test]
fn schouten_bracket_is_symmetric_and_bilinear_on_bivectors() {
    // [P0 + P, P0 + P] = [P0, P0] + 2 [P0, P] + [P, P]; each side is a sum of terms of size
    // |P| |dP| ~ 1e1, so 1e-12 absolute is round-off with a margin.
    for x in points() {
        let p0 = Jet::at(&LiePoisson, &x);
        let p = Jet::at(&generic_first(body()), &x);
        let s = Jet::at(&Sum, &x);
        let (pq, qp) = (schouten(&p0, &p), schouten(&p, &p0));
        let (pp, p0p0, ss) = (schouten(&p, &p), schouten(&p0, &p0), schouten(&s, &s));
        for n in 0..20 {
            assert!((pq[n] - qp[n]).abs() < 1e-12);
            assert!((ss[n] - (p0p0[n] + 2.0 * pq[n] + pp[n])).abs() < 1e-12);
        }
    }
}
