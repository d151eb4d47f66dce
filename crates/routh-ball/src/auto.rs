//! What [`Method::Auto`] runs for a rolling ball: the method measured fastest on the Routh
//! sphere at each tolerance, with and without projection onto the level set of the integrals.
//! The integrator crate keeps only the mechanism ([`Method::resolve_in`] with a table); the
//! tables are the model's, measured on its field.

use crate::integrate::Method;

/// What `auto` picks: `(tol_min, method)` rows, the first with `tol >= tol_min` wins.
///
/// From the work–precision benchmark (docs/benchmarks-history.md, section "Work-precision", run of
/// 2026-11-24 09:59 UTC, three cases to t = 1000, plain integration): at each tolerance, the
/// method that reaches the error the other reaches there in less time. At tol 1e-12 and below
/// the Taylor method is both faster and 7 to 20x more accurate than Vern9 (default: 12.2 ms
/// for 2.3e-9 against 12.6 ms for 4.9e-8); at 1e-11 Vern9's error (4.8e-7 default, 6.7e-8
/// tilted) costs the Taylor method about as much or more (default 9.7 against 9.3 ms,
/// nogravity a tie, tilted less), and at 1e-10 and above Vern9 is the faster (its errors there,
/// 1e-6 and above, are where its low cost per step wins). Hence Vern9 for tol >= 5e-12 and
/// the Taylor method below.
pub const AUTO_TABLE: [(f64, Method); 2] = [(5e-12, Method::Vern9), (0.0, Method::Taylor)];

/// What `auto` picks for a run projected onto the level set of the integrals
/// ([`crate::simulate::Settings::project`]): `(tol_min, method)` rows as [`AUTO_TABLE`]'s.
///
/// From the same run, the rows "+proj/10" (projection after every 10th step): at tol 1e-11
/// the Taylor method with projection is faster than Vern9 with projection and more accurate
/// on the three cases (default 10.1 ms for 3.5e-10 at its tol 1e-10 against Vern9's 10.5 ms
/// for 6.0e-10 at 1e-11; tilted 5.8 against 7.5 ms); at tol 1e-10 Vern9's error (5.5e-9 to
/// 6.0e-9) costs the Taylor method more on default and nogravity (about 9.7 against 8.0 ms)
/// and about the same on tilted; above, Vern9. Projection moves the crossing up by a decade:
/// it makes the Taylor method's larger steps as accurate over long times as Vern9's, and its
/// cost is a smaller part of a Taylor step than of a Vern9 step. Hence Vern9 for tol >= 5e-11.
pub const AUTO_TABLE_PROJECTED: [(f64, Method); 2] =
    [(5e-11, Method::Vern9), (0.0, Method::Taylor)];

/// The method that runs a ball's `method` at the tolerance `tol = min(rtol, atol)`, the run
/// `projected` onto the level set of the integrals or not: [`AUTO_TABLE_PROJECTED`] or
/// [`AUTO_TABLE`] for [`Method::Auto`], the method itself otherwise.
pub fn resolve(method: Method, tol: f64, projected: bool) -> Method {
    let table: &[(f64, Method)] = if projected {
        &AUTO_TABLE_PROJECTED
    } else {
        &AUTO_TABLE
    };
    method.resolve_in(tol, table)
}
