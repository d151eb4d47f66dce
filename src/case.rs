//! Cases: a body, an initial state and integration settings, read from a TOML file.
//!
//! Schema (other commands add tables of their own, which this module leaves to them):
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
//! [integration]
//! t_end = 100.0
//! rtol = 1e-12
//! atol = 1e-12
//! ```
//!
//! Unknown keys and missing fields are errors that name the key and the file.

use crate::ball::{AsBall, Ball};
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::state::{Normalise, State};
use serde::Deserialize;
use std::path::Path;

/// The built-in default case, `cases/default.toml`.
pub const DEFAULT_CASE: &str = include_str!("../cases/default.toml");

/// Integration settings of a case.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Integration {
    /// Final time.
    pub t_end: f64,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
}

impl Integration {
    /// Check the settings with the one validation of the library,
    /// [`crate::simulate::validate_span`].
    pub fn validate(&self) -> Result<()> {
        crate::simulate::validate_span(self.t_end, self.rtol, self.atol)
    }
}

/// Fail with [`RouthError::Option`] unless `ok`.
pub fn check_option(name: &'static str, value: f64, ok: bool, rule: &'static str) -> Result<()> {
    if ok {
        Ok(())
    } else {
        Err(RouthError::Option {
            name,
            value: value.to_string(),
            rule,
        })
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
    /// The integration settings.
    pub integration: Integration,
    /// The whole document, for command-specific tables.
    pub document: toml::Table,
}

#[derive(Deserialize)]
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
    #[serde(rename = "G")]
    gravity: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InitialTable {
    gamma: [f64; 3],
    omega: Option<[f64; 3]>,
    #[serde(rename = "M")]
    m: Option<[f64; 3]>,
    #[serde(default)]
    normalize: bool,
}

/// The tables this module owns; other top-level tables are left to their commands.
const OWN_TABLES: [&str; 3] = ["body", "initial", "integration"];

impl Case {
    /// The built-in default case.
    pub fn default_case() -> Result<Self> {
        Self::parse(DEFAULT_CASE, "<built-in default>")
    }

    /// Read and validate a case file.
    pub fn from_file(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| RouthError::Case {
            file: path.display().to_string(),
            message: format!("cannot read: {e}"),
        })?;
        Self::parse(&text, &path.display().to_string())
    }

    /// The case in `path`, or the built-in default when `None`.
    pub fn load(path: Option<&Path>) -> Result<Self> {
        match path {
            Some(p) => Self::from_file(p),
            None => Self::default_case(),
        }
    }

    /// Parse and validate case text; `source` names the file in error messages.
    pub fn parse(text: &str, source: &str) -> Result<Self> {
        let document: toml::Table =
            text.parse()
                .map_err(|e: toml::de::Error| RouthError::Case {
                    file: source.to_string(),
                    message: format!("malformed TOML: {e}"),
                })?;
        Self::from_document(document, source)
    }

    /// Validate a parsed case document (as [`Case::parse`] does with text); `source` names
    /// the file in error messages.
    pub fn from_document(document: toml::Table, source: &str) -> Result<Self> {
        Self::from_document_unlabelled(document, source).map_err(|e| match e {
            RouthError::Case { .. } => e,
            other => RouthError::Case {
                file: source.to_string(),
                message: other.to_string(),
            },
        })
    }

    fn from_document_unlabelled(document: toml::Table, source: &str) -> Result<Self> {
        let err = |message: String| RouthError::Case {
            file: source.to_string(),
            message,
        };
        let body: BodyTable = table(&document, "body").map_err(&err)?;
        let initial: InitialTable = table(&document, "initial").map_err(&err)?;
        let integration: Integration = table(&document, "integration").map_err(&err)?;
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
                return Err(err(
                    "[body] needs exactly one of the keys `a` and `com`".into()
                ));
            }
        };
        let normalise = if initial.normalize {
            Normalise::Rescale
        } else {
            Normalise::Reject
        };
        let state = match (initial.omega, initial.m) {
            (Some(omega), None) => State::from_omega(&ball, initial.gamma, omega, normalise)?,
            (None, Some(m)) => State::new(initial.gamma, m, normalise)?,
            _ => {
                return Err(err(
                    "[initial] needs exactly one of the keys `omega` and `M`".into(),
                ));
            }
        };
        integration.validate()?;
        Ok(Case {
            source: source.to_string(),
            ball,
            initial: state,
            integration,
            document,
        })
    }

    /// The ball as a [`Body`] (the paper's parameters, centre of mass on e3); an
    /// [`RouthError::OffAxis`] naming `what` for a centre of mass off the axis.
    pub fn body(&self, what: &'static str) -> Result<Body> {
        self.ball.axial_body(what)
    }

    /// A command's own table `[name]`, if present, deserialised with unknown keys rejected
    /// by the target type.
    pub fn extra_table<T: serde::de::DeserializeOwned>(&self, name: &str) -> Result<Option<T>> {
        match self.document.get(name) {
            None => Ok(None),
            Some(_) => table(&self.document, name)
                .map(Some)
                .map_err(|message| RouthError::Case {
                    file: self.source.clone(),
                    message,
                }),
        }
    }

    /// Check that the document has no top-level table outside `OWN_TABLES` and `extra`.
    pub fn reject_unknown_tables(&self, extra: &[&str]) -> Result<()> {
        for key in self.document.keys() {
            if !OWN_TABLES.contains(&key.as_str()) && !extra.contains(&key.as_str()) {
                return Err(RouthError::Case {
                    file: self.source.clone(),
                    message: format!("unknown key `{key}` at the top level"),
                });
            }
        }
        Ok(())
    }
}

fn table<T: serde::de::DeserializeOwned>(
    document: &toml::Table,
    name: &str,
) -> std::result::Result<T, String> {
    let value = document
        .get(name)
        .ok_or_else(|| format!("missing table [{name}]"))?;
    value
        .clone()
        .try_into()
        .map_err(|e: toml::de::Error| format!("in [{name}]: {}", e.message()))
}
