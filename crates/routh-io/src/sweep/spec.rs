//! The `[sweep]` table of a case file: which quantities vary and how.
//!
//! ```toml
//! [sweep]
//! tilt = { range = [0.05, 1.5], n = 50 }          # a grid axis: n points, ends included
//! spin = { values = [4.0, 8.0] }                  # a grid axis: listed values
//! "body.a" = { values = [0.3] }
//! ```
//!
//! is a grid, the Cartesian product of its axes (100 runs here). A random design over a box
//! gives every axis a `range` only and adds `samples = N`, `design = "sobol" | "latin" |
//! "uniform"` (default `sobol`) and `seed = S` (default 0):
//!
//! ```toml
//! [sweep]
//! samples = 1024
//! design = "latin"
//! seed = 7
//! tilt = { range = [0.05, 1.5] }
//! "body.G" = { range = [0.1, 100.0], scale = "log" }
//! ```
//!
//! `scale = "log"` spaces a range geometrically (both ends > 0). The quantities are the body
//! keys `body.m`, `body.R`, `body.a`, `body.I1`, `body.I2`, `body.I3`, `body.G`; `tilt` (the
//! initial gamma becomes (sin tilt, 0, cos tilt)); `spin` (omega3); `omega1`, `omega2`,
//! `omega3`; `gamma1`, `gamma2`, `gamma3`. The initial omega components need a case whose
//! `[initial]` gives `omega` (not `M`). `contact.mu`, the friction coefficient, needs a case
//! of `[contact] law = "sliding"` (each run is then a sliding run: [`super::contact`]). Axes are taken in the order of their keys sorted as
//! text, which is also the order of their columns. The key `columns = [...]`, the columns of
//! the table, is [`super::columns`]'s.

use serde::Deserialize;

/// The most runs of a sweep, on a grid (the product of its axes' points, and each axis) or a
/// random design (`samples`), refused before any value is built: a run takes milliseconds to
/// seconds, so 10^6 runs are hours to weeks of a core, and their table about 0.5 GB of CSV
/// (and, with `--json`, about 2 GB of rows kept in memory until printed).
pub const MAX_RUNS: u64 = 1_000_000;

/// The rule of [`MAX_RUNS`], as the refusals state it.
const MAX_RUNS_RULE: &str = "a sweep has at most 1000000 runs (a run takes milliseconds to \
                             seconds: 10^6 runs are hours to weeks of a core)";

/// A `[sweep]` table that cannot be run, refused before any run starts; it names the key
/// and the value. [`crate::sweep::Sweep::new`] reports it as an error of the case file.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("[sweep] key `{key}` = {value}: {rule}")]
pub struct Refusal {
    /// The key of the `[sweep]` table.
    pub key: String,
    /// The offending value, as text.
    pub value: String,
    /// What is wrong.
    pub rule: String,
}

/// Shorthand for the checks of a `[sweep]` table.
pub type Result<T> = std::result::Result<T, Refusal>;

/// A quantity that a sweep can vary.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// A key of the `[body]` table (`m`, `R`, `a`, `I1`, `I2`, `I3`, `G`).
    Body(&'static str),
    /// The initial tilt theta: gamma = (sin theta, 0, cos theta).
    Tilt,
    /// The initial spin omega3 (same as `omega3`).
    Spin,
    /// A component (0, 1, 2) of the initial angular velocity.
    Omega(usize),
    /// A component (0, 1, 2) of the initial gamma.
    Gamma(usize),
    /// The friction coefficient `mu` of a sliding contact (`contact.mu`).
    Mu,
}

const BODY_KEYS: [&str; 7] = ["m", "R", "a", "I1", "I2", "I3", "G"];

impl Quantity {
    /// The quantity named `key` in the `[sweep]` table, if any.
    pub fn from_key(key: &str) -> Option<Self> {
        if let Some(name) = key.strip_prefix("body.") {
            return BODY_KEYS
                .iter()
                .find(|k| **k == name)
                .map(|k| Quantity::Body(k));
        }
        let component = |prefix: &str| {
            key.strip_prefix(prefix)
                .and_then(|i| ["1", "2", "3"].iter().position(|c| *c == i))
        };
        match key {
            "contact.mu" => Some(Quantity::Mu),
            "tilt" => Some(Quantity::Tilt),
            "spin" => Some(Quantity::Spin),
            _ => component("omega")
                .map(Quantity::Omega)
                .or_else(|| component("gamma").map(Quantity::Gamma)),
        }
    }

    /// Whether the quantity sets the initial gamma (tilt and the gamma components exclude
    /// each other).
    fn sets_gamma(self) -> bool {
        matches!(self, Quantity::Tilt | Quantity::Gamma(_))
    }

    /// Whether the quantity sets omega3 (`spin` and `omega3` exclude each other).
    fn sets_spin(self) -> bool {
        matches!(self, Quantity::Spin | Quantity::Omega(2))
    }
}

/// How the points of an axis are spaced on its range.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Equal differences.
    Linear,
    /// Equal ratios (both ends > 0).
    Log,
}

impl Scale {
    /// The point at fraction `u` of `[lo, hi]` (u = 0 gives lo, u = 1 gives hi exactly).
    pub fn at(self, lo: f64, hi: f64, u: f64) -> f64 {
        if u == 0.0 {
            return lo;
        }
        if u == 1.0 {
            return hi;
        }
        match self {
            Scale::Linear => lo + (hi - lo) * u,
            Scale::Log => (lo.ln() + (hi.ln() - lo.ln()) * u).exp(),
        }
    }
}

/// One varied quantity: its name as in the table (also its column), and its values (a grid
/// axis) or its range (a random design).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The key, as written in `[sweep]`.
    pub name: String,
    /// The quantity.
    pub quantity: Quantity,
    /// The points or the box side.
    pub points: Points,
}

/// The points of an axis.
#[derive(Debug, Clone, PartialEq)]
pub enum Points {
    /// Grid values.
    Values(Vec<f64>),
    /// A range sampled by a random design.
    Range {
        /// Lower end.
        lo: f64,
        /// Upper end.
        hi: f64,
        /// Spacing.
        scale: Scale,
    },
}

impl Points {
    /// The number of points on a grid axis (a range of a random design counts as one).
    pub fn count(&self) -> u64 {
        match self {
            Points::Values(v) => v.len() as u64,
            Points::Range { .. } => 1,
        }
    }
}

/// A random design over a box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RandomDesign {
    /// Sobol's low-discrepancy sequence (Joe–Kuo direction numbers), digitally shifted by
    /// the seed (no shift for seed 0).
    Sobol,
    /// A Latin hypercube: each axis cut into `samples` equal strata, each stratum used once.
    Latin,
    /// Independent uniform points.
    Uniform,
}

/// How the runs are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plan {
    /// The Cartesian product of the axes' values.
    Grid,
    /// `samples` points of a random design.
    Random {
        /// The design.
        design: RandomDesign,
        /// The number of runs.
        samples: u64,
        /// The seed.
        seed: u64,
    },
}

/// A parsed and checked `[sweep]` table.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// The axes, in the order of their keys.
    pub axes: Vec<Axis>,
    /// Grid or random design.
    pub plan: Plan,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct AxisTable {
    values: Option<Vec<f64>>,
    range: Option<Vec<f64>>,
    n: Option<i64>,
    scale: Option<String>,
}

/// A [`Refusal`] of `key` = `value`.
pub fn refuse(key: &str, value: impl std::fmt::Display, rule: &str) -> Refusal {
    Refusal {
        key: key.to_string(),
        value: value.to_string(),
        rule: rule.to_string(),
    }
}

/// The texts of the `[sweep]` key `key`, whose value `listed` must be a list of texts (such
/// as `columns` and `events`), else a [`Refusal`] with `rule`.
pub fn texts<'v>(key: &str, listed: &'v toml::Value, rule: &str) -> Result<Vec<&'v str>> {
    listed
        .as_array()
        .and_then(|a| a.iter().map(|v| v.as_str()).collect::<Option<Vec<_>>>())
        .ok_or_else(|| refuse(key, listed, rule))
}

fn integer(key: &str, value: &toml::Value) -> Result<i64> {
    value
        .as_integer()
        .ok_or_else(|| refuse(key, value, "must be an integer"))
}

impl Spec {
    /// Parse and check the `[sweep]` table: unknown keys, empty ranges, n = 0, empty value
    /// lists, non-finite numbers, and conflicting quantities are refused, naming the key and
    /// the value.
    pub fn parse(table: &toml::Table) -> Result<Self> {
        let mut samples = None;
        let mut design = None;
        let mut seed = 0u64;
        let mut axes = Vec::new();
        for (key, value) in table {
            match key.as_str() {
                "samples" => {
                    let n = integer(key, value)?;
                    if n <= 0 {
                        return Err(refuse(key, n, "must be >= 1"));
                    }
                    if n as u64 > MAX_RUNS {
                        return Err(refuse(key, n, MAX_RUNS_RULE));
                    }
                    samples = Some(n as u64);
                }
                "design" => {
                    design = Some(match value.as_str() {
                        Some("sobol") => RandomDesign::Sobol,
                        Some("latin") => RandomDesign::Latin,
                        Some("uniform") => RandomDesign::Uniform,
                        _ => {
                            return Err(refuse(
                                key,
                                value,
                                "must be \"sobol\", \"latin\" or \"uniform\"",
                            ))
                        }
                    })
                }
                "seed" => {
                    let s = integer(key, value)?;
                    if s < 0 {
                        return Err(refuse(key, s, "must be >= 0"));
                    }
                    seed = s as u64;
                }
                _ => axes.push(Self::axis(key, value, table.contains_key("samples"))?),
            }
        }
        if axes.is_empty() {
            return Err(refuse(
                "[sweep]",
                "(no quantity)",
                "needs at least one quantity to vary",
            ));
        }
        for (i, a) in axes.iter().enumerate() {
            for b in &axes[..i] {
                let clash = (a.quantity.sets_gamma()
                    && b.quantity.sets_gamma()
                    && (a.quantity == Quantity::Tilt || b.quantity == Quantity::Tilt))
                    || (a.quantity.sets_spin() && b.quantity.sets_spin());
                if clash {
                    return Err(refuse(
                        &a.name,
                        format!("(with `{}`)", b.name),
                        "sets the same initial quantity as another key: keep one of them",
                    ));
                }
            }
        }
        let plan = match (samples, design) {
            (None, None) => Plan::Grid,
            (None, Some(_)) => {
                return Err(refuse(
                    "design",
                    table["design"].clone(),
                    "needs `samples = N` (a grid has no design key)",
                ))
            }
            (Some(samples), design) => Plan::Random {
                design: design.unwrap_or(RandomDesign::Sobol),
                samples,
                seed,
            },
        };
        if plan == Plan::Grid && table.contains_key("seed") {
            return Err(refuse(
                "seed",
                seed,
                "needs `samples = N` (a grid is not random)",
            ));
        }
        let spec = Spec { axes, plan };
        if spec.runs() > MAX_RUNS {
            let sizes: Vec<String> = spec
                .axes
                .iter()
                .map(|a| format!("{} ({})", a.name, a.points.count()))
                .collect();
            return Err(refuse(
                "[sweep]",
                format!("a grid of {} runs: {}", spec.runs(), sizes.join(" x ")),
                MAX_RUNS_RULE,
            ));
        }
        Ok(spec)
    }

    fn axis(key: &str, value: &toml::Value, random: bool) -> Result<Axis> {
        let quantity = Quantity::from_key(key).ok_or_else(|| {
            refuse(
                key,
                value,
                "unknown key: expected body.m, body.R, body.a, body.I1, body.I2, body.I3, \
                 body.G, tilt, spin, omega1..3, gamma1..3, contact.mu, samples, design, seed or \
                 columns",
            )
        })?;
        let t: AxisTable = value.clone().try_into().map_err(|e: toml::de::Error| {
            refuse(
                key,
                value,
                &format!(
                    "expected {{ values = [...] }} or {{ range = [lo, hi], n = N }}: {}",
                    e.message()
                ),
            )
        })?;
        let scale = match t.scale.as_deref() {
            None | Some("linear") => Scale::Linear,
            Some("log") => Scale::Log,
            Some(other) => return Err(refuse(key, other, "scale must be \"linear\" or \"log\"")),
        };
        let finite = |v: &[f64]| -> Result<()> {
            match v.iter().find(|x| !x.is_finite()) {
                Some(x) => Err(refuse(key, x, "must be finite")),
                None => Ok(()),
            }
        };
        let points = match (t.values, t.range, t.n) {
            (Some(values), None, None) if !random => {
                if values.is_empty() {
                    return Err(refuse(key, "values = []", "empty list of values"));
                }
                finite(&values)?;
                if t.scale.is_some() {
                    return Err(refuse(key, "scale", "applies to a range, not to values"));
                }
                values
            }
            (None, Some(range), n) => {
                finite(&range)?;
                let [lo, hi] = range[..] else {
                    return Err(refuse(key, format!("{range:?}"), "range must be [lo, hi]"));
                };
                if lo >= hi {
                    return Err(refuse(
                        key,
                        format!("range = [{lo}, {hi}]"),
                        "empty range: needs lo < hi",
                    ));
                }
                if scale == Scale::Log && lo <= 0.0 {
                    return Err(refuse(
                        key,
                        format!("range = [{lo}, {hi}]"),
                        "a log scale needs lo > 0",
                    ));
                }
                match (n, random) {
                    (None, true) => {
                        return Ok(Axis {
                            name: key.to_string(),
                            quantity,
                            points: Points::Range { lo, hi, scale },
                        })
                    }
                    (Some(n), false) if n as u64 > MAX_RUNS => {
                        return Err(refuse(key, format!("n = {n}"), MAX_RUNS_RULE))
                    }
                    (Some(n), false) if n >= 2 => (0..n)
                        .map(|i| scale.at(lo, hi, i as f64 / (n - 1) as f64))
                        .collect(),
                    (Some(n), false) => {
                        return Err(refuse(key, format!("n = {n}"), "a range needs n >= 2"))
                    }
                    (None, false) => {
                        return Err(refuse(key, value, "a grid range needs `n = N`"));
                    }
                    (Some(n), true) => {
                        return Err(refuse(
                            key,
                            format!("n = {n}"),
                            "a random design (samples = N) takes `range` only",
                        ))
                    }
                }
            }
            _ if random => {
                return Err(refuse(
                    key,
                    value,
                    "a random design (samples = N) needs `range = [lo, hi]` only",
                ))
            }
            _ => {
                return Err(refuse(
                    key,
                    value,
                    "needs exactly one of `values = [...]` and `range = [lo, hi]` with `n`",
                ))
            }
        };
        Ok(Axis {
            name: key.to_string(),
            quantity,
            points: Points::Values(points),
        })
    }

    /// The number of runs (saturating at `u64::MAX`: [`Spec::parse`] refuses more than
    /// [`MAX_RUNS`]).
    pub fn runs(&self) -> u64 {
        match self.plan {
            Plan::Grid => self
                .axes
                .iter()
                .map(|a| a.points.count())
                .fold(1u64, u64::saturating_mul),
            Plan::Random { samples, .. } => samples,
        }
    }

    /// The column names of the swept quantities.
    pub fn names(&self) -> Vec<String> {
        self.axes.iter().map(|a| a.name.clone()).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Spec> {
        Spec::parse(&text.parse::<toml::Table>().unwrap())
    }

    #[test]
    fn the_runs_are_bounded_before_any_value_is_built() {
        assert_eq!(
            parse(
                "tilt = { range = [0.1, 1.0], n = 1000 }\nspin = { range = [1.0, 9.0], n = 1000 }"
            )
            .unwrap()
            .runs(),
            MAX_RUNS
        );
        for (text, key, value) in [
            (
                "tilt = { range = [0.1, 1.0], n = 1000000000000 }",
                "tilt",
                "n = 1000000000000",
            ),
            (
                "samples = 1000001\ntilt = { range = [0.1, 1.0] }",
                "samples",
                "1000001",
            ),
            (
                "tilt = { range = [0.1, 1.0], n = 1000 }\nspin = { range = [1.0, 9.0], n = 1001 }",
                "[sweep]",
                "a grid of 1001000 runs: spin (1001) x tilt (1000)",
            ),
        ] {
            let e = parse(text).unwrap_err();
            assert_eq!((e.key.as_str(), e.value.as_str()), (key, value), "{e}");
            assert!(e.rule.contains(&format!("at most {MAX_RUNS} runs")), "{e}");
        }
    }
}
