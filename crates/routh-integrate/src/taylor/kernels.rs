//! Straight-line kernels of a family of tapes: the passes through the tapes of given shapes
//! generated as Rust source by [`super::codegen::source`] (the command `cargo xtask kernels`),
//! checked in by the crate that owns the systems (the model crate's kernels of its families),
//! and found by a [`Tape`](super::Tape) whose shape is one of [`Kernels::SHAPES`].
//!
//! A system names its kernels in [`OdeSystem::Kernels`](crate::OdeSystem::Kernels); a system
//! without generated kernels names [`Interpreted`], and its tapes run in the interpreter of
//! [`super::tape`]. A kernel makes the interpreter's calls with the same values in its order:
//! the coefficients are bitwise the interpreter's (the model crate's kernel tests).

pub use super::coefficient::Coefficient;
pub use super::convolution::{at, mul_add};
pub use super::recurrence;

/// The generated kernels of a family of tapes, each found by its shape.
///
/// The methods dispatch on the kernel's number (its place in [`Kernels::SHAPES`]); the tape
/// calls them only with a number it found there, so that their `match` has no other arm.
pub trait Kernels: 'static + Clone + std::fmt::Debug {
    /// The name and the shape ([`super::Tape::shape`]) of each kernel, by number.
    const SHAPES: &'static [(&'static str, &'static str)];

    /// Order 0 of the tape of shape `SHAPES[kernel]`, in slots of `s` coefficients: the
    /// field's own operations, with the inline constants `z` (the tape's instructions' inline constants, in their order).
    fn zero<T: Coefficient>(kernel: usize, c: &mut [T], s: usize, z: &[f64]);

    /// The pass of order `k >= 1` through the tape of shape `SHAPES[kernel]`, in slots of
    /// `s` coefficients, with the histories `h` ([`super::convolution`]) and the inline
    /// constants `q`.
    fn pass<T: Coefficient, const FMA: bool>(
        kernel: usize,
        c: &mut [T],
        s: usize,
        k: usize,
        h: &[T],
        q: &[f64],
    );

    /// The histories ([`super::convolution`]) at order `k >= 1` of the tape of shape
    /// `SHAPES[kernel]` into `h` (and the next order's terms summed with them into `g`).
    fn histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
        kernel: usize,
        c: &[T],
        s: usize,
        k: usize,
        h: &mut [T],
        g: &mut [T],
    );
}

/// No generated kernel: every tape runs in the interpreter of [`super::tape`].
#[derive(Debug, Clone, Copy, Default)]
pub struct Interpreted;

impl Kernels for Interpreted {
    const SHAPES: &'static [(&'static str, &'static str)] = &[];

    fn zero<T: Coefficient>(_: usize, _: &mut [T], _: usize, _: &[f64]) {
        unreachable!("Interpreted has no kernel")
    }

    fn pass<T: Coefficient, const FMA: bool>(
        _: usize,
        _: &mut [T],
        _: usize,
        _: usize,
        _: &[T],
        _: &[f64],
    ) {
        unreachable!("Interpreted has no kernel")
    }

    fn histories<T: Coefficient, const FMA: bool, const WIDE: bool>(
        _: usize,
        _: &[T],
        _: usize,
        _: usize,
        _: &mut [T],
        _: &mut [T],
    ) {
        unreachable!("Interpreted has no kernel")
    }
}
