//! The figures of the diagram (PNG and SVG, through [`crate::plot::render_figure`]):
//!
//! * [`EnergyMomentum`]: the plane (K, H1) at fixed H3, regions shaded by the number of tori,
//!   critical curves coloured by stability type, the vertical spins and focus–focus points,
//!   the monodromy loop and the marked values;
//! * [`SleepingTopFigure`]: the plane (H3, K) with the lines of vertical spins, coloured where
//!   they are stable and where not (Routh's criterion), the thresholds marked;
//! * [`RotationNumberFigure`]: the rotation number W along the monodromy loop;
//! * [`SectionFigure`]: a Poincaré section, the crossings of each run in a colour of its own;
//! * [`RegimeChartFigure`]: a chart of regimes, the mean MEGNO over a parameter plane as a
//!   heat map with its colour bar;
//! * [`InversionFigure`]: the tippe top's inversion region, the final tilt over (alpha,
//!   I1 / I3) with the published boundaries.

use crate::plot::{
    bounds, chart_ranges, plotting_area, tick_label, Figure, MARGIN, TITLE_HEIGHT, X_LABEL_AREA,
    Y_LABEL_AREA,
};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use routh_sphere::diagram::energy_momentum::{Diagram, SleepingTop};
use routh_sphere::diagram::monodromy::Monodromy;
use routh_sphere::diagram::stability::StabilityType;
use routh_sphere::diagram::Value;

/// The colour of a stability type.
pub fn stability_colour(kind: StabilityType) -> RGBColor {
    match kind {
        StabilityType::Elliptic => RGBColor(31, 119, 180),
        StabilityType::Hyperbolic => RGBColor(214, 39, 40),
        StabilityType::FocusFocus => RGBColor(148, 0, 211),
        StabilityType::Degenerate => RGBColor(0, 0, 0),
        StabilityType::Undecided => RGBColor(150, 150, 150),
    }
}

/// The shade of a region with `tori` tori (`None`: critical).
fn region_colour(tori: Option<usize>) -> RGBColor {
    match tori {
        Some(0) => RGBColor(255, 255, 255),
        Some(1) => RGBColor(222, 235, 247),
        Some(2) => RGBColor(199, 233, 192),
        Some(_) => RGBColor(253, 208, 162),
        None => RGBColor(190, 190, 190),
    }
}

/// A chart with linear axes in f64.
type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

type Drawn<DB> = std::result::Result<(), DrawingAreaErrorKind<<DB as DrawingBackend>::ErrorType>>;

fn mesh<'a, DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x: (f64, f64),
    y: (f64, f64),
    labels: (&str, &str),
) -> std::result::Result<Chart<'a, DB>, DrawingAreaErrorKind<DB::ErrorType>> {
    area.fill(&WHITE)?;
    let (top, body) = area.split_vertically(TITLE_HEIGHT);
    top.titled(title, ("sans-serif", 24))?;
    let mut chart = ChartBuilder::on(&body)
        .margin(MARGIN)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    let (sx, sy) = (x.1 - x.0, y.1 - y.0);
    chart
        .configure_mesh()
        .x_desc(labels.0)
        .y_desc(labels.1)
        .x_label_formatter(&|v| tick_label(*v, sx))
        .y_label_formatter(&|v| tick_label(*v, sy))
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .disable_mesh()
        .draw()?;
    Ok(chart)
}

/// A marked value: a black triangle with its label.
fn mark<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    label: &str,
    at: (f64, f64),
) -> Drawn<DB> {
    chart.draw_series(std::iter::once(
        EmptyElement::at(at)
            + TriangleMarker::new((0, 0), 8, BLACK.filled())
            + Text::new(label.to_string(), (10, -22), ("sans-serif", 16)),
    ))?;
    Ok(())
}

/// The legend box at `position`.
fn legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    position: SeriesLabelPosition,
) -> Drawn<DB> {
    chart
        .configure_series_labels()
        .position(position)
        .label_font(("sans-serif", 15))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
}

/// The (K, H1) plane of a [`Diagram`], with the values to mark (label, value).
pub struct EnergyMomentum<'a> {
    /// The diagram.
    pub diagram: &'a Diagram,
    /// Values marked with a star and a label (the case's own).
    pub marks: Vec<(String, Value)>,
}

impl Figure for EnergyMomentum<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        let d = self.diagram;
        let title = format!("Energy-momentum diagram at Jellett H3 = {:.6}", d.h3);
        let mut chart = mesh(
            root,
            &title,
            d.window.k,
            d.window.h1,
            ("Routh's K", "energy H1"),
        )?;
        let (grid, ks, hs) = (&d.tori.tori, &d.tori.k, &d.tori.h1);
        let half = |v: &[f64]| 0.5 * (v[v.len() - 1] - v[0]) / (v.len() - 1) as f64;
        let (dk, dh) = (half(ks), half(hs));
        // One rectangle per run of equal cells in a row (a small SVG).
        let mut cells = vec![];
        for (row, &h) in grid.iter().zip(hs) {
            let mut start = 0;
            for i in 1..=row.len() {
                if i == row.len() || row[i] != row[start] {
                    let corners = [(ks[start] - dk, h - dh), (ks[i - 1] + dk, h + dh)];
                    cells.push(Rectangle::new(corners, region_colour(row[start]).filled()));
                    start = i;
                }
            }
        }
        chart.draw_series(cells)?;
        for n in 0..=3 {
            let label = match n {
                3 => "3 or more tori".to_string(),
                1 => "1 torus".to_string(),
                _ => format!("{n} tori"),
            };
            if grid
                .iter()
                .flatten()
                .any(|&c| c.map(|c| c.min(3)) == Some(n))
            {
                let colour = region_colour(Some(n));
                chart
                    .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())?
                    .label(label)
                    .legend(move |(x, y)| {
                        Rectangle::new([(x, y - 6), (x + 20, y + 6)], colour.filled())
                    });
            }
        }
        let inside = |v: &Value| {
            v.k >= d.window.k.0
                && v.k <= d.window.k.1
                && v.h1 >= d.window.h1.0
                && v.h1 <= d.window.h1.1
        };
        let mut legend_done = vec![];
        for curve in &d.critical_curves {
            let colour = stability_colour(curve.stability);
            // Only the runs of points inside the window (plotters would clamp the others onto
            // its border).
            let runs = curve
                .points
                .split(|p| !inside(&p.value))
                .filter(|run| run.len() > 1);
            let mut series = None;
            for run in runs {
                series = Some(chart.draw_series(LineSeries::new(
                    run.iter().map(|p| (p.value.k, p.value.h1)),
                    colour.stroke_width(3),
                ))?);
            }
            let Some(series) = series else {
                continue;
            };
            if !legend_done.contains(&curve.stability) {
                legend_done.push(curve.stability);
                series
                    .label(format!("steady precessions, {}", curve.stability.name()))
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(3))
                    });
            }
        }
        if let Some(m) = &d.monodromy {
            let grey = RGBColor(90, 90, 90);
            chart
                .draw_series(LineSeries::new(
                    m.points.iter().map(|p| (p.value.k, p.value.h1)),
                    grey.stroke_width(2),
                ))?
                .label("monodromy loop")
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(2))
                });
        }
        for spin in d.vertical_spins.iter().filter(|s| inside(&s.value)) {
            let colour = stability_colour(spin.stability);
            let name = if spin.stability == StabilityType::FocusFocus {
                "focus-focus".to_string()
            } else {
                format!("vertical spin ({})", spin.stability.name())
            };
            let label = format!("{name}, gamma3 = {:+}", spin.state.gamma()[2].round());
            // Labels of points in the right half go to their left.
            let right = spin.value.k > 0.5 * (d.window.k.0 + d.window.k.1);
            let offset = if right {
                (-12 - 8 * label.len() as i32, 6)
            } else {
                (12, 6)
            };
            chart.draw_series(std::iter::once(
                EmptyElement::at((spin.value.k, spin.value.h1))
                    + Cross::new((0, 0), 9, colour.stroke_width(3))
                    + Circle::new((0, 0), 9, colour.stroke_width(2))
                    + Text::new(label, offset, ("sans-serif", 16)),
            ))?;
        }
        for (label, value) in self.marks.iter().filter(|(_, v)| inside(v)) {
            mark(&mut chart, label, (value.k, value.h1))?;
        }
        legend(&mut chart, SeriesLabelPosition::UpperLeft)
    }
}

/// The plane (H3, K) of the sleeping tops, with the marked values (label, (H3, K)).
pub struct SleepingTopFigure<'a> {
    /// The two lines.
    pub lines: &'a [SleepingTop],
    /// Values marked with a star and a label.
    pub marks: Vec<(String, (f64, f64))>,
    /// The H3 of the energy–momentum diagram (drawn as a vertical line).
    pub h3: f64,
}

impl Figure for SleepingTopFigure<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        let points = || self.lines.iter().flat_map(|l| &l.spins);
        let fold = |f: fn(&routh_sphere::diagram::RelativeEquilibrium) -> f64| {
            points()
                .map(f)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                    (a.min(v), b.max(v))
                })
        };
        let (x, y) = (fold(|p| p.value.h3), fold(|p| p.value.k));
        let pad = |(a, b): (f64, f64)| (a - 0.05 * (b - a), b + 0.05 * (b - a));
        let mut chart = mesh(
            root,
            "Sleeping tops: stable (elliptic) or not (focus-focus), Routh's criterion",
            pad(x),
            pad(y),
            ("Jellett H3", "Routh's K"),
        )?;
        let mut legend_done = vec![];
        for line in self.lines {
            for pair in line.spins.windows(2) {
                let kind = pair[0].stability.max(pair[1].stability);
                let colour = stability_colour(kind);
                let series = chart.draw_series(LineSeries::new(
                    pair.iter().map(|p| (p.value.h3, p.value.k)),
                    colour.stroke_width(3),
                ))?;
                if !legend_done.contains(&kind) {
                    legend_done.push(kind);
                    series
                        .label(format!("vertical spins, {}", kind.name()))
                        .legend(move |(x, y)| {
                            PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(3))
                        });
                }
            }
            let end = &line.spins[line.spins.len() - 1];
            chart.draw_series(std::iter::once(
                EmptyElement::at((end.value.h3, end.value.k))
                    + Text::new(
                        format!("gamma3 = {:+}", line.pole),
                        (-110, 10),
                        ("sans-serif", 16),
                    ),
            ))?;
            if let Some(t) = line.threshold_h3 {
                let slope = end.value.k / end.value.h3;
                for h3 in [-t, t] {
                    chart.draw_series(std::iter::once(
                        EmptyElement::at((h3, slope * h3))
                            + Circle::new((0, 0), 6, BLACK.filled())
                            + Text::new("Routh's threshold", (8, 8), ("sans-serif", 15)),
                    ))?;
                }
            }
        }
        let grey = RGBColor(120, 120, 120);
        chart
            .draw_series(LineSeries::new(
                [(self.h3, y.0), (self.h3, y.1)],
                grey.stroke_width(1),
            ))?
            .label(format!("H3 = {:.4} of the diagram", self.h3))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], grey.stroke_width(1))
            });
        for (label, point) in &self.marks {
            mark(&mut chart, label, *point)?;
        }
        legend(&mut chart, SeriesLabelPosition::UpperLeft)
    }
}

/// The rotation number along the monodromy loop.
pub struct RotationNumberFigure<'a> {
    /// The monodromy.
    pub monodromy: &'a Monodromy,
}

impl Figure for RotationNumberFigure<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        let m = self.monodromy;
        let w = m.points.iter().map(|p| p.rotation_number);
        let lo = w.clone().fold(0.0_f64, f64::min).floor();
        let hi = w.fold(1.0_f64, f64::max).ceil();
        let title = format!(
            "Rotation number W along the loop around the focus-focus value: change {}",
            m.winding
        );
        let mut chart = mesh(
            root,
            &title,
            (0.0, 2.0 * std::f64::consts::PI),
            (lo - 0.05, hi + 0.05),
            (
                "loop angle phi (counter-clockwise in the (K, H1) plane)",
                "W = Theta / (2 pi)",
            ),
        )?;
        let blue = stability_colour(StabilityType::Elliptic);
        chart
            .draw_series(LineSeries::new(
                m.points.iter().map(|p| (p.phi, p.rotation_number)),
                blue.stroke_width(3),
            ))?
            .label("W followed continuously")
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], blue.stroke_width(3))
            });
        let orange = RGBColor(255, 127, 14);
        chart
            .draw_series(m.points.iter().map(|p| {
                Circle::new(
                    (p.phi, p.advance / (2.0 * std::f64::consts::PI)),
                    3,
                    orange.filled(),
                )
            }))?
            .label("Theta / (2 pi) from the quadrature, in [0, 1)")
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, orange.filled()));
        legend(&mut chart, SeriesLabelPosition::LowerLeft)
    }
}

/// A Poincaré section: two components of the crossings, one dot each, coloured by run (the
/// hue from red for the first run to violet for the last).
pub struct SectionFigure<'a> {
    /// The title above the chart.
    pub title: String,
    /// The names of the horizontal and vertical components.
    pub labels: (&'a str, &'a str),
    /// The crossings: `(run, x, y)`.
    pub points: Vec<(usize, f64, f64)>,
    /// The number of runs (for the colours).
    pub runs: usize,
}

impl Figure for SectionFigure<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        let x = bounds(self.points.iter().map(|p| p.1));
        let y = bounds(self.points.iter().map(|p| p.2));
        let (xr, yr) = chart_ranges(x, y, false, plotting_area());
        let mut chart = mesh(
            root,
            &self.title,
            (xr.start, xr.end),
            (yr.start, yr.end),
            self.labels,
        )?;
        let runs = self.runs.max(1) as f64;
        chart.draw_series(
            self.points
                .iter()
                .filter(|p| p.1.is_finite() && p.2.is_finite())
                .map(|&(run, x, y)| {
                    let colour = HSLColor(0.8 * run as f64 / runs, 0.85, 0.42);
                    Circle::new((x, y), 1, colour.filled())
                }),
        )?;
        Ok(())
    }
}

/// The top of the colour scale of a [`RegimeChartFigure`]: `<Y>` above it has its colour.
pub const MEGNO_SCALE_TOP: f64 = 8.0;

/// The colour of a mean MEGNO `<Y>` (ColorBrewer's RdYlBu, reversed, piecewise linear): dark
/// blue at 0 and below (periodic, attractors), light blue at 1, pale yellow at 2 (tori),
/// orange at 4, dark red at [`MEGNO_SCALE_TOP`] and above (chaos); grey for a failed run.
pub fn megno_colour(mean_megno: f64) -> RGBColor {
    ramp(
        &[
            (0.0, (49.0, 54.0, 149.0)),
            (1.0, (116.0, 173.0, 209.0)),
            (2.0, (255.0, 255.0, 191.0)),
            (4.0, (244.0, 109.0, 67.0)),
            (MEGNO_SCALE_TOP, (165.0, 0.0, 38.0)),
        ],
        mean_megno,
    )
}

/// The colour of a final tilt of the centre of mass (ColorBrewer's RdYlBu, reversed): dark
/// blue at 0 (upright), pale yellow at pi / 2, dark red at pi (inverted); grey for a failed
/// run.
pub fn tilt_colour(tilt: f64) -> RGBColor {
    use std::f64::consts::PI;
    ramp(
        &[
            (0.0, (49.0, 54.0, 149.0)),
            (0.25 * PI, (116.0, 173.0, 209.0)),
            (0.5 * PI, (255.0, 255.0, 191.0)),
            (0.75 * PI, (244.0, 109.0, 67.0)),
            (PI, (165.0, 0.0, 38.0)),
        ],
        tilt,
    )
}

/// The colour of `v` on the piecewise linear scale `stops` (value, RGB), ascending, clamped
/// to its ends; grey for NaN.
fn ramp(stops: &[(f64, (f64, f64, f64))], v: f64) -> RGBColor {
    if v.is_nan() {
        return RGBColor(150, 150, 150);
    }
    let v = v.clamp(stops[0].0, stops[stops.len() - 1].0);
    let i = stops
        .iter()
        .rposition(|s| s.0 <= v)
        .unwrap_or(0)
        .min(stops.len() - 2);
    let ((a, ca), (b, cb)) = (stops[i], stops[i + 1]);
    let u = (v - a) / (b - a);
    let mix = |p: f64, q: f64| (p + (q - p) * u).round() as u8;
    RGBColor(mix(ca.0, cb.0), mix(ca.1, cb.1), mix(ca.2, cb.2))
}

/// The width of the colour bar's strip at the right of a [`RegimeChartFigure`].
const COLOUR_BAR_STRIP: u32 = 150;

/// A chart of regimes: a heat map of the mean MEGNO `<Y>` over a grid of two parameters (one
/// rectangle a point, [`megno_colour`]), with its colour bar.
pub struct RegimeChartFigure<'a> {
    /// The title above the chart.
    pub title: String,
    /// The names of the horizontal and vertical parameters.
    pub labels: (&'a str, &'a str),
    /// The horizontal axis: first and last values, number of points.
    pub x: (f64, f64, usize),
    /// The vertical axis.
    pub y: (f64, f64, usize),
    /// The points: `(x, y, <Y>)`, NaN for a failed run.
    pub points: Vec<(f64, f64, f64)>,
}

impl Figure for RegimeChartFigure<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        root.fill(&WHITE)?;
        let (map, strip) = root.split_horizontally(root.dim_in_pixel().0 - COLOUR_BAR_STRIP);
        let half = |(from, to, n): (f64, f64, usize)| 0.5 * (to - from) / (n - 1) as f64;
        let (hx, hy) = (half(self.x), half(self.y));
        let mut chart = mesh(
            &map,
            &self.title,
            (self.x.0 - hx, self.x.1 + hx),
            (self.y.0 - hy, self.y.1 + hy),
            self.labels,
        )?;
        chart.draw_series(self.points.iter().map(|&(x, y, v)| {
            Rectangle::new(
                [(x - hx, y - hy), (x + hx, y + hy)],
                megno_colour(v).filled(),
            )
        }))?;
        colour_bar(
            &strip,
            "mean MEGNO <Y>",
            MEGNO_SCALE_TOP,
            &megno_colour,
            &|v| {
                if v >= MEGNO_SCALE_TOP {
                    format!(">= {v}")
                } else {
                    tick_label(v, MEGNO_SCALE_TOP)
                }
            },
        )?;
        Ok(())
    }
}

/// A vertical colour bar on `strip` from 0 to `top`, `colour` its scale, `label` its ticks.
fn colour_bar<DB: DrawingBackend>(
    strip: &DrawingArea<DB, Shift>,
    description: &str,
    top: f64,
    colour: &dyn Fn(f64) -> RGBColor,
    label: &dyn Fn(f64) -> String,
) -> Drawn<DB> {
    let (_, bar_area) = strip.split_vertically(TITLE_HEIGHT);
    let mut bar = ChartBuilder::on(&bar_area)
        .margin(MARGIN)
        .margin_left(0)
        .x_label_area_size(X_LABEL_AREA)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..1.0, 0.0..top)?;
    bar.configure_mesh()
        .disable_x_axis()
        .disable_mesh()
        .y_desc(description)
        .y_label_formatter(&|v| label(*v))
        .label_style(("sans-serif", 16))
        .axis_desc_style(("sans-serif", 18))
        .draw()?;
    let steps = 160;
    let dv = top / f64::from(steps);
    bar.draw_series((0..steps).map(|i| {
        let v = f64::from(i) * dv;
        Rectangle::new([(0.0, v), (1.0, v + dv)], colour(v + dv / 2.0).filled())
    }))?;
    Ok(())
}

/// The points of a curve of a figure.
type Curve = Vec<(f64, f64)>;

/// The inversion region of the tippe top ([`crate::inversion`]): the final tilt of each point
/// of the plane (alpha, I1 / I3) as a heat map ([`tilt_colour`]) with its colour bar, and the
/// published boundaries drawn on it: `I1 / I3 = 1 - alpha` and `1 + alpha` (black),
/// `1 - alpha^2` (grey: where the threshold's theorem is proved) and the curve where Jellett's
/// integral meets its threshold (magenta).
pub struct InversionFigure<'a> {
    /// The title above the chart.
    pub title: String,
    /// The alpha axis: first and last values, number of points.
    pub x: (f64, f64, usize),
    /// The I1 / I3 axis.
    pub y: (f64, f64, usize),
    /// The points `(alpha, ratio, final tilt)`, NaN for a failed run.
    pub points: Vec<(f64, f64, f64)>,
    /// The curve `lambda = lambda_thres`.
    pub threshold: &'a [(f64, f64)],
}

impl Figure for InversionFigure<'_> {
    fn draw_on<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Drawn<DB> {
        root.fill(&WHITE)?;
        let (map, strip) = root.split_horizontally(root.dim_in_pixel().0 - COLOUR_BAR_STRIP);
        let half = |(from, to, n): (f64, f64, usize)| 0.5 * (to - from) / (n - 1) as f64;
        let (hx, hy) = (half(self.x), half(self.y));
        let (xs, ys) = (
            (self.x.0 - hx, self.x.1 + hx),
            (self.y.0 - hy, self.y.1 + hy),
        );
        let mut chart = mesh(&map, &self.title, xs, ys, ("alpha = a / R", "I1 / I3"))?;
        chart.draw_series(self.points.iter().map(|&(x, y, v)| {
            Rectangle::new(
                [(x - hx, y - hy), (x + hx, y + hy)],
                tilt_colour(v).filled(),
            )
        }))?;
        let n = 200;
        let line = |f: &dyn Fn(f64) -> f64| -> Vec<(f64, f64)> {
            (0..=n)
                .map(|i| xs.0 + (xs.1 - xs.0) * f64::from(i) / f64::from(n))
                .map(|a| (a, f(a)))
                .filter(|&(_, q)| q >= ys.0 && q <= ys.1)
                .collect()
        };
        let grey = RGBColor(110, 110, 110);
        let magenta = RGBColor(200, 0, 160);
        let curves: [(Curve, RGBColor, &str); 4] = [
            (line(&|a| 1.0 - a), BLACK, "I1/I3 = 1 - alpha, 1 + alpha"),
            (line(&|a| 1.0 + a), BLACK, ""),
            (line(&|a| 1.0 - a * a), grey, "I1/I3 = 1 - alpha^2"),
            (self.threshold.to_vec(), magenta, "Jellett = lambda_thres"),
        ];
        for (points, colour, label) in curves {
            if points.len() < 2 {
                continue;
            }
            let series = chart.draw_series(LineSeries::new(points, colour.stroke_width(3)))?;
            if !label.is_empty() {
                series.label(label).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(3))
                });
            }
        }
        legend(&mut chart, SeriesLabelPosition::LowerRight)?;
        colour_bar(
            &strip,
            "final tilt of the centre of mass, rad",
            std::f64::consts::PI,
            &tilt_colour,
            &|v| tick_label(v, std::f64::consts::PI),
        )?;
        Ok(())
    }
}
