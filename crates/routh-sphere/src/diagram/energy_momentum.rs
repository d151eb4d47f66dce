//! The energy–momentum diagram at a fixed Jellett H3: the window of the plane (K, H1), the
//! critical curves and the vertical spins in it, the number of tori on a grid of values, the
//! focus–focus points and the monodromy around them.

use super::monodromy::{monodromy, Monodromy};
use super::relative_equilibria::RelativeEquilibrium;
use super::relative_equilibria::{critical_curves, vertical_spin_at, CriticalCurve};
use super::stability::StabilityType;
use super::tori::torus_count;
use super::value::plane_units;
use super::value::{jellett_in_units, Value};
use crate::body::Body;
use crate::error::{Result, RouthError};
use crate::integrals::jellett;
use crate::steady::{largest_rate, missing_threshold, routh_threshold, vertical_spin_state};
use crate::units::Units;
use serde::Serialize;

/// How finely the diagram is computed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Resolution {
    /// Tilts at which the steady precessions are computed.
    pub tilts: usize,
    /// Columns (K) of the grid of torus counts; the rows (H1) are two thirds as many.
    pub grid: usize,
    /// Points of the monodromy loop.
    pub loop_points: usize,
}

impl Default for Resolution {
    fn default() -> Self {
        Resolution {
            tilts: 400,
            grid: 150,
            loop_points: 64,
        }
    }
}

/// The largest tilts, grid columns and loop points accepted, each alone (a bound of memory:
/// the work of the grid is bounded by [`MAX_GRID_CELLS`]).
pub const MAX_RESOLUTION: usize = 5000;

/// The most cells of the grid of torus counts, `grid` columns times [`grid_rows`] rows,
/// refused before any work beyond it. The grid is the work of a diagram: each cell is one
/// [`torus_count`], which samples Q' at the same 4192 tilts whatever the body and the value
/// ([`super::tori::CRITICAL_POINT_SAMPLES`] and the halvings toward the poles), so its time is
/// proportional to the cells. Measured (release build, `docs/diagram.md`): 0.41 ms of CPU a
/// cell, so 100,000 cells are about 40 s; the other parts are bounded by [`MAX_RESOLUTION`]
/// alone and add to it, not multiply (5000 tilts 0.2 s, a loop of 5000 points 6 s). The
/// largest request accepted, `--grid 387 --tilts 5000 --loop-points 5000`, takes about a
/// minute; `--grid 5000` (16.7 million cells) would take about two hours.
pub const MAX_GRID_CELLS: usize = 100_000;

/// The rows (H1) of a grid of `columns` columns (K): two thirds as many, at least 2.
pub fn grid_rows(columns: usize) -> usize {
    (2 * columns / 3).max(2)
}

/// A rectangle of the plane (K, H1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Window {
    /// The range of K.
    pub k: (f64, f64),
    /// The range of H1.
    pub h1: (f64, f64),
}

impl Window {
    /// This window computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Self {
        let (p, e) = (units.momentum(), units.energy());
        Window {
            k: (self.k.0 * p, self.k.1 * p),
            h1: (self.h1.0 * e, self.h1.1 * e),
        }
    }
}

/// The torus counts on a grid of values (cell centres).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TorusGrid {
    /// The values of K (columns).
    pub k: Vec<f64>,
    /// The values of H1 (rows).
    pub h1: Vec<f64>,
    /// `tori[row][column]`: the number of tori, `None` at a critical value.
    pub tori: Vec<Vec<Option<usize>>>,
}

impl TorusGrid {
    /// This grid computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Self {
        TorusGrid {
            k: self.k.iter().map(|k| k * units.momentum()).collect(),
            h1: self.h1.iter().map(|h| h * units.energy()).collect(),
            tori: self.tori.clone(),
        }
    }
}

/// The energy–momentum diagram at one H3.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagram {
    /// Jellett's H3 of the plane.
    #[serde(rename = "H3")]
    pub h3: f64,
    /// The window drawn.
    pub window: Window,
    /// The vertical spins (gamma3 = +1, then -1) at this H3.
    pub vertical_spins: Vec<RelativeEquilibrium>,
    /// The critical curves of the steady precessions.
    pub critical_curves: Vec<CriticalCurve>,
    /// The focus–focus relative equilibria.
    pub focus_focus: Vec<RelativeEquilibrium>,
    /// The monodromy around the first focus–focus point, if any.
    pub monodromy: Option<Monodromy>,
    /// The number of tori on a grid of the window.
    pub tori: TorusGrid,
}

/// `(lo, hi)` of finite values, or `None`.
fn range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .filter(|v| v.is_finite())
        .fold(None, |acc: Option<(f64, f64)>, v| {
            Some(acc.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v))))
        })
}

fn check_resolution(name: &'static str, value: usize, least: usize) -> Result<()> {
    if (least..=MAX_RESOLUTION).contains(&value) {
        Ok(())
    } else {
        Err(RouthError::Option {
            name,
            value: value.to_string(),
            rule: "must be between 2 (8 for the loop) and 5000",
        })
    }
}

/// `columns` of the grid within [`MAX_GRID_CELLS`], refused with the cells and the largest
/// grid accepted otherwise.
fn check_grid_cells(columns: usize) -> Result<()> {
    let cells = columns.saturating_mul(grid_rows(columns));
    if cells <= MAX_GRID_CELLS {
        return Ok(());
    }
    let largest = (2..columns)
        .rev()
        .find(|&c| c * grid_rows(c) <= MAX_GRID_CELLS)
        .unwrap_or(2);
    Err(RouthError::Option {
        name: "grid",
        value: format!(
            "{columns} ({columns} x {} = {cells} cells, each a count of tori; at most \
             {MAX_GRID_CELLS} cells: grid <= {largest})",
            grid_rows(columns)
        ),
        rule: "the grid's cells are the work of the diagram (about 0.4 ms each on one core, \
               whatever the body): at most about 40 s of it, so that the diagram ends within \
               about a minute (MAX_GRID_CELLS; tilts and loop points add little)",
    })
}

/// The largest ratio of the spin of a vertical spin to Routh's threshold for which the
/// diagram is computed. Far above the threshold gravity is a small part of the motion: the
/// slow steady precessions (the slow branch of the critical curves) have omega_t of relative
/// size `(w_c / w)^2`, and the round-off of the quadratic that fixes them costs them about
/// `6 eps (w / w_c)^2` of their value (measured on the default body: 1e-7 at 1e4, 1e-3 at
/// 1e6, nothing resolved beyond 1e7). A ratio of the body's own rates: scale-free. (Issue 33:
/// at H3 = 1e6 the default body's sleeping tops were called degenerate, which `steady` calls
/// stable; that was the norm of the Jacobian in the body's variables, now made dimensionless,
/// and the sleeping tops are elliptic at any spin above the threshold.)
pub const MAX_SPIN_RATIO: f64 = 1e4;

/// The largest |H3| of a diagram of `body` (finite and positive), and the rule that sets it:
/// the vertical spins at most [`MAX_SPIN_RATIO`] times Routh's threshold (when the body has
/// one), and their rate at most [`largest_rate`] (the range of f64).
pub fn largest_h3(body: &Body) -> Result<(f64, &'static str)> {
    let units = Units::with_rate(body, 0.0);
    let per_spin = [1.0, -1.0]
        .into_iter()
        .try_fold(f64::INFINITY, |least, pole| {
            let unit = vertical_spin_state(body, pole, 1.0)?;
            Ok::<f64, RouthError>(least.min(jellett(body, &unit.to_array()).abs()))
        })?;
    let range = largest_rate(units.inertia()) * per_spin;
    let pole = body.a().signum();
    let resolution = match missing_threshold(body, pole) {
        None => MAX_SPIN_RATIO * routh_threshold(body, pole) * per_spin,
        Some(_) => f64::INFINITY,
    };
    Ok(if resolution < range {
        (
            resolution,
            "the vertical spins at this H3 must spin at most 1e4 times Routh's threshold: \
             beyond, the slow steady precessions (omega_t of relative size (w_c / w)^2) lose \
             more than 1e-7 of their value to the round-off of f64, about 6 eps (w / w_c)^2",
        )
    } else {
        (
            range,
            "the rate of the vertical spins at this H3 must keep their energy and Q'' below \
             1e150 in the body's units (the range of f64)",
        )
    })
}

/// The units of the plane at Jellett's `h3` ([`plane_units`]), refused before any work when
/// `|h3|` exceeds [`largest_h3`]; `name` is the option's.
fn checked_plane(body: &Body, h3: f64, name: &'static str) -> Result<Units> {
    let (limit, rule) = largest_h3(body)?;
    if h3.abs() <= limit {
        plane_units(body, h3)
    } else {
        Err(RouthError::Option {
            name,
            value: format!("{h3:e} (|H3| <= {limit:.4e} for this body)"),
            rule,
        })
    }
}

impl Diagram {
    /// The diagram of `body` at Jellett's `h3`; `marked` values (the case's own) are kept
    /// inside the window. Computed in the units of the plane ([`plane_units`]: in them the
    /// faster of the fall and the vertical spins is 1, and the window's least spans, the
    /// `1e-3 (1 + |K|)` below, are relative to the body's scales) and converted back.
    pub fn new(body: &Body, h3: f64, marked: &[Value], resolution: Resolution) -> Result<Self> {
        body.require_symmetric("the energy-momentum diagram")?;
        if !h3.is_finite() {
            return Err(RouthError::Option {
                name: "h3",
                value: h3.to_string(),
                rule: "must be finite",
            });
        }
        check_resolution("tilts", resolution.tilts, 2)?;
        check_resolution("grid", resolution.grid, 2)?;
        check_resolution("loop_points", resolution.loop_points, 8)?;
        check_grid_cells(resolution.grid)?;
        let units = checked_plane(body, h3, "h3")?;
        let marked: Vec<Value> = marked.iter().map(|v| v.in_units(&units)).collect();
        let scaled = Self::in_units(
            &units.body(body)?,
            jellett_in_units(h3, &units),
            &marked,
            resolution,
        )?;
        Ok(Diagram {
            h3,
            window: scaled.window.back(&units),
            vertical_spins: scaled
                .vertical_spins
                .iter()
                .map(|v| v.back(&units))
                .collect::<Result<_>>()?,
            critical_curves: scaled
                .critical_curves
                .iter()
                .map(|c| c.back(&units))
                .collect::<Result<_>>()?,
            focus_focus: scaled
                .focus_focus
                .iter()
                .map(|v| v.back(&units))
                .collect::<Result<_>>()?,
            monodromy: scaled.monodromy.map(|m| m.back(&units)).transpose()?,
            tori: scaled.tori.back(&units),
        })
    }

    /// [`Diagram::new`] in the units of its arguments.
    fn in_units(body: &Body, h3: f64, marked: &[Value], resolution: Resolution) -> Result<Self> {
        let vertical_spins = [1.0, -1.0]
            .into_iter()
            .map(|pole| vertical_spin_at(body, pole, h3))
            .collect::<Result<Vec<_>>>()?;
        let anchors: Vec<Value> = vertical_spins
            .iter()
            .map(|v| v.value)
            .chain(marked.iter().copied())
            .collect();
        // The least spans and the default ranges are in the units of the plane (its body's
        // own scales of K and H1), not absolute numbers.
        let (k_lo, k_hi) = range(anchors.iter().map(|v| v.k)).unwrap_or((-1.0, 1.0));
        let k_span = (k_hi - k_lo).max(1e-3 * (1.0 + k_hi.abs()));
        let k = (k_lo - 0.6 * k_span, k_hi + 0.6 * k_span);
        let k_limit = 3.0 * k.0.abs().max(k.1.abs());
        let critical_curves = critical_curves(body, h3, resolution.tilts, k_limit)?;
        let inside = critical_curves
            .iter()
            .flat_map(|c| &c.points)
            .filter(|p| p.value.k >= k.0 && p.value.k <= k.1)
            .map(|p| p.value.h1);
        let (h_lo, _) = range(inside.chain(anchors.iter().map(|v| v.h1))).unwrap_or((0.0, 1.0));
        let (_, h_top) = range(anchors.iter().map(|v| v.h1)).unwrap_or((0.0, 1.0));
        let h_span = (h_top - h_lo).max(1e-3 * (1.0 + h_top.abs()));
        let window = Window {
            k,
            h1: (h_lo - 0.1 * h_span, h_top + 0.6 * h_span),
        };
        let focus_focus: Vec<RelativeEquilibrium> = vertical_spins
            .iter()
            .filter(|v| v.stability == StabilityType::FocusFocus)
            .cloned()
            .collect();
        let monodromy = focus_focus
            .first()
            .map(|centre| {
                let radii = loop_radii(&window, centre.value, &critical_curves);
                monodromy(body, centre, radii, resolution.loop_points)
            })
            .transpose()?;
        let tori = torus_grid(body, h3, &window, resolution.grid)?;
        Ok(Diagram {
            h3,
            window,
            vertical_spins,
            critical_curves,
            focus_focus,
            monodromy,
            tori,
        })
    }
}

/// The largest fraction of the window taken by the monodromy loop's semi-axes.
const LOOP_FRACTION: f64 = 0.04;

/// The semi-axes of the monodromy loop around `centre`: the same fraction of the window in K
/// and in H1 (so that the loop is round on the figure), [`LOOP_FRACTION`] at most and half the
/// distance from `centre` to the critical curves (in units of the window) at most, so that the
/// loop keeps clear of them by at least its own size on the figure.
fn loop_radii(window: &Window, centre: Value, curves: &[CriticalCurve]) -> (f64, f64) {
    let fraction = LOOP_FRACTION.min(0.5 * clearance(window, centre, curves));
    (
        fraction * (window.k.1 - window.k.0),
        fraction * (window.h1.1 - window.h1.0),
    )
}

/// The distance from `value` to the polylines of the critical curves in the plane (K, H1)
/// scaled to the unit square by the window (infinite when there is no curve).
pub fn clearance(window: &Window, value: Value, curves: &[CriticalCurve]) -> f64 {
    let scale = |v: &Value| {
        [
            (v.k - value.k) / (window.k.1 - window.k.0),
            (v.h1 - value.h1) / (window.h1.1 - window.h1.0),
        ]
    };
    curves
        .iter()
        .flat_map(|curve| curve.points.windows(2))
        .map(|pair| segment_distance(scale(&pair[0].value), scale(&pair[1].value)))
        .filter(|d| d.is_finite())
        .fold(f64::INFINITY, f64::min)
}

/// The distance from the origin to the segment from `a` to `b`.
fn segment_distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length2 = d[0] * d[0] + d[1] * d[1];
    let s = if length2 > 0.0 {
        (-(a[0] * d[0] + a[1] * d[1]) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (a[0] + s * d[0]).hypot(a[1] + s * d[1])
}

/// The torus counts at the centres of a grid of `columns` x `2 columns / 3` cells.
fn torus_grid(body: &Body, h3: f64, window: &Window, columns: usize) -> Result<TorusGrid> {
    let rows = grid_rows(columns);
    let centres = |(lo, hi): (f64, f64), n: usize| -> Vec<f64> {
        (0..n)
            .map(|i| lo + (hi - lo) * (i as f64 + 0.5) / n as f64)
            .collect()
    };
    let (ks, hs) = (centres(window.k, columns), centres(window.h1, rows));
    let tori = hs
        .iter()
        .map(|&h1| {
            ks.iter()
                .map(|&k| Ok(torus_count(body, Value { h1, h3, k })?.tori()))
                .collect::<Result<Vec<_>>>()
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(TorusGrid {
        k: ks,
        h1: hs,
        tori,
    })
}

/// The sleeping tops (vertical spins) in the plane (H3, K): for each pole, the spins at
/// `samples` values of H3 in `[-h3_max, h3_max]`, each classified, and Routh's threshold
/// value of H3 (`None` for the pole where the centre of mass is not above the geometric
/// centre, which is stable at every spin).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SleepingTop {
    /// gamma3 = +1 or -1.
    pub pole: f64,
    /// The vertical spins along the line.
    pub spins: Vec<RelativeEquilibrium>,
    /// |H3| at Routh's threshold spin.
    pub threshold_h3: Option<f64>,
}

impl SleepingTop {
    /// This line computed in `units`, in the body's units.
    pub fn back(&self, units: &Units) -> Result<Self> {
        Ok(SleepingTop {
            pole: self.pole,
            spins: self
                .spins
                .iter()
                .map(|v| v.back(units))
                .collect::<Result<_>>()?,
            threshold_h3: self
                .threshold_h3
                .map(|h3| h3 * units.momentum() * units.length()),
        })
    }
}

/// |H3| of the vertical spin at `gamma3 = pole` spinning at Routh's threshold, `None` where
/// there is no threshold ([`missing_threshold`]).
pub fn threshold_h3(body: &Body, pole: f64) -> Result<Option<f64>> {
    if missing_threshold(body, pole).is_some() {
        return Ok(None);
    }
    let state = vertical_spin_state(body, pole, routh_threshold(body, pole))?;
    Ok(Some(jellett(body, &state.to_array()).abs()))
}

/// The two lines of sleeping tops in the plane (H3, K) (see [`SleepingTop`]).
/// `h3_max` must be finite, positive and at most [`largest_h3`], `samples` (per line) between
/// 2 and [`MAX_RESOLUTION`]. Computed in the units of the plane at `h3_max` and converted
/// back.
pub fn sleeping_tops(body: &Body, h3_max: f64, samples: usize) -> Result<Vec<SleepingTop>> {
    body.require_symmetric("the sleeping tops")?;
    check_resolution("samples", samples, 2)?;
    if !(h3_max.is_finite() && h3_max > 0.0) {
        return Err(RouthError::Option {
            name: "h3_max",
            value: h3_max.to_string(),
            rule: "must be finite and positive",
        });
    }
    let units = checked_plane(body, h3_max, "h3_max")?;
    let scaled = units.body(body)?;
    let h3_max = jellett_in_units(h3_max, &units);
    [1.0, -1.0]
        .into_iter()
        .map(|pole| {
            let spins = (0..samples)
                .map(|i| {
                    let h3 = h3_max * (2.0 * i as f64 / (samples - 1) as f64 - 1.0);
                    vertical_spin_at(&scaled, pole, h3)
                })
                .collect::<Result<Vec<_>>>()?;
            let line = SleepingTop {
                pole,
                spins,
                threshold_h3: threshold_h3(&scaled, pole)?,
            };
            line.back(&units)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bound on the grid's work is checked before any work: the largest grid within
    /// [`MAX_GRID_CELLS`] passes the check, the next is refused naming the option, its cells
    /// and the largest grid accepted (exact integer arithmetic: no tolerance). Its time is
    /// measured, not tested here (docs/diagram.md).
    #[test]
    fn the_grid_is_bounded_by_its_cells_before_any_work() {
        let largest = (2..=MAX_RESOLUTION)
            .take_while(|&c| c * grid_rows(c) <= MAX_GRID_CELLS)
            .last()
            .unwrap();
        assert_eq!(largest, 387, "387 x 258 = 99846 cells");
        assert!(check_grid_cells(largest).is_ok());
        let e = check_grid_cells(largest + 1).unwrap_err().to_string();
        assert!(
            e.contains("grid = 388 (388 x 258 = 100104 cells")
                && e.contains("at most 100000 cells: grid <= 387"),
            "{e}"
        );
        // The diagram itself refuses it before computing anything (its checks come first),
        // as it does the largest grid of MAX_RESOLUTION: hours of work before the bound.
        for grid in [largest + 1, MAX_RESOLUTION] {
            let resolution = Resolution {
                grid,
                ..Resolution::default()
            };
            let e = Diagram::new(&Body::default(), 1.0, &[], resolution).unwrap_err();
            assert!(e.to_string().contains(&format!("grid = {grid} (")), "{e}");
        }
    }
}
