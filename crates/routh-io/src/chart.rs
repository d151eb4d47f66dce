//! A chart of regimes over a parameter plane (`routh megno --x KEY=FROM:TO:N --y ...`): the
//! mean MEGNO `<Y>` of the motion at every point of a grid of two quantities of a case
//! ([`ball_megno`]), which tells the regimes apart (Cincotta and Simó 2000; the charts of
//! Borisov, Jalnine, Kuznetsov, Sataev and Sedova, RCD 17 (2012), use the largest exponent
//! instead): about 2 on a torus (regular), 0 or below on a stable periodic orbit or where
//! the motion is drawn to an attractor (a ball without invariant measure has them), large in
//! chaos (`lambda t / 2`). [`Regime`] sorts a value by [`PERIODIC_BELOW`] and
//! [`CHAOTIC_ABOVE`].
//!
//! The grid is a sweep's ([`crate::sweep`]): its two axes are the `[sweep]` quantities of the
//! same names (`body.I1`, `tilt`, `spin`, `omega2`, `gamma1`, ...: [`Quantity::from_key`]),
//! put into the case's document as a `[sweep]` grid, so that the sweep's rules (two axes that
//! set the same quantity refused) and its validation of every point's body and state (before
//! any run) apply unchanged; the points run on a pool of threads ([`pool`]), one run of
//! [`ball_megno`] each.

use crate::ball::AsBall;
use crate::case::Case;
use crate::case::Overrides;
use crate::error::AppResult as Result;
use crate::error::RouthError;
use crate::integrate::megno::Indicators;
use crate::row::{write_csv_file, Cell};
use crate::simulate::Settings;
use crate::sweep::spec::Quantity;
use crate::sweep::{pool, Sweep};
use rayon::prelude::*;
use routh_ball::lyapunov::tangent_method;
use routh_ball::megno::ball_megno;
use serde::Serialize;
use std::path::Path;

/// The most points of an axis: a chart of 1000 x 1000 points is the most runs of a sweep
/// ([`crate::sweep::spec::MAX_RUNS`]).
pub const MAX_POINTS: usize = 1000;

/// `<Y>` below this: a stable periodic orbit or an attractor (`<Y> -> 0`, or negative where
/// the motion contracts).
pub const PERIODIC_BELOW: f64 = 1.0;

/// `<Y>` above this (twice the value on a torus): chaos. A weakly chaotic motion, whose
/// `lambda t / 2` has not reached it at the chart's time, is counted regular.
pub const CHAOTIC_ABOVE: f64 = 4.0;

/// The regime of a point by its `<Y>`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Regime {
    /// `<Y> <` [`PERIODIC_BELOW`].
    Periodic,
    /// In between: quasi-periodic.
    Regular,
    /// `<Y> >` [`CHAOTIC_ABOVE`].
    Chaotic,
    /// The run failed (or `<Y>` is not a number).
    Failed,
}

impl Regime {
    /// The regime of `mean_megno`.
    pub fn of(mean_megno: f64) -> Self {
        if mean_megno < PERIODIC_BELOW {
            Regime::Periodic
        } else if mean_megno > CHAOTIC_ABOVE {
            Regime::Chaotic
        } else if mean_megno.is_nan() {
            Regime::Failed
        } else {
            Regime::Regular
        }
    }

    /// The regime's name, as in the CSV and the JSON.
    pub fn name(self) -> &'static str {
        match self {
            Regime::Periodic => "periodic",
            Regime::Regular => "regular",
            Regime::Chaotic => "chaotic",
            Regime::Failed => "failed",
        }
    }
}

/// One axis of a chart: a quantity of the `[sweep]` table, `n` points from `from` to `to`
/// (ends included). Valid once built ([`ChartAxis::parse`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChartAxis {
    /// The quantity's key, as in `[sweep]` (or its name, for the axes of
    /// [`crate::inversion`]).
    pub key: String,
    /// The first value.
    pub from: f64,
    /// The last value.
    pub to: f64,
    /// The number of points, 2 to [`MAX_POINTS`].
    pub n: usize,
}

/// The rule of a range without its three parts.
const NOT_A_RANGE: &str = "must be FROM:TO:N";

/// The `(FROM, TO, N)` of the range `FROM:TO:N`, or the rule it breaks: FROM < TO finite, N
/// from 2 to [`MAX_POINTS`].
fn points(range: &str) -> std::result::Result<(f64, f64, usize), &'static str> {
    let parts: Vec<&str> = range.split(':').map(str::trim).collect();
    let [from, to, n] = parts[..] else {
        return Err(NOT_A_RANGE);
    };
    let (Ok(from), Ok(to)) = (from.parse::<f64>(), to.parse::<f64>()) else {
        return Err("FROM and TO must be numbers");
    };
    if !(from.is_finite() && to.is_finite() && from < to) {
        return Err("FROM and TO must be finite with FROM < TO");
    }
    match n.parse::<usize>() {
        Ok(n) if (2..=MAX_POINTS).contains(&n) => Ok((from, to, n)),
        _ => Err("N must be an integer from 2 to 1000"),
    }
}

impl ChartAxis {
    /// The axis `KEY=FROM:TO:N` of the option `option`: KEY a quantity of `[sweep]`
    /// ([`Quantity::from_key`]), FROM < TO finite, N from 2 to [`MAX_POINTS`]; refused naming
    /// the option ([`RouthError::Option`]).
    pub fn parse(text: &str, option: &'static str) -> Result<Self> {
        let refused = |rule: &'static str| RouthError::Option {
            name: option,
            value: format!("{text:?}"),
            rule,
        };
        let (key, range) = text
            .split_once('=')
            .ok_or_else(|| refused("must be KEY=FROM:TO:N"))?;
        let key = key.trim();
        if Quantity::from_key(key).is_none() {
            return Err(refused(
                "KEY must be a quantity of [sweep]: body.m, body.R, body.a, body.I1, body.I2, \
                 body.I3, body.G, tilt, spin, omega1..3, gamma1..3 or contact.mu",
            )
            .into());
        }
        let (from, to, n) = points(range).map_err(|rule| match rule {
            NOT_A_RANGE => refused("must be KEY=FROM:TO:N"),
            rule => refused(rule),
        })?;
        Ok(ChartAxis {
            key: key.to_string(),
            from,
            to,
            n,
        })
    }

    /// The axis `key` of the range `FROM:TO:N` given to the option `option`: FROM < TO finite,
    /// N from 2 to [`MAX_POINTS`]; refused naming the option ([`RouthError::Option`]).
    pub fn range(key: &str, range: &str, option: &'static str) -> Result<Self> {
        let (from, to, n) = points(range).map_err(|rule| RouthError::Option {
            name: option,
            value: format!("{range:?}"),
            rule,
        })?;
        Ok(ChartAxis {
            key: key.to_string(),
            from,
            to,
            n,
        })
    }

    /// The axis's label in a figure: the key and what it sets.
    pub fn label(&self) -> String {
        let meaning = match Quantity::from_key(&self.key) {
            Some(Quantity::Tilt) => "initial tilt theta, rad".to_string(),
            Some(Quantity::Spin) => "initial spin omega3".to_string(),
            Some(Quantity::Omega(i)) => format!("initial omega{}", i + 1),
            Some(Quantity::Gamma(i)) => format!("initial gamma{}", i + 1),
            Some(Quantity::Body(key)) => format!("[body] {key}"),
            Some(Quantity::Mu) => "[contact] mu".to_string(),
            None => return self.key.clone(),
        };
        format!("{} ({meaning})", self.key)
    }

    /// The axis as a grid axis of a `[sweep]` table, `{ range = [from, to], n = n }`.
    fn sweep_axis(&self) -> toml::Value {
        let mut axis = toml::Table::new();
        axis.insert("range".into(), vec![self.from, self.to].into());
        axis.insert("n".into(), (self.n as i64).into());
        axis.into()
    }
}

/// One point of a chart: its values of the two axes and its indicators (or why the run
/// failed).
#[derive(Debug, Clone, PartialEq)]
pub struct ChartPoint {
    /// The value of the horizontal axis.
    pub x: f64,
    /// The value of the vertical axis.
    pub y: f64,
    /// The indicators at `t_end`, or the run's error.
    pub indicators: std::result::Result<Indicators, String>,
}

impl ChartPoint {
    /// `<Y>`, NaN for a failed run.
    pub fn mean_megno(&self) -> f64 {
        self.indicators.as_ref().map_or(f64::NAN, |i| i.mean_megno)
    }
}

/// A chart: its axes, its points (in the sweep's order), and the counts of the regimes.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// The horizontal axis.
    pub x: ChartAxis,
    /// The vertical axis.
    pub y: ChartAxis,
    /// The `x.n * y.n` points.
    pub points: Vec<ChartPoint>,
}

/// The number of points of each regime.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct RegimeCounts {
    /// [`Regime::Periodic`].
    pub periodic: usize,
    /// [`Regime::Regular`].
    pub regular: usize,
    /// [`Regime::Chaotic`].
    pub chaotic: usize,
    /// [`Regime::Failed`].
    pub failed: usize,
}

impl Chart {
    /// The number of points of each regime.
    pub fn regimes(&self) -> RegimeCounts {
        let mut counts = RegimeCounts::default();
        for p in &self.points {
            match Regime::of(p.mean_megno()) {
                Regime::Periodic => counts.periodic += 1,
                Regime::Regular => counts.regular += 1,
                Regime::Chaotic => counts.chaotic += 1,
                Regime::Failed => counts.failed += 1,
            }
        }
        counts
    }
}

/// The chart of `<Y>` of `case` over the grid of `x` and `y` (two different keys), each point
/// one run of [`ball_megno`] with `settings`, on `threads` threads (0: one per core; at most
/// [`crate::sweep::runner::MAX_THREADS_PER_CORE`] per core). Every point's body and state are
/// validated before any run, as a sweep's; a run that fails is a [`Regime::Failed`] point
/// with its error, not an error of the chart; a method that does not integrate the tangent
/// flow is refused before ([`tangent_method`]).
pub fn chart(
    case: &Case,
    settings: &Settings,
    x: &ChartAxis,
    y: &ChartAxis,
    threads: usize,
) -> Result<Chart> {
    tangent_method(settings.method())?;
    if x.key == y.key {
        return Err(RouthError::Option {
            name: "y",
            value: y.key.clone(),
            rule: "must be another quantity than --x's",
        }
        .into());
    }
    let mut grid = toml::Table::new();
    grid.insert(x.key.clone(), x.sweep_axis());
    grid.insert(y.key.clone(), y.sweep_axis());
    let mut document = case.document.clone();
    document.insert("sweep".into(), grid.into());
    let text = toml::to_string(&document).expect("a TOML document serialises");
    let overrides = Overrides::of(settings);
    let sweep = Sweep::new(&text, &case.source, overrides, None, None)?;
    let names = sweep.names();
    let position = |key: &str| {
        names
            .iter()
            .position(|n| n == key)
            .expect("an axis of the grid")
    };
    let (ix, iy) = (position(&x.key), position(&y.key));
    let points = pool(threads)?.install(|| {
        (0..sweep.runs())
            .into_par_iter()
            .map(|k| {
                let values = sweep.design().point(k);
                let indicators =
                    sweep
                        .case_of(k)
                        .map_err(|e| e.to_string())
                        .and_then(|(ball, state)| {
                            point_megno(&ball, &state.to_array(), settings)
                                .map_err(|e| e.to_string())
                        });
                ChartPoint {
                    x: values[ix],
                    y: values[iy],
                    indicators,
                }
            })
            .collect()
    });
    Ok(Chart {
        x: x.clone(),
        y: y.clone(),
        points,
    })
}

/// The indicators at `t_end` of one point.
fn point_megno(ball: &impl AsBall, x0: &[f64; 6], settings: &Settings) -> Result<Indicators> {
    Ok(ball_megno(ball, x0, settings)?.last)
}

/// The columns of the chart's table: the two keys, `mean_megno`, `megno`, `fli`, `regime`,
/// `message` (a failed run's error, empty otherwise).
pub fn columns(chart: &Chart) -> Vec<&str> {
    vec![
        chart.x.key.as_str(),
        chart.y.key.as_str(),
        "mean_megno",
        "megno",
        "fli",
        "regime",
        "message",
    ]
}

/// The cells of one point, in the order of [`columns`] (the indicators empty for a failed
/// run).
pub fn cells(point: &ChartPoint) -> Vec<Cell> {
    let (numbers, message) = match &point.indicators {
        Ok(i) => (
            [Some(i.mean_megno), Some(i.megno), Some(i.fli)],
            String::new(),
        ),
        Err(e) => ([None; 3], e.clone()),
    };
    [Some(point.x), Some(point.y)]
        .into_iter()
        .chain(numbers)
        .map(Cell::Float)
        .chain([
            Cell::Text(Regime::of(point.mean_megno()).name().into()),
            Cell::Text(message),
        ])
        .collect()
}

/// The chart's table as CSV into `path`, written whole or not at all.
pub fn write_csv(path: &Path, chart: &Chart) -> Result<()> {
    write_csv_file(path, &columns(chart), chart.points.iter().map(cells))
}
