//! The Schouten bracket of two bivectors at a point, and the Jacobi identity of (geom-eq).
//!
//! Convention: `[P, Q]^{ijk} = sum over the cyclic permutations (a, b, c) of (i, j, k) of
//! sum_l (P^{al} d_l Q^{bc} + Q^{al} d_l P^{bc})`. Then `[P, P]^{ijk} = 2 J^{ijk}` with the
//! Jacobiator `J^{ijk} = {x_i, {x_j, x_k}} + {x_j, {x_k, x_i}} + {x_k, {x_i, x_j}}`, so
//! `[P, P] = 0` is the Jacobi identity, and `[P0, P] = 0` is the compatibility of (cond2).
//! Only first derivatives of the entries are needed; they come from [`Jet`].

use super::{Bivector, Jet};

/// The 20 index triples `i < j < k` of the components of a trivector on R^6, in
/// lexicographic order.
pub const TRIPLES: [[usize; 3]; 20] = {
    let mut t = [[0; 3]; 20];
    let mut n = 0;
    let mut i = 0;
    while i < 6 {
        let mut j = i + 1;
        while j < 6 {
            let mut k = j + 1;
            while k < 6 {
                t[n] = [i, j, k];
                n += 1;
                k += 1;
            }
            j += 1;
        }
        i += 1;
    }
    t
};

/// The 20 components `[P, Q]^{ijk}`, `i < j < k` in the order of [`TRIPLES`].
pub fn schouten(p: &Jet, q: &Jet) -> [f64; 20] {
    TRIPLES.map(|[i, j, k]| {
        [[i, j, k], [j, k, i], [k, i, j]]
            .iter()
            .map(|&[a, b, c]| {
                (0..6)
                    .map(|l| {
                        p.value[a][l] * q.derivative[l][b][c]
                            + q.value[a][l] * p.derivative[l][b][c]
                    })
                    .sum::<f64>()
            })
            .sum()
    })
}

/// Relative size of `[P, Q]` at a point: `max_ijk |[P, Q]^{ijk}| / (|P| |dQ| + |Q| |dP|)`
/// (Frobenius norms of the entries and of all their first derivatives), the scale of a single
/// term of the sum, so that round-off gives about 1e-16 whatever the units.
pub fn relative_schouten(p: &Jet, q: &Jet) -> f64 {
    let scale = p.norm() * q.derivative_norm() + q.norm() * p.derivative_norm();
    let largest = schouten(p, q).iter().fold(0.0f64, |m, v| m.max(v.abs()));
    largest / scale.max(f64::MIN_POSITIVE)
}

/// The relative Jacobi defect `|[P, P]| / (2 |P| |dP|)` of a bivector at a point (see
/// [`relative_schouten`]): zero iff P is Poisson there (geom-eq).
pub fn jacobi_defect<P: Bivector>(p: &P, x: &[f64; 6]) -> f64 {
    let jet = Jet::at(p, x);
    relative_schouten(&jet, &jet)
}

/// The relative compatibility defect `|[P, Q]| / (|P| |dQ| + |Q| |dP|)` at a point: for two
/// Poisson bivectors, zero iff every `P + lambda Q` is Poisson.
pub fn compatibility_defect<P: Bivector, Q: Bivector>(p: &P, q: &Q, x: &[f64; 6]) -> f64 {
    relative_schouten(&Jet::at(p, x), &Jet::at(q, x))
}
