//! The energy–momentum diagram of the Routh sphere: the relative equilibria and their
//! stability types, the number of tori of every regular value, and the monodromy around the
//! focus–focus values (`docs/diagram.md`).
//!
//! The integrals H1 (int-g), Jellett's H3 (int), Routh's K (raus-int) and H4 = (gamma, gamma)
//! map the phase space onto values (H1, H3, K) at H4 = 1. Their regular level sets are unions
//! of tori, each the product of a nutation of the tilt and the circle of rotations about e3;
//! the critical values are those of the relative equilibria (steady precessions and vertical
//! spins). At a fixed H3 the diagram is drawn in the plane (K, H1).

pub mod energy_momentum;
pub mod monodromy;
pub mod relative_equilibria;
pub mod stability;
pub mod tori;
pub mod value;

pub use energy_momentum::{clearance, Diagram, Resolution, TorusGrid, Window};
pub use energy_momentum::{largest_h3, sleeping_tops, threshold_h3, SleepingTop, MAX_SPIN_RATIO};
pub use monodromy::{follow_loop, monodromy, winding, LoopPoint, Monodromy};
pub use relative_equilibria::{
    critical_curves, precession_spins, steady_precession_at, vertical_spin_at, CriticalCurve,
    RelativeEquilibrium,
};
pub use stability::{linearise, Eigenvalue, Linearisation, StabilityType};
pub use tori::{integrate_level_set, torus_count, Excursion, TorusCount};
pub use value::{plane_rate, plane_units, Value};
