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
//! | `user_events` | per user event `k` (`[sweep] events`, `--events`): `event{k}_count event{k}_first_t` | the planes' values at every step, a located crossing per crossing |
//! | `contact` | a sliding contact's run ([`CONTACT_NAMES`]): `transitions`, `height_initial height_final height_min height_max tilt_final slip_speed_final normal_force_min jellett_initial jellett_drift energy_balance energy_increase work_final` | nothing: the run's balances |
//! | `all` | every column of the sweep's contact law (the table of a sweep before `--columns`) | all of the above |
//!
//! A sweep of the rolling law (the paper's system) has every group but `contact`; a sweep of
//! `[contact] law = "sliding"` has `final` (its `final_M` null: the sliding state has no M)
//! and `contact`, and refuses the others ([`Columns::of_law`]). The default, [`DEFAULT_GROUPS`],
//! is `final`, `integrals` and `user_events` for the rolling law: the cheap columns, and the
//! user's events when they are given (without events the group has no column); `final` and
//! `contact` for the sliding law. A column can also be named alone; the table keeps the columns' order whatever
//! the order asked, the user events' columns last, in the order of the events.

use super::spec::{refuse, texts, Refusal};
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
    /// The crossings of the user's events ([`super::crossings`]).
    UserEvents,
    /// The balances of a sliding run ([`super::contact`]).
    Contact,
}

/// The groups of columns that can be asked for by name, with their parts (`all`: those of
/// the rolling law; [`Columns::of_law`] gives a sliding sweep's).
pub const GROUPS: [(&str, &[Part]); 8] = [
    ("final", &[Part::Final]),
    ("integrals", &[Part::Integrals]),
    ("events", &[Part::Events]),
    ("quadrature", &[Part::Quadrature]),
    (
        "nutation",
        &[Part::Events, Part::Quadrature, Part::Difference],
    ),
    ("user_events", &[Part::UserEvents]),
    ("contact", &[Part::Contact]),
    (
        "all",
        &[
            Part::Final,
            Part::Integrals,
            Part::Events,
            Part::Quadrature,
            Part::Difference,
            Part::UserEvents,
        ],
    ),
];

/// The groups of a table when none are asked for: the final state, the integrals and their
/// drift, and the user's events when there are (before `--columns`, a table held every
/// column: ask for `all`).
pub const DEFAULT_GROUPS: [&str; 3] = ["final", "integrals", "user_events"];

/// The columns of a sliding run ([`Part::Contact`]), in the table's order: the switches
/// between sliding and rolling (Coulomb's friction; 0 for the viscous), the height of the
/// centre of mass at the start, the end and its extremes, the tilt at the end (the angle
/// from the downward vertical to the line from the geometric centre to the centre of mass:
/// 0 in the low position, pi turned upside down; null for a centre of mass at the centre),
/// the slip speed at the end, the least normal force, Jellett's integral at the start and
/// its drift (null where it is not an integral), the energy balance and its largest
/// increase, and the friction's work (the balances of `routh simulate`'s summary).
pub const CONTACT_NAMES: [&str; 13] = [
    "transitions",
    "height_initial",
    "height_final",
    "height_min",
    "height_max",
    "tilt_final",
    "slip_speed_final",
    "normal_force_min",
    "jellett_initial",
    "jellett_drift",
    "energy_balance",
    "energy_increase",
    "work_final",
];

/// The most user events of a sweep (each has two columns, a bit each in [`Columns`]).
pub const MAX_EVENTS: usize = 32;

/// The columns of user event `k`, in the table's order: its number of crossings in
/// `(0, t_end]` and the time of the first (null without one).
pub fn event_columns(k: usize) -> [(String, Kind); 2] {
    [
        (format!("event{k}_count"), Kind::Int),
        (format!("event{k}_first_t"), Kind::Float),
    ]
}

/// The user event and which of its [`event_columns`] (0 or 1) `name` is, for any `k` below
/// [`MAX_EVENTS`] (whether the sweep has event `k` is checked by [`Columns::of_events`]).
fn event_column(name: &str) -> Option<(usize, usize)> {
    let rest = name.strip_prefix("event")?;
    let (k, which) = [("_count", 0), ("_first_t", 1)]
        .into_iter()
        .find_map(|(suffix, which)| Some((rest.strip_suffix(suffix)?, which)))?;
    let k: usize = k.parse().ok().filter(|&k| k < MAX_EVENTS)?;
    (event_columns(k)[which].0 == name).then_some((k, which))
}

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
    for name in CONTACT_NAMES {
        let kind = if name == "transitions" {
            Kind::Int
        } else {
            Kind::Float
        };
        cols.push(column(name, kind, Part::Contact));
    }
    cols
}

/// The columns a sweep's table holds: a subset of [`catalogue`] (bit i for its column i),
/// always with the [`Part::Run`] columns, and the parts they need (bit `part as u8`), known
/// without building the catalogue again for every run; and the user events' columns (bit
/// `2 k + j` for column `j` of [`event_columns`]`(k)`): those asked for, and those of the
/// sweep's events ([`Columns::of_events`]; none before).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Columns {
    chosen: u64,
    parts: u8,
    /// Every user event's columns were asked for (`user_events`, `all`, the default).
    every_event: bool,
    /// `all` was asked for: every column of the sweep's law ([`Columns::of_law`]).
    every: bool,
    /// Nothing was asked for: the default of the sweep's law ([`Columns::of_law`]).
    default: bool,
    /// The user events' columns named one by one.
    named_events: u64,
    /// The user events' columns of the table, once the sweep's events are known.
    events: u64,
}

/// A name that is neither a column nor a group: its message lists the valid ones.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown column `{name}`: the groups are {} (default: {}), the columns {}, and \
     `event{{k}}_count`, `event{{k}}_first_t` for each user event k = 0, 1, ... given by \
     `events` (`run` and the swept quantities are always written)",
    GROUPS.map(|g| g.0).join(", "),
    DEFAULT_GROUPS.join(", "),
    catalogue().into_iter().map(|c| c.name).collect::<Vec<_>>().join(", ")
)]
pub struct UnknownColumn {
    /// The name asked for.
    pub name: String,
}

impl Columns {
    /// The columns named by `names`: groups of [`GROUPS`], single columns of [`catalogue`]
    /// and of user events ([`event_columns`]), in any order (the table keeps its own); the
    /// [`Part::Run`] columns are always in. The user events' columns are in the table only
    /// once the sweep's events are known ([`Columns::of_events`]).
    pub fn parse<'a>(names: impl IntoIterator<Item = &'a str>) -> Result<Self, UnknownColumn> {
        let all = catalogue();
        let of_parts = |parts: &[Part]| {
            all.iter()
                .enumerate()
                .filter(|(_, c)| parts.contains(&c.part))
                .fold(0u64, |bits, (i, _)| bits | 1 << i)
        };
        let mut columns = Columns {
            chosen: of_parts(&[Part::Run]),
            parts: 0,
            every_event: false,
            every: false,
            default: false,
            named_events: 0,
            events: 0,
        };
        for name in names {
            let name = name.trim();
            if let Some((_, parts)) = GROUPS.iter().find(|g| g.0 == name) {
                columns.chosen |= of_parts(parts);
                columns.every_event |= parts.contains(&Part::UserEvents);
                columns.every |= name == "all";
            } else if let Some(i) = all.iter().position(|c| c.name == name) {
                columns.chosen |= 1 << i;
            } else if let Some((k, which)) = event_column(name) {
                columns.named_events |= 1 << (2 * k + which);
            } else {
                return Err(UnknownColumn {
                    name: name.to_string(),
                });
            }
        }
        columns.parts = columns.parts_of_chosen();
        Ok(columns)
    }

    /// The parts of the chosen columns (bit `part as u8`).
    fn parts_of_chosen(&self) -> u8 {
        self.select(catalogue())
            .fold(0, |bits, c| bits | 1 << c.part as u8)
    }

    /// These columns in a sweep of the rolling law (`sliding = false`), or of the sliding
    /// contact: there the default is `final` and `contact`, `all` is the run's, the final
    /// state's and the contact's columns, and a column of the rolling law alone (integrals,
    /// events, quadrature, user events) is refused, as the `contact` columns are in a sweep of
    /// the rolling law; the error names the column.
    pub fn of_law(self, sliding: bool) -> Result<Self, String> {
        let rolling_only = [
            Part::Integrals,
            Part::Events,
            Part::Quadrature,
            Part::Difference,
            Part::UserEvents,
        ];
        let mut columns = match (sliding, self.default, self.every) {
            (true, true, _) => Self::parse(["final", "contact"]).expect("groups"),
            (true, false, true) => Self::parse(["final", "contact"]).expect("groups"),
            _ => self,
        };
        let (refused, law): (&[Part], &str) = if sliding {
            columns.every_event = false;
            (&rolling_only, "law = \"sliding\"")
        } else {
            (&[Part::Contact], "the rolling law")
        };
        let named = catalogue()
            .into_iter()
            .enumerate()
            .find(|(i, c)| columns.chosen >> i & 1 == 1 && refused.contains(&c.part));
        if let Some((_, column)) = named {
            return Err(format!(
                "column `{}` is not one of a sweep of {law} (its groups: {})",
                column.name,
                if sliding {
                    "final, contact"
                } else {
                    "final, integrals, events, quadrature, nutation, user_events"
                }
            ));
        }
        if sliding && columns.named_events != 0 {
            let bit = columns.named_events.trailing_zeros() as usize;
            return Err(format!(
                "column `{}` is not one of a sweep of {law} (it has no user events)",
                event_columns(bit / 2)[bit % 2].0
            ));
        }
        if sliding {
            columns.parts = columns.parts_of_chosen();
        }
        (columns.every, columns.default) = (false, false);
        Ok(columns)
    }

    /// These columns in a sweep of `events` user events (at most [`MAX_EVENTS`]): the user
    /// events' columns asked for, of its events. A column named for an event the sweep does
    /// not have is refused.
    pub fn of_events(mut self, events: usize) -> Result<Self, UnknownColumn> {
        let mask = match 2 * events.min(MAX_EVENTS) {
            0 => 0,
            64 => u64::MAX,
            bits => (1 << bits) - 1,
        };
        let beyond = self.named_events & !mask;
        if beyond != 0 {
            let bit = beyond.trailing_zeros() as usize;
            return Err(UnknownColumn {
                name: event_columns(bit / 2)[bit % 2].0.clone(),
            });
        }
        self.events = if self.every_event {
            mask
        } else {
            self.named_events
        };
        self.parts &= !(1 << Part::UserEvents as u8);
        if self.events != 0 {
            self.parts |= 1 << Part::UserEvents as u8;
        }
        Ok(self)
    }

    /// Of the items of the user events' columns in their order (two per event: the
    /// [`event_columns`] of event 0, then of event 1, ...), those in the table.
    pub fn select_events<T>(&self, items: impl IntoIterator<Item = T>) -> impl Iterator<Item = T> {
        let events = self.events;
        items
            .into_iter()
            .enumerate()
            .filter(move |(i, _)| *i < 64 && events >> i & 1 == 1)
            .map(|(_, item)| item)
    }

    /// The columns of the `[sweep]` table's key `columns = ["final", "events", ...]`.
    pub fn from_toml(listed: &toml::Value) -> Result<Self, Refusal> {
        let names = texts(
            "columns",
            listed,
            "must be a list of column names and groups, such as [\"final\", \"events\"]",
        )?;
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

    /// Whether the user's events are located along each run.
    pub fn locates_user_events(&self) -> bool {
        self.asks(&[Part::UserEvents])
    }

    /// Whether the table holds a sliding run's columns ([`Part::Contact`]).
    pub fn has_contact(&self) -> bool {
        self.asks(&[Part::Contact])
    }

    /// Whether the quadrature of each run is computed.
    pub fn solves_quadrature(&self) -> bool {
        self.asks(&[Part::Quadrature, Part::Difference])
    }
}

impl Default for Columns {
    /// [`DEFAULT_GROUPS`].
    fn default() -> Self {
        Self {
            default: true,
            ..Self::parse(DEFAULT_GROUPS).expect("groups")
        }
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
        let rolling = |c: Columns| c.of_law(false).unwrap();
        assert_eq!(
            Columns::all().select(catalogue()).count(),
            catalogue().len() - CONTACT_NAMES.len()
        );
        assert_eq!(
            rolling(parse(&["final", "integrals", "user_events"])),
            rolling(d)
        );
        assert_eq!(
            rolling(parse(&["nutation", "final", "integrals", "user_events"])),
            rolling(Columns::all())
        );
        // The always-written columns only, named or not.
        let run: Vec<String> = parse(&[]).select(catalogue()).map(|c| c.name).collect();
        assert_eq!(run[0], "t_end");
        assert_eq!(run.len(), 9);
        assert_eq!(parse(&["status"]), parse(&[]));
    }

    /// A sliding sweep's columns: by default and with `all` the final state's and the
    /// contact's; a column of the rolling law alone refused, naming it, as `contact` is in a
    /// sweep of the rolling law.
    #[test]
    fn a_sliding_sweep_has_the_contact_columns() {
        let names = |c: Columns| c.select(catalogue()).map(|c| c.name).collect::<Vec<_>>();
        let sliding = names(Columns::default().of_law(true).unwrap());
        assert_eq!(sliding, names(Columns::all().of_law(true).unwrap()));
        assert_eq!(sliding.len(), 9 + 6 + CONTACT_NAMES.len());
        assert!(sliding.contains(&"tilt_final".to_string()));
        assert!(Columns::default().of_law(true).unwrap().has_contact());
        assert!(!Columns::default().of_law(false).unwrap().has_contact());
        let parse = |names: &[&str]| Columns::parse(names.iter().copied()).unwrap();
        let e = parse(&["H1_drift"]).of_law(true).unwrap_err();
        assert!(
            e.contains("`H1_drift`") && e.contains("final, contact"),
            "{e}"
        );
        let e = parse(&["contact"]).of_law(false).unwrap_err();
        assert!(e.contains("`transitions`"), "{e}");
        let e = parse(&["event0_count"]).of_law(true).unwrap_err();
        assert!(e.contains("no user events"), "{e}");
        assert_eq!(
            names(parse(&["jellett_drift"]).of_law(true).unwrap()).len(),
            10
        );
    }

    /// The user events' columns are those of the sweep's events: all of them with the group
    /// (in the default and in `all`), the ones named otherwise, none without events; a
    /// column of an event the sweep does not have is refused.
    #[test]
    fn user_event_columns_are_those_of_the_sweeps_events() {
        let names = |names: &[&str], events| {
            let chosen = Columns::parse(names.iter().copied())?.of_events(events)?;
            Ok::<_, UnknownColumn>(
                chosen
                    .select_events((0..MAX_EVENTS).flat_map(event_columns))
                    .map(|c| c.0)
                    .collect::<Vec<_>>(),
            )
        };
        let default = Columns::default().of_events(2).unwrap();
        assert!(default.locates_user_events() && !default.locates_turning_points());
        assert!(!Columns::default()
            .of_events(0)
            .unwrap()
            .locates_user_events());
        assert_eq!(
            names(&["user_events"], 2).unwrap(),
            [
                "event0_count",
                "event0_first_t",
                "event1_count",
                "event1_first_t"
            ]
        );
        assert_eq!(
            names(&["all"], 1).unwrap(),
            ["event0_count", "event0_first_t"]
        );
        assert_eq!(names(&["all"], 0).unwrap(), Vec::<String>::new());
        assert_eq!(names(&["final"], 2).unwrap(), Vec::<String>::new());
        assert!(!parse_final().of_events(2).unwrap().locates_user_events());
        assert_eq!(
            names(&["event1_first_t", "final"], 2).unwrap(),
            ["event1_first_t"]
        );
        assert_eq!(
            names(&["user_events"], MAX_EVENTS).unwrap().len(),
            2 * MAX_EVENTS
        );
        assert_eq!(
            names(&["event2_count"], 2).unwrap_err().name,
            "event2_count"
        );
        for bad in [
            "event32_count",
            "event01_count",
            "event0_first",
            "eventx_count",
        ] {
            assert!(Columns::parse([bad]).is_err(), "{bad}");
        }
    }

    fn parse_final() -> Columns {
        Columns::parse(["final"]).unwrap()
    }

    #[test]
    fn an_unknown_name_is_refused_listing_the_valid_ones() {
        let e = Columns::parse(["final", "theta"]).unwrap_err().to_string();
        for part in [
            "`theta`",
            "quadrature",
            "nutation",
            "theta_min",
            "K_drift",
            "user_events",
            "event{k}_first_t",
        ] {
            assert!(e.contains(part), "{e}");
        }
    }
}
