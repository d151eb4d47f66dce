//! `routh lyapunov`: the Lyapunov exponents of a case's motion on `|gamma| = 1`
//! ([`routh::lyapunov::report_case`]), as text or JSON.

use super::case_file::CaseFile;
use super::integration::{parse_method, Integration};
use super::{print_json, Readable};
use routh::integrate::Method;
use routh::lyapunov::{report_case, LyapunovSettings, Report};
use routh::run::{Run, Work};
use routh::AppResult as Result;

/// Options of `routh lyapunov`; each overrides the case file.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    pub case: CaseFile,
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
    let case = args.case.load()?;
    let integration = args.integration.settings(args.method, &case)?;
    let settings = LyapunovSettings::new(integration, args.transient, args.interval)?;
    let r = report_case(&case, &settings)?;
    if args.json {
        print_json(&r)
    } else {
        out!("{}", report_text(&r))
    }
}

/// The first lines of the text report of a run of the tangent flow (`lyapunov`, `megno`):
/// the command and the case, the method and its tolerances, the work.
pub(super) struct RunLines<'a> {
    /// The command's name.
    pub command: &'a str,
    /// The case and the settings.
    pub run: &'a Run,
    /// The work.
    pub work: &'a Work,
}

impl std::fmt::Display for RunLines<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (run, work) = (self.run, self.work);
        writeln!(
            f,
            "routh {}: {}",
            self.command,
            run.case.as_deref().unwrap_or_default()
        )?;
        writeln!(
            f,
            "  method   {} (rtol {}, atol {})",
            run.method,
            Readable(run.rtol),
            Readable(run.atol)
        )?;
        writeln!(
            f,
            "  work     {} steps ({} rejected), {} field evaluations in {:.3} s",
            work.steps, work.rejected, work.rhs_evals, work.elapsed_s
        )
    }
}

/// The report as lines of text (the history only in JSON).
fn report_text(r: &Report) -> String {
    use std::fmt::Write;
    let mut text = RunLines {
        command: "lyapunov",
        run: &r.run,
        work: &r.work,
    }
    .to_string();
    let _ = writeln!(
        text,
        "  time     {} (averaged after {}, renormalised every {})",
        Readable(r.run.t_end),
        Readable(r.transient),
        Readable(r.interval)
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
