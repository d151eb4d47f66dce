//! The columns of a sweep's table, and the ones a sweep asks for: a sweep computes only what
//! its table holds (`routh sweep --columns`, `[sweep] columns = [...]`, Python's `columns=`).
//!
//! Every table holds `run`, the swept quantities, the settings, `status`, `message` and the
//! work (`steps`, `rejected`, `rhs_evals`). The other columns come in groups, each with its
//! own cost beyond the integration:
//!
//! | group | columns | what it costs |
//! |---|---|---|
//! | `final` | `final_gamma1..3`, `final_M1..3` | nothing: the integration's end |
//! | `integrals` | `H1 H2 H3 H4 K` x `_initial _final _drift` | the integrals at every step |
//! | `events` | `theta_min theta_max period_events precession_events` | the sign of d gamma3/dt at every step, a located turning point per half period |
//! | `quadrature` | `period_quadrature precession_quadrature` | the quadrature of `routh exact` of every run (Routh sphere only) |
//! | `nutation` | `events`, `quadrature` and their differences `period_difference precession_difference` | both |
//! | `all` | every column (the table of a sweep before `--columns`) | all of the above |
//!
//! The default, [`DEFAULT_GROUPS`], is `final` and `integrals`: the cheap columns. A column
//! can also be named alone; the table keeps the columns' order whatever the order asked.

use super::spec::{refuse, Refusal};
use crate::integrals::INTEGRAL_NAMES;
use crate::row::Kind;

/// What a column needs computed along a run, beyond the integration itself.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Part {
    /// Always written: the settings, status, message and work.
    Run,
    /// The final state.
    Final,
    /// The integrals and their drift, tracked at every step.
    Integrals,
    /// The turning points of the tilt, located along the run ([`super::turning`]).
    Events,
    /// The nutation by quadrature ([`crate::quadrature::ExactSolution`]).
    Quadrature,
    /// Events minus quadrature: both.
    Difference,
}

/// The groups of columns that can be asked for by name, with their parts.
pub const GROUPS: [(&str, &[Part]); 6] = [
    ("final", &[Part::Final]),
    ("integrals", &[Part::Integrals]),
    ("events", &[Part::Events]),
    ("quadrature", &[Part::Quadrature]),
    (
        "nutation",
        &[Part::Events, Part::Quadrature, Part::Difference],
    ),
    (
        "all",
        &[
            Part::Final,
            Part::Integrals,
            Part::Events,
            Part::Quadrature,
            Part::Difference,
        ],
    ),
];

/// The groups of a table when none are asked for: the final state, the integrals and their
/// drift (before `--columns`, a table held every column: ask for `all`).
pub const DEFAULT_GROUPS: [&str; 2] = ["final", "integrals"];

/// One column after `run` and the swept quantities.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Column {
    /// Its name in the table.
    pub name: String,
    /// Its type.
    pub kind: Kind,
    /// What it needs computed.
    pub part: Part,
}

const STATE_NAMES: [&str; 6] = ["gamma1", "gamma2", "gamma3", "M1", "M2", "M3"];

/// Every column after `run` and the swept quantities, in the table's order: the settings,
/// status and message, the work, the final state, each integral's initial and final value
/// and maximal relative drift (null where not an integral), and the nutation from events and
/// from the quadrature.
pub fn catalogue() -> Vec<Column> {
    let column = |name: &str, kind, part| Column {
        name: name.to_string(),
        kind,
        part,
    };
    let mut cols: Vec<Column> = [
        ("t_end", Kind::Float),
        ("rtol", Kind::Float),
        ("atol", Kind::Float),
        ("method", Kind::Text),
        ("status", Kind::Text),
        ("message", Kind::Text),
        ("steps", Kind::Int),
        ("rejected", Kind::Int),
        ("rhs_evals", Kind::Int),
    ]
    .into_iter()
    .map(|(n, k)| column(n, k, Part::Run))
    .collect();
    for name in STATE_NAMES {
        cols.push(column(&format!("final_{name}"), Kind::Float, Part::Final));
    }
    for name in INTEGRAL_NAMES {
        for part in ["initial", "final", "drift"] {
            cols.push(column(
                &format!("{name}_{part}"),
                Kind::Float,
                Part::Integrals,
            ));
        }
    }
    for (name, part) in [
        ("theta_min", Part::Events),
        ("theta_max", Part::Events),
        ("period_events", Part::Events),
        ("period_quadrature", Part::Quadrature),
        ("period_difference", Part::Difference),
        ("precession_events", Part::Events),
        ("precession_quadrature", Part::Quadrature),
        ("precession_difference", Part::Difference),
    ] {
        cols.push(column(name, Kind::Float, part));
    }
    cols
}

/// The columns a sweep's table holds: a subset of [`catalogue`] (bit i for its column i),
/// always with the [`Part::Run`] columns, and the parts they need (bit `part as u8`), known
/// without building the catalogue again for every run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Columns {
    chosen: u64,
    parts: u8,
}

/// A name that is neither a column nor a group: its message lists the valid ones.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown column `{name}`: the groups are {} (default: {}), the columns {} (`run` and the \
     swept quantities are always written)",
    GROUPS.map(|g| g.0).join(", "),
    DEFAULT_GROUPS.join(", "),
    catalogue().into_iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
)]
pub struct UnknownColumn {
    /// The name asked for.
    pub name: String,
}

impl Columns {
    /// The columns named by `names`: groups of [`GROUPS`] and single columns of
    /// [`catalogue`], in any order (the table keeps its own); the [`Part::Run`] columns are
    /// always in.
    pub fn parse<'a>(names: impl IntoIterator<Item = &'a str>) -> Result<Self, UnknownColumn> {
        let all = catalogue();
        let of_parts = |parts: &[Part]| {
            all.iter()
                .enumerate()
                .filter(|(_, c)| parts.contains(&c.part))
                .fold(0u64, |bits, (i, _)| bits | 1 << i)
        };
        let mut chosen = of_parts(&[Part::Run]);
        for name in names {
            let name = name.trim();
            chosen |= match GROUPS.iter().find(|g| g.0 == name) {
                Some((_, parts)) => of_parts(parts),
                None => match all.iter().position(|c| c.name == name) {
                    Some(i) => 1 << i,
                    None => {
                        return Err(UnknownColumn {
                            name: name.to_string(),
                        })
                    }
                },
            };
        }
        let mut columns = Columns { chosen, parts: 0 };
        columns.parts = columns
            .select(all)
            .fold(0, |bits, c| bits | 1 << c.part as u8);
        Ok(columns)
    }

    /// The columns of the `[sweep]` table's key `columns = ["final", "events", ...]`.
    pub fn from_toml(listed: &toml::Value) -> Result<Self, Refusal> {
        let names = listed
            .as_array()
            .and_then(|a| a.iter().map(|v| v.as_str()).collect::<Option<Vec<_>>>())
            .ok_or_else(|| {
                refuse(
                    "columns",
                    listed,
                    "must be a list of column names and groups, such as [\"final\", \"events\"]",
                )
            })?;
        Self::parse(names).map_err(|e| refuse("columns", format!("\"{}\"", e.name), &e.to_string()))
    }

    /// Every column (the table of a sweep before `--columns`).
    pub fn all() -> Self {
        Self::parse(["all"]).expect("a group")
    }

    /// Of the items of [`catalogue`]'s order (a column each), those of the chosen columns.
    pub fn select<T>(&self, items: impl IntoIterator<Item = T>) -> impl Iterator<Item = T> {
        let chosen = self.chosen;
        items
            .into_iter()
            .enumerate()
            .filter(move |(i, _)| chosen >> i & 1 == 1)
            .map(|(_, item)| item)
    }

    /// Whether a chosen column is of one of `parts`.
    fn asks(&self, parts: &[Part]) -> bool {
        parts.iter().any(|&p| self.parts >> p as u8 & 1 == 1)
    }

    /// Whether the integrals are tracked along each run.
    pub fn tracks_integrals(&self) -> bool {
        self.asks(&[Part::Integrals])
    }

    /// Whether the turning points are located along each run.
    pub fn locates_turning_points(&self) -> bool {
        self.asks(&[Part::Events, Part::Difference])
    }

    /// Whether the quadrature of each run is computed.
    pub fn solves_quadrature(&self) -> bool {
        self.asks(&[Part::Quadrature, Part::Difference])
    }
}

impl Default for Columns {
    /// [`DEFAULT_GROUPS`].
    fn default() -> Self {
        Self::parse(DEFAULT_GROUPS).expect("groups")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_column_has_a_bit() {
        assert!(catalogue().len() <= u64::BITS as usize);
    }

    /// Each group asks for the work its columns need and no more; `all` is every column.
    #[test]
    fn groups_ask_for_their_work_only() {
        let parse = |names: &[&str]| Columns::parse(names.iter().copied()).unwrap();
        let d = Columns::default();
        assert!(d.tracks_integrals() && !d.locates_turning_points() && !d.solves_quadrature());
        let q = parse(&["quadrature"]);
        assert!(!q.tracks_integrals() && !q.locates_turning_points() && q.solves_quadrature());
        let e = parse(&["events"]);
        assert!(e.locates_turning_points() && !e.solves_quadrature());
        let diff = parse(&["period_difference"]);
        assert!(diff.locates_turning_points() && diff.solves_quadrature());
        assert_eq!(
            Columns::all().select(catalogue()).count(),
            catalogue().len()
        );
        assert_eq!(parse(&["final", "integrals"]), d);
        assert_eq!(parse(&["nutation", "final", "integrals"]), Columns::all());
        // The always-written columns only, named or not.
        let run: Vec<String> = parse(&[]).select(catalogue()).map(|c| c.name).collect();
        assert_eq!(run[0], "t_end");
        assert_eq!(run.len(), 9);
        assert_eq!(parse(&["status"]), parse(&[]));
    }

    #[test]
    fn an_unknown_name_is_refused_listing_the_valid_ones() {
        let e = Columns::parse(["final", "theta"]).unwrap_err().to_string();
        for part in ["`theta`", "quadrature", "nutation", "theta_min", "K_drift"] {
            assert!(e.contains(part), "{e}");
        }
    }
}
