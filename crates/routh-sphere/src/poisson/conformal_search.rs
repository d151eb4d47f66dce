//! The search for a conformally Hamiltonian form (eq-cf), `X = g P dF(H1, H2, H3, H4)`, with a
//! linear-in-momenta bivector (anzats) `P_ij = sum_k a_ijk(gamma) M_k + b_ij(gamma)` that has
//! the Casimirs and the involutive pair of (geom-eq).
//!
//! **The conditions are pointwise in gamma.** (eq-cf), the Casimir conditions `P dC = 0` and
//! the involution `{H_l, H_k} = 0` of (geom-eq) contain the entries of P but none of their
//! derivatives; only `[P, P] = 0` differentiates P. At a fixed gamma the 60 numbers
//! `a_ijk(gamma)`, `b_ij(gamma)` (15 entries `i < j` of the skew matrix, each with the
//! coefficients of `M1, M2, M3, 1`) are therefore the unknowns of a linear system that must
//! hold for every M. If that system is inconsistent at one gamma, no P of any functional form
//! in gamma (polynomial, rational, algebraic, with g or without) satisfies the linear
//! conditions, and [P, P] never needs to be examined. The conformal factor is a function of
//! gamma (the g of (rho)), so at fixed gamma it is absorbed into the unknowns: the result
//! holds for every conformal factor `c(gamma)`, g included.
//!
//! **The identities in M.** At fixed gamma each condition is a polynomial in M of degree at
//! most 5 (the involution `dH_l^T P dH_k` with quadratic H_l, H_k: 2 + 1 + 2), a space of 56
//! monomials; it vanishes identically iff it vanishes at 56 unisolvent momenta, which random
//! momenta are with probability one. [`MOMENTA`] = 80 random momenta leave a margin.
//!
//! **F.** `dF = sum_a F_a dH_a`. Here `F_a = f_a` are constants (F linear in the integrals);
//! the terms of the two Casimirs drop out of `P dF`, so only the coefficients of the other
//! integrals matter ([`Foliation::hamiltonians`]), up to a common factor absorbed into P: a
//! projective family of ratios. The system is bilinear in the ratio and P: [`decide`] first
//! solves the linear lifted system ([`Section::lifted`]), then searches the ratio
//! ([`minimax_ratio`]).
//!
//! **Rows and scales.** The rows of each momentum sample are divided by the natural size of
//! the terms they sum (`|m| |dC|` for a Casimir, `|m| |dH_l| |dH_k|` for the involution,
//! `|m| (sum_a |dH_a|^2)^(1/2)` for (eq-cf), with `m = (M1, M2, M3, 1)`), so that every
//! residual is relative and round-off gives about 1e-15.
//!
//! **Rank decision.** The homogeneous conditions (Casimirs, involution) are solved first: their
//! null space is spanned by the right singular vectors of singular values at most
//! [`RANK_TOLERANCE`] times the largest. The decision is safe only if the singular values have
//! a gap around that threshold; [`Section::gap`] reports it (largest dropped over smallest kept
//! singular value), and the tests require it to be below 1e-10 (measured 1e-15 to 3e-12).

use crate::body::Body;
use crate::differential::{gradient, Dual6};
use crate::integrals::{energy, geometric, jellett, quadratic_integral, routh_integral};
use crate::sampling::SplitMix64;
use nalgebra::{DMatrix, DVector};

/// An integral of a body, evaluated on dual numbers (gradients by automatic differentiation).
pub type Integral = fn(&Body, &[Dual6; 6]) -> Dual6;

/// The number of unknowns at a fixed gamma: 15 entries `P_ij`, `i < j`, each
/// `a_ij1 M1 + a_ij2 M2 + a_ij3 M3 + b_ij`.
pub const UNKNOWNS: usize = 60;

/// The number of random momenta at which the identities in M are imposed (56 monomials of
/// degree at most 5 in M, with margin).
pub const MOMENTA: usize = 80;

/// Relative threshold of the rank decisions: singular values at most this times the largest
/// count as zero. Round-off leaves about 1e-15 of the largest; the tests check that the
/// singular values have a gap of many orders around the threshold.
pub const RANK_TOLERANCE: f64 = 1e-9;

/// The 15 index pairs `i < j` of the entries of a skew 6x6 matrix.
const PAIRS: [(usize, usize); 15] = {
    let mut p = [(0, 0); 15];
    let mut n = 0;
    let mut i = 0;
    while i < 6 {
        let mut j = i + 1;
        while j < 6 {
            p[n] = (i, j);
            n += 1;
            j += 1;
        }
        i += 1;
    }
    p
};

fn h4(_: &Body, x: &[Dual6; 6]) -> Dual6 {
    geometric(x)
}

/// The paper's three choices of the Casimirs `C1, C2` and the involutive pair `H_l, H_k` in
/// (geom-eq), section 2.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Foliation {
    /// `C = (H4, H3)`, `{H1, H2} = 0`: the first bracket (p-br).
    First,
    /// `C = (H4, K)`, `{H1, H3} = 0`: the second bracket (p-bv2).
    Second,
    /// `C = (H3, K)`, `{H1, H4} = 0`: the third bracket P''.
    Third,
}

impl Foliation {
    /// The three choices, in the paper's order.
    pub const ALL: [Foliation; 3] = [Foliation::First, Foliation::Second, Foliation::Third];

    /// A short name: `C = (H4, H3)`, ...
    pub fn name(self) -> &'static str {
        match self {
            Foliation::First => "C = (H4, H3), {H1, H2} = 0",
            Foliation::Second => "C = (H4, K), {H1, H3} = 0",
            Foliation::Third => "C = (H3, K), {H1, H4} = 0",
        }
    }

    /// The Casimirs `C1, C2`.
    pub fn casimirs(self) -> [Integral; 2] {
        match self {
            Foliation::First => [h4, jellett],
            Foliation::Second => [h4, routh_integral],
            Foliation::Third => [jellett, routh_integral],
        }
    }

    /// The involutive pair `H_l, H_k`.
    pub fn involutive_pair(self) -> [Integral; 2] {
        match self {
            Foliation::First => [energy, quadratic_integral],
            Foliation::Second => [energy, jellett],
            Foliation::Third => [energy, h4],
        }
    }

    /// The integrals whose coefficients `f_a` in `dF = sum_a f_a dH_a` survive in `P dF`: those
    /// that are not Casimirs. With `H2 = I1 H1 + (I3 - I1)/I1 K^2 - (m/I1) H3^2` (raus-int),
    /// `P dH2 = I1 P dH1` when H3 and K are Casimirs (the third choice), so H2 is left out
    /// there; with only K a Casimir (the second) `P dH2 = I1 P dH1 - (2m/I1) H3 P dH3` has a
    /// coefficient that varies with M, so H2 stays.
    pub fn hamiltonians(self) -> Vec<Integral> {
        match self {
            Foliation::First => vec![energy, quadratic_integral],
            Foliation::Second => vec![energy, quadratic_integral, jellett],
            Foliation::Third => vec![energy, h4],
        }
    }
}

/// [`MOMENTA`] momenta with components uniform in [-2, 2], from the SplitMix64 stream of
/// `seed` (the scale of the audit's points).
pub fn random_momenta(seed: u64) -> Vec<[f64; 3]> {
    let mut rng = SplitMix64::new(seed);
    (0..MOMENTA)
        .map(|_| std::array::from_fn(|_| rng.uniform(-2.0, 2.0)))
        .collect()
}

/// The sections of one foliation at several gammas, with the same momenta.
pub fn sections(
    body: &Body,
    field: &dyn Fn(&[f64; 6]) -> [f64; 6],
    foliation: Foliation,
    gammas: &[[f64; 3]],
    momenta: &[[f64; 3]],
) -> Vec<Section> {
    gammas
        .iter()
        .map(|g| Section::new(body, field, foliation, g, momenta))
        .collect()
}

/// The unknown vector of a bivector's values at a point: `q[4 p + c]` is the coefficient of
/// `m_c` (`m = (M1, M2, M3, 1)`) in the entry of pair `p`.
fn momentum_monomials(x: &[f64; 6]) -> [f64; 4] {
    [x[3], x[4], x[5], 1.0]
}

/// The rows of `Q v = w` at one point, as coefficients of the unknowns: row i of `Q v` is
/// `sum_j Q_ij v_j`, and the unknown of pair `(i, j)`, monomial c contributes `m_c v_j` to
/// row i and `-m_c v_i` to row j.
fn apply_rows(m: &[f64; 4], v: &[f64; 6], scale: f64) -> [[f64; UNKNOWNS]; 6] {
    let mut rows = [[0.0; UNKNOWNS]; 6];
    for (p, &(i, j)) in PAIRS.iter().enumerate() {
        for (c, mc) in m.iter().enumerate() {
            rows[i][4 * p + c] += mc * v[j] / scale;
            rows[j][4 * p + c] -= mc * v[i] / scale;
        }
    }
    rows
}

/// The row of `u^T Q v` at one point.
fn pairing_row(m: &[f64; 4], u: &[f64; 6], v: &[f64; 6], scale: f64) -> [f64; UNKNOWNS] {
    let mut row = [0.0; UNKNOWNS];
    for (p, &(i, j)) in PAIRS.iter().enumerate() {
        for (c, mc) in m.iter().enumerate() {
            row[4 * p + c] = mc * (u[i] * v[j] - u[j] * v[i]) / scale;
        }
    }
    row
}

fn euclid(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

/// The unknown vector of a bivector that is linear in M, read off from its values at `M = 0`
/// and `M = e_k` at the given gamma (exact for a bivector of the form (anzats)).
pub fn unknowns_of(entries: impl Fn(&[f64; 6]) -> [[f64; 6]; 6], gamma: &[f64; 3]) -> Vec<f64> {
    let at = |m: [f64; 3]| entries(&[gamma[0], gamma[1], gamma[2], m[0], m[1], m[2]]);
    let base = at([0.0; 3]);
    let units = [
        at([1.0, 0.0, 0.0]),
        at([0.0, 1.0, 0.0]),
        at([0.0, 0.0, 1.0]),
    ];
    let mut q = vec![0.0; UNKNOWNS];
    for (p, &(i, j)) in PAIRS.iter().enumerate() {
        for k in 0..3 {
            q[4 * p + k] = units[k][i][j] - base[i][j];
        }
        q[4 * p + 3] = base[i][j];
    }
    q
}

/// The linear system of (eq-cf) and (geom-eq) at one gamma: the null space of the homogeneous
/// conditions (Casimirs, involution) and, on it, one block of (eq-cf) per surviving
/// Hamiltonian, with the field as right-hand side.
#[derive(Debug, Clone)]
pub struct Section {
    /// The point gamma.
    pub gamma: [f64; 3],
    /// The rows of the homogeneous conditions (Casimirs, involution), `rows x 60`.
    pub constraints: DMatrix<f64>,
    /// The singular values of [`Section::constraints`] with the gauge rows of the kernel below,
    /// largest first.
    pub singular_values: Vec<f64>,
    /// A basis of the null space of the constraints and of the gauge that sets to zero the
    /// components vanishing at every sampled momentum, the idle directions removed, `60 x k`.
    pub kernel: DMatrix<f64>,
    /// The dimension of the idle part of the null space: bivectors with the Casimirs and the
    /// involution that also annihilate every `dH_a`, so that they can be added to any solution
    /// and change no `Q dF`.
    pub idle_dimension: usize,
    /// The blocks `A_a` of (eq-cf), `Q dH_a` as rows in the unknowns, `rows x 60`.
    pub blocks: Vec<DMatrix<f64>>,
    /// The field X, stacked and scaled like the rows of the blocks.
    pub rhs: DVector<f64>,
}

impl Section {
    /// The system at gamma for the field X, the body's integrals and the foliation, imposed at
    /// the momenta `momenta` (at least [`MOMENTA`] random ones for the identities in M).
    pub fn new(
        body: &Body,
        field: &dyn Fn(&[f64; 6]) -> [f64; 6],
        foliation: Foliation,
        gamma: &[f64; 3],
        momenta: &[[f64; 3]],
    ) -> Self {
        let hamiltonians = foliation.hamiltonians();
        let [l, k] = foliation.involutive_pair();
        let mut constraint_rows: Vec<[f64; UNKNOWNS]> = Vec::new();
        let mut block_rows: Vec<Vec<[f64; UNKNOWNS]>> = vec![Vec::new(); hamiltonians.len()];
        let mut rhs = Vec::new();
        let grad = |h: Integral, x: &[f64; 6]| gradient(|y| h(body, y), x).1;
        for mv in momenta {
            let x = [gamma[0], gamma[1], gamma[2], mv[0], mv[1], mv[2]];
            let m = momentum_monomials(&x);
            let size = euclid(&m);
            for c in foliation.casimirs() {
                let dc = grad(c, &x);
                constraint_rows.extend(apply_rows(&m, &dc, size * euclid(&dc)));
            }
            let (dl, dk) = (grad(l, &x), grad(k, &x));
            constraint_rows.push(pairing_row(&m, &dl, &dk, size * euclid(&dl) * euclid(&dk)));
            let dh: Vec<[f64; 6]> = hamiltonians.iter().map(|&h| grad(h, &x)).collect();
            let scale = size * dh.iter().map(|v| euclid(v).powi(2)).sum::<f64>().sqrt();
            for (rows, v) in block_rows.iter_mut().zip(&dh) {
                rows.extend(apply_rows(&m, v, scale));
            }
            rhs.extend(field(&x).iter().map(|v| v / scale));
        }
        let to_matrix =
            |rows: &[[f64; UNKNOWNS]]| DMatrix::from_fn(rows.len(), UNKNOWNS, |r, c| rows[r][c]);
        let constraints = to_matrix(&constraint_rows);
        let gauged = to_matrix(&[constraint_rows, invisible_rows(momenta)].concat());
        let (singular_values, null) = null_space(&gauged);
        let blocks: Vec<DMatrix<f64>> = block_rows.iter().map(|r| to_matrix(r)).collect();
        // The null vectors that every block annihilates (Q dH_a = 0 for all a) change no
        // Q dF: keep the orthogonal complement of theirs, on which Q dF is faithful.
        let stacked = DMatrix::from_fn(blocks.len() * rhs.len(), null.ncols(), |r, c| {
            (&blocks[r / rhs.len()] * null.column(c))[r % rhs.len()]
        });
        let (_, idle) = null_space(&stacked);
        let active = complement(&idle);
        Section {
            gamma: *gamma,
            constraints,
            singular_values,
            kernel: &null * active,
            idle_dimension: idle.ncols(),
            blocks,
            rhs: DVector::from_vec(rhs),
        }
    }

    /// The dimension of the null space of the homogeneous conditions without its idle part.
    pub fn kernel_dimension(&self) -> usize {
        self.kernel.ncols()
    }

    /// The gap of the rank decision: the largest singular value counted as zero over the
    /// smallest one kept (0 if none is dropped, 1 if none is kept: no gap).
    pub fn gap(&self) -> f64 {
        let rank = UNKNOWNS - self.kernel_dimension() - self.idle_dimension;
        match rank {
            0 => 1.0,
            r if r == self.singular_values.len() => 0.0,
            r => self.singular_values[r] / self.singular_values[r - 1],
        }
    }

    /// The relative residual `|Q dF - X| / |X|` of the least-squares Q on the null space of
    /// the homogeneous conditions, for `dF = sum_a f_a dH_a`: about 1e-15 iff (eq-cf) has a
    /// solution at this gamma for these constants.
    pub fn residual(&self, f: &[f64]) -> f64 {
        Reduced::of(self).residual(f)
    }

    /// The distance `|q - q*| / |q|` of a given unknown vector q from the least-squares
    /// solution q* of the section with the given constants `f_a` (both with the components
    /// that vanish at every sampled momentum removed): zero iff q is that solution, which is
    /// the only one where the system has full column rank on the null space.
    pub fn distance_to_solution(&self, q: &[f64], f: &[f64]) -> f64 {
        let (_, y, _) = least_squares(&(combination(&self.blocks, f) * &self.kernel), &self.rhs);
        let q = DVector::from_column_slice(q);
        let visible = &self.kernel * (self.kernel.transpose() * &q);
        (&self.kernel * y - &visible).norm() / visible.norm()
    }

    /// The lifted system `sum_a A_a N z_a = X`, with independent `z_a` in place of `f_a y`
    /// (N the basis of [`Section::kernel`]): every solution `(f, y)` of (eq-cf) gives the
    /// lifted solution `z_a = f_a y`.
    pub fn lifted(&self) -> Lifted {
        let k = self.kernel_dimension();
        let mut matrix = DMatrix::zeros(self.rhs.len(), k * self.blocks.len());
        for (n, a) in self.blocks.iter().enumerate() {
            matrix.columns_mut(n * k, k).copy_from(&(a * &self.kernel));
        }
        let (singular_values, _, residual) = least_squares(&matrix, &self.rhs);
        Lifted {
            residual,
            rank: singular_values
                .iter()
                .filter(|&&v| v > RANK_TOLERANCE * singular_values[0])
                .count(),
            singular_values,
        }
    }

    /// The largest relative defect of a given unknown vector q (for instance a known bracket
    /// times a conformal factor) in the homogeneous conditions and in (eq-cf) for the given
    /// constants: zero iff q solves the system.
    pub fn defect(&self, q: &[f64], f: &[f64]) -> f64 {
        let q = DVector::from_column_slice(q);
        let homogeneous = (&self.constraints * &q).amax() / q.norm();
        let fitted = combination(&self.blocks, f) * &q;
        homogeneous.max((fitted - &self.rhs).norm() / self.rhs.norm())
    }
}

/// Rows that set to zero the components of P that vanish at every sampled momentum: for
/// momenta on a plane (the level `(M, r) = 0` of a negative control) the coefficient of the
/// normal direction is not determined by the sample, and fixing it to zero keeps the solution
/// unique where it is unique on the plane. For momenta that span R^3 there are none.
fn invisible_rows(momenta: &[[f64; 3]]) -> Vec<[f64; UNKNOWNS]> {
    let sample = DMatrix::from_fn(momenta.len(), 4, |r, c| {
        momentum_monomials(&[0.0, 0.0, 0.0, momenta[r][0], momenta[r][1], momenta[r][2]])[c]
    });
    let (_, normals) = null_space(&sample);
    let mut rows = Vec::new();
    for normal in normals.column_iter() {
        for p in 0..PAIRS.len() {
            let mut row = [0.0; UNKNOWNS];
            for c in 0..4 {
                row[4 * p + c] = normal[c];
            }
            rows.push(row);
        }
    }
    rows
}

/// An orthonormal basis of the orthogonal complement of the span of the orthonormal columns
/// of `basis` in `R^n`, `n` its number of rows.
fn complement(basis: &DMatrix<f64>) -> DMatrix<f64> {
    let n = basis.nrows();
    let projector = DMatrix::identity(n, n) - basis * basis.transpose();
    // The projector's singular values are 1 on the complement and 0 on the span.
    let svd = projector.svd(true, false);
    let u = svd.u.expect("SVD with U");
    let kept: Vec<DVector<f64>> = (0..n)
        .filter(|&i| svd.singular_values[i] > 0.5)
        .map(|i| u.column(i).into_owned())
        .collect();
    if kept.is_empty() {
        DMatrix::zeros(n, 0)
    } else {
        DMatrix::from_columns(&kept)
    }
}

/// The singular values of a tall matrix (largest first) and a basis of its numerical null
/// space (right singular vectors of the singular values at most
/// [`RANK_TOLERANCE`] times the largest).
fn null_space(a: &DMatrix<f64>) -> (Vec<f64>, DMatrix<f64>) {
    let svd = a.clone().svd(false, true);
    let v_t = svd.v_t.expect("SVD with V^T");
    let mut order: Vec<usize> = (0..svd.singular_values.len()).collect();
    order.sort_by(|&i, &j| svd.singular_values[j].total_cmp(&svd.singular_values[i]));
    let values: Vec<f64> = order.iter().map(|&i| svd.singular_values[i]).collect();
    let largest = values.first().copied().unwrap_or(0.0);
    let kernel: Vec<DVector<f64>> = order
        .iter()
        .filter(|&&i| svd.singular_values[i] <= RANK_TOLERANCE * largest)
        .map(|&i| v_t.row(i).transpose())
        .collect();
    let basis = if kernel.is_empty() {
        DMatrix::zeros(a.ncols(), 0)
    } else {
        DMatrix::from_columns(&kernel)
    };
    (values, basis)
}

/// The least-squares solution y of `A y = b` (SVD, singular values at most [`RANK_TOLERANCE`]
/// times the largest dropped): the singular values of A (largest first), y and the relative
/// residual `|b - A y| / |b|` (1 for an empty A).
fn least_squares(a: &DMatrix<f64>, b: &DVector<f64>) -> (Vec<f64>, DVector<f64>, f64) {
    if a.ncols() == 0 {
        return (Vec::new(), DVector::zeros(0), 1.0);
    }
    let svd = a.clone().svd(true, true);
    let mut values: Vec<f64> = svd.singular_values.iter().copied().collect();
    values.sort_by(|x, y| y.total_cmp(x));
    let y = svd
        .solve(b, RANK_TOLERANCE * values[0])
        .expect("SVD with both factors");
    let residual = (b - a * &y).norm() / b.norm();
    (values, y, residual)
}

/// `sum_a f_a A_a` for blocks of equal shape.
fn combination(blocks: &[DMatrix<f64>], f: &[f64]) -> DMatrix<f64> {
    let zero = DMatrix::zeros(blocks[0].nrows(), blocks[0].ncols());
    blocks.iter().zip(f).fold(zero, |acc, (a, c)| acc + a * *c)
}

/// The least-squares solution of a lifted system [`Section::lifted`].
#[derive(Debug, Clone)]
pub struct Lifted {
    /// The relative residual: above [`CONSISTENCY`], no constants `f_a` solve (eq-cf) at this
    /// gamma.
    pub residual: f64,
    /// The singular values of the lifted matrix, largest first.
    pub singular_values: Vec<f64>,
    /// Its numerical rank.
    pub rank: usize,
}

/// The residual below which a system counts as consistent. Measured (tests/eq_cf.rs,
/// docs/audit.md): round-off leaves 1e-15 to 2e-12 with momenta that span R^3 and up to 3e-10
/// on the plane `(M, r) = 0` of a negative control (its null spaces are less sharp: gaps 1e-11
/// instead of 1e-13), while the inconsistent systems of the real field leave 0.2 or more.
/// 1e-8 is 30 times above the first and seven orders below the second.
pub const CONSISTENCY: f64 = 1e-8;

/// Points per angle of the grid of ratios `f_1 : ... : f_p` (p - 1 angles): 720 for one angle,
/// 90 x 90 for two.
fn grid_size(angles: usize) -> usize {
    match angles {
        0 => 1,
        1 => 720,
        _ => 90,
    }
}

/// The unit vector of hyperspherical angles: `(cos t1, sin t1 cos t2, sin t1 sin t2 cos t3,
/// ...)`; the angles in `[0, pi)` (the last) and `[0, pi]` (the others) reach every ratio up to
/// sign.
fn direction(angles: &[f64]) -> Vec<f64> {
    let mut f = Vec::with_capacity(angles.len() + 1);
    let mut sine = 1.0;
    for t in angles {
        f.push(sine * t.cos());
        sine *= t.sin();
    }
    f.push(sine);
    f
}

/// The section projected on an orthonormal basis of the span of its blocks' columns and the
/// field: the same least-squares residuals with at most `p k + 1` rows.
struct Reduced {
    blocks: Vec<DMatrix<f64>>,
    rhs: DVector<f64>,
}

impl Reduced {
    fn of(section: &Section) -> Self {
        let active: Vec<DMatrix<f64>> =
            section.blocks.iter().map(|a| a * &section.kernel).collect();
        let mut columns: Vec<DVector<f64>> = active
            .iter()
            .flat_map(|b| b.column_iter().map(|c| c.into_owned()).collect::<Vec<_>>())
            .collect();
        columns.push(section.rhs.clone());
        let basis = DMatrix::from_columns(&columns).qr().q();
        Reduced {
            blocks: active.iter().map(|b| basis.transpose() * b).collect(),
            rhs: basis.transpose() * &section.rhs,
        }
    }

    fn residual(&self, f: &[f64]) -> f64 {
        let combined = combination(&self.blocks, f);
        least_squares(&combined, &self.rhs).2
    }
}

/// The smallest over the ratios `f` of the largest residual over the sections,
/// `min_f max_j |Q_j dF - X| / |X|`: a grid (720 points for one angle, 90 x 90 for two), then a compass
/// search (steps halved down to 1e-12 rad) from the best grid point. The minimiser and the
/// minimum.
pub fn minimax_ratio(sections: &[Section]) -> (Vec<f64>, f64) {
    let reduced: Vec<Reduced> = sections.iter().map(Reduced::of).collect();
    let angles = sections.first().map_or(0, |s| s.blocks.len() - 1);
    let worst = |t: &[f64]| {
        let f = direction(t);
        reduced.iter().map(|r| r.residual(&f)).fold(0.0, f64::max)
    };
    let n = grid_size(angles);
    let mut best = (vec![0.0; angles], f64::INFINITY);
    for index in 0..n.pow(angles as u32) {
        let t: Vec<f64> = (0..angles)
            .map(|a| {
                let i = (index / n.pow(a as u32)) % n;
                let span = if a + 1 == angles { n } else { n - 1 };
                std::f64::consts::PI * i as f64 / span.max(1) as f64
            })
            .collect();
        let value = worst(&t);
        if value < best.1 {
            best = (t, value);
        }
    }
    let mut step = std::f64::consts::PI / n as f64;
    while step > 1e-12 && angles > 0 {
        let mut moved = false;
        for a in 0..angles {
            for sign in [-1.0, 1.0] {
                let mut t = best.0.clone();
                t[a] += sign * step;
                let value = worst(&t);
                if value < best.1 {
                    best = (t, value);
                    moved = true;
                }
            }
        }
        if !moved {
            step /= 2.0;
        }
    }
    (direction(&best.0), best.1)
}

/// What the search found for one foliation, over a set of gammas.
#[derive(Debug, Clone, PartialEq)]
pub enum Decision {
    /// The lifted system is inconsistent at some gamma: no constants F_a at all, whatever the
    /// ratio. The largest lifted residual over the gammas.
    NoRatio {
        /// The largest lifted residual.
        residual: f64,
    },
    /// The lifted systems are consistent, but no ratio serves all gammas: the smallest over the
    /// ratios of the largest residual over the gammas ([`minimax_ratio`]) is above
    /// [`CONSISTENCY`].
    RatioVaries {
        /// The minimax residual.
        residual: f64,
        /// The ratio that attains it (unit vector).
        ratio: Vec<f64>,
    },
    /// A common ratio solves the linear conditions at every gamma (minimax residual at most
    /// [`CONSISTENCY`]): the linear part has a solution, [P, P] = 0 remains to be tested.
    Consistent {
        /// The minimax residual.
        residual: f64,
        /// The common ratio (unit vector).
        ratio: Vec<f64>,
    },
}

impl Decision {
    /// How far the linear conditions are from a solution with constant F_a: the residual of
    /// [`Decision::NoRatio`] or [`Decision::RatioVaries`], 0 for [`Decision::Consistent`].
    pub fn margin(&self) -> f64 {
        match self {
            Decision::NoRatio { residual } | Decision::RatioVaries { residual, .. } => *residual,
            Decision::Consistent { .. } => 0.0,
        }
    }
}

/// The search for one foliation over the sections at several gammas: first the lifted
/// systems (linear; one inconsistent section excludes every ratio), then [`minimax_ratio`].
pub fn decide(sections: &[Section]) -> Decision {
    let worst = sections
        .iter()
        .map(|s| s.lifted().residual)
        .fold(0.0, f64::max);
    if worst > CONSISTENCY {
        return Decision::NoRatio { residual: worst };
    }
    let (ratio, residual) = minimax_ratio(sections);
    if residual > CONSISTENCY {
        Decision::RatioVaries { residual, ratio }
    } else {
        Decision::Consistent { residual, ratio }
    }
}
