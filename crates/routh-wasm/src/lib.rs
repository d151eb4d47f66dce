//! The routh library compiled to WebAssembly (target `wasm32-unknown-unknown`) for the explorer
//! page that `routh explore` writes: the same functions as the command-line tool, called on
//! a body and an initial state that the page's controls set.
//!
//! The interface is four plain `extern "C"` functions (no wasm-bindgen: see the README): the
//! page copies a request, JSON in UTF-8, into memory from [`routh_alloc`], calls
//! [`routh_call`], and reads the JSON answer at the pointer it returns, [`routh_answer_len`]
//! bytes long; [`routh_free`] gives the request's memory back. Numbers cross as JSON (the
//! shortest decimal that reads back as the same f64), so the page sees every bit of them.
//!
//! A request names its `command` ([`Request`]):
//! * `simulate`: the run of `routh simulate` (the reduced system (mg-eq), no samples, the same
//!   settings: [`routh_ball::simulate::run`] on a [`ReducedSystem`]), whose summary (final
//!   state, work, drift) is the tool's `--json`; then the motion in space
//!   ([`FullMotion`], the same field for its reduced part) at `samples` times for the 3D view:
//!   the columns of the viewer (`routh animate`), theta(t) and the running drift of the
//!   integrals.
//! * `exact`: the exact solution by quadrature (`routh exact`,
//!   [`ExactSolution`]) at the same times, where it exists (a symmetric body off a
//!   separatrix), else the reason.
//! * `steady`: the vertical spins with Routh's threshold and the steady precessions at the
//!   initial tilt for the initial spin omega3 (`routh steady`, [`routh_sphere::steady`]).
//! * `diagram`: the energy–momentum diagram's numbers at the motion's Jellett H3 (`routh
//!   diagram`, [`Diagram`]) with the motion's value (H1, H3, K) as its point.
//!
//! An invalid request or body (the library's own validation, with its message) answers
//! `{"error": "..."}`.

use routh_ball::body::Body;
use routh_ball::integrals::INTEGRAL_NAMES;
use routh_ball::motion::{full_columns, initial_full, FullMotion, FULL_COLUMN_NAMES};
use routh_ball::range::{check_body, check_state};
use routh_ball::simulate::{reduced, run, DriftTracker, ReducedSystem, Settings, Summary};
use routh_ball::state::{Normalise, Point, State};
use routh_ball::{AsBall, Ball, RouthError};
use routh_integrate::Method;
use routh_sphere::diagram::{Diagram, Resolution, Value};
use routh_sphere::quadrature::ExactSolution;
use routh_sphere::steady::{precessions_at_tilt, vertical_spin, SteadyPrecession, VerticalSpin};
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::collections::BTreeMap;

/// The body of a request: the Routh sphere's parameters of a case file's `[body]` (I2 = I1).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyParameters {
    /// Mass.
    pub m: f64,
    /// Radius.
    #[serde(rename = "R")]
    pub radius: f64,
    /// Offset of the centre of mass from the geometric centre along e3.
    pub a: f64,
    /// Moment of inertia about e1 and e2.
    #[serde(rename = "I1")]
    pub i1: f64,
    /// Moment of inertia about the symmetry axis e3.
    #[serde(rename = "I3")]
    pub i3: f64,
    /// Gravity.
    #[serde(rename = "G")]
    pub gravity: f64,
}

/// What the page asks: a command, the body, the initial state, the run's settings.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Request {
    /// `simulate`, `exact`, `steady` or `diagram`.
    pub command: String,
    /// The body.
    pub body: BodyParameters,
    /// The initial unit normal gamma (body frame).
    pub gamma: [f64; 3],
    /// The initial angular velocity omega (body frame).
    pub omega: [f64; 3],
    /// Final time.
    pub t_end: f64,
    /// The integrator, as `routh simulate --method` names it.
    pub method: String,
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance (in the motion's units, as the tool's).
    pub atol: f64,
    /// Equally spaced times on [0, t_end] of the 3D view and the curves (>= 2).
    pub samples: usize,
    /// The resolution of the diagram (`diagram` only; the tool's defaults when absent).
    #[serde(default)]
    pub resolution: Option<[usize; 3]>,
}

/// The ball and state of a request, validated as a case file's are (`routh_io::case`): the
/// body's parameters, its inertia within f64 ([`check_body`]), a unit gamma, the energy
/// within f64 ([`check_state`]).
fn ball_and_state(request: &Request) -> Result<(Body, Ball, State), RouthError> {
    let p = request.body;
    let body = Body::new(p.m, p.radius, p.a, p.i1, p.i1, p.i3, p.gravity)?;
    let ball = body.ball();
    check_body(&ball)?;
    let state = State::from_omega(&ball, request.gamma, request.omega, Normalise::Reject)?;
    check_state(&ball, &state)?;
    Ok((body, ball, state))
}

/// The settings of `routh simulate` (no projection, the step limit of the defaults) with the
/// request's method, t_end and tolerances, and `samples` samples; validated when built.
fn settings(request: &Request, samples: usize) -> Result<Settings, String> {
    let method: Method = request.method.parse().map_err(|e| format!("{e}"))?;
    Settings::builder()
        .method(method)
        .t_end(request.t_end)
        .tolerances(request.rtol, request.atol)
        .samples(samples)
        .build()
        .map_err(|e| e.to_string())
}

/// The samples of the 3D view and the curves, as `routh animate` embeds them: columns by
/// name (t, the orientation and position of [`FULL_COLUMN_NAMES`], theta in degrees) and the
/// running maximum relative drift of each integral.
#[derive(Debug, Serialize)]
struct View {
    radius: f64,
    a: f64,
    gamma0: [f64; 3],
    columns: BTreeMap<&'static str, Vec<f64>>,
    drift: Vec<(&'static str, Vec<f64>)>,
}

/// The tilt theta of the symmetry axis in degrees, `cos theta = gamma3 / |gamma|` (as the
/// figures of `routh plot` and `routh animate` draw it).
fn tilt_degrees(gamma: &[f64]) -> f64 {
    let norm = (gamma[0].powi(2) + gamma[1].powi(2) + gamma[2].powi(2)).sqrt();
    (gamma[2] / norm).clamp(-1.0, 1.0).acos().to_degrees()
}

/// The answer of `simulate`.
#[derive(Debug, Serialize)]
struct Simulation {
    /// The summary of `routh simulate --json` (final state, work, drift).
    summary: Summary,
    /// The motion in space at the samples.
    view: View,
}

fn simulate(request: &Request) -> Result<Simulation, String> {
    let (_, ball, state) = ball_and_state(request).map_err(|e| e.to_string())?;
    let summary = run(
        &ball,
        &ReducedSystem(&ball),
        state.to_array(),
        &settings(request, 0)?,
        &mut |_, _| Ok(()),
    )
    .map_err(|e| e.to_string())?;
    let mut columns: BTreeMap<&'static str, Vec<f64>> = BTreeMap::new();
    let mut tracker = DriftTracker::new(&ball, &state.to_array());
    let mut drift: Vec<(&'static str, Vec<f64>)> =
        INTEGRAL_NAMES.iter().map(|&n| (n, Vec::new())).collect();
    run(
        &ball,
        &FullMotion { body: &ball },
        initial_full(&state),
        &settings(request, request.samples)?,
        &mut |t, y| {
            columns.entry("t").or_default().push(t);
            for (name, value) in FULL_COLUMN_NAMES.iter().zip(full_columns(&ball, y)) {
                columns.entry(name).or_default().push(value);
            }
            columns.entry("theta").or_default().push(tilt_degrees(y));
            tracker.observe(&ball, &reduced(y));
            let report = tracker.report();
            for (name, values) in &mut drift {
                if let Some(d) = report.get(name) {
                    values.push(d.max_rel_drift);
                }
            }
            Ok(())
        },
    )
    .map_err(|e| e.to_string())?;
    drift.retain(|(_, values)| !values.is_empty());
    let p = request.body;
    Ok(Simulation {
        summary,
        view: View {
            radius: p.radius,
            a: p.a,
            gamma0: state.gamma(),
            columns,
            drift,
        },
    })
}

/// The answer of `exact`: theta(t) of the quadrature at the samples' times and its final
/// state, or why there is none.
#[derive(Debug, Serialize)]
struct Exact {
    /// theta in degrees at the samples' times.
    theta: Vec<f64>,
    /// The state at t_end.
    final_state: Point,
    /// The estimated relative error at t_end.
    estimated_error: f64,
}

fn exact(request: &Request) -> Result<Exact, String> {
    let (body, _, state) = ball_and_state(request).map_err(|e| e.to_string())?;
    let settings = settings(request, request.samples)?;
    let exact = ExactSolution::new(&body, &state).map_err(|e| e.to_string())?;
    let estimated_error = exact
        .accuracy
        .checked_error_at(request.t_end)
        .map_err(|e| e.to_string())?;
    let n = settings.samples();
    let theta = (0..n)
        .map(|i| {
            let t = request.t_end * i as f64 / (n - 1) as f64;
            tilt_degrees(&exact.state_at(t).gamma)
        })
        .collect();
    Ok(Exact {
        theta,
        final_state: exact.state_at(request.t_end),
        estimated_error,
    })
}

/// The answer of `steady`, as `routh steady` reports them for the request's spin.
#[derive(Debug, Serialize)]
struct Steady {
    /// The spin omega3 of the initial state.
    spin: f64,
    /// The vertical spins gamma3 = +1 and -1 at this spin, each with Routh's threshold (or
    /// why there is none).
    vertical: Vec<VerticalSpin>,
    /// The steady precessions at the initial tilt (none when it is vertical).
    precessions: Vec<SteadyPrecession>,
    /// The initial tilt theta (radians).
    theta: f64,
}

fn steady(request: &Request) -> Result<Steady, String> {
    let (body, ball, state) = ball_and_state(request).map_err(|e| e.to_string())?;
    let spin = state.omega(&ball)[2];
    let vertical = [1.0, -1.0]
        .into_iter()
        .map(|pole| vertical_spin(&body, pole, spin))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| e.to_string())?;
    let theta = state.gamma()[2].clamp(-1.0, 1.0).acos();
    let precessions = if theta > 0.0 && theta < std::f64::consts::PI {
        precessions_at_tilt(&body, theta, spin)
            .map_err(|e| e.to_string())?
            .precessions
    } else {
        Vec::new()
    };
    Ok(Steady {
        spin,
        vertical,
        precessions,
        theta,
    })
}

/// The answer of `diagram`: the diagram at the motion's H3 and the motion's value.
#[derive(Debug, Serialize)]
struct DiagramAnswer {
    diagram: Diagram,
    value: Value,
}

fn diagram(request: &Request) -> Result<DiagramAnswer, String> {
    let (body, _, state) = ball_and_state(request).map_err(|e| e.to_string())?;
    let value = Value::of_state(&body, &state);
    let resolution = match request.resolution {
        Some([tilts, grid, loop_points]) => Resolution {
            tilts,
            grid,
            loop_points,
        },
        None => Resolution::default(),
    };
    let diagram = Diagram::new(&body, value.h3, &[value], resolution).map_err(|e| e.to_string())?;
    Ok(DiagramAnswer { diagram, value })
}

/// The JSON answer to a JSON request (see the module documentation).
pub fn answer(request: &str) -> String {
    #[derive(Serialize)]
    struct Failure {
        error: String,
    }
    fn json<T: Serialize>(result: Result<T, String>) -> String {
        let text = match result {
            Ok(value) => serde_json::to_string(&value),
            Err(error) => serde_json::to_string(&Failure { error }),
        };
        text.unwrap_or_else(|e| format!("{{\"error\":\"cannot write the answer: {e}\"}}"))
    }
    let request: Request = match serde_json::from_str(request) {
        Ok(r) => r,
        Err(e) => return json::<()>(Err(format!("invalid request: {e}"))),
    };
    match request.command.as_str() {
        "simulate" => json(simulate(&request)),
        "exact" => json(exact(&request)),
        "steady" => json(steady(&request)),
        "diagram" => json(diagram(&request)),
        other => json::<()>(Err(format!(
            "unknown command `{other}` (simulate, exact, steady, diagram)"
        ))),
    }
}

thread_local! {
    /// The last answer, kept until the next call so that the page can read it.
    static ANSWER: RefCell<String> = const { RefCell::new(String::new()) };
}

/// `len` bytes of memory for a request (freed by [`routh_free`]).
#[no_mangle]
pub extern "C" fn routh_alloc(len: usize) -> *mut u8 {
    let mut buffer = Vec::<u8>::with_capacity(len);
    let pointer = buffer.as_mut_ptr();
    std::mem::forget(buffer);
    pointer
}

/// Give back memory from [`routh_alloc`].
///
/// # Safety
/// `pointer` and `len` come from one call of [`routh_alloc`], not freed before.
#[no_mangle]
pub unsafe extern "C" fn routh_free(pointer: *mut u8, len: usize) {
    drop(Vec::from_raw_parts(pointer, 0, len));
}

/// Answer the request of `len` bytes at `pointer` (UTF-8 JSON): the pointer of the answer,
/// valid until the next call, [`routh_answer_len`] bytes long.
///
/// # Safety
/// `pointer` holds `len` initialised bytes (from [`routh_alloc`]).
#[no_mangle]
pub unsafe extern "C" fn routh_call(pointer: *const u8, len: usize) -> *const u8 {
    let bytes = std::slice::from_raw_parts(pointer, len);
    let text = match std::str::from_utf8(bytes) {
        Ok(text) => answer(text),
        Err(e) => format!("{{\"error\":\"the request is not UTF-8: {e}\"}}"),
    };
    ANSWER.with(|a| {
        *a.borrow_mut() = text;
        a.borrow().as_ptr()
    })
}

/// The length in bytes of the last answer of [`routh_call`].
#[no_mangle]
pub extern "C" fn routh_answer_len() -> usize {
    ANSWER.with(|a| a.borrow().len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::Value as Json;

    /// The issue's request: the default body, tilt 0.7, omega = (0.5, 0.2, 6), 20 s.
    fn request(command: &str, change: &str) -> String {
        let gamma = [0.7_f64.sin(), 0.0, 0.7_f64.cos()];
        format!(
            r#"{{"command": "{command}", "body": {{"m": 1, "R": 1, "a": 0.3, "I1": 0.4,
            "I3": 0.5, "G": {change}}}, "gamma": [{}, {}, {}], "omega": [0.5, 0.2, 6],
            "t_end": 20, "method": "dop853", "rtol": 1e-12, "atol": 1e-12, "samples": 101,
            "resolution": [40, 10, 16]}}"#,
            gamma[0], gamma[1], gamma[2]
        )
    }

    fn call(command: &str, gravity: &str) -> Json {
        serde_json::from_str(&answer(&request(command, gravity))).unwrap()
    }

    #[test]
    fn simulate_is_the_run_of_routh_simulate() {
        let got = call("simulate", "9.81");
        let parsed: Request = serde_json::from_str(&request("simulate", "9.81")).unwrap();
        let (_, ball, state) = ball_and_state(&parsed).unwrap();
        let settings = Settings::builder().t_end(20.0).build().unwrap();
        let summary = run(
            &ball,
            &ReducedSystem(&ball),
            state.to_array(),
            &settings,
            &mut |_, _| Ok(()),
        )
        .unwrap();
        // The same function and settings: the same numbers, to the bit. Compared as the JSON
        // text (serde_json's parser may move the last bit; the page's JSON.parse does not).
        let text = answer(&request("simulate", "9.81"));
        let want = serde_json::to_string(&summary.final_state).unwrap();
        assert!(text.contains(&format!("\"final_state\":{want}")), "{want}");
        // The view: every column at the 101 samples, theta from 40.1 degrees (tilt 0.7 rad).
        let columns = got["view"]["columns"].as_object().unwrap();
        assert_eq!(columns.len(), 2 + FULL_COLUMN_NAMES.len());
        assert!(columns.values().all(|c| c.as_array().unwrap().len() == 101));
        let theta0 = columns["theta"][0].as_f64().unwrap();
        assert!((theta0 - 0.7_f64.to_degrees()).abs() < 1e-12, "{theta0}");
        assert_eq!(got["view"]["drift"].as_array().unwrap().len(), 5);
    }

    #[test]
    fn every_command_answers() {
        for command in ["exact", "steady", "diagram"] {
            let got = call(command, "9.81");
            assert!(got.get("error").is_none(), "{command}: {got}");
        }
        // The quadrature agrees with the integration at t_end within the integration's error:
        // DOP853 at 1e-12 is 2.3e-9 off in gamma1 at t = 20 on this case (measured: the Taylor
        // method at 3e-14 agrees with the quadrature to 7e-15, whose own estimate is 2e-11).
        let exact = call("exact", "9.81")["final_state"]["gamma"].clone();
        let integrated = call("simulate", "9.81")["summary"]["final_state"]["gamma"].clone();
        for i in 0..3 {
            let d = exact[i].as_f64().unwrap() - integrated[i].as_f64().unwrap();
            assert!(d.abs() < 1e-8, "gamma{}: {d}", i + 1);
        }
    }

    #[test]
    fn bad_input_is_a_message_not_a_panic() {
        let got = call("simulate", "-1");
        assert!(got["error"].as_str().unwrap().contains("G"), "{got}");
        let got = call("teleport", "9.81");
        assert!(
            got["error"].as_str().unwrap().contains("unknown command"),
            "{got}"
        );
        let got: Json = serde_json::from_str(&answer("{")).unwrap();
        assert!(
            got["error"].as_str().unwrap().contains("invalid request"),
            "{got}"
        );
    }
}
