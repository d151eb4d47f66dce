//! Our side of the work–precision benchmark (`bench/work_precision/run.py` drives it).
//!
//! * `work_precision run CASE METHOD TOL REPEAT`: integrates the case file to t = 1000 with
//!   METHOD (a name of `Method`: `dop853`, `vern9`, `taylor`, `auto`; with `-plain`, without
//!   compensated summation of the update; with `+project<N>`, projected onto the level set
//!   of the integrals after every N-th step, `+project` every step) at rtol = atol = TOL,
//!   REPEAT times (the Taylor
//!   method's recording of the field is part of each), and prints one JSON
//!   object: the minimum wall time of the integration (constructor and steps, and the
//!   projections if asked; no samples), the final state, the step and field-evaluation counts and the relative
//!   drift of the energy H1 at the end.
//! * `work_precision eval CASE`: reads states (six numbers a line) from stdin and prints, a
//!   line each, the field (mg-eq) and the energy H1 there: the peers' right-hand sides are
//!   checked against it, and their final states' energy drift computed with it.
//!
//! * `work_precision plot RESULTS.json OUT_STEM`: draws the work–precision diagram (final
//!   error against time, log–log, one panel per case; the runs without compensated summation
//!   are left out) as `OUT_STEM.png` and `OUT_STEM.svg`.
//!
//! Build with `cargo bench --bench work_precision --no-run`.

use routh::auto;
use routh::case::Case;
use routh::field::vector_field;
use routh::integrals::Integrals;
use routh::integrate::{drive, stepper, Control, Drive, IntegrateError, Method, Options, Stats};
use routh::plot::{render_figure_sized, Figure, Format};
use routh::projection::LevelSet;
use routh::simulate::{project_every, ReducedSystem};
use std::convert::Infallible;
use std::io::BufRead;
use std::path::Path;
use std::time::Instant;

const T_END: f64 = 1000.0;

fn energy(case: &Case, x: &[f64; 6]) -> f64 {
    Integrals::at(&case.ball, x).values()[0].expect("H1 is always tracked")
}

fn run(case: &Case, method: &str, tol: f64) -> Result<([f64; 6], Stats), IntegrateError> {
    let sys = ReducedSystem(&case.ball);
    let x0 = case.initial.to_array();
    // "+project<N>": projected onto the level set of the integrals after every N-th step.
    let (method, every) = match method.split_once("+project") {
        Some((name, "")) => (name, Some(1)),
        Some((name, n)) => (name, Some(n.parse().expect("+project<N>: N is a count"))),
        None => (method, None),
    };
    // "-plain": the update summed without compensation, to measure what compensation gains.
    let (name, compensated) = match method.strip_suffix("-plain") {
        Some(name) => (name, false),
        None => (method, true),
    };
    let method: Method = name.parse().unwrap_or_else(|e| panic!("{e}"));
    // `auto` by the plain runs' table, as the benchmark has always resolved it.
    let method = auto::resolve(method, tol, false);
    let opts = Options::new(tol, tol)?.with_compensated(compensated);
    let mut s = stepper(method, &sys, 0.0, x0, T_END, &opts)?;
    match every {
        None => while !s.step()? {},
        Some(every) => {
            // The library's step loop with its projection, as `routh simulate --project
            // --project-every N` runs it (without its tracking of the integrals).
            let level = LevelSet::through(&case.ball, &x0);
            let project = project_every(Some(&level), every);
            let plan = Drive {
                project: Some(&project),
                ..Drive::default()
            };
            let Ok(outcome) =
                drive::<_, Infallible, 6>(s.as_mut(), &plan, &mut |_, _| Ok(()), &mut |_, _, _| {
                    Ok(Control::Continue)
                });
            outcome.into_result()?;
        }
    }
    Ok((*s.y(), s.stats()))
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let usage = "usage: work_precision run CASE METHOD TOL REPEAT | eval CASE";
    if args.first().map(String::as_str) == Some("plot") {
        return plot(&args[1], &args[2]);
    }
    let case = Case::from_file(Path::new(args.get(1).expect(usage))).expect("a valid case file");
    match args[0].as_str() {
        "run" => {
            let method = args[2].as_str();
            let tol: f64 = args[3].parse().expect("TOL is a number");
            let repeat: usize = args[4].parse().expect("REPEAT is a count");
            let mut best = f64::INFINITY;
            let mut result = None;
            for _ in 0..repeat {
                let start = Instant::now();
                let r = run(&case, method, tol);
                best = best.min(start.elapsed().as_secs_f64());
                result = Some(r);
            }
            match result.expect("REPEAT >= 1") {
                Ok((x, stats)) => {
                    let h0 = energy(&case, &case.initial.to_array());
                    let drift = ((energy(&case, &x) - h0) / h0).abs();
                    println!(
                        "{}",
                        serde_json::json!({
                            "time_s": best, "final": x, "steps": stats.steps,
                            "rejected": stats.rejected, "rhs_evals": stats.rhs_evals,
                            "energy_drift": drift,
                        })
                    );
                }
                Err(e) => println!("{}", serde_json::json!({ "error": e.to_string() })),
            }
        }
        "eval" => {
            for line in std::io::stdin().lock().lines() {
                let v: Vec<f64> = line
                    .expect("stdin is readable")
                    .split_whitespace()
                    .map(|s| s.parse().expect("a number"))
                    .collect();
                let x: [f64; 6] = v.try_into().expect("six numbers a line");
                let f = vector_field::<f64>(&case.ball, &x);
                println!(
                    "{}",
                    serde_json::json!({ "field": f, "energy": energy(&case, &x) })
                );
            }
        }
        _ => panic!("{usage}"),
    }
}

/// One series of the diagram: a method's (time, error) points over the tolerances.
type Series = Vec<(String, Vec<(f64, f64)>)>;

fn series(rows: &[serde_json::Value]) -> Series {
    let mut out: Series = vec![];
    for r in rows {
        let name = r["method"].as_str().expect("method").to_string();
        // The runs without compensated summation are for the table, not the diagram.
        if name.ends_with("plain sum") {
            continue;
        }
        let point = (
            r["time_s"].as_f64().expect("time"),
            r["error"].as_f64().expect("error"),
        );
        match out.iter_mut().find(|(n, _)| *n == name) {
            Some((_, points)) => points.push(point),
            None => out.push((name, vec![point])),
        }
    }
    out
}

/// The work-precision chart of `results`, one panel per case.
struct Chart(serde_json::Value);

impl Figure for Chart {
    fn draw_on<DB: plotters::prelude::DrawingBackend>(
        &self,
        root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    ) -> Result<(), plotters::drawing::DrawingAreaErrorKind<DB::ErrorType>> {
        draw(root, &self.0)
    }
}

fn draw<DB: plotters::prelude::DrawingBackend>(
    root: &plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    results: &serde_json::Value,
) -> Result<(), plotters::drawing::DrawingAreaErrorKind<DB::ErrorType>> {
    use plotters::prelude::*;
    root.fill(&WHITE)?;
    let cases = results["cases"].as_object().expect("cases");
    let panels = root.split_evenly((1, cases.len()));
    let colours = [RED, BLUE, BLACK, MAGENTA, RGBColor(0, 150, 0), CYAN];
    // A method with projection (" +proj/10") is drawn dashed in its method's colour.
    let base = |name: &str| name.split(" +proj").next().unwrap_or(name).to_string();
    for (area, (case, data)) in panels.iter().zip(cases) {
        let all = series(data["rows"].as_array().expect("rows"));
        let pts = || all.iter().flat_map(|(_, p)| p.iter());
        let (t0, t1) = pts().fold((f64::INFINITY, 0.0_f64), |(a, b), p| {
            (a.min(p.0), b.max(p.0))
        });
        let (e0, e1) = pts().fold((f64::INFINITY, 0.0_f64), |(a, b), p| {
            (a.min(p.1), b.max(p.1))
        });
        let mut chart = ChartBuilder::on(area)
            .caption(format!("{case}, t = 1000"), ("sans-serif", 22))
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(70)
            .build_cartesian_2d(
                (t0 / 1.5..t1 * 1.5).log_scale(),
                (e0.max(1e-16) / 3.0..e1 * 3.0).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("wall time [s]")
            .y_desc("final-state error")
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .label_style(("sans-serif", 14))
            .draw()?;
        let mut bases: Vec<String> = vec![];
        for (name, _) in &all {
            if !bases.contains(&base(name)) {
                bases.push(base(name));
            }
        }
        for (name, points) in &all {
            let k = bases.iter().position(|b| *b == base(name)).unwrap_or(0);
            let colour = colours[k % colours.len()];
            let style = colour.stroke_width(2);
            if base(name) == *name {
                chart
                    .draw_series(LineSeries::new(points.iter().copied(), style))?
                    .label(name.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], style));
            } else {
                chart
                    .draw_series(DashedLineSeries::new(points.iter().copied(), 6, 4, style))?
                    .label(name.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 8, y)], style));
            }
            chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font(("sans-serif", 14))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}

fn plot(results: &str, stem: &str) {
    let text = std::fs::read_to_string(results).expect("results file is readable");
    let chart = Chart(serde_json::from_str(&text).expect("results are JSON"));
    for format in [Format::Png, Format::Svg] {
        let path = format!("{stem}.{}", format.extension());
        render_figure_sized(&chart, Path::new(&path), format, (1500, 520))
            .unwrap_or_else(|e| panic!("{path}: {e}"));
    }
}
