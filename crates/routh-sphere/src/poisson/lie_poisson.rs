//! The Lie-Poisson bivector P0 of the Lie algebra e*(3), printed after (cond2), in the
//! coordinates (gamma, M): `{M_i, M_j} = eps_ijk M_k`, `{M_i, gamma_j} = eps_ijk gamma_k`,
//! `{gamma_i, gamma_j} = 0`; the same bivector in the coordinates (gamma, L) is the target
//! of the Poisson map (p-map), (e3).

use super::{from_blocks, Bivector, Matrix6};
use crate::scalar::{lift, Real};

/// The canonical Lie-Poisson bivector P0 on e*(3), blocks `Gamma` and `M` as printed.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct LiePoisson;

impl Bivector for LiePoisson {
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
        let zero = lift::<D>(0.0);
        let [g1, g2, g3, m1, m2, m3] = *x;
        from_blocks(
            [[zero, g3, -g2], [-g3, zero, g1], [g2, -g1, zero]],
            [m3, -m2, m1],
        )
    }
}
