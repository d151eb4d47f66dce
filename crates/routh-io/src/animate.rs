//! The 3D viewer of the rolling ball: one self-contained HTML page (WebGL through an inlined
//! build of three.js, the samples embedded, no network at view time).
//!
//! The page shows the ball in space (z up, the plane z = 0 with a grid), textured with the
//! octants of its body frame so that its rotation is visible, with the symmetry axis e3 as a
//! rod (red tip at +e3), the centre of mass (seen through the ball), the body point that
//! touched the plane at the first sample, and the trail of the contact point; an orbit/zoom
//! camera; play, pause, speed and a time slider; beside it theta(t) and the drift of the
//! integrals with a cursor at the current time. Between samples the page interpolates: the
//! quaternion by slerp, positions linearly. Every sample is embedded (none is dropped), as
//! base64 of little-endian `f32` columns, about 5.3 characters a number.
//!
//! Frames (see [`crate::motion`]): the body group of the scene has its origin at the centre of
//! mass and is turned by the samples' quaternion `q` (body to space, `v_space = Q v_body`);
//! the sphere is centred at `+a e3` in the body frame. The marker of the first contact point
//! sits at the body point `r = R gamma(0) + a e3`, with gamma from the gamma columns, so that
//! a quaternion read with the wrong convention puts it away from the plane at t = 0 (the
//! browser test in `tests/browser` checks this and the contact point at every sample).
//!
//! The page needs the columns of `routh simulate --full`. The radius R and the offset a are
//! recovered from the samples, so a CSV file suffices: the horizontal offset from the centre of
//! mass to the contact point is `a n_h`, with `n = Q e3` the symmetry axis in space (least
//! squares over the samples), and the height of the centre of mass is `R + a gamma3`.

use crate::error::{AppError, AppResult as Result, FileError};
use crate::motion::{rotate, FULL_COLUMN_NAMES};
use crate::plot::{balance_plot, drift_plot, theta_plot};
use crate::table::Table;
use nalgebra::Quaternion;
use serde::Serialize;
use std::collections::BTreeMap;

const TEMPLATE: &str = include_str!("animate.html");

/// three.js r187 (npm `three@0.187.0`, MIT licence in `assets/viewer/three-LICENSE.txt`): the
/// classes listed in `assets/viewer/three-entry.js`, bundled by `assets/viewer/build-three.sh`.
const THREE_JS: &str = include_str!("../../../assets/viewer/three.min.js");

/// The 3D view of the ball and its charts (`viewer.js`): the one script of this page and of
/// the explorer's ([`crate::explore`]).
const VIEWER_JS: &str = include_str!("viewer.js");

/// The parts of the page that the explorer's page shares, as the keys of [`fill`]:
/// `VIEWER_STYLE` (`viewer.css`), `PLAYBACK` (play, speed, time, follow: `viewer-playback.html`)
/// and `VIEWER_SCRIPTS` (three.js and `viewer.js`, in `viewer-scripts.html`).
fn viewer_parts() -> [(&'static str, String); 3] {
    [
        ("VIEWER_STYLE", include_str!("viewer.css").to_string()),
        ("PLAYBACK", include_str!("viewer-playback.html").to_string()),
        (
            "VIEWER_SCRIPTS",
            fill(
                include_str!("viewer-scripts.html"),
                &[("THREE", THREE_JS), ("VIEWER", VIEWER_JS)],
            ),
        ),
    ]
}

/// The decades of slip speed below the largest over which a sliding contact's trail is shaded.
const SLIP_DECADES: f64 = 4.0;

/// The columns a frame needs, in the order of [`frame_rows`]: t, gamma and the columns of
/// `routh simulate --full` ([`FULL_COLUMN_NAMES`]).
const FRAME_COLUMNS: usize = 4 + FULL_COLUMN_NAMES.len();

/// The data embedded in the page.
#[derive(Debug, Serialize)]
struct Embedded {
    radius: f64,
    a: f64,
    /// gamma at the first sample, from the gamma columns.
    gamma0: [f64; 3],
    /// Name to base64 of little-endian f32: t, qw, qx, qy, qz, x, y, z, contact_x, contact_y,
    /// theta (degrees).
    columns: BTreeMap<&'static str, String>,
    /// (integral, base64 of its running maximum relative drift), in the order of the figure.
    drift: Vec<(String, String)>,
}

fn frame_names() -> impl Iterator<Item = &'static str> {
    ["t", "gamma1", "gamma2", "gamma3"]
        .into_iter()
        .chain(FULL_COLUMN_NAMES)
}

/// The rows of `table` restricted to the columns a frame needs ([`FRAME_COLUMNS`]), checked:
/// every value finite, t strictly increasing.
fn frame_rows(table: &Table) -> Result<Vec<[f64; FRAME_COLUMNS]>> {
    let error = |message: String| {
        AppError::from(FileError::Table {
            origin: table.origin.clone(),
            message,
        })
    };
    if let Some(missing) = frame_names().find(|n| !table.has(n)) {
        return Err(error(format!(
            "no column `{missing}`: the animation needs the columns of `routh simulate --full`"
        )));
    }
    let columns: Vec<&[f64]> = frame_names()
        .map(|n| table.column(n))
        .collect::<Result<_>>()?;
    let rows: Vec<[f64; FRAME_COLUMNS]> = (0..table.len())
        .map(|i| std::array::from_fn(|j| columns[j][i]))
        .collect();
    for (i, row) in rows.iter().enumerate() {
        if let Some(j) = row.iter().position(|v| !v.is_finite()) {
            let name = frame_names().nth(j).unwrap_or("?");
            return Err(error(format!(
                "sample {} (row {}): `{name}` = {} is not finite",
                i + 1,
                i + 2,
                row[j]
            )));
        }
        if i > 0 && row[0] <= rows[i - 1][0] {
            return Err(error(format!(
                "sample {} (row {}): t = {} does not increase (t = {} before it)",
                i + 1,
                i + 2,
                row[0],
                rows[i - 1][0]
            )));
        }
    }
    Ok(rows)
}

/// The radius R and offset a of the ball that produced `table`, from the columns of
/// `routh simulate --full` (see the module documentation). If the symmetry axis stays vertical,
/// a cannot be separated from R and is taken as 0.
pub fn recover_geometry(table: &Table) -> Result<(f64, f64)> {
    geometry(&frame_rows(table)?, &table.origin)
}

fn geometry(rows: &[[f64; FRAME_COLUMNS]], origin: &str) -> Result<(f64, f64)> {
    let (mut num, mut den) = (0.0, 0.0);
    for [_, _, _, _, qw, qx, qy, qz, x, y, _, cx, cy] in rows {
        let n = rotate(&Quaternion::new(*qw, *qx, *qy, *qz), &[0.0, 0.0, 1.0]);
        num += (cx - x) * n[0] + (cy - y) * n[1];
        den += n[0] * n[0] + n[1] * n[1];
    }
    let a = if den > 1e-12 * rows.len() as f64 {
        num / den
    } else {
        0.0
    };
    let radius = rows.iter().map(|r| r[10] - a * r[3]).sum::<f64>() / rows.len() as f64;
    if !(radius.is_finite() && radius > 0.0) {
        return Err(FileError::Table {
            origin: origin.to_string(),
            message: format!("the samples give a ball radius R = {radius}, not > 0"),
        }
        .into());
    }
    Ok((radius, a))
}

/// Standard base64 (RFC 4648, with padding) of `bytes`.
pub(crate) fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let word = chunk
            .iter()
            .enumerate()
            .fold(0u32, |w, (i, &b)| w | u32::from(b) << (16 - 8 * i));
        for i in 0..4 {
            out.push(if i <= chunk.len() {
                ALPHABET[(word >> (18 - 6 * i) & 63) as usize] as char
            } else {
                '='
            });
        }
    }
    out
}

/// base64 of the values as little-endian `f32` (7 significant digits: far below a pixel).
fn f32_column(values: impl Iterator<Item = f64>) -> String {
    let bytes: Vec<u8> = values.flat_map(|v| (v as f32).to_le_bytes()).collect();
    base64(&bytes)
}

/// `template` with its own `values` and the parts shared by the viewer's pages
/// ([`viewer_parts`]) in place of their keys ([`fill`]).
pub(crate) fn fill_viewer_page(template: &str, values: &[(&str, String)]) -> String {
    let parts = viewer_parts();
    let all: Vec<(&str, &str)> = values
        .iter()
        .chain(&parts)
        .map(|(key, value)| (*key, value.as_str()))
        .collect();
    fill(template, &all)
}

/// Replace each `__KEY__` of `template` by its value, in one pass (a value that itself
/// contains `__KEY__`, such as a file name, is left alone).
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out =
        String::with_capacity(template.len() + values.iter().map(|v| v.1.len()).sum::<usize>());
    let mut rest = template;
    while let Some(start) = rest.find("__") {
        let found = values.iter().find(|(key, _)| {
            rest[start + 2..].starts_with(key) && rest[start + 2 + key.len()..].starts_with("__")
        });
        let Some((key, value)) = found else {
            out.push_str(&rest[..start + 2]);
            rest = &rest[start + 2..];
            continue;
        };
        out.push_str(&rest[..start]);
        out.push_str(value);
        rest = &rest[start + 4 + key.len()..];
    }
    out.push_str(rest);
    out
}

/// The HTML page showing the samples of `table` (columns of `routh simulate --full`) in 3D.
pub fn html(table: &Table) -> Result<String> {
    let rows = frame_rows(table)?;
    let (radius, a) = geometry(&rows, &table.origin)?;
    let column = |j: usize| f32_column(rows.iter().map(|r| r[j]));
    // gamma (columns 1 to 3) is embedded at the first sample only, as `gamma0`.
    let mut columns: BTreeMap<&'static str, String> = frame_names()
        .enumerate()
        .filter(|(j, _)| !(1..4).contains(j))
        .map(|(j, n)| (n, column(j)))
        .collect();
    let theta = theta_plot(table)?;
    columns.insert(
        "theta",
        f32_column(theta.series[0].points.iter().map(|p| p.1)),
    );
    // A sliding contact's trail is shaded by its slip speed, on a log scale over the four
    // decades below the largest (0: rolling, or a slip 1e-4 of the largest; 1: the largest).
    if let Ok(slip) = table.column("slip_speed") {
        let top = slip.iter().copied().fold(0.0, f64::max);
        let share = |v: f64| {
            if top > 0.0 && v > 0.0 {
                (1.0 + (v / top).log10() / SLIP_DECADES).clamp(0.0, 1.0)
            } else {
                0.0
            }
        };
        columns.insert("slip", f32_column(slip.iter().map(|&v| share(v))));
    }
    // A CSV without integral columns still animates; the page says the drift is missing. A
    // sliding contact's drift is that of its balances (its H1 is no integral).
    let drift = balance_plot(table)
        .or_else(|_| drift_plot(table))
        .map(|plot| plot.series)
        .unwrap_or_default()
        .into_iter()
        .map(|s| (s.label, f32_column(s.points.iter().map(|p| p.1))))
        .collect();
    let embedded = Embedded {
        radius,
        a,
        gamma0: [rows[0][1], rows[0][2], rows[0][3]],
        columns,
        drift,
    };
    let data = serde_json::to_string(&embedded).map_err(|e| FileError::Table {
        origin: table.origin.clone(),
        message: format!("cannot embed the samples: {e}"),
    })?;
    let number = |v: f64| format!("{}", (v * 1e6).round() / 1e6);
    let last = rows[rows.len() - 1][0];
    Ok(fill_viewer_page(
        TEMPLATE,
        &[
            ("SOURCE", escape_html(&table.origin)),
            ("SAMPLES", rows.len().to_string()),
            ("T0", number(rows[0][0])),
            ("T1", number(last)),
            ("RADIUS", number(radius)),
            ("OFFSET", number(a)),
            ("DATA", data),
        ],
    ))
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::case::{Case, Overrides};

    /// The full motion of `case` over [0, `t_end`] (DOP853 at its tolerances), in
    /// `samples` samples.
    fn simulate_full(case: &Case, t_end: f64, samples: usize) -> Table {
        let overrides = Overrides {
            t_end: Some(t_end),
            ..Overrides::default()
        };
        crate::table::simulate_full(case, &overrides, samples).unwrap()
    }

    #[test]
    fn recovers_radius_and_offset_from_samples() {
        let case = crate::case::Case::default_case().unwrap();
        let table = simulate_full(&case, 2.0, 101);
        let (radius, a) = recover_geometry(&table).unwrap();
        assert!((radius - case.ball.radius()).abs() < 1e-12, "R = {radius}");
        assert!((a + case.ball.com()[2]).abs() < 1e-12, "a = {a}");
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(escape_html("<a&b>"), "&lt;a&amp;b&gt;");
    }

    #[test]
    fn base64_matches_the_rfc_4648_vectors() {
        // RFC 4648, section 10; a wrong bit order or padding changes these strings.
        for (input, expected) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(input.as_bytes()), expected, "{input}");
        }
        assert_eq!(base64(&[0xff, 0xfe, 0x00]), "//4A");
    }

    #[test]
    fn fill_replaces_keys_once_and_leaves_the_rest() {
        let page = fill("a __X__ b __Y__ c __Z__ d__", &[("X", "__Y__"), ("Y", "1")]);
        assert_eq!(page, "a __Y__ b 1 c __Z__ d__");
    }

    /// `table` with the value of column `name` in row `row` replaced.
    fn changed(table: &Table, row: usize, name: &str, value: f64) -> Table {
        let mut out = Table::new("changed.csv", table.names().to_vec());
        for i in 0..table.len() {
            let cells: Vec<f64> = table
                .names()
                .iter()
                .map(|n| match (i, n.as_str()) {
                    (i, n) if i == row && n == name => value,
                    _ => table.column(n).unwrap()[i],
                })
                .collect();
            out.push_row(&cells).unwrap();
        }
        out
    }

    #[test]
    fn samples_without_integrals_still_animate() {
        let case = crate::case::Case::default_case().unwrap();
        let full = simulate_full(&case, 1.0, 5);
        let mut table = Table::new("frames.csv", frame_names().map(str::to_string).collect());
        for i in 0..full.len() {
            let row: Vec<f64> = frame_names().map(|n| full.column(n).unwrap()[i]).collect();
            table.push_row(&row).unwrap();
        }
        let page = html(&table).unwrap();
        assert!(page.contains("\"drift\":[]"), "no drift series");
        assert!(
            html(&full).unwrap().contains("\"drift\":[[\"H1\","),
            "drift series"
        );
    }

    #[test]
    fn refuses_samples_that_do_not_advance_or_are_not_finite() {
        let case = crate::case::Case::default_case().unwrap();
        let table = simulate_full(&case, 1.0, 5);
        assert!(html(&changed(&table, 2, "qx", table.column("qx").unwrap()[2])).is_ok());
        let err = html(&changed(&table, 1, "t", 0.0)).unwrap_err();
        assert!(err.to_string().contains("does not increase"), "{err}");
        let err = html(&changed(&table, 3, "qx", f64::NAN)).unwrap_err();
        assert!(err.to_string().contains("`qx` = NaN"), "{err}");
        let err = html(&changed(&table, 0, "gamma2", f64::INFINITY)).unwrap_err();
        assert!(err.to_string().contains("`gamma2` = inf"), "{err}");
    }
}
