//! Figures of a trajectory, drawn from a [`Table`] of samples with `plotters` into PNG or SVG.
//!
//! Each figure is first described as a [`Plot`] (title, axis labels with units, named
//! series, linear or logarithmic vertical axis, equal axis scales or not); one renderer draws
//! every description. The figures:
//!
//! * [`theta_plot`]: the tilt theta(t), `cos theta = gamma3`, the angle between the downward
//!   vertical and e3; for a > 0, the angle between the upward vertical and the line from the
//!   geometric centre to the centre of mass (theta = 0: the centre of mass straight above);
//! * [`path_plot`]: the paths of the contact point and of the centre of mass on the plane,
//!   equal axis scales;
//! * [`drift_plot`]: the relative drift `|H(t) - H(0)| / |H(0)|` of each integral, log scale;
//! * [`gamma_plot`]: the trace of (gamma1, gamma2) in the body frame, equal axis scales;
//! * [`contact_plots`]: of a sliding run, the height of the centre of mass, the slip speed,
//!   the normal force over time and the drift of Jellett's integral and of the energy
//!   balance;
//! * [`difference_plot`]: `|a - b|` over time of the state columns of two tables sampled at
//!   the same times (the quadrature solution against the integrator's).
//!
//! Units: the SI units of the case (lengths in m, times in s; `G = 9.81` means metres and
//! seconds).

use crate::error::{AppError, AppResult as Result, FileError};
use crate::integrals::INTEGRAL_NAMES;
use crate::output::write_atomic;
use crate::simulate::Drift;
use crate::table::Table;
use plotters::coord::combinators::IntoLogRange;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;
use std::path::Path;
use std::str::FromStr;

/// DejaVu Sans (see `assets/DejaVuSans-LICENSE.txt`), the font of every label.
const FONT: &[u8] = include_bytes!("../../../assets/DejaVuSans.ttf");

/// Size of every figure in pixels (PNG) or user units (SVG).
pub const SIZE: (u32, u32) = (960, 640);

/// Margin around the chart and sizes of the label areas, in pixels.
pub(crate) const MARGIN: u32 = 20;
pub(crate) const X_LABEL_AREA: u32 = 60;
pub(crate) const Y_LABEL_AREA: u32 = 90;
pub(crate) const TITLE_HEIGHT: u32 = 40;

/// The colours of successive series (the "tab10" palette).
const PALETTE: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
];

/// Output format of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Portable Network Graphics, 8-bit RGB.
    Png,
    /// Scalable Vector Graphics.
    Svg,
}

impl Format {
    /// The file extension, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Png => "png",
            Format::Svg => "svg",
        }
    }
}

impl FromStr for Format {
    type Err = String;

    /// `png` or `svg`, ignoring ASCII case.
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "png" => Ok(Format::Png),
            "svg" => Ok(Format::Svg),
            _ => Err(format!("unknown format `{s}`: expected `png` or `svg`")),
        }
    }
}

/// One named curve of a figure.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub label: String,
    /// The points (x, y); non-finite points are left out when drawing.
    pub points: Vec<(f64, f64)>,
}

/// A figure, described independently of the drawing backend.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    /// The file name without extension.
    pub name: &'static str,
    /// The title above the chart.
    pub title: String,
    /// The horizontal axis label, with units.
    pub x_label: String,
    /// The vertical axis label, with units.
    pub y_label: String,
    /// The curves, coloured in order from the palette.
    pub series: Vec<Series>,
    /// Logarithmic vertical axis (values <= 0, such as the zero drift at t = 0, left out).
    pub log_y: bool,
    /// The same length per unit on both axes (for paths in a plane).
    pub equal_scale: bool,
    /// Where the legend goes (a corner the curves leave free).
    pub legend: SeriesLabelPosition,
    /// Labelled points drawn as dots (the start and the end of a path).
    pub marks: Vec<(String, (f64, f64))>,
}

fn column_series(table: &Table, x: &str, y: &str, label: &str) -> Result<Series> {
    let points = table
        .column(x)?
        .iter()
        .zip(table.column(y)?)
        .map(|(&a, &b)| (a, b))
        .collect();
    Ok(Series {
        label: label.to_string(),
        points,
    })
}

/// theta(t) in degrees, from `cos theta = gamma3 / |gamma|`.
pub fn theta_plot(table: &Table) -> Result<Plot> {
    let t = table.column("t")?;
    let g: Vec<&[f64]> = ["gamma1", "gamma2", "gamma3"]
        .iter()
        .map(|n| table.column(n))
        .collect::<Result<_>>()?;
    let points = (0..t.len())
        .map(|i| {
            let norm = (g[0][i].powi(2) + g[1][i].powi(2) + g[2][i].powi(2)).sqrt();
            (t[i], (g[2][i] / norm).clamp(-1.0, 1.0).acos().to_degrees())
        })
        .collect();
    Ok(Plot {
        name: "theta",
        title: "Tilt of the symmetry axis".into(),
        x_label: "time t (s)".into(),
        y_label: "θ (degrees), cos θ = γ3".into(),
        series: vec![Series {
            label: "θ(t)".into(),
            points,
        }],
        log_y: false,
        equal_scale: false,
        legend: SeriesLabelPosition::UpperRight,
        marks: Vec::new(),
    })
}

/// The contact-point path and the centre-of-mass path on the plane (needs the columns of
/// `routh simulate --full`).
pub fn path_plot(table: &Table) -> Result<Plot> {
    let contact = column_series(table, "contact_x", "contact_y", "contact point")?;
    let ends = [contact.points.first(), contact.points.last()];
    let marks = ["start", "end"]
        .into_iter()
        .zip(ends)
        .filter_map(|(label, point)| Some((label.to_string(), *point?)))
        .collect();
    Ok(Plot {
        name: "contact_path",
        title: "Paths on the plane (seen from above)".into(),
        x_label: "x (m)".into(),
        y_label: "y (m)".into(),
        series: vec![contact, column_series(table, "x", "y", "centre of mass")?],
        log_y: false,
        equal_scale: true,
        legend: SeriesLabelPosition::UpperRight,
        marks,
    })
}

/// The running maximum over `[0, t]` of the relative drift `|H(s) - H(0)| / |H(0)|` of each
/// integral column present with finite values: the raw drift jumps over orders of magnitude
/// from sample to sample, its running maximum reads at a glance. A table holds no body, so
/// the drift of an integral with H(0) = 0 cannot be measured in its unit (as the summaries'
/// [`Drift`](crate::simulate::Drift) is): it is drawn as `|H(s)|`, in the table's units, and
/// its label says so.
pub fn drift_plot(table: &Table) -> Result<Plot> {
    let t = table.column("t")?;
    let mut series = Vec::new();
    for name in INTEGRAL_NAMES {
        let Ok(h) = table.column(name) else { continue };
        if !h[0].is_finite() {
            continue;
        }
        let points = running_drift(t, h);
        let label = if h[0] == 0.0 {
            format!("{name} (absolute: {name}(0) = 0)")
        } else {
            name.to_string()
        };
        series.push(Series { label, points });
    }
    if series.is_empty() {
        return Err(FileError::Table {
            origin: table.origin.clone(),
            message: format!("no integral columns ({})", INTEGRAL_NAMES.join(", ")),
        }
        .into());
    }
    Ok(Plot {
        name: "integral_drift",
        title: "Relative drift of the integrals (running maximum)".into(),
        x_label: "time t (s)".into(),
        y_label: "max over [0, t] of |H − H(0)| / |H(0)|".into(),
        series,
        log_y: true,
        equal_scale: false,
        legend: SeriesLabelPosition::UpperLeft,
        marks: Vec::new(),
    })
}

/// The running maximum of the relative drift of `h` from `h[0]` over the times `t` (in the
/// unit 1 of the table's units where `h[0] = 0`: a table holds no body).
fn running_drift(t: &[f64], h: &[f64]) -> Vec<(f64, f64)> {
    t.iter()
        .zip(h)
        .scan(Drift::start(h[0], || 1.0), |drift, (&t, &v)| {
            drift.observe(v);
            Some((t, drift.max_rel_drift))
        })
        .collect()
}

/// A quantity of a sliding run over time: the column `column` of the table.
fn time_plot(
    table: &Table,
    column: &str,
    name: &'static str,
    title: &str,
    y: &str,
) -> Result<Plot> {
    Ok(Plot {
        name,
        title: title.into(),
        x_label: "time t (s)".into(),
        y_label: y.into(),
        series: vec![column_series(table, "t", column, column)?],
        log_y: false,
        equal_scale: false,
        legend: SeriesLabelPosition::UpperRight,
        marks: Vec::new(),
    })
}

/// The figures of a sliding run (a table of `routh simulate` with `[contact] law =
/// "sliding"`): the height of the centre of mass, the slip speed and the normal force over
/// time, and the balances: the drift of Jellett's integral and of the energy plus the
/// friction's work (running maximum, log scale), both constant for any friction.
pub fn contact_plots(table: &Table) -> Result<Vec<Plot>> {
    Ok(vec![
        time_plot(
            table,
            "height",
            "height",
            "Height of the centre of mass",
            "height above the plane (m)",
        )?,
        time_plot(
            table,
            "slip_speed",
            "slip_speed",
            "Slip speed of the contact point",
            "|v_P| (m/s)",
        )?,
        time_plot(
            table,
            "normal_force",
            "normal_force",
            "Normal force of the plane",
            "N (newton)",
        )?,
        balance_plot(table)?,
    ])
}

/// The balances of a sliding run: the drift of Jellett's integral and of H1 + W (running
/// maximum, log scale), both constant for any friction.
pub fn balance_plot(table: &Table) -> Result<Plot> {
    let t = table.column("t")?;
    let (jellett, balance) = (table.column("jellett")?, table.column("H1_plus_work")?);
    Ok(Plot {
        name: "balance",
        title: "Drift of Jellett's integral and of the energy plus the friction's work".into(),
        x_label: "time t (s)".into(),
        y_label: "max over [0, t] of the relative drift".into(),
        series: vec![
            Series {
                label: "Jellett (L, r)".into(),
                points: running_drift(t, jellett),
            },
            Series {
                label: "H1 + W (energy plus the friction's work)".into(),
                points: running_drift(t, balance),
            },
        ],
        log_y: true,
        equal_scale: false,
        legend: SeriesLabelPosition::UpperLeft,
        marks: Vec::new(),
    })
}

/// The trace of (gamma1, gamma2), the horizontal part of the normal in the body frame.
pub fn gamma_plot(table: &Table) -> Result<Plot> {
    Ok(Plot {
        name: "gamma_trace",
        title: "Trace of (γ1, γ2) in the body frame".into(),
        x_label: "γ1 (dimensionless)".into(),
        y_label: "γ2 (dimensionless)".into(),
        series: vec![column_series(table, "gamma1", "gamma2", "(γ1, γ2)")?],
        log_y: false,
        equal_scale: true,
        legend: SeriesLabelPosition::UpperRight,
        marks: Vec::new(),
    })
}

/// The vectors compared by [`difference_plot`]: legend label and component columns.
const COMPARED_VECTORS: [(&str, [&str; 3]); 3] = [
    ("|Δγ| (dimensionless)", ["gamma1", "gamma2", "gamma3"]),
    ("|ΔM| (kg m²/s)", ["M1", "M2", "M3"]),
    ("|Δω| (rad/s)", ["omega1", "omega2", "omega3"]),
];

/// The Euclidean norm of the difference `a - b` over time of gamma, M and omega (each vector
/// whose three columns are in both tables); the tables must be sampled at the same times.
/// `labels` name a and b in the title (for example `("quadrature", "DOP853")`).
pub fn difference_plot(a: &Table, b: &Table, labels: (&str, &str)) -> Result<Plot> {
    let error = |message: &str| {
        AppError::from(FileError::Table {
            origin: format!("{} and {}", a.origin, b.origin),
            message: message.to_string(),
        })
    };
    let (ta, tb) = (a.column("t")?, b.column("t")?);
    let same_times = ta.len() == tb.len()
        && ta
            .iter()
            .zip(tb)
            .all(|(x, y)| (x - y).abs() <= 1e-9 * (1.0 + x.abs()));
    if !same_times {
        return Err(error("the two tables are not sampled at the same times"));
    }
    let mut series = Vec::new();
    for (label, names) in COMPARED_VECTORS {
        if !names.iter().all(|n| a.has(n) && b.has(n)) {
            continue;
        }
        let mut squares = vec![0.0; ta.len()];
        for name in names {
            for ((sum, x), y) in squares.iter_mut().zip(a.column(name)?).zip(b.column(name)?) {
                *sum += (x - y) * (x - y);
            }
        }
        series.push(Series {
            label: label.to_string(),
            points: ta
                .iter()
                .zip(squares)
                .map(|(&t, s)| (t, s.sqrt()))
                .collect(),
        });
    }
    if series.is_empty() {
        return Err(error(
            "no common columns gamma1..3, M1..3 or omega1..3 to compare",
        ));
    }
    Ok(Plot {
        name: "difference",
        title: format!("Difference {} − {}", labels.0, labels.1),
        x_label: "time t (s)".into(),
        y_label: "norm of the difference".into(),
        series,
        log_y: true,
        equal_scale: false,
        legend: SeriesLabelPosition::LowerRight,
        marks: Vec::new(),
    })
}

/// The four standard figures of a table; the path figure only when the table has the columns
/// of `routh simulate --full`; of a sliding run's table, theta, [`contact_plots`] and the trace
/// of gamma. Returns the figures and, for each left out, the reason.
pub fn standard_plots(table: &Table) -> Result<(Vec<Plot>, Vec<String>)> {
    let mut plots = vec![theta_plot(table)?];
    let mut skipped = Vec::new();
    if table.column("slip_speed").is_ok() {
        plots.extend(contact_plots(table)?);
        plots.push(gamma_plot(table)?);
        return Ok((plots, skipped));
    }
    match path_plot(table) {
        Ok(plot) => plots.push(plot),
        Err(e) => skipped.push(format!(
            "contact_path: {e} (write the CSV with `routh simulate --full`)"
        )),
    }
    plots.push(drift_plot(table)?);
    plots.push(gamma_plot(table)?);
    Ok((plots, skipped))
}

/// Bounds `(min, max)` of the finite values, widened when empty or degenerate.
pub(crate) fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        (0.0, 1.0)
    } else if hi - lo <= 1e-12 * (1.0 + lo.abs()) {
        let pad = 1e-3 * (1.0 + lo.abs());
        (lo - pad, hi + pad)
    } else {
        (lo, hi)
    }
}

/// Ranges with 5% padding; with `equal`, the shorter one widened about its middle so that a
/// unit has the same length on both axes of a plotting area of `pixels` (width, height).
pub fn chart_ranges(
    x: (f64, f64),
    y: (f64, f64),
    equal: bool,
    pixels: (u32, u32),
) -> (Range<f64>, Range<f64>) {
    let pad = |(lo, hi): (f64, f64)| {
        let p = 0.05 * (hi - lo);
        (lo - p, hi + p)
    };
    let (mut x, mut y) = (pad(x), pad(y));
    if equal {
        let per_pixel = ((x.1 - x.0) / f64::from(pixels.0)).max((y.1 - y.0) / f64::from(pixels.1));
        let widen = |(lo, hi): (f64, f64), n: u32| {
            let mid = 0.5 * (lo + hi);
            let half = 0.5 * per_pixel * f64::from(n);
            (mid - half, mid + half)
        };
        x = widen(x, pixels.0);
        y = widen(y, pixels.1);
    }
    (x.0..x.1, y.0..y.1)
}

/// The size in pixels of the plotting area inside a figure of [`SIZE`].
pub fn plotting_area() -> (u32, u32) {
    (
        SIZE.0 - 2 * MARGIN - Y_LABEL_AREA,
        SIZE.1 - TITLE_HEIGHT - 2 * MARGIN - X_LABEL_AREA,
    )
}

/// A tick label on an axis spanning `span`: round-off zeros (|v| < 1e-9 span) as `0`, exponent
/// notation on very long or short axes, else four decimals without trailing zeros, no `-0`.
pub fn tick_label(v: f64, span: f64) -> String {
    if v.abs() < 1e-9 * span {
        return "0".to_string();
    }
    if !(1e-3..1e5).contains(&span) {
        return format!("{v:.2e}");
    }
    let text = format!("{v:.4}");
    match text.trim_end_matches('0').trim_end_matches('.') {
        "-0" => "0".to_string(),
        t => t.to_string(),
    }
}

fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
            .unwrap_or_else(|_| panic!("the shipped DejaVu Sans parses"));
    });
}

impl Plot {
    fn draw<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        root.fill(&WHITE)?;
        let (top, body) = root.split_vertically(TITLE_HEIGHT);
        top.titled(&self.title, ("sans-serif", 26))?;
        let x = bounds(
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.0)),
        );
        let y = bounds(self.drawn_points().map(|p| p.1));
        if self.log_y {
            let (xr, _) = chart_ranges(x, y, false, plotting_area());
            let (lo, hi) = if y.0 > 0.0 { y } else { (1e-16, 1.0) };
            self.draw_chart(&body, xr, (lo / 2.0..hi * 2.0).log_scale(), hi - lo)
        } else {
            let (xr, yr) = chart_ranges(x, y, self.equal_scale, plotting_area());
            let span = yr.end - yr.start;
            self.draw_chart(&body, xr, yr, span)
        }
    }

    /// The points that can be drawn: finite, and positive on a logarithmic axis.
    fn drawn_points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.series.iter().flat_map(|s| self.drawable(s))
    }

    fn drawable<'s>(&self, series: &'s Series) -> impl Iterator<Item = (f64, f64)> + 's {
        let log = self.log_y;
        series
            .points
            .iter()
            .copied()
            .filter(move |p| p.0.is_finite() && p.1.is_finite() && (!log || p.1 > 0.0))
    }

    fn draw_chart<DB: DrawingBackend, Y>(
        &self,
        area: &DrawingArea<DB, Shift>,
        x: Range<f64>,
        y: Y,
        y_span: f64,
    ) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>>
    where
        Y: AsRangedCoord<Value = f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let y_format = |v: &f64| {
            if self.log_y {
                format!("{v:.0e}")
            } else {
                tick_label(*v, y_span)
            }
        };
        let x_span = x.end - x.start;
        let mut chart = ChartBuilder::on(area)
            .margin(MARGIN)
            .x_label_area_size(X_LABEL_AREA)
            .y_label_area_size(Y_LABEL_AREA)
            .build_cartesian_2d(x, y)?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .x_label_formatter(&|v| tick_label(*v, x_span))
            .y_label_formatter(&y_format)
            .label_style(("sans-serif", 16))
            .axis_desc_style(("sans-serif", 18))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()?;
        for (series, &colour) in self.series.iter().zip(PALETTE.iter().cycle()) {
            chart
                .draw_series(LineSeries::new(
                    self.drawable(series),
                    colour.stroke_width(1),
                ))?
                .label(series.label.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(3))
                });
        }
        for (label, point) in &self.marks {
            chart.draw_series(std::iter::once(
                EmptyElement::at(*point)
                    + Circle::new((0, 0), 5, BLACK.filled())
                    + Text::new(label.clone(), (8, -20), ("sans-serif", 16)),
            ))?;
        }
        chart
            .configure_series_labels()
            .position(self.legend.clone())
            .label_font(("sans-serif", 16))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
        Ok(())
    }

    /// Draw into `dir/<name>.<ext>` (written atomically) and return the path.
    pub fn render(&self, dir: &Path, format: Format) -> Result<std::path::PathBuf> {
        let path = dir.join(format!("{}.{}", self.name, format.extension()));
        render_figure(self, &path, format)?;
        Ok(path)
    }
}

/// Something drawn onto a figure of [`SIZE`] by any plotters backend.
pub trait Figure {
    /// Draw onto `root` (already the whole figure).
    fn draw_on<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>>;
}

impl Figure for Plot {
    fn draw_on<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
    ) -> std::result::Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
        self.draw(root)
    }
}

/// Draw `figure` into `path` in `format` (written atomically, with the shipped font).
pub fn render_figure(figure: &impl Figure, path: &Path, format: Format) -> Result<()> {
    render_figure_sized(figure, path, format, SIZE)
}

/// [`render_figure`] at `size` pixels (width, height) instead of [`SIZE`]: the one writer of
/// every figure's SVG and PNG (the PNG drawn into memory and encoded by the `png` crate).
pub fn render_figure_sized(
    figure: &impl Figure,
    path: &Path,
    format: Format,
    size: (u32, u32),
) -> Result<()> {
    register_font();
    let failed = |e: &dyn std::fmt::Display| {
        AppError::from(FileError::Plot {
            figure: path.display().to_string(),
            message: e.to_string(),
        })
    };
    match format {
        Format::Svg => {
            let mut text = String::new();
            {
                let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
                figure.draw_on(&root).map_err(|e| failed(&e))?;
                root.present().map_err(|e| failed(&e))?;
            }
            crate::output::write_bytes_atomic(path, text.as_bytes())?;
        }
        Format::Png => {
            let mut pixels = vec![0u8; (size.0 * size.1 * 3) as usize];
            {
                let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
                figure.draw_on(&root).map_err(|e| failed(&e))?;
                root.present().map_err(|e| failed(&e))?;
            }
            write_atomic(path, |w| {
                let mut encoder = png::Encoder::new(w, size.0, size.1);
                encoder.set_color(png::ColorType::Rgb);
                encoder.set_depth(png::BitDepth::Eight);
                encoder.set_compression(png::Compression::Best);
                encoder.set_filter(png::FilterType::Paeth);
                let mut writer = encoder.write_header().map_err(|e| failed(&e))?;
                writer.write_image_data(&pixels).map_err(|e| failed(&e))
            })?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_scale_has_equal_units_per_pixel() {
        let pixels = plotting_area();
        let (x, y) = chart_ranges((0.0, 10.0), (-1.0, 1.0), true, pixels);
        let per_x = (x.end - x.start) / f64::from(pixels.0);
        let per_y = (y.end - y.start) / f64::from(pixels.1);
        assert!((per_x / per_y - 1.0).abs() < 1e-12);
        assert!(x.start <= 0.0 && x.end >= 10.0 && y.start <= -1.0 && y.end >= 1.0);
        // Negative control: without equal scales the units differ here.
        let (x, y) = chart_ranges((0.0, 10.0), (-1.0, 1.0), false, pixels);
        let ratio =
            (x.end - x.start) / f64::from(pixels.0) / ((y.end - y.start) / f64::from(pixels.1));
        assert!((ratio - 1.0).abs() > 0.5);
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick_label(-5.55e-17, 0.6), "0");
        assert_eq!(tick_label(0.25, 0.6), "0.25");
        assert_eq!(tick_label(-2.0, 10.0), "-2");
        assert_eq!(tick_label(2e-5, 4e-5), "2.00e-5");
    }

    #[test]
    fn format_names() {
        assert_eq!("PNG".parse::<Format>(), Ok(Format::Png));
        assert_eq!("svg".parse::<Format>(), Ok(Format::Svg));
        assert!("gif".parse::<Format>().is_err());
    }
}
