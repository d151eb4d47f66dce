//! The first Poisson bracket, section 3: the brackets (p-br), their matrix form (p-bv), the
//! special choices (cond), (cond2) of the functions alpha and beta, the coefficients of the
//! decompositions (g-eq1), (g-eq2), and the bivector P_f of the conformally Hamiltonian form.
//!
//! Notation: `s = gamma1^2 + gamma2^2`, `h = R gamma3 + a`, `u = gamma1 M1 + gamma2 M2`,
//! `g = g(gamma)` of (rho), `C2 = (M, r)` and
//! `sigma = m R (m (r, gamma) C2 + I3 u + I1 M3 gamma3)`.

use super::{from_blocks, Bivector, Matrix6};
use crate::body::Body;
use crate::scalar::{dot, lift, split, Real};

/// A user-supplied function of one variable, given with its derivative. It is evaluated on any
/// [`Real`] as its first-order Taylor jet at the real part, `f(t0) + f'(t0) (t - t0)`: exact in
/// value and first derivatives, which is all the Schouten bracket, the Casimir tests and the
/// brackets of functions need (second derivatives of a bivector built from it would be wrong).
#[derive(Debug, Clone, Copy)]
pub struct UserFunction {
    /// `t -> f(t)`.
    pub value: fn(f64) -> f64,
    /// `t -> f'(t)`.
    pub derivative: fn(f64) -> f64,
}

impl UserFunction {
    /// The value at `t`, with the first derivatives of `t` carried through.
    pub fn at<D: Real>(&self, t: D) -> D {
        let t0 = t.re();
        (t - t0) * (self.derivative)(t0) + (self.value)(t0)
    }
}

/// The function `alpha(gamma1/gamma2)` of (p-br), of `t = gamma1/gamma2`.
#[derive(Debug, Clone, Copy)]
pub enum Alpha {
    /// A polynomial `c0 + c1 t + c2 t^2` (`[c, 0, 0]` is the constant alpha of (cond), (cond2)).
    Polynomial([f64; 3]),
    /// Any function of t with its derivative.
    Function(UserFunction),
}

impl Alpha {
    /// A constant alpha.
    pub const fn constant(c: f64) -> Self {
        Alpha::Polynomial([c, 0.0, 0.0])
    }

    /// The value at gamma. A constant alpha is defined everywhere, also at gamma2 = 0.
    pub fn at<D: Real>(&self, gamma: &[D; 3]) -> D {
        let t = gamma[0] / gamma[1];
        match self {
            Alpha::Polynomial([c, 0.0, 0.0]) => lift(*c),
            Alpha::Polynomial(c) => polynomial(c, t),
            Alpha::Function(f) => f.at(t),
        }
    }
}

/// The function `beta` of (p-br).
#[derive(Debug, Clone, Copy)]
pub enum Beta {
    /// A polynomial `c0 + c1 gamma3 + c2 gamma3^2`: a generic `beta(gamma3)`.
    Gamma3([f64; 3]),
    /// Any function of gamma3 with its derivative.
    Function(UserFunction),
    /// (cond): `beta = alpha g (1 + a/(R gamma3))`.
    Cond,
    /// (cond2), read as `beta = alpha g (I1 R gamma3 - I3 (R gamma3 + a)) / (R ((I1 - I3) gamma3
    /// + a m (r, gamma)))` (the printed numerator misses its closing parenthesis).
    Cond2,
    /// The choice of the conformally Hamiltonian section: `beta = -g (r, I r)/(gamma, I r)`.
    Conformal,
}

impl Beta {
    /// The value at gamma, for the given alpha.
    pub fn at<D: Real>(&self, body: &Body, alpha: D, gamma: &[D; 3]) -> D {
        let g = body.routh_g(gamma);
        let r = body.contact_vector(gamma);
        match self {
            Beta::Gamma3(c) => polynomial(c, gamma[2]),
            Beta::Function(f) => f.at(gamma[2]),
            Beta::Cond => alpha * g * (gamma[2].recip() * (body.a() / body.radius()) + 1.0),
            Beta::Cond2 => {
                let num = gamma[2] * (body.i1() * body.radius()) - r[2] * body.i3();
                let den = (gamma[2] * (body.i1() - body.i3())
                    + dot(&r, gamma) * (body.a() * body.m()))
                    * body.radius();
                alpha * g * num / den
            }
            Beta::Conformal => {
                let ir = inertia_times(body, &r);
                -g * dot(&r, &ir) / dot(gamma, &ir)
            }
        }
    }
}

/// `I v = (I1 v1, I2 v2, I3 v3)`.
pub fn inertia_times<D: Real>(body: &Body, v: &[D; 3]) -> [D; 3] {
    [v[0] * body.i1(), v[1] * body.i2(), v[2] * body.i3()]
}

fn polynomial<D: Real>(c: &[f64; 3], t: D) -> D {
    t * t * c[2] + t * c[1] + c[0]
}

/// Which printed text of the first bracket to evaluate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FirstForm {
    /// The list of brackets (p-br).
    Brackets,
    /// The matrix form (p-bv) with its blocks Gamma_alpha, Gamma_beta, M_alpha, M_beta as printed
    /// (the entry `--` of Gamma_beta read as a single minus sign).
    Matrix,
    /// The matrix form (p-bv) corrected: in M_beta the printed `m sigma R (R gamma3 + a)/g^2`,
    /// `m sigma gamma2 R^2/g^2`, `-m sigma gamma1 R^2/g^2` lose the factor `m R` (sigma already
    /// contains it), as in the brackets (p-br).
    MatrixCorrected,
}

/// The first Poisson bracket: (p-br) or (p-bv) with the functions alpha and beta.
#[derive(Debug, Clone, Copy)]
pub struct FirstBracket {
    /// The body (I1 = I2 assumed).
    pub body: Body,
    /// alpha(gamma1/gamma2).
    pub alpha: Alpha,
    /// beta(gamma3) or one of the special choices.
    pub beta: Beta,
    /// Which printed form.
    pub form: FirstForm,
}

impl FirstBracket {
    /// The bracket (p-br) with the given alpha and beta.
    pub fn new(body: Body, alpha: Alpha, beta: Beta) -> Self {
        FirstBracket {
            body,
            alpha,
            beta,
            form: FirstForm::Brackets,
        }
    }

    /// The same functions alpha, beta in another printed form.
    pub fn with_form(self, form: FirstForm) -> Self {
        FirstBracket { form, ..self }
    }

    /// The bivector P_f of the conformally Hamiltonian section: (p-bv) at `alpha = -R`,
    /// `beta = -g (r, I r)/(gamma, I r)`.
    pub fn conformal(body: Body) -> Self {
        FirstBracket::new(body, Alpha::constant(-body.radius()), Beta::Conformal)
    }

    /// The values `(alpha, beta)` at gamma.
    pub fn alpha_beta<D: Real>(&self, gamma: &[D; 3]) -> (D, D) {
        let alpha = self.alpha.at(gamma);
        (alpha, self.beta.at(&self.body, alpha, gamma))
    }
}

/// The quantities shared by (p-br) and (p-bv) at a point.
struct Common<D> {
    s: D,
    h: D,
    u: D,
    g: D,
    sigma: D,
}

impl<D: Real> Common<D> {
    fn at(body: &Body, x: &[D; 6]) -> Self {
        let (gamma, m) = split(x);
        let r = body.contact_vector(&gamma);
        let u = gamma[0] * m[0] + gamma[1] * m[1];
        let c2 = dot(&m, &r);
        let sigma = (dot(&r, &gamma) * c2 * body.m() + u * body.i3() + m[2] * gamma[2] * body.i1())
            * (body.m() * body.radius());
        Common {
            s: gamma[0] * gamma[0] + gamma[1] * gamma[1],
            h: r[2],
            u,
            g: body.routh_g(&gamma),
            sigma,
        }
    }
}

impl Bivector for FirstBracket {
    fn entries<D: Real>(&self, x: &[D; 6]) -> Matrix6<D> {
        let b = &self.body;
        let (gamma, m) = split(x);
        let [g1, g2, g3] = gamma;
        let (alpha, beta) = self.alpha_beta(&gamma);
        let Common { s, h, u, g, sigma } = Common::at(b, x);
        let ag = alpha * g;
        let zero = lift::<D>(0.0);
        let q = h / (s * b.radius());
        let t = g3 / s;
        match self.form {
            FirstForm::Brackets => {
                // {M_j, gamma_i} as printed in (p-br); Gamma_ij = {gamma_i, M_j} = -{M_j, gamma_i}.
                let m1g1 = -ag * g1 * g2 * q + beta * g1 * g2 * t;
                let m1g2 = ag * g1 * g1 * q + beta * g2 * g2 * t;
                let m1g3 = -beta * g2;
                let m2g1 = -ag * g2 * g2 * q - beta * g1 * g1 * t;
                let m2g2 = ag * g1 * g2 * q - beta * g1 * g2 * t;
                let m2g3 = beta * g1;
                let m3g1 = ag * g2;
                let m3g2 = -ag * g1;
                let sg = sigma / (g * g);
                from_blocks(
                    [
                        [-m1g1, -m2g1, -m3g1],
                        [-m1g2, -m2g2, -m3g2],
                        [-m1g3, -m2g3, zero],
                    ],
                    [
                        ag * u * q + beta * (m[2] - t * u - sg * h),
                        -ag * m[1] + beta * sg * b.radius() * g2,
                        ag * m[0] - beta * sg * b.radius() * g1,
                    ],
                )
            }
            FirstForm::Matrix | FirstForm::MatrixCorrected => {
                let gamma_alpha = [
                    [g1 * g2 * q, g2 * g2 * q, -g2],
                    [-g1 * g1 * q, -g1 * g2 * q, g1],
                    [zero, zero, zero],
                ];
                let gamma_beta = [
                    [-g1 * g2 * t, g1 * g1 * t, zero],
                    [-g2 * g2 * t, g1 * g2 * t, zero],
                    [g2, -g1, zero],
                ];
                let m_alpha = [u * q, -m[1], m[0]];
                let printed_factor = match self.form {
                    FirstForm::Matrix => b.m() * b.radius(),
                    _ => 1.0,
                };
                let msr = sigma * printed_factor / (g * g);
                let m_beta = [
                    m[2] - t * u - msr * h,
                    msr * b.radius() * g2,
                    -msr * b.radius() * g1,
                ];
                from_blocks(
                    std::array::from_fn(|i| {
                        std::array::from_fn(|j| ag * gamma_alpha[i][j] + beta * gamma_beta[i][j])
                    }),
                    std::array::from_fn(|k| ag * m_alpha[k] + beta * m_beta[k]),
                )
            }
        }
    }
}

/// The coefficients `(g1, g2)` of (g-eq1) as printed, with the alpha of the bracket (constant
/// under (cond)):
/// `g1 = -((R gamma3 + a) I1 - R gamma3 I3) / (2 alpha g (I1 - I3)(R gamma3 + a))`,
/// `g2 = a / (2 alpha g (I1 - I3)(R gamma3 + a))`.
pub fn g_eq1_coefficients(bracket: &FirstBracket, gamma: &[f64; 3]) -> [f64; 2] {
    let body = &bracket.body;
    let alpha = bracket.alpha.at(gamma);
    let h = body.radius() * gamma[2] + body.a();
    let den = 2.0 * alpha * body.routh_g(gamma) * (body.i1() - body.i3()) * h;
    [
        -(h * body.i1() - body.radius() * gamma[2] * body.i3()) / den,
        body.a() / den,
    ]
}

/// The coefficients `(g^1, g^2)` of (g-eq2) as printed, for constant alpha and beta of (cond2):
/// `g^1 = -1/(2 beta)`, `g^2 = a (M3 - gamma3 u / s) / (alpha I1 (I1 R gamma3 - I3 (R gamma3 + a)))`.
pub fn g_eq2_coefficients(bracket: &FirstBracket, x: &[f64; 6]) -> [f64; 2] {
    let body = &bracket.body;
    let (gamma, m) = split(x);
    let (alpha, beta) = bracket.alpha_beta(&gamma);
    let s = gamma[0] * gamma[0] + gamma[1] * gamma[1];
    let u = gamma[0] * m[0] + gamma[1] * m[1];
    let h = body.radius() * gamma[2] + body.a();
    [
        -0.5 / beta,
        body.a() * (m[2] - gamma[2] * u / s)
            / (alpha * body.i1() * (body.i1() * body.radius() * gamma[2] - body.i3() * h)),
    ]
}
