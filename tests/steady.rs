//! Stationary motions: Routh's threshold against the double root of Q and against the
//! eigenvalues of the Jacobian; steady precessions against the integrator.

use routh::body::Body;
use routh::field::vector_field;
use routh::integrate::{solve, Options};
use routh::quadrature::Reduction;
use routh::state::State;
use routh::steady::{
    max_real_eigenvalue, routh_threshold, steady_precessions, vertical_spin, vertical_spin_state,
};

fn top_heavy() -> Body {
    Body::default()
}

#[test]
fn explore() {
    let body = top_heavy();
    let wc = routh_threshold(&body, 1.0);
    println!("wc = {wc}");
    for w in [0.5 * wc, 0.99 * wc, wc, 1.01 * wc, 2.0 * wc] {
        let v = vertical_spin(&body, 1.0, w).unwrap();
        println!("{w}: {:?}", v.stability);
    }
    for w in [0.0, 1.0, 5.0] {
        let v = vertical_spin(&body, -1.0, w).unwrap();
        println!("bottom {w}: {:?}", v.stability);
    }
    for theta in [0.3, 1.0, 1.5, 2.5] {
        for p in steady_precessions(&body, theta, 8.0).unwrap() {
            println!(
                "{theta}: wt {} psidot {} {:?}",
                p.omega_t, p.precession, p.stability
            );
        }
    }
}
