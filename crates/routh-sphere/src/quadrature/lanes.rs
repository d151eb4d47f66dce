//! Lanes: `W` numbers of one type that a formula written over [`Scalar`] evaluates at once,
//! each lane by the very operations, in the same order, that the formula makes on one number
//! (so each lane's result is that of the formula on its number, bit for bit). The lanes are
//! independent chains of operations, which the processor overlaps: the quadrature evaluates
//! Q'' at the 8 nodes of a Gauss-Legendre rule as one number of 8 lanes (`Nutation::cofactor`).

use crate::scalar::Scalar;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// `W` numbers of type `D`, every operation applied lane by lane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lanes<D, const W: usize>(pub [D; W]);

macro_rules! lane_operator {
    ($trait:ident, $method:ident) => {
        impl<D: Scalar, const W: usize> $trait for Lanes<D, W> {
            type Output = Self;
            #[inline(always)]
            fn $method(mut self, other: Self) -> Self {
                for (a, b) in self.0.iter_mut().zip(other.0) {
                    *a = a.$method(b);
                }
                self
            }
        }

        impl<D: Scalar, const W: usize> $trait<f64> for Lanes<D, W> {
            type Output = Self;
            #[inline(always)]
            fn $method(mut self, other: f64) -> Self {
                for a in &mut self.0 {
                    *a = a.$method(other);
                }
                self
            }
        }
    };
}

lane_operator!(Add, add);
lane_operator!(Sub, sub);
lane_operator!(Mul, mul);
lane_operator!(Div, div);

impl<D: Scalar, const W: usize> Neg for Lanes<D, W> {
    type Output = Self;
    #[inline(always)]
    fn neg(mut self) -> Self {
        for a in &mut self.0 {
            *a = -*a;
        }
        self
    }
}

impl<D: Scalar, const W: usize> Scalar for Lanes<D, W> {
    #[inline(always)]
    fn from_f64(c: f64) -> Self {
        Lanes([D::from_f64(c); W])
    }

    #[inline(always)]
    fn sqrt(mut self) -> Self {
        for a in &mut self.0 {
            *a = a.sqrt();
        }
        self
    }

    #[inline(always)]
    fn recip(mut self) -> Self {
        for a in &mut self.0 {
            *a = a.recip();
        }
        self
    }

    #[inline(always)]
    fn mul_add(mut self, a: Self, b: Self) -> Self {
        for ((s, a), b) in self.0.iter_mut().zip(a.0).zip(b.0) {
            *s = s.mul_add(a, b);
        }
        self
    }
}
