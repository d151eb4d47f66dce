//! The model families with generated Taylor kernels ([`crate::kernels`]): one ball of each,
//! whose tape's shape (the operations, with the constants left out: `0` and `1` kept) the
//! kernel serves for every ball of the family. `cargo xtask kernels` records their tapes
//! through the one generic field ([`crate::field`]) and writes `kernels.rs`. The test
//! `generated_kernels_are_up_to_date` checks that the file is what it would write, and the
//! kernels' other tests that they are bitwise the interpreter: in the library's suite
//! (`crates/routh/tests/suite/integrators.rs`, module `kernels`), whose binary compiles the
//! kernels in lanes anyway (as unit tests here, they were compiled a second time for them
//! alone: a fifth of the README's test command).

use crate::ball::Ball;
use crate::kernels::BallKernels;
use crate::simulate::ReducedSystem;
use routh_integrate::taylor::{codegen, Tape};

/// The command that rewrites `kernels.rs`, named in its header.
pub const REGENERATE: &str = "cargo xtask kernels";

/// The path of the generated kernels in the crate.
pub const KERNELS: &str = "src/kernels.rs";

/// The families: the Routh sphere of the default case (m = R = 1; the case "tilted" of the
/// work-precision benchmark is of this family) and of a general body (no parameter 0 or 1),
/// each with and without gravity; the Chaplygin ball (the centre of mass at the centre, three
/// moments); a general ball (three moments, the centre of mass off the axis). omega is
/// computed in the body's unit of inertia k ([`Ball::inertia_unit`]), whose products by
/// `1 / k` the tape folds when k = 1: the general bodies come twice, with k = 4 (m R^2 = 4.5)
/// and with k = 1 (`_unit`: m R^2 = 0.98), two shapes; the default body and the Chaplygin
/// ball of the family have k = 1.
pub fn families() -> Vec<(&'static str, Ball)> {
    let ball = |m, r, inertia, com, gravity| {
        Ball::new(m, r, inertia, com, gravity).expect("a valid ball of the family")
    };
    let routh = |gravity| ball(1.0, 1.0, [0.4, 0.4, 0.5], [0.0, 0.0, -0.3], gravity);
    let general = |gravity| ball(2.0, 1.5, [0.7, 0.7, 1.1], [0.0, 0.0, 0.3], gravity);
    let general_unit = |gravity| ball(2.0, 0.7, [0.3, 0.3, 0.45], [0.0, 0.0, 0.25], gravity);
    vec![
        ("routh", routh(9.81)),
        ("routh_free", routh(0.0)),
        ("routh_general", general(9.81)),
        ("routh_general_free", general(0.0)),
        ("routh_general_unit", general_unit(9.81)),
        ("routh_general_unit_free", general_unit(0.0)),
        ("chaplygin", ball(1.0, 1.0, [0.3, 0.4, 0.5], [0.0; 3], 0.0)),
        (
            "ball",
            ball(2.0, 1.5, [0.7, 0.9, 1.1], [0.1, -0.2, 0.3], 9.81),
        ),
        (
            "ball_unit",
            ball(2.0, 0.7, [0.3, 0.35, 0.45], [0.1, -0.2, 0.25], 9.81),
        ),
    ]
}

/// The source of `kernels.rs`: the kernels of the tapes of [`families`] as the type
/// `BallKernels`.
pub fn kernels_source() -> String {
    source_of(families())
}

/// The source of the kernels of `families`' tapes, recorded through the generic field (the
/// generator reads the tapes' code, never the kernel a tape found).
pub fn source_of(families: Vec<(&'static str, Ball)>) -> String {
    let tapes: Vec<(&str, Tape<6, f64, BallKernels>)> = families
        .into_iter()
        .map(|(name, ball)| {
            let tape = Tape::record(&ReducedSystem(&ball), 2).expect("the reduced field records");
            (name, tape)
        })
        .collect();
    let named: Vec<_> = tapes.iter().map(|(name, tape)| (*name, tape)).collect();
    codegen::source("BallKernels", &named, REGENERATE)
}
