//! `routh exact --flow X1|X2|Xhat2`: the flow of a Hamiltonian field of the first bracket
//! (p-br) at (cond) or (cond2) by the theta quadrature of section 3.2 ([`routh::poisson::flows`]),
//! with the outputs of `routh exact` (the same JSON keys where they apply, the same CSV).

use super::exact::{integrals_text, state_text, tilt_text, write_samples, Args, Sample, Tilt};
use routh::case::check_option;
use routh::diagram::Value;
use routh::poisson::flows::{Field, Flow};
use routh::{AppResult as Result, Point};
use serde::Serialize;
use std::fmt::Write as _;

/// The summary printed by `routh exact --flow`.
#[derive(Serialize)]
struct Summary {
    case: String,
    flow: &'static str,
    condition: &'static str,
    alpha: f64,
    /// The motion of theta; the precession is that of phi = atan2(gamma1, gamma2).
    #[serde(flatten)]
    tilt: Tilt,
    /// The state at t.
    #[serde(flatten)]
    state: Sample,
    /// The integrals' values (at the initial state: the flow keeps them).
    #[serde(flatten)]
    integrals: Value,
}

/// Run `routh exact --flow` (chosen in [`super::main`]).
pub fn run(args: &Args, field: Field) -> Result<()> {
    let case = args.case.load()?;
    let body = case.body("the flows of the first bracket")?;
    let t = args.checked_time(&case)?;
    check_option(
        "alpha",
        args.alpha,
        args.alpha.is_finite() && args.alpha != 0.0,
        "must be finite and nonzero",
    )?;
    let bracket = args.condition.bracket(body, args.alpha);
    let x0 = case.initial.to_array();
    let flow = Flow::new(bracket, field, &x0)?;
    let state_at = |ti: f64| Point::from_array(&flow.state_at(ti));
    let stream = args.report_stream();
    if let Some(n) = args.csv_samples() {
        write_samples(args.out.as_deref(), &body, t, n, state_at)?;
        if args.out.is_none() {
            return Ok(());
        }
    }
    let shape = flow.shape();
    let [theta_min, theta_max] = shape.theta;
    let summary = Summary {
        case: case.source.clone(),
        flow: field.name(),
        condition: args.condition.name(),
        alpha: bracket.alpha.at(&case.initial.gamma()),
        tilt: Tilt {
            motion: if shape.period.is_some() {
                "nutation"
            } else {
                "steady"
            },
            theta_min,
            theta_max,
            gamma3_min: theta_max.cos(),
            gamma3_max: theta_min.cos(),
            period: shape.period,
            precession_advance_per_period: shape.advance,
            precession_rate: shape.rate,
        },
        state: Sample::new(&body, t, &state_at(t)),
        integrals: Value::of_state(&body, &case.initial),
    };
    stream.print(&summary, args.json, summary_text)
}

fn summary_text(s: &Summary) -> String {
    let mut text = String::new();
    let _ = writeln!(
        text,
        "case: {}\nflow {} = P dH of the first bracket (p-br) at ({}), alpha = {}",
        s.case, s.flow, s.condition, s.alpha
    );
    tilt_text(
        &mut text,
        &s.tilt,
        [
            "period of theta T",
            "advance of phi per period",
            "theta constant: dphi/dt",
        ],
    );
    integrals_text(&mut text, &s.integrals);
    state_text(&mut text, format_args!("{}", s.state.t), &s.state);
    text
}
