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
            fn $method(self, other: Self) -> Self {
                Lanes(std::array::from_fn(|i| self.0[i].$method(other.0[i])))
            }
        }

        impl<D: Scalar, const W: usize> $trait<f64> for Lanes<D, W> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: f64) -> Self {
                Lanes(self.0.map(|a| a.$method(other)))
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
    fn neg(self) -> Self {
        Lanes(self.0.map(|a| -a))
    }
}

impl<D: Scalar, const W: usize> Scalar for Lanes<D, W> {
    #[inline(always)]
    fn from_f64(c: f64) -> Self {
        Lanes([D::from_f64(c); W])
    }

    #[inline(always)]
    fn sqrt(self) -> Self {
        Lanes(self.0.map(D::sqrt))
    }

    #[inline(always)]
    fn recip(self) -> Self {
        Lanes(self.0.map(D::recip))
    }

    #[inline(always)]
    fn mul_add(self, a: Self, b: Self) -> Self {
        Lanes(std::array::from_fn(|i| self.0[i].mul_add(a.0[i], b.0[i])))
    }
}
