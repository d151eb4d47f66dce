//! `routh lyapunov`: the Lyapunov exponents of a case's motion on `|gamma| = 1`
//! ([`routh::lyapunov::report_case`]), as text or JSON.

use super::integration::{parse_method, Integration};
use super::{print_json, Readable};
use routh::case::Case;
use routh::integrate::Method;
use routh::lyapunov::{report_case, LyapunovSettings, Report};
use routh::AppResult as Result;
use std::path::PathBuf;

/// Options of `routh lyapunov`; each overrides the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Case file (TOML); the built-in default case when omitted.
    #[arg(long)]
    pub case: Option<PathBuf>,
    /// The final time, tolerances and step limit.
    #[command(flatten)]
    pub integration: Integration,
    /// The exponents are averaged over [transient, t_end] (default: t_end / 10; the tangent
    /// vectors are renormalised during the transient too).
    #[arg(long, allow_hyphen_values = true)]
    pub transient: Option<f64>,
    /// Time between two renormalisations of the tangent vectors, at most t_end - transient
    /// (default: (t_end - transient) / 100).
    #[arg(long, allow_hyphen_values = true)]
    pub interval: Option<f64>,
    /// Integrator of the state and its tangent vectors: `dop853`, `vern9` or `rk4:<steps>`
    /// (RK4 with that many steps per renormalisation interval); the Taylor method does not
    /// integrate the tangent flow.
    #[arg(long, default_value = "dop853", value_parser = parse_method)]
    pub method: Method,
    /// Print the report as JSON (with the history of the estimates).
    #[arg(long)]
    pub json: bool,
}

/// Run the command.
pub fn run(args: Args) -> Result<()> {
    let case = Case::load(args.case.as_deref())?;
    let integration = args.integration.settings(args.method, &case)?;
    let settings = LyapunovSettings::new(integration, args.transient, args.interval)?;
    let r = report_case(&case, &settings)?;
    if args.json {
        print_json(&r)
    } else {
        out!("{}", report_text(&r))
    }
}

/// The report as lines of text (the history only in JSON).
fn report_text(r: &Report) -> String {
    use std::fmt::Write;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "routh lyapunov: {}",
        r.case.as_deref().unwrap_or_default()
    );
    let _ = writeln!(
        text,
        "  method   {} (rtol {}, atol {})",
        r.method,
        Readable(r.rtol),
        Readable(r.atol)
    );
    let _ = writeln!(
        text,
        "  time     {} (averaged after {}, renormalised every {})",
        Readable(r.t_end),
        Readable(r.transient),
        Readable(r.interval)
    );
    let _ = writeln!(
        text,
        "  work     {} steps ({} rejected), {} field evaluations in {:.3} s",
        r.steps, r.rejected, r.rhs_evals, r.elapsed_s
    );
    let _ = writeln!(text, "  exponents on |gamma| = 1:");
    for (k, lambda) in r.exponents.iter().enumerate() {
        let _ = writeln!(text, "    lambda{} = {lambda:+.6e}", k + 1);
    }
    let _ = writeln!(
        text,
        "  Kaplan-Yorke dimension        {:.6}",
        r.kaplan_yorke_dimension
    );
    let _ = writeln!(
        text,
        "  sum of the exponents          {:+.6e}",
        r.sum_of_exponents
    );
    let _ = writeln!(
        text,
        "  mean divergence of the field  {:+.6e}",
        r.divergence_mean
    );
    text
}
