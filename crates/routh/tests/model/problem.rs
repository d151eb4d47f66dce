//! Problem and Solution as plain values, and the dense solution against the steps.

use routh::case::Case;
use routh::integrate::Method;
use routh::problem::{Crossing, DenseSolution, Problem, Solution, Status};
use routh::simulate::{run, ReducedSystem, Settings};

fn plain_value<T: Clone + Send + Sync + serde::Serialize>() {}

fn default_problem(t_end: f64, samples: usize) -> Problem {
    let case = Case::default_case().unwrap();
    Problem {
        ball: case.ball,
        initial: case.initial,
        settings: Settings {
            method: Method::Dop853,
            t_end,
            rtol: 1e-12,
            atol: 1e-12,
            project: false,
            project_every: 1,
            samples,
            ..Settings::default()
        },
        event: None,
    }
}

#[test]
fn problems_and_solutions_are_plain_values() {
    plain_value::<Problem>();
    plain_value::<Solution>();
    plain_value::<DenseSolution>();
    // Thousands of them go to threads: four here, each solved on its own thread, agree with
    // the same problem solved here (the same code: bit for bit).
    let problems: Vec<Problem> = (0..4).map(|i| default_problem(1.0 + i as f64, 3)).collect();
    let handles: Vec<_> = problems
        .iter()
        .cloned()
        .map(|p| std::thread::spawn(move || p.solve().unwrap()))
        .collect();
    for (p, h) in problems.iter().zip(handles) {
        let there = h.join().unwrap();
        let here = p.solve().unwrap();
        assert_eq!(there.final_state, here.final_state);
        assert_eq!(there.status, Status::Reached);
        let json = serde_json::to_value(&there).unwrap();
        assert_eq!(json["status"], "Reached");
        assert_eq!(json["samples"].as_array().unwrap().len(), 3);
    }
}

#[test]
fn a_solution_is_the_run_of_simulate() {
    let p = default_problem(5.0, 11);
    let s = p.solve().unwrap();
    let mut samples = Vec::new();
    let summary = run(
        &p.ball,
        &ReducedSystem(&p.ball),
        p.initial.to_array(),
        &p.settings,
        &mut |t, x| {
            samples.push((t, *x));
            Ok(())
        },
    )
    .unwrap();
    assert_eq!(s.final_state, summary.final_state);
    assert_eq!(s.stats.steps, summary.steps);
    assert_eq!(s.integrals, summary.integrals);
    for (a, (t, x)) in s.samples.iter().zip(&samples) {
        assert_eq!((a.t, a.state.to_array()), (*t, *x));
    }
}

#[test]
fn the_dense_solution_reproduces_the_dense_output_of_the_steps() {
    // The samples of a run come from the stepper's own dense output on each step; the dense
    // solution stores each step at 8 Chebyshev points and interpolates with degree 7, exact
    // for DOP853's degree-7 interpolant up to round-off of the barycentric formula (1e-12 of
    // |x| ~ 10). Against a run at a tighter tolerance the error is that of DOP853 at 1e-12.
    let p = default_problem(10.0, 101);
    let (s, dense) = p.solve_dense().unwrap();
    assert_eq!(dense.times.len(), s.stats.steps + 1);
    let mut worst: f64 = 0.0;
    for sample in &s.samples {
        let x = dense.at(sample.t).unwrap();
        for (a, b) in x.iter().zip(sample.state.to_array()) {
            worst = worst.max((a - b).abs());
        }
    }
    assert!(worst < 1e-12, "dense solution vs dense output: {worst:e}");
    // At the step ends it is the step's end (unprojected = projected here).
    let end = dense.at(s.t).unwrap();
    assert_eq!(end, s.final_state.to_array());
    // Outside the span it refuses.
    assert!(dense.at(10.5).is_err());
    assert!(dense.at(-0.1).is_err());
    // Negative control: a corrupted node shows.
    let mut bad = dense.clone();
    bad.nodes[3][4][0] += 1e-6;
    let t_mid = 0.5 * (bad.times[3] + bad.times[4]);
    let diff = (bad.at(t_mid).unwrap()[0] - dense.at(t_mid).unwrap()[0]).abs();
    assert!(diff > 1e-8, "{diff:e}");
}

#[test]
fn failure_and_events_are_statuses_with_a_message() {
    // RK4 with two steps over t = 100 blows up: a status, not an error, with the state reached.
    let mut p = default_problem(100.0, 0);
    p.settings.method = Method::Rk4 { steps: 2 };
    let s = p.solve().unwrap();
    assert_eq!(s.status, Status::Failed);
    assert!(s.message.contains("non-finite"), "{}", s.message);
    // An event: gamma1 crosses 0 (the tilt turns), located to round-off.
    let mut p = default_problem(10.0, 0);
    p.event = Some(Crossing {
        component: 0,
        value: 0.0,
    });
    let s = p.solve().unwrap();
    assert_eq!(s.status, Status::Event, "{}", s.message);
    let e = s.events[0];
    assert!(e.t > 0.0 && e.t < 10.0);
    assert!(e.state.gamma[0].abs() < 1e-12, "{:?}", e.state);
    // Negative control: invalid event component is an error, not a status.
    p.event = Some(Crossing {
        component: 6,
        value: 0.0,
    });
    assert!(p.solve().is_err());
}
