//! `routh steady`: the stationary motions for the body of a case and their linear stability
//! (from the double root of Q and from the Jacobian's eigenvalues), with Routh's threshold.

use super::Readable;
use routh::case::Case;
use routh::steady::{
    missing_threshold, precessions_at_tilt, routh_threshold, vertical_spin, Decision, Stability,
    SteadyPrecession, Verdict, VerticalSpin, RESOLVED_PRECISION,
};
use routh::{AppResult as Result, Body};
use serde::Serialize;
use std::path::PathBuf;

/// Tilts (degrees) at which the steady precessions are listed.
const TILTS_DEGREES: [f64; 11] = [
    15.0, 30.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0, 165.0,
];

/// Options of `routh steady`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML); the built-in default case when omitted. Its body is used, and the
    /// spin omega3 of its initial state.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    pub json: bool,
}

#[derive(Serialize)]
struct Report {
    case: String,
    body: Body,
    /// The spin rate omega3 used (the case's initial omega3).
    spin: f64,
    /// Routh's threshold |omega3| for the vertical spin with the centre of mass above the
    /// geometric centre (0 when there is none: a = 0 or G = 0; kept as it was, see
    /// `routh_threshold`).
    threshold_spin: f64,
    /// Routh's threshold |omega3| of the vertical spin with the centre of mass above the
    /// geometric centre; `null` when there is none, `no_threshold` saying why.
    routh_threshold: Option<f64>,
    /// Why there is no threshold (`null` when there is one).
    no_threshold: Option<&'static str>,
    /// gamma3 of the vertical spin with the centre of mass above (None when a = 0).
    top_heavy_gamma3: Option<f64>,
    vertical: Vec<VerticalSpin>,
    precessions: Vec<SteadyPrecession>,
    /// The tilts at which a far steady precession, if one exists, is beyond the resolution of
    /// the samples and not listed (omega_t of order 1 / m for a tiny mass m).
    unlisted_far_precessions: Vec<Unlisted>,
}

/// A tilt with an unlisted far steady precession.
#[derive(Serialize)]
struct Unlisted {
    theta: f64,
    /// A steady precession at this tilt, if any is unlisted, has |omega_t| beyond about this.
    beyond_omega_t: f64,
}

/// The one answer of the two criteria with the margin of each: "stable: Q'' = .. (round-off
/// ..), max Re lambda = .. (tolerance ..)", or "undecided within the accuracy: ...".
fn verdict(s: &Stability, v: &Verdict) -> String {
    format!(
        "{}: Q'' = {:.6e} (round-off {:.1e}), max Re lambda = {:.3e} (tolerance {:.1e})",
        v.decision.words(),
        s.q_second_derivative,
        v.q_accuracy,
        s.max_real_eigenvalue,
        v.eigenvalue_tolerance
    )
}

fn print_text(r: &Report) -> Result<()> {
    outln!("case: {}", r.case)?;
    outln!("spin omega3 = {}", r.spin)?;
    outln!("vertical spins (gamma = (0, 0, +-1), omega = (0, 0, omega3)):")?;
    for v in &r.vertical {
        let threshold = match (v.routh_threshold, v.no_threshold) {
            (Some(w), _) => format!("threshold |omega3| = {}", Readable(w)),
            (None, reason) => format!("no threshold ({})", reason.unwrap_or_default()),
        };
        outln!(
            "  gamma3 = {:+}: centre of mass {}, {threshold}; {}",
            v.gamma3,
            v.centre_of_mass,
            verdict(&v.stability, &v.verdict)
        )?;
    }
    outln!(
        "steady precessions at constant tilt (omega_n = 0); dpsi/dt: gamma about e3 in the body,"
    )?;
    outln!("dphi/dt: the symmetry axis e3 about the upward vertical in space:")?;
    outln!("  theta        omega_t      dpsi/dt      dphi/dt      Q''          verdict")?;
    for p in &r.precessions {
        let mut words = match p.verdict.decision {
            Decision::Undecided => verdict(&p.stability, &p.verdict),
            decided => decided.words().to_string(),
        };
        if p.omega_t_accuracy > RESOLVED_PRECISION * p.omega_t.abs() {
            words += &format!(
                " (omega_t known only to +-{:.1e}, its round-off)",
                p.omega_t_accuracy
            );
        }
        outln!(
            "  {:<12.6} {:<12.6} {:<12.6} {:<12.6} {:<12.4e} {words}",
            p.theta,
            p.omega_t,
            p.precession,
            p.axis_precession,
            p.stability.q_second_derivative,
        )?;
    }
    for u in &r.unlisted_far_precessions {
        outln!(
            "  at theta = {:.6}: a steady precession with |omega_t| beyond about {:.3e}, if one exists, is not resolved and not listed",
            u.theta,
            u.beyond_omega_t
        )?;
    }
    Ok(())
}

/// Run `routh steady`.
pub fn run(args: Args) -> Result<()> {
    let case = Case::load(args.case.as_deref())?;
    let body = case.body("routh steady")?;
    let spin = case.initial.omega(&body)[2];
    let vertical = [1.0, -1.0]
        .into_iter()
        .map(|pole| vertical_spin(&body, pole, spin))
        .collect::<routh::Result<Vec<_>>>()?;
    let top_heavy_gamma3 = (body.a() != 0.0).then(|| body.a().signum());
    let mut precessions = vec![];
    let mut unlisted_far_precessions = vec![];
    for degrees in TILTS_DEGREES {
        let theta = degrees.to_radians();
        let found = precessions_at_tilt(&body, theta, spin)?;
        precessions.extend(found.precessions);
        if let Some(beyond_omega_t) = found.unlisted_beyond {
            unlisted_far_precessions.push(Unlisted {
                theta,
                beyond_omega_t,
            });
        }
    }
    let report = Report {
        case: case.source.clone(),
        body,
        spin,
        threshold_spin: top_heavy_gamma3.map_or(0.0, |p| routh_threshold(&body, p)),
        routh_threshold: vertical
            .iter()
            .find(|v| v.centre_of_mass_above)
            .and_then(|v| v.routh_threshold),
        no_threshold: missing_threshold(&body, top_heavy_gamma3.unwrap_or(1.0)),
        top_heavy_gamma3,
        vertical,
        precessions,
        unlisted_far_precessions,
    };
    if args.json {
        super::print_json(&report)?;
    } else {
        print_text(&report)?;
    }
    Ok(())
}
