//! A sweep of the sliding contact (`[contact] law = "sliding"`, viscous or Coulomb's
//! friction): each run is the sliding run of `routh simulate` on the run's case (the same
//! numbers), its row the work and the balances of its summary
//! ([`super::columns::CONTACT_NAMES`]): the switches, the height of the centre of mass, the
//! final tilt (which tells a top that turned upside down from one that did not), the slip,
//! the least normal force, Jellett's integral and the energy balance. A run where the ball
//! leaves the plane ends with status `event` and that reason.

use super::record::{Row, SlidingRun, Status};
use crate::case::SlidingStart;
use crate::contact::sliding::run;
use crate::error::AppError;
use crate::integrate::scalar::dot;
use crate::simulate::Settings;

/// The row of run `k` (swept values `values`) of a sweep of the sliding contact, from the
/// run's validated start: [`run`] with `settings` (no samples), its summary kept.
pub fn row(
    k: u64,
    values: Vec<f64>,
    start: &SlidingStart,
    settings: &Settings,
) -> Result<Row, AppError> {
    let summary = run::<AppError>(&start.model, start.y0, settings, &mut |_| Ok(()))?;
    let com = start.model.ball().com();
    let size = dot(&com, &com).sqrt();
    let gamma = summary.final_state.gamma;
    let tilt_final = (size > 0.0).then(|| (dot(&com, &gamma) / size).clamp(-1.0, 1.0).acos());
    let (status, message) = match summary.status {
        "ok" => (Status::Reached, String::new()),
        _ => (Status::Event, summary.message.clone()),
    };
    Ok(Row {
        run: k,
        values,
        status,
        message,
        summary: None,
        events: None,
        quadrature: None,
        user_events: Vec::new(),
        sliding: Some(SlidingRun {
            summary,
            tilt_final,
        }),
    })
}

#[cfg(test)]
mod tests {
    use crate::case::{Case, Overrides};
    use crate::row::Cell;
    use crate::sweep::record::RunSettings;
    use crate::sweep::Sweep;

    const TIPPE_TOP: &str = include_str!("../../../../cases/tippe_top.toml");

    /// The tippe top's case with the `[sweep]` table `sweep` added.
    fn sweep(case: &str, sweep: &str) -> crate::error::AppResult<Sweep> {
        let text = format!("{case}\n[sweep]\n{sweep}\n");
        Sweep::new(&text, "tippe_top.toml", Overrides::default(), None, None)
    }

    /// Each row's cells by column name.
    fn cells(sweep: &Sweep) -> Vec<std::collections::BTreeMap<String, Cell>> {
        let settings: RunSettings = sweep.run_settings();
        let names: Vec<String> = sweep.table_columns().into_iter().map(|c| c.0).collect();
        sweep
            .rows(0, sweep.runs(), 1)
            .unwrap()
            .iter()
            .map(|r| names.iter().cloned().zip(r.cells(&settings)).collect())
            .collect()
    }

    fn float(row: &std::collections::BTreeMap<String, Cell>, name: &str) -> f64 {
        match &row[name] {
            Cell::Float(Some(v)) => *v,
            other => panic!("{name}: {other:?}"),
        }
    }

    /// The tippe top spun at 20 turns upside down (the final tilt near pi, the centre
    /// of mass at R + a) and spun at 6 does not (it rises part of the way, its centre of mass
    /// staying below the centre: a tilt below pi / 2); each row is
    /// `routh simulate`'s run of the same case (the heights equal bit for bit), with Jellett's
    /// integral kept (1e-9: the runs' 1e-12 over 20 time units). `contact.mu` is swept: with
    /// no friction (mu = 0) nothing can raise the centre of mass (the tilt stays within 0.3).
    #[test]
    fn a_sweep_of_the_tippe_top_tells_the_tops_that_turn_over() {
        let s = sweep(
            TIPPE_TOP,
            "spin = { values = [6.0, 20.0] }\n\"contact.mu\" = { values = [0.0, 0.3] }",
        )
        .unwrap();
        let rows = cells(&s);
        assert_eq!(rows.len(), 4);
        for row in &rows {
            let (spin, mu) = (float(row, "spin"), float(row, "contact.mu"));
            let tilt = float(row, "tilt_final");
            let inverted = spin == 20.0 && mu > 0.0;
            if inverted {
                assert!(
                    tilt > 3.0 && (float(row, "height_final") - 1.3).abs() < 1e-2,
                    "{row:?}"
                );
            } else if mu > 0.0 {
                assert!(tilt < std::f64::consts::FRAC_PI_2, "{spin} {mu}: {tilt}");
            } else {
                assert!(tilt < 0.3, "{spin} {mu}: {tilt}");
            }
            assert!(float(row, "jellett_drift") <= 1e-9, "{row:?}");
            assert!(matches!(&row["status"], Cell::Text(t) if t == "ok"));
            let text = TIPPE_TOP
                .replace(
                    "omega = [0.0, 0.0, 20.0]",
                    &format!("omega = [0.0, 0.0, {spin:?}]"),
                )
                .replace("mu = 0.3", &format!("mu = {mu:?}"));
            let case = Case::parse_any_contact(&text, "one run").unwrap();
            let start = case.sliding.unwrap();
            let one = crate::contact::sliding::run::<crate::error::AppError>(
                &start.model,
                start.y0,
                &s.settings,
                &mut |_| Ok(()),
            )
            .unwrap();
            assert_eq!(float(row, "height_final"), one.final_state.height);
        }
    }

    /// The same sweep in other units (masses x 1e6, lengths x 1e-2, times x 1e-3: G, the
    /// moments, the spin, t_end and the viscous mu, of dimension time over length, follow)
    /// gives the same final tilts to 1e-7 (the runs' 1e-12 amplified by the inversion's
    /// sensitivity) and the heights in the new unit of length: the thresholds are relative.
    #[test]
    fn the_sliding_sweep_is_the_same_in_other_units() {
        let (mass, length, time) = (1e6_f64, 1e-2_f64, 1e-3_f64);
        let scaled = crate::inversion::tippe_top_in_units(mass, length, time)
            .replace("omega = [0.0, 0.0, 20.0]", "omega = [0.0, 0.0, 0.0]");
        let axis = |unit: f64| {
            format!(
                "spin = {{ values = [{:?}, {:?}] }}",
                6.0 / unit,
                20.0 / unit
            )
        };
        let base = cells(&sweep(TIPPE_TOP, &axis(1.0)).unwrap());
        let other = cells(&sweep(&scaled, &axis(time)).unwrap());
        for (a, b) in base.iter().zip(&other) {
            let (ta, tb) = (float(a, "tilt_final"), float(b, "tilt_final"));
            assert!((ta - tb).abs() <= 1e-7, "{ta} {tb}");
            let (ha, hb) = (float(a, "height_final"), float(b, "height_final") / length);
            assert!((ha - hb).abs() <= 1e-7, "{ha} {hb}");
            assert!(float(b, "jellett_drift") <= 1e-9);
        }
    }

    /// What a sweep of the sliding contact cannot do is refused with the reason: `contact.mu`
    /// in a case of the rolling law (naming the key), the rolling law's columns, the rubber
    /// ball.
    #[test]
    fn what_a_sliding_sweep_cannot_do_is_refused() {
        let default = include_str!("../../../../cases/default.toml");
        let e = sweep(default, "\"contact.mu\" = { values = [0.3] }")
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("contact.mu") && e.contains("law = \"sliding\""),
            "{e}"
        );
        let text = format!("{TIPPE_TOP}\n[sweep]\nspin = {{ values = [6.0] }}\n");
        let columns = crate::sweep::Columns::parse(["integrals"]).unwrap();
        let e = Sweep::new(&text, "t", Overrides::default(), Some(columns), None)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("H1_initial") && e.contains("final, contact"),
            "{e}"
        );
        let rubber = include_str!("../../../../cases/rubber.toml");
        let e = sweep(rubber, "tilt = { values = [0.3] }")
            .unwrap_err()
            .to_string();
        assert!(e.contains("rubber"), "{e}");
    }
}
