//! Cases: a body, an initial state and integration settings, read from a TOML file.
//!
//! Schema (commands may add tables of their own, listed in [`COMMAND_TABLES`]):
//!
//! ```toml
//! [body]
//! m = 1.0
//! R = 1.0
//! a = 0.3         # or com = [x, y, z], exactly one of the two (a is com = [0, 0, -a])
//! I1 = 0.4
//! I3 = 0.5        # I2 optional, defaults to I1
//! G = 9.81
//! [initial]
//! gamma = [0.29552020666133955, 0.0, 0.955336489125606]
//! omega = [0.5, 0.2, 8.0]   # or M = [...], exactly one of the two
//! normalize = false         # optional: rescale gamma to unit length
//! [integration]     # optional, and so is each key (these are the defaults)
//! t_end = 100.0
//! rtol = 1e-12
//! atol = 1e-12
//! max_steps = 10000000
//! [contact]         # optional: the contact law, rolling without slipping by default
//! law = "sliding"   # "rolling" (the default: the paper's system), "rubber" or "sliding"
//! friction = "viscous"      # optional with "sliding": "viscous" (the default) or "coulomb"
//! mu = 0.3                  # with "sliding": F = -mu N v_P (viscous), |F| <= mu N (coulomb)
//! ```
//!
//! With `law = "rubber"` (rolling without slipping or twisting, `routh_ball::contact::rubber`)
//! the state is the rolling law's; the initial state must not twist,
//! `|omega . gamma| <= 1e-12 |omega|` (`routh_ball::contact::rubber::TWIST_TOLERANCE`), and is
//! refused otherwise, never changed; the case then holds the rubber ball ([`Case::rubber`]).
//!
//! With `law = "sliding"`, `[initial]` may give `velocity = [x, y, z]`, the horizontal velocity
//! of the centre of mass in the body frame (default: at rest); the case then holds the
//! sliding ball and its initial state ([`Case::sliding`], see
//! `routh_ball::contact::sliding`). Only [`Case::load_any_contact`] (`routh simulate`) reads
//! a case of the rubber or the sliding law; every other way of reading a case refuses it, naming the command that can.
//!
//! `G` is optional (default 9.81). Unknown keys and tables anywhere (at the top level, in a
//! table) and missing fields are errors that name the key, the table and the file.

use crate::ball::{AsBall, Ball};
use crate::body::Body;
use crate::contact::rubber::Rubber;
use crate::contact::sliding::{Sliding, DIM};
use crate::contact::{Contact, Friction};
use crate::error::{AppError, AppResult as Result, FileError};
use crate::integrate::Method;
use crate::simulate::{Settings, SettingsBuilder};
use crate::state::{Normalise, State};
use serde::Deserialize;
use std::path::Path;

/// The built-in default case, `cases/default.toml`.
pub const DEFAULT_CASE: &str = include_str!("../../../cases/default.toml");

/// The table `[integration]` as written: optional, and so is each key (defaults:
/// [`Integration::default`]); [`Integration::settings`] builds the case's settings from it.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
struct Integration {
    /// Final time.
    t_end: f64,
    /// Relative tolerance.
    rtol: f64,
    /// Absolute tolerance.
    atol: f64,
    /// Most steps (accepted and rejected) an adaptive integration may attempt, and most
    /// steps of a fixed-step one.
    max_steps: usize,
}

/// Default final time of a case without `t_end`.
pub const DEFAULT_T_END: f64 = 100.0;
/// Default relative and absolute tolerance of a case without `rtol` or `atol`.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;
pub use crate::simulate::DEFAULT_MAX_STEPS;
pub use crate::simulate::{check_option, check_tolerances, MAX_RTOL, MIN_RTOL};

impl Default for Integration {
    fn default() -> Self {
        Integration {
            t_end: DEFAULT_T_END,
            rtol: DEFAULT_TOLERANCE,
            atol: DEFAULT_TOLERANCE,
            max_steps: DEFAULT_MAX_STEPS,
        }
    }
}

impl Integration {
    /// The settings of the table (t_end, rtol, atol, max_steps; the other settings at their
    /// defaults), validated as they are built ([`Settings`]).
    fn settings(self) -> crate::Result<Settings> {
        Settings::builder()
            .t_end(self.t_end)
            .tolerances(self.rtol, self.atol)
            .max_steps(self.max_steps)
            .build()
    }
}

/// A validated case: body, initial state, integration settings, and the raw TOML document
/// for the tables that other commands read.
#[derive(Debug, Clone)]
pub struct Case {
    /// Where it came from (a path or `<built-in default>`).
    pub source: String,
    /// The ball (the model: any moments, any centre of mass).
    pub ball: Ball,
    /// The initial state.
    pub initial: State,
    /// The integration settings of the table `[integration]` (t_end, rtol, atol, max_steps;
    /// the others at their defaults), validated when the case was read.
    pub integration: Settings,
    /// The whole document, for command-specific tables.
    pub document: toml::Table,
    /// The sliding ball and its initial state, with `[contact] law = "sliding"`; `None` for
    /// the rolling law (the default).
    pub sliding: Option<SlidingStart>,
    /// The rubber ball and its initial state, with `[contact] law = "rubber"`; `None` for the
    /// other laws.
    pub rubber: Option<RubberStart>,
}

/// A rubber ball and its state at t = 0, on the constraint ([`Rubber::start`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RubberStart {
    /// The ball.
    pub model: Rubber,
    /// The state `(gamma, M)` at t = 0.
    pub x0: [f64; 6],
}

/// A sliding ball and its state at t = 0, validated ([`Sliding::initial`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlidingStart {
    /// The ball and its friction.
    pub model: Sliding,
    /// The state `(gamma, omega, v, W)` at t = 0.
    pub y0: [f64; DIM],
}

/// Which contact laws the command reading a case integrates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Laws {
    /// The rolling law only: a case of another law is refused.
    Rolling,
    /// Every law of [`Contact`].
    Any,
}

/// The table `[contact]` as written.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactTable {
    #[serde(default = "rolling")]
    law: String,
    friction: Option<String>,
    mu: Option<f64>,
}

fn rolling() -> String {
    "rolling".into()
}

impl ContactTable {
    /// The contact law of the table, validated ([`Contact::sliding`]).
    fn contact(&self) -> std::result::Result<Contact, String> {
        match (self.law.as_str(), &self.friction, self.mu) {
            ("rolling", None, None) => Ok(Contact::Rolling),
            ("rubber", None, None) => Ok(Contact::Rubber),
            (law @ ("rolling" | "rubber"), _, _) => Err(format!(
                "in [contact]: `friction` and `mu` belong to law = \"sliding\"; \
                 law = \"{law}\" has no friction"
            )),
            ("sliding", friction, mu) => {
                let name = friction.as_deref().unwrap_or("viscous");
                let friction = Friction::named(name).ok_or_else(|| {
                    format!(
                        "in [contact]: unknown friction = \"{name}\"; known: \"viscous\", \
                         \"coulomb\""
                    )
                })?;
                let mu = mu.ok_or("in [contact]: law = \"sliding\" needs `mu`")?;
                Contact::sliding(friction, mu).map_err(|e| format!("in [contact]: {e}"))
            }
            (other, _, _) => Err(format!(
                "in [contact]: unknown law = \"{other}\"; known: \"rolling\", \"rubber\", \
                 \"sliding\""
            )),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
struct BodyTable {
    m: f64,
    #[serde(rename = "R")]
    radius: f64,
    a: Option<f64>,
    com: Option<[f64; 3]>,
    #[serde(rename = "I1")]
    i1: f64,
    #[serde(rename = "I2")]
    i2: Option<f64>,
    #[serde(rename = "I3")]
    i3: f64,
    #[serde(rename = "G", default = "standard_gravity")]
    gravity: f64,
}

/// The gravitational acceleration of a case without `G`: 9.81 (the units of the case are
/// then metres and seconds).
pub const DEFAULT_G: f64 = 9.81;

fn standard_gravity() -> f64 {
    DEFAULT_G
}

#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
struct InitialTable {
    gamma: [f64; 3],
    omega: Option<[f64; 3]>,
    #[serde(rename = "M")]
    m: Option<[f64; 3]>,
    #[serde(default)]
    normalize: bool,
    velocity: Option<[f64; 3]>,
}

/// The tables this module owns.
const OWN_TABLES: [&str; 4] = ["body", "initial", "integration", "contact"];

/// Top-level tables of the commands that read their own (by [`Case::extra_table`]); any
/// other top-level key or table is refused.
pub const COMMAND_TABLES: [&str; 1] = ["sweep"];

impl Case {
    /// The built-in default case.
    pub fn default_case() -> Result<Self> {
        Self::parse(DEFAULT_CASE, "<built-in default>")
    }

    /// Read and validate a case file of the rolling law (a case of another contact law is
    /// refused: [`Case::load_any_contact`] reads those).
    pub fn from_file(path: &Path) -> Result<Self> {
        Self::read_file(path, Laws::Rolling)
    }

    fn read_file(path: &Path, laws: Laws) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| FileError::Case {
            file: path.display().to_string(),
            message: format!("cannot read: {e}"),
        })?;
        Self::parse_in(&text, &path.display().to_string(), laws)
    }

    /// The case in `path`, or the built-in default when `None` (the rolling law only, as
    /// [`Case::from_file`]).
    pub fn load(path: Option<&Path>) -> Result<Self> {
        match path {
            Some(p) => Self::from_file(p),
            None => Self::default_case(),
        }
    }

    /// [`Case::load`] for a command that integrates every contact law (`routh simulate`): a
    /// case with `[contact] law = "sliding"` is read, its [`Case::sliding`] set.
    pub fn load_any_contact(path: Option<&Path>) -> Result<Self> {
        match path {
            Some(p) => Self::read_file(p, Laws::Any),
            None => Self::default_case(),
        }
    }

    /// Parse and validate case text of the rolling law; `source` names the file in error
    /// messages.
    pub fn parse(text: &str, source: &str) -> Result<Self> {
        Self::parse_in(text, source, Laws::Rolling)
    }

    /// [`Case::parse`] for every contact law (as [`Case::load_any_contact`]).
    pub fn parse_any_contact(text: &str, source: &str) -> Result<Self> {
        Self::parse_in(text, source, Laws::Any)
    }

    fn parse_in(text: &str, source: &str, laws: Laws) -> Result<Self> {
        let document: toml::Table = text.parse().map_err(|e: toml::de::Error| FileError::Case {
            file: source.to_string(),
            message: format!("malformed TOML: {e}"),
        })?;
        Self::from_document_unlabelled(document, source, laws).map_err(|e| labelled(e, source))
    }

    /// Validate a parsed case document of the rolling law (as [`Case::parse`] does with
    /// text); `source` names the file in error messages.
    pub fn from_document(document: toml::Table, source: &str) -> Result<Self> {
        Self::from_document_unlabelled(document, source, Laws::Rolling)
            .map_err(|e| labelled(e, source))
    }

    fn from_document_unlabelled(document: toml::Table, source: &str, laws: Laws) -> Result<Self> {
        let values = CaseValues::read(&document, source)?;
        let ball = values.ball(source)?;
        let initial = values.state(&ball, source)?;
        let integration = values.integration.settings()?;
        if values.contact != Contact::Rolling && laws == Laws::Rolling {
            return Err(FileError::Case {
                file: source.to_string(),
                message: format!(
                    "[contact] law = \"{}\" is integrated by `routh simulate` (every law) and \
                     `routh sweep` (the rolling and sliding laws) only (so far); this command \
                     integrates the rolling law",
                    values.contact.law()
                ),
            }
            .into());
        }
        Ok(Case {
            source: source.to_string(),
            rubber: values.rubber(&ball, &initial)?,
            sliding: values.sliding(&ball, &initial)?,
            ball,
            initial,
            integration,
            document,
        })
    }

    /// The ball as a [`Body`] (the paper's parameters, centre of mass on e3); an
    /// [`crate::error::RouthError::OffAxis`] naming `what` for a centre of mass off the axis.
    pub fn body(&self, what: &'static str) -> crate::Result<Body> {
        self.ball.axial_body(what)
    }

    /// A command's own table `[name]`, if present, deserialised with unknown keys rejected
    /// by the target type.
    pub fn extra_table<T: serde::de::DeserializeOwned>(&self, name: &str) -> Result<Option<T>> {
        match self.document.get(name) {
            None => Ok(None),
            Some(_) => table(&self.document, name).map(Some).map_err(|message| {
                FileError::Case {
                    file: self.source.clone(),
                    message,
                }
                .into()
            }),
        }
    }
}

/// The settings given beside a case file (the command line's `--method`, `--t-end`, `--rtol`,
/// `--atol`, `--max-steps`; Python's keywords) that override its `[integration]` table; each
/// left `None` keeps the case's value (the method: DOP853, a case file names none).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// The integrator.
    pub method: Option<Method>,
    /// Final time.
    pub t_end: Option<f64>,
    /// Relative tolerance.
    pub rtol: Option<f64>,
    /// Absolute tolerance.
    pub atol: Option<f64>,
    /// The most steps of one run.
    pub max_steps: Option<usize>,
}

impl Overrides {
    /// Every setting of `settings` as an override (method, t_end, tolerances, step limit): a
    /// case built from another's document runs with those settings ([`crate::chart`],
    /// [`crate::inversion`]).
    pub fn of(settings: &Settings) -> Self {
        Overrides {
            method: Some(settings.method()),
            t_end: Some(settings.t_end()),
            rtol: Some(settings.rtol()),
            atol: Some(settings.atol()),
            max_steps: Some(settings.max_steps()),
        }
    }

    /// The settings of `case` with these overrides, to be completed (projection, samples) and
    /// built: [`SettingsBuilder::build`] checks them, with the same rules and messages for
    /// every command, the sweep and Python.
    pub fn applied_to(&self, case: &Case) -> SettingsBuilder {
        let base = case.integration;
        base.to_builder()
            .method(self.method.unwrap_or(base.method()))
            .t_end(self.t_end.unwrap_or(base.t_end()))
            .tolerances(
                self.rtol.unwrap_or(base.rtol()),
                self.atol.unwrap_or(base.atol()),
            )
            .max_steps(self.max_steps.unwrap_or(base.max_steps()))
    }
}

/// An error met reading the case `source`, as an error of that case file (one that already
/// is one is left as it is).
fn labelled(e: AppError, source: &str) -> AppError {
    match e {
        AppError::File(FileError::Case { .. }) => e,
        other => FileError::Case {
            file: source.to_string(),
            message: other.to_string(),
        }
        .into(),
    }
}

/// A case's own tables as typed values, read but not yet validated: what a sweep changes
/// from run to run ([`crate::sweep`]) before it builds each run's ball and state with the
/// same validation as [`Case::from_document`], without a TOML document per run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaseValues {
    body: BodyTable,
    initial: InitialTable,
    integration: Integration,
    contact: Contact,
}

impl CaseValues {
    /// The tables `[body]`, `[initial]` and `[integration]` of `document` (unknown keys and
    /// tables refused, as by [`Case::parse`]); `source` names the file in error messages.
    pub fn read(document: &toml::Table, source: &str) -> Result<Self> {
        let err = |message: String| FileError::Case {
            file: source.to_string(),
            message,
        };
        reject_unknown_keys(document).map_err(err)?;
        let body: BodyTable = table(document, "body").map_err(err)?;
        let initial: InitialTable = table(document, "initial").map_err(err)?;
        let integration = match document.get("integration") {
            None => Integration::default(),
            Some(_) => table(document, "integration").map_err(err)?,
        };
        let contact = match document.get("contact") {
            None => Contact::Rolling,
            Some(_) => table::<ContactTable>(document, "contact")
                .and_then(|t| t.contact())
                .map_err(err)?,
        };
        if initial.velocity.is_some() && !matches!(contact, Contact::Sliding { .. }) {
            return Err(err(format!(
                "in [initial]: `velocity` belongs to a sliding contact ([contact] law = \
                 \"sliding\"); a rolling ball's velocity follows from omega (law = \"{}\")",
                contact.law()
            ))
            .into());
        }
        Ok(CaseValues {
            body,
            initial,
            integration,
            contact,
        })
    }

    /// The contact law of `[contact]` (rolling without it).
    pub fn contact(&self) -> Contact {
        self.contact
    }

    /// Set the coefficient `mu` of a sliding contact to `value`, checked as in `[contact]`
    /// ([`Contact::sliding`]); refused for the other laws, which have no friction.
    pub fn set_mu(&mut self, value: f64) -> std::result::Result<(), String> {
        match self.contact {
            Contact::Sliding { friction, .. } => {
                self.contact = Contact::sliding(friction, value).map_err(|e| e.to_string())?;
                Ok(())
            }
            other => Err(format!(
                "needs [contact] law = \"sliding\" (law = \"{}\" has no friction)",
                other.law()
            )),
        }
    }

    /// The rubber ball `ball` and its state on the constraint from `initial`, with `[contact]
    /// law = "rubber"` ([`Rubber::start`] refuses a twisting state); `None` for the other laws.
    pub fn rubber(&self, ball: &Ball, initial: &State) -> Result<Option<RubberStart>> {
        if self.contact != Contact::Rubber {
            return Ok(None);
        }
        let model = Rubber::new(ball);
        let x0 = model.start(initial)?;
        Ok(Some(RubberStart { model, x0 }))
    }

    /// The sliding ball `ball` and its state from `initial` and `[initial] velocity` (the
    /// centre of mass at rest without it), with `[contact] law = "sliding"`, validated
    /// ([`Sliding::initial`]); `None` for the other laws.
    pub fn sliding(&self, ball: &Ball, initial: &State) -> Result<Option<SlidingStart>> {
        let Contact::Sliding { friction, mu } = self.contact else {
            return Ok(None);
        };
        let model = Sliding::with_friction(ball, friction, mu)?;
        let y0 = model.initial(
            initial.gamma(),
            initial.omega(ball),
            self.initial.velocity.unwrap_or([0.0; 3]),
            Normalise::Reject,
        )?;
        Ok(Some(SlidingStart { model, y0 }))
    }

    /// Set the key `key` of `[body]` (`m`, `R`, `a`, `I1`, `I2`, `I3` or `G`) to `value`.
    pub fn set_body(&mut self, key: &str, value: f64) -> std::result::Result<(), String> {
        let body = &mut self.body;
        match key {
            "m" => body.m = value,
            "R" => body.radius = value,
            "a" => body.a = Some(value),
            "I1" => body.i1 = value,
            "I2" => body.i2 = Some(value),
            "I3" => body.i3 = value,
            "G" => body.gravity = value,
            _ => return Err(format!("[body] has no key `{key}`")),
        }
        Ok(())
    }

    /// Set the component `i` of the initial gamma to `value`.
    pub fn set_gamma(&mut self, i: usize, value: f64) {
        self.initial.gamma[i] = value;
    }

    /// Set the component `i` of the initial omega to `value`; refused when the case gives
    /// M instead of omega.
    pub fn set_omega(&mut self, i: usize, value: f64) -> std::result::Result<(), String> {
        let omega = self
            .initial
            .omega
            .as_mut()
            .ok_or("needs `omega = [x, y, z]` in [initial]")?;
        omega[i] = value;
        Ok(())
    }

    /// The ball of `[body]`, validated (its parameters, and that its inertia can be inverted
    /// in f64: [`crate::range::check_body`]); `source` names the file in error messages.
    pub fn ball(&self, source: &str) -> Result<Ball> {
        self.unlabelled_ball(source)
            .map_err(|e| labelled(e, source))
    }

    fn unlabelled_ball(&self, source: &str) -> Result<Ball> {
        let body = &self.body;
        let inertia = [body.i1, body.i2.unwrap_or(body.i1), body.i3];
        let ball = match (body.a, body.com) {
            (Some(a), None) => Body::new(
                body.m,
                body.radius,
                a,
                inertia[0],
                inertia[1],
                inertia[2],
                body.gravity,
            )?
            .ball(),
            (None, Some(com)) => Ball::new(body.m, body.radius, inertia, com, body.gravity)?,
            _ => {
                return Err(FileError::Case {
                    file: source.to_string(),
                    message: "[body] needs exactly one of the keys `a` and `com`".into(),
                }
                .into());
            }
        };
        crate::range::check_body(&ball)?;
        Ok(ball)
    }

    /// The state of `[initial]` for `ball`, validated (a unit gamma, or rescaled with
    /// `normalize = true`; its energy and field within f64: [`crate::range::check_state`]);
    /// `source` names the file in error messages.
    pub fn state(&self, ball: &Ball, source: &str) -> Result<State> {
        self.unlabelled_state(ball, source)
            .map_err(|e| labelled(e, source))
    }

    fn unlabelled_state(&self, ball: &Ball, source: &str) -> Result<State> {
        let initial = &self.initial;
        let normalise = if initial.normalize {
            Normalise::Rescale
        } else {
            Normalise::Reject
        };
        let state = match (initial.omega, initial.m) {
            (Some(omega), None) => State::from_omega(ball, initial.gamma, omega, normalise)?,
            (None, Some(m)) => State::new(initial.gamma, m, normalise)?,
            _ => {
                return Err(FileError::Case {
                    file: source.to_string(),
                    message: "[initial] needs exactly one of the keys `omega` and `M`".into(),
                }
                .into());
            }
        };
        crate::range::check_state(ball, &state)?;
        Ok(state)
    }
}

/// Refuse a top-level key that is not one of the known tables: a key such as `t_end` written
/// above the first table, or an unknown table such as `[extra]`.
fn reject_unknown_keys(document: &toml::Table) -> std::result::Result<(), String> {
    for (key, value) in document {
        let known = OWN_TABLES.contains(&key.as_str()) || COMMAND_TABLES.contains(&key.as_str());
        if known && value.is_table() {
            continue;
        }
        let hint = if value.is_table() {
            format!("unknown table [{key}]")
        } else if known {
            format!("`{key}` must be a table [{key}]")
        } else {
            format!(
                "unknown key `{key}` at the top level, outside any table (keys belong in \
                 [body], [initial] or [integration], after the table's header)"
            )
        };
        return Err(format!(
            "{hint}; known tables: {}",
            OWN_TABLES.map(|t| format!("[{t}]")).join(", ")
        ));
    }
    Ok(())
}

/// The table `[name]` of `document` deserialised as `T`, the one place where a case's tables
/// meet serde: an error names the table, and a type or length error (whose text from the
/// parser names neither the key nor the value) the key and its value as well, with the
/// parser's text as the rule ([`key_in_error`]).
fn table<T: serde::de::DeserializeOwned>(
    document: &toml::Table,
    name: &str,
) -> std::result::Result<T, String> {
    let value = document
        .get(name)
        .ok_or_else(|| format!("missing table [{name}]"))?;
    let Some(entries) = value.as_table() else {
        return Err(format!("`{name}` must be a table [{name}]"));
    };
    deserialise::<T>(entries).map_err(|rule| match key_in_error::<T>(entries, &rule) {
        Some((key, value)) => format!("in [{name}]: invalid {key} = {value}: {rule}"),
        None => format!("in [{name}]: {rule}"),
    })
}

/// `entries` deserialised as `T`, or the parser's message.
fn deserialise<T: serde::de::DeserializeOwned>(
    entries: &toml::Table,
) -> std::result::Result<T, String> {
    toml::Value::Table(entries.clone())
        .try_into()
        .map_err(|e: toml::de::Error| e.message().to_string())
}

/// The key (and its value) whose value causes the error `rule` of deserialising `entries` as
/// `T`. serde reads the entries in order and stops at the first error, so the culprit is the
/// entry whose addition to the entries before it first gives that error; none for a missing
/// key (serde's "missing field `R`", which names it, comes after all entries are read, so
/// the last entry would seem to cause it).
fn key_in_error<'a, T: serde::de::DeserializeOwned>(
    entries: &'a toml::Table,
    rule: &str,
) -> Option<(&'a String, &'a toml::Value)> {
    if rule.starts_with("missing field") {
        return None;
    }
    let mut before = toml::Table::new();
    for (key, value) in entries {
        before.insert(key.clone(), value.clone());
        if deserialise::<T>(&before).err().as_deref() == Some(rule) {
            return Some((key, value));
        }
    }
    None
}

/// Every refusal of a case file names the table, the key, the value and the rule.
#[cfg(test)]
mod messages;

#[cfg(test)]
mod tests {
    use super::*;

    /// Overrides replace what they give and keep the rest from the case's own `[integration]`
    /// (not from the defaults: the case below sets every key to another value).
    #[test]
    fn overrides_replace_only_what_they_give() {
        let text = DEFAULT_CASE.replace(
            "t_end = 100.0\nrtol = 1e-12\natol = 1e-12",
            "t_end = 7.0\nrtol = 1e-9\natol = 1e-10\nmax_steps = 1234",
        );
        let case = Case::parse(&text, "test").unwrap();
        let kept = Overrides::default().applied_to(&case).build().unwrap();
        assert_eq!(kept, case.integration);
        assert_eq!(
            (kept.t_end(), kept.rtol(), kept.atol(), kept.max_steps()),
            (7.0, 1e-9, 1e-10, 1234)
        );
        let given = Overrides {
            method: Some(Method::Vern9),
            t_end: Some(2.0),
            rtol: Some(1e-8),
            atol: Some(1e-11),
            max_steps: Some(99),
        };
        let changed = given.applied_to(&case).build().unwrap();
        assert_eq!(
            (
                changed.method(),
                changed.t_end(),
                changed.rtol(),
                changed.atol(),
                changed.max_steps()
            ),
            (Method::Vern9, 2.0, 1e-8, 1e-11, 99)
        );
        let refused = Overrides {
            t_end: Some(-1.0),
            ..Overrides::default()
        };
        let err = refused.applied_to(&case).build().unwrap_err();
        assert!(err.to_string().contains("t_end"), "{err}");
    }
}
