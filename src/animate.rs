//! An animation of the rolling ball: a self-contained HTML page (inline JavaScript, a canvas,
//! the samples embedded as JSON, no network) with two views of the motion in space, from
//! above and from the side (looking along +y). It shows the ball, the centre of mass, a
//! body-fixed marker (the pole where the symmetry axis +e3 leaves the ball, red) and the
//! body-fixed circle of the e1-e2 plane, both projected with the quaternion, and the trail
//! of the contact point. Play, pause, speed and a time slider.
//!
//! The page needs the columns of `routh simulate --full`. The radius R and the offset a are
//! recovered from the samples, so a CSV file suffices: the horizontal offset from the centre of
//! mass to the contact point is `a n_h`, with `n = Q e3` the symmetry axis in space (least
//! squares over the samples), and the height of the centre of mass is `R + a gamma3`.

use crate::error::{Result, RouthError};
use crate::motion::{rotate, FULL_COLUMN_NAMES};
use crate::table::Table;
use nalgebra::Quaternion;
use serde::Serialize;

/// At most this many frames are embedded (the samples are thinned evenly beyond it).
pub const MAX_FRAMES: usize = 1500;

const TEMPLATE: &str = include_str!("animate.html");

/// The data embedded in the page.
#[derive(Debug, Serialize)]
struct Frames {
    radius: f64,
    a: f64,
    t: Vec<f64>,
    q: Vec<[f64; 4]>,
    com: Vec<[f64; 3]>,
    contact: Vec<[f64; 2]>,
}

/// The rows of `table` restricted to the columns a frame needs: t, gamma3 and the columns of
/// `routh simulate --full` ([`FULL_COLUMN_NAMES`]), in that order.
fn frame_rows(table: &Table) -> Result<Vec<[f64; 11]>> {
    let names = || ["t", "gamma3"].into_iter().chain(FULL_COLUMN_NAMES);
    if let Some(missing) = names().find(|n| !table.has(n)) {
        return Err(RouthError::Table {
            origin: table.origin.clone(),
            message: format!(
                "no column `{missing}`: the animation needs the columns of `routh simulate --full`"
            ),
        });
    }
    let columns: Vec<&[f64]> = names().map(|n| table.column(n)).collect::<Result<_>>()?;
    Ok((0..table.len())
        .map(|i| std::array::from_fn(|j| columns[j][i]))
        .collect())
}

/// The radius R and offset a of the ball that produced `table`, from the columns of
/// `routh simulate --full` (see the module documentation). If the symmetry axis stays vertical,
/// a cannot be separated from R and is taken as 0.
pub fn recover_geometry(table: &Table) -> Result<(f64, f64)> {
    let rows = frame_rows(table)?;
    let (mut num, mut den) = (0.0, 0.0);
    for [_, _, qw, qx, qy, qz, x, y, _, cx, cy] in &rows {
        let n = rotate(&Quaternion::new(*qw, *qx, *qy, *qz), &[0.0, 0.0, 1.0]);
        num += (cx - x) * n[0] + (cy - y) * n[1];
        den += n[0] * n[0] + n[1] * n[1];
    }
    let a = if den > 1e-12 * rows.len() as f64 {
        num / den
    } else {
        0.0
    };
    let radius = rows.iter().map(|r| r[8] - a * r[1]).sum::<f64>() / rows.len() as f64;
    if !(radius.is_finite() && radius > 0.0) {
        return Err(RouthError::Table {
            origin: table.origin.clone(),
            message: format!("the samples give a ball radius R = {radius}, not > 0"),
        });
    }
    Ok((radius, a))
}

/// The HTML page animating the samples of `table` (columns of `routh simulate --full`).
pub fn html(table: &Table) -> Result<String> {
    let (radius, a) = recover_geometry(table)?;
    let rows = frame_rows(table)?;
    let stride = rows.len().div_ceil(MAX_FRAMES).max(1);
    let shown: Vec<&[f64; 11]> = rows.iter().step_by(stride).collect();
    let frames = Frames {
        radius,
        a,
        t: shown.iter().map(|r| r[0]).collect(),
        q: shown.iter().map(|r| [r[2], r[3], r[4], r[5]]).collect(),
        com: shown.iter().map(|r| [r[6], r[7], r[8]]).collect(),
        contact: shown.iter().map(|r| [r[9], r[10]]).collect(),
    };
    let data = serde_json::to_string(&frames).map_err(|e| RouthError::Table {
        origin: table.origin.clone(),
        message: format!("cannot embed the samples: {e}"),
    })?;
    Ok(TEMPLATE
        .replace("__SOURCE__", &escape_html(&table.origin))
        .replace("__DATA__", &data))
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_radius_and_offset_from_samples() {
        let case = crate::case::Case::default_case().unwrap();
        let table = crate::table::simulate_full(&case, 2.0, 101).unwrap();
        let (radius, a) = recover_geometry(&table).unwrap();
        assert!((radius - case.ball.radius).abs() < 1e-12, "R = {radius}");
        assert!((a + case.ball.com[2]).abs() < 1e-12, "a = {a}");
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(escape_html("<a&b>"), "&lt;a&amp;b&gt;");
    }
}
