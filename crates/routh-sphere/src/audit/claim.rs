//! A claim of the paper and its verdict, the random points it is evaluated at, and the setting
//! shared by every group of claims: the body of the audit, the generic alpha and beta, the field
//! and the integrals as functions on the phase space.
//!
//! Points: gamma uniform on the unit sphere with `|gamma_i| >= 0.15` for each i and
//! `|R gamma3 + a| >= 0.1 R` (away from the singular sets `gamma1 gamma2 gamma3 = 0`,
//! `gamma1^2 + gamma2^2 = 0`, `R gamma3 + a = 0` of the printed formulas), each component of M
//! uniform in [-2, 2]; for claims at `b = 0`, M is projected on `(M, r) = 0`.
//!
//! Status: OK iff the largest relative residual is at most [`THRESHOLD`] = 1e-10. The residuals
//! are relative to the scale of the terms that cancel (see [`super::checks`]); round-off leaves
//! 1e-16 to 1e-13 of that scale at these points (a few hundred operations, condition numbers up
//! to about 1e2 near the excluded sets), while a wrong formula leaves 1e-3 or more. 1e-10 is
//! three orders above the first and seven below the second. Measured: over 80 seeds with 200

use crate::body::Body;
use crate::differential::Dual6;
use crate::error::{Result, RouthError};
use crate::field::vector_field;
use crate::integrals::geometric;
use crate::poisson::first::{Alpha, Beta, FirstBracket, UserFunction};
use crate::sampling::SplitMix64;
use crate::scalar::{dot, split};
use serde::Serialize;

/// The largest relative residual of an OK claim.
pub const THRESHOLD: f64 = 1e-10;

/// The verdict of a check.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Status {
    /// The residual is at most [`THRESHOLD`].
    #[serde(rename = "OK")]
    Ok,
    /// The residual exceeds [`THRESHOLD`].
    #[serde(rename = "FAIL")]
    Fail,
    /// The claim cannot be decided numerically; the note says why.
    #[serde(rename = "NOT-CHECKED")]
    NotChecked,
    /// A non-existence claim decided within a stated ansatz (the note states it): the residual
    /// is the margin, the smallest relative residual of the conditions over the ansatz, above
    /// [`THRESHOLD`].
    #[serde(rename = "OK-WITHIN-ANSATZ")]
    OkWithinAnsatz,
}

impl Status {
    /// The status as printed in the table: `OK`, `FAIL`, `NOT-CHECKED`, `OK-WITHIN-ANSATZ`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Status::Ok => "OK",
            Status::Fail => "FAIL",
            Status::NotChecked => "NOT-CHECKED",
            Status::OkWithinAnsatz => "OK-WITHIN-ANSATZ",
        }
    }
}

/// The most points per claim of an audit run ([`Sample::new`]). The audit of 20 points takes
/// about a second and a half (on one core of the machine of docs/reliability.md), and its time
/// grows with the points: 100,000 points are a few hours and a few megabytes (each point is
/// 48 bytes), where 10^12 asked for 48 TB at once.
pub const MAX_POINTS: usize = 100_000;

/// The random points of an audit run: `count` points from the SplitMix64 stream of `seed`.
/// Built only by [`Sample::new`], which checks the count: a sample holds a valid one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sample {
    seed: u64,
    count: usize,
}

impl Sample {
    /// The sample of `count` points from the stream of `seed`: `count` between 1 and
    /// [`MAX_POINTS`], refused with the rule otherwise, before any point is drawn.
    pub fn new(seed: u64, count: usize) -> Result<Self> {
        if (1..=MAX_POINTS).contains(&count) {
            Ok(Sample { seed, count })
        } else {
            Err(RouthError::Option {
                name: "points",
                value: count.to_string(),
                rule: "must be between 1 and 100000 (the audit of 20 points takes about 1.5 s: \
                       100000 take hours)",
            })
        }
    }

    /// The seed of the generator.
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The number of points per claim.
    pub fn count(&self) -> usize {
        self.count
    }

    /// Points on `|gamma| = 1` away from the singular sets (see the module documentation).
    pub fn points(&self, body: &Body) -> Vec<[f64; 6]> {
        let mut rng = SplitMix64::new(self.seed);
        let mut out = Vec::with_capacity(self.count);
        while out.len() < self.count {
            let x = rng.phase_point(2.0, 0.0, 0.15);
            if x[0].abs() >= 0.15
                && x[1].abs() >= 0.15
                && (body.radius() * x[2] + body.a()).abs() >= 0.1 * body.radius()
            {
                out.push(x);
            }
        }
        out
    }

    /// The same points with M projected on the Jellett level `b = (M, r) = 0`.
    pub fn points_jellett_zero(&self, body: &Body) -> Vec<[f64; 6]> {
        self.points(body)
            .into_iter()
            .map(|x| {
                let (gamma, m) = split(&x);
                let r = body.contact_vector(&gamma);
                let k = dot(&m, &r) / dot(&r, &r);
                [
                    x[0],
                    x[1],
                    x[2],
                    m[0] - k * r[0],
                    m[1] - k * r[1],
                    m[2] - k * r[2],
                ]
            })
            .collect()
    }
}

/// The result of a claim's check: the largest relative residual (`None`: not checked) and a
/// note (what was evaluated, readings of ambiguous text, the fitted values of a failure).
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The largest relative residual over the points; for a non-existence claim the margin.
    pub residual: Option<f64>,
    /// What the number means, or why there is none.
    pub note: String,
    /// Whether the claim is a non-existence statement decided within an ansatz: then the
    /// residual is the margin by which the conditions miss a solution, and a margin above
    /// [`THRESHOLD`] is [`Status::OkWithinAnsatz`] (at most: [`Status::NotChecked`], since a
    /// solution of the linear conditions alone refutes nothing).
    pub within_ansatz: bool,
}

impl Outcome {
    /// A checked claim with its residual and note.
    pub fn checked(residual: f64, note: impl Into<String>) -> Self {
        Outcome {
            residual: Some(residual),
            note: note.into(),
            within_ansatz: false,
        }
    }

    /// A non-existence claim decided within an ansatz, with its margin and note.
    pub fn excluded(margin: f64, note: impl Into<String>) -> Self {
        Outcome {
            within_ansatz: true,
            ..Outcome::checked(margin, note)
        }
    }
}

/// A claim of the paper.
#[derive(Debug, Clone, Copy)]
pub struct Claim {
    /// The id, e.g. `p-br.jacobi`; a `.corrected` suffix marks the corrected formula.
    pub id: &'static str,
    /// The paper's equation label, e.g. `p-br`.
    pub label: &'static str,
    /// The claim in one line.
    pub statement: &'static str,
    /// The check.
    pub check: fn(&Sample) -> Outcome,
}

/// The verdict on one claim, as printed by `routh audit`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Verdict {
    /// The claim's id.
    pub id: &'static str,
    /// The equation label.
    pub label: &'static str,
    /// The claim in one line.
    pub statement: &'static str,
    /// OK, FAIL, NOT-CHECKED or OK-WITHIN-ANSATZ.
    pub status: Status,
    /// The largest relative residual (`null` when not checked).
    pub residual: Option<f64>,
    /// The note of the check.
    pub note: String,
}

impl Claim {
    /// Run the check and judge it against [`THRESHOLD`].
    pub fn verdict(&self, sample: &Sample) -> Verdict {
        let Outcome {
            residual,
            note,
            within_ansatz,
        } = (self.check)(sample);
        let status = match (residual, within_ansatz) {
            (None, _) => Status::NotChecked,
            (Some(margin), true) if margin > THRESHOLD => Status::OkWithinAnsatz,
            (Some(_), true) => Status::NotChecked,
            (Some(r), false) if r <= THRESHOLD => Status::Ok,
            (Some(_), false) => Status::Fail,
        };
        Verdict {
            id: self.id,
            label: self.label,
            statement: self.statement,
            status,
            residual,
            note,
        }
    }
}

/// The body of the audit: m = 1.3, R = 0.8, a = 0.25, I1 = I2 = 0.4, I3 = 0.55, G = 9.81.
/// Deliberately not m = R = 1, so that a misplaced factor m or R cannot go unnoticed.
pub fn body() -> Body {
    Body::new(1.3, 0.8, 0.25, 0.4, 0.4, 0.55, 9.81).expect("the audit's body satisfies the rules")
}

/// The same body rolling without gravity, (m-eq).
pub fn free_body() -> Body {
    body().without_gravity()
}

/// The potential of gravity of a check: ours, `U = +m G (r, gamma)` (gamma points into the
/// plane), or the paper's printed `U = -m g (r, gamma)` with g = G, which is ours with G -> -G.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Potential {
    /// `U = +m G (r, gamma)` of the body.
    Ours(Body),
    /// The printed `U = -m G (r, gamma)` of the body: ours with G -> -G. No body has G < 0;
    /// the field and the integrals are affine in G (through U alone), so a function f of the
    /// body is taken as `2 f(G = 0) - f(G)`, f at -G up to round-off (exactly f where f does
    /// not involve G).
    Printed(Body),
}

impl Potential {
    /// The body (G >= 0, as every body's).
    pub fn body(&self) -> Body {
        match *self {
            Potential::Ours(b) | Potential::Printed(b) => b,
        }
    }

    /// The field X of (mg-eq) with this potential, in `f64`.
    pub fn field(self) -> impl Fn(&[f64; 6]) -> [f64; 6] {
        let (body, free) = (self.body(), self.body().without_gravity());
        move |x| {
            let with = vector_field(&body, x);
            match self {
                Potential::Ours(_) => with,
                Potential::Printed(_) => {
                    let without = vector_field(&free, x);
                    std::array::from_fn(|i| 2.0 * without[i] - with[i])
                }
            }
        }
    }

    /// An integral of the body with this potential, as a function on the phase space.
    pub fn integral(self, h: fn(&Body, &[Dual6; 6]) -> Dual6) -> impl Fn(&[Dual6; 6]) -> Dual6 {
        let (body, free) = (self.body(), self.body().without_gravity());
        move |x| match self {
            Potential::Ours(_) => h(&body, x),
            Potential::Printed(_) => h(&free, x) * 2.0 - h(&body, x),
        }
    }
}

/// The generic alpha(gamma1/gamma2) of the audit.
pub const GENERIC_ALPHA: Alpha = Alpha::Polynomial([0.7, 0.2, -0.1]);
/// The generic beta(gamma3) of the audit.
pub const GENERIC_BETA: Beta = Beta::Gamma3([1.1, -0.3, 0.4]);
/// The constant alpha of (cond), (cond2).
pub const CONSTANT_ALPHA: Alpha = Alpha::constant(0.8);

/// The first bracket (p-br) with the generic alpha and beta.
pub fn generic_first(body: Body) -> FirstBracket {
    FirstBracket::new(body, GENERIC_ALPHA, GENERIC_BETA)
}

/// A transcendental user-supplied alpha: `1.5 + sin t`, `t = gamma1/gamma2`.
pub const USER_ALPHA: Alpha = Alpha::Function(UserFunction {
    value: |t| 1.5 + t.sin(),
    derivative: f64::cos,
});

/// A transcendental user-supplied beta: `exp(gamma3)`.
pub const USER_BETA: Beta = Beta::Function(UserFunction {
    value: f64::exp,
    derivative: f64::exp,
});

/// The first bracket (p-br) with the two generic choices of alpha and beta: the polynomials
/// [`GENERIC_ALPHA`], [`GENERIC_BETA`] and the functions [`USER_ALPHA`], [`USER_BETA`].
pub fn generic_firsts(body: Body) -> [FirstBracket; 2] {
    [
        generic_first(body),
        FirstBracket::new(body, USER_ALPHA, USER_BETA),
    ]
}

/// The field X of (mg-eq) of a body, in `f64`.
pub fn field_of(body: Body) -> impl Fn(&[f64; 6]) -> [f64; 6] {
    move |x| vector_field(&body, x)
}

/// An integral of the body as a function on the phase space.
pub fn of(body: Body, h: fn(&Body, &[Dual6; 6]) -> Dual6) -> impl Fn(&[Dual6; 6]) -> Dual6 {
    move |x| h(&body, x)
}

/// `H4 = (gamma, gamma)`.
pub fn h4(x: &[Dual6; 6]) -> Dual6 {
    geometric(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sample_is_bounded_before_any_point_is_drawn() {
        let sample = Sample::new(3, 7).unwrap();
        assert_eq!((sample.seed(), sample.count()), (3, 7));
        assert_eq!(sample.points(&body()).len(), 7);
        assert!(Sample::new(3, MAX_POINTS).is_ok());
        for count in [0, MAX_POINTS + 1, 1_000_000_000_000] {
            let e = Sample::new(3, count).unwrap_err().to_string();
            assert!(
                e.contains("points") && e.contains(&count.to_string()),
                "{e}"
            );
            assert!(
                e.contains(&MAX_POINTS.to_string()),
                "the rule states the bound: {e}"
            );
        }
    }
}
