//! Coulomb's friction: the ball slides against `F = -mu N v_P / |v_P|` while its contact
//! point slips, rolls without slipping (the paper's system (mg-eq)) once the slip has stopped
//! and the friction that rolling needs ([`Reaction`]) is at most `mu N`, and slides again when
//! rolling would need more. A run is a sequence of phases, each integrated by the one driver
//! ([`drive`]) with the switch to the next as its event, located by the one locator (Brent's
//! method on the step's dense output, to about 2 ulp of t), and the step restarted there:
//!
//! - **sliding** (the state `x = (gamma, omega, v, W)` of [`crate::contact::sliding`]): the
//!   slip stops where the signed slip `s = (v_P, d)` crosses zero, `d` the direction of the
//!   slip at the last step end (a field of the phase, kept between steps). On each step the
//!   friction is written `-mu N v_P / sigma`, `sigma = sign(s) |v_P|` ([`Heading::Signed`]):
//!   before the stop it is Coulomb's friction, and past it the same formula continues the
//!   field smoothly (the friction keeps its direction while `v_P` goes through zero along a
//!   line), so that the stop is a simple zero of a smooth function on a step of a smooth
//!   field, not a kink that the step control would shrink its steps onto. A zero of `s` where
//!   `|v_P|` has not vanished (the direction of the slip turned by a right angle within one
//!   step) is not a stop: the phase goes on with the new direction. The normal force's zero
//!   (the ball would leave the plane) is the other event of the phase: the smaller of the two,
//!   each in the motion's units, changes sign first.
//! - **rolling** (the rolling law's `(gamma, M)`, [`ReducedSystem`]): its event is the zero
//!   of `mu N - |F|` of the reaction; past it the ball slides again, its slip starting against
//!   the friction it had, `d = -F / |F|` (the force is continuous at the switch). A zero of N
//!   ends the run (the ball leaves the plane).
//!
//! Where the slip stops while rolling would need more than `mu N`, the ball slides on from
//! zero slip in the direction opposite to the friction that rolling needed (a turn of the
//! slip). Every switch is listed ([`Transition`]). The work of friction, twice
//! `mu N |v_P|` per unit of time while it slides and nothing while it rolls, is the state's
//! last component, so that H1 + W stays H1(0); Jellett's integral is constant in both phases
//! (any force at the contact point of the Routh sphere).
//!
//! The phases' fields are not analytic through a switch, so the Taylor method (a series over
//! a step) and RK4 (no step control) are refused; `auto` runs Vern9.

use super::reaction::{centre_velocity, Reaction};
use super::sliding::{Heading, Observation, Sliding, DIM};
use crate::error::{Result, RouthError};
use crate::integrate::taylor::Interpreted;
use crate::integrate::{
    drive, stepper, Control, Drive, IntegrateError, Method, OdeSystem, Options, Outcome, RunUnits,
    Stats, Stop,
};
use crate::scalar::{cross, dot};
use crate::simulate::{ReducedSystem, Settings};
use serde::Serialize;

/// What `auto` runs under Coulomb's friction: Vern9 at every tolerance (the table of
/// [`Method::resolve_in`]; the Taylor method cannot cross a switch).
pub const COULOMB_AUTO_TABLE: [(f64, Method); 1] = [(0.0, Method::Vern9)];

/// The method that runs `method` under Coulomb's friction at the tolerance `tol`: DOP853 and
/// Vern9 as asked, `auto` by [`COULOMB_AUTO_TABLE`]; the Taylor method and RK4 refused.
pub fn method(method: Method, tol: f64) -> Result<Method> {
    match method.resolve_in(tol, &COULOMB_AUTO_TABLE) {
        m @ (Method::Dop853 | Method::Vern9) => Ok(m),
        other => Err(RouthError::Option {
            name: "method",
            value: other.to_string(),
            rule: "is not available with Coulomb's friction (its switches between sliding and \
                   rolling are not smooth: a Taylor series or a fixed step cannot cross them); \
                   use dop853, vern9 or auto",
        }),
    }
}

/// A switch of the contact, at the time `t`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Transition {
    /// The time of the switch.
    pub t: f64,
    /// `stick` (the slip stopped: the ball rolls), `slip` (rolling needed more friction
    /// than `mu N`: the ball slides) or `turn` (the slip stopped where rolling needs more
    /// than `mu N`: it slides on in a new direction).
    pub kind: &'static str,
}

/// The phase a run is in.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Phase {
    /// Sliding, the slip in the direction `reference` (a unit vector, body frame); `from_rest`:
    /// the phase starts at zero slip.
    Sliding {
        reference: [f64; 3],
        from_rest: bool,
    },
    /// Rolling without slipping.
    Rolling,
}

/// How a run of the Coulomb law ended: the driver's outcome (the work of all phases summed),
/// the last observation and the switches.
pub(super) struct Ending {
    pub outcome: Outcome<DIM>,
    pub last: Observation,
    pub transitions: Vec<Transition>,
}

/// The unit vector along `u`.
fn unit(u: &[f64; 3]) -> [f64; 3] {
    let size = dot(u, u).sqrt();
    u.map(|c| c / size)
}

/// The dimension of a sliding phase's state: the sliding state and the reference direction
/// `d` (body components of a direction fixed in space, `d' = d x omega`).
const PHASE: usize = DIM + 3;

/// The sliding state of a phase's state.
fn sliding_part(y: &[f64; PHASE]) -> [f64; DIM] {
    std::array::from_fn(|i| y[i])
}

/// The reference direction of a phase's state.
fn reference_of(y: &[f64; PHASE]) -> [f64; 3] {
    [y[DIM], y[DIM + 1], y[DIM + 2]]
}

/// The phase's state of the sliding state `x` and the reference `d`.
fn with_reference(x: &[f64; DIM], d: &[f64; 3]) -> [f64; PHASE] {
    std::array::from_fn(|i| if i < DIM { x[i] } else { d[i - DIM] })
}

/// The sliding phase as a system: the sliding field with the friction's direction decided on
/// the state against the reference direction carried with it (the module's continuation).
struct SlidePhase<'m> {
    model: &'m Sliding,
}

impl SlidePhase<'_> {
    /// The friction's heading at `y`: along the reference where the slip is zero to
    /// round-off, else signed by the slip's side of the reference.
    fn heading(&self, y: &[f64; PHASE]) -> Heading {
        let x = sliding_part(y);
        let slip = self.model.slip_velocity(&x);
        let d = reference_of(y);
        if at_rest(self.model, &x) {
            Heading::Along(d)
        } else if dot(&slip, &d) >= 0.0 {
            Heading::Signed(1.0)
        } else {
            Heading::Signed(-1.0)
        }
    }

    fn observe(&self, t: f64, y: &[f64; PHASE]) -> Observation {
        let x = sliding_part(y);
        let normal = self.model.normal_force_heading(&x, self.heading(y));
        self.model.observe_with(t, &x, normal)
    }
}

impl OdeSystem<PHASE> for SlidePhase<'_> {
    type Kernels = Interpreted;

    #[inline(always)]
    fn rhs(&self, _t: f64, y: &[f64; PHASE]) -> [f64; PHASE] {
        let f = self.model.field_heading(&sliding_part(y), self.heading(y));
        let turn = cross(&reference_of(y), &[y[3], y[4], y[5]]);
        std::array::from_fn(|i| if i < DIM { f[i] } else { turn[i - DIM] })
    }

    fn units(&self, y0: &[f64; PHASE]) -> RunUnits<PHASE> {
        let u = self.model.units(&sliding_part(y0));
        RunUnits {
            time: u.time,
            components: std::array::from_fn(|i| if i < DIM { u.components[i] } else { 1.0 }),
        }
    }
}

/// Whether the slip at `x` is zero to round-off: `|v_P|` within 64 ulp of the speeds it is
/// the sum of, `|v| + |omega| |r|`.
fn at_rest(model: &Sliding, x: &[f64; DIM]) -> bool {
    let slip = model.slip_velocity(x);
    let (omega, v) = ([x[3], x[4], x[5]], [x[6], x[7], x[8]]);
    let r = model.ball().contact_vector(&[x[0], x[1], x[2]]);
    let scale = dot(&v, &v).sqrt() + (dot(&omega, &omega) * dot(&r, &r)).sqrt();
    dot(&slip, &slip).sqrt() <= 64.0 * f64::EPSILON * scale
}

/// The rolling law's state `(gamma, M)` of the sliding state `x` (its slip ignored).
fn rolling_state(model: &Sliding, x: &[f64; DIM]) -> [f64; 6] {
    let gamma = [x[0], x[1], x[2]];
    let m = model.ball().angular_momentum(&gamma, &[x[3], x[4], x[5]]);
    [gamma[0], gamma[1], gamma[2], m[0], m[1], m[2]]
}

/// The sliding state of the rolling state `y` with the work `work` so far: the angular
/// velocity of (om-m), the centre of mass at `r x omega` (zero slip).
fn sliding_state(model: &Sliding, y: &[f64; 6], work: f64) -> [f64; DIM] {
    let ball = model.ball();
    let omega = ball.angular_velocity(&[y[0], y[1], y[2]], &[y[3], y[4], y[5]]);
    let v = centre_velocity(&ball, y);
    [
        y[0], y[1], y[2], omega[0], omega[1], omega[2], v[0], v[1], v[2], work,
    ]
}

/// The phase of a state at zero slip: rolling if the reaction that rolling needs presses
/// the ball on the plane with a friction of at most `mu N`, else sliding from rest against
/// that friction; with the normal force of that phase there.
fn phase_at_rest(model: &Sliding, x: &[f64; DIM]) -> (Phase, f64) {
    let reaction = Reaction::of(&model.ball(), &rolling_state(model, x));
    let needed = reaction.friction_size();
    if needed <= model.mu() * reaction.normal {
        return (Phase::Rolling, reaction.normal);
    }
    let reference = unit(&reaction.friction.map(|c| -c));
    let normal = model.normal_force_heading(x, Heading::Along(reference));
    (
        Phase::Sliding {
            reference,
            from_rest: true,
        },
        normal,
    )
}

/// The phase a run starts in at `x0`, and the normal force there.
fn first_phase(model: &Sliding, x0: &[f64; DIM]) -> (Phase, f64) {
    if at_rest(model, x0) {
        return phase_at_rest(model, x0);
    }
    let reference = unit(&model.slip_velocity(x0));
    (
        Phase::Sliding {
            reference,
            from_rest: false,
        },
        model.normal_force_heading(x0, Heading::Signed(1.0)),
    )
}

/// The normal force at the start `x0` of a run under Coulomb's friction (of the phase it
/// starts in).
pub(super) fn initial_normal_force(model: &Sliding, x0: &[f64; DIM]) -> f64 {
    first_phase(model, x0).1
}

/// The observation at the start `x0` of a run under Coulomb's friction.
pub(super) fn first_observation(model: &Sliding, x0: &[f64; DIM]) -> Observation {
    model.observe_with(0.0, x0, initial_normal_force(model, x0))
}

/// Integrates the ball `model` under Coulomb's friction from `x0` at t = 0 to `t_end` with
/// `method` (of [`method`]) and `opts` (its step limit for the whole run, every phase's steps
/// counted), through its phases (the module's rules); the samples of `settings` (checked by
/// the driver) handed to `on_sample`, every step end to `on_step`. A failure of the integrator is
/// an error.
pub(super) fn integrate<E: From<RouthError>>(
    model: &Sliding,
    x0: [f64; DIM],
    method: Method,
    opts: &Options,
    settings: &Settings,
    on_sample: &mut dyn FnMut(&Observation) -> std::result::Result<(), E>,
    on_step: &mut dyn FnMut(&Observation, &[f64; DIM]),
) -> std::result::Result<Ending, E> {
    let (t_end, samples) = (settings.t_end(), settings.sample_times());
    let units = model.problem_units(&x0);
    // The events' units: speed R / T and force m R / T^2.
    let speed = model.ball().radius() / units.time();
    let force = model.ball().m() * speed / units.time();
    let (mut phase, _) = first_phase(model, &x0);
    let (mut t, mut x) = (0.0, x0);
    let mut stats = Stats::default();
    let mut transitions = Vec::new();
    let mut reported = 0;
    loop {
        let left = opts.max_steps().saturating_sub(stats.steps);
        let phase_opts = opts.with_max_steps(left.max(1)).map_err(RouthError::from)?;
        let todo = &samples[reported..];
        let ended = match phase {
            Phase::Sliding {
                reference,
                from_rest,
            } => {
                let system = SlidePhase { model };
                let t0 = t;
                let event = |t: f64, y: &[f64; PHASE]| {
                    if from_rest && t == t0 {
                        return 0.0;
                    }
                    let x = sliding_part(y);
                    let normal = model.normal_force_heading(&x, system.heading(y)) / force;
                    let along = dot(&model.slip_velocity(&x), &reference_of(y)) / speed;
                    normal.min(along)
                };
                // The reference follows the slip where they part by more than 45 degrees
                // (the state otherwise left as it is, bit for bit).
                let refresh = |y: &mut [f64; PHASE]| {
                    let x = sliding_part(y);
                    let slip = model.slip_velocity(&x);
                    let size = dot(&slip, &slip).sqrt();
                    if !at_rest(model, &x) && dot(&slip, &reference_of(y)) < 0.7 * size {
                        *y = with_reference(&x, &unit(&slip));
                    }
                };
                let start = with_reference(&x, &reference);
                let mut st = stepper(method, &system, t, start, t_end, &phase_opts)
                    .map_err(RouthError::from)?;
                let plan = Drive {
                    samples: todo,
                    project: Some(&refresh),
                    event: Some(&event),
                };
                let first = model.slip_velocity(&x);
                let mut slips = [0.0, dot(&first, &first).sqrt()];
                let outcome = drive(
                    st.as_mut(),
                    &plan,
                    &mut |t, y| {
                        reported += 1;
                        on_sample(&system.observe(t, y))
                    },
                    &mut |t, y, _| {
                        let x = sliding_part(y);
                        on_step(&system.observe(t, y), &x);
                        let slip = model.slip_velocity(&x);
                        slips = [slips[1], dot(&slip, &slip).sqrt()];
                        Ok(Control::Continue)
                    },
                )?;
                let last = system.observe(outcome.t, &outcome.y);
                let end = sliding_part(&outcome.y);
                let next = if outcome.stop != Stop::Event
                    || last.normal_force / force <= last.slip_speed / speed
                {
                    None
                } else if last.slip_speed <= 1e-3 * slips[0] || at_rest(model, &end) {
                    // The slip stopped: the ball rolls from there (its slip set to zero, a
                    // change at round-off), or turns.
                    let y = sliding_state(model, &rolling_state(model, &end), end[9]);
                    let (next, _) = phase_at_rest(model, &y);
                    let kind = if next == Phase::Rolling {
                        "stick"
                    } else {
                        "turn"
                    };
                    transitions.push(Transition { t: outcome.t, kind });
                    Some((next, y))
                } else {
                    // The slip's direction turned by a right angle within a step.
                    let reference = unit(&model.slip_velocity(&end));
                    Some((
                        Phase::Sliding {
                            reference,
                            from_rest: false,
                        },
                        end,
                    ))
                };
                let outcome = Outcome {
                    stop: outcome.stop,
                    t: outcome.t,
                    y: end,
                    stats: outcome.stats,
                };
                (outcome, last, next)
            }
            Phase::Rolling => {
                let ball = model.ball();
                let system = ReducedSystem(&ball);
                let work = x[9];
                let observe = |t: f64, y: &[f64; 6]| {
                    let reaction = Reaction::of(&ball, y);
                    model.observe_with(t, &sliding_state(model, y, work), reaction.normal)
                };
                let event = |_: f64, y: &[f64; 6]| {
                    let reaction = Reaction::of(&ball, y);
                    (model.mu() * reaction.normal - reaction.friction_size()) / force
                };
                let y0 = rolling_state(model, &x);
                let mut st = stepper(method, &system, t, y0, t_end, &phase_opts)
                    .map_err(RouthError::from)?;
                let plan = Drive {
                    samples: todo,
                    project: None,
                    event: Some(&event),
                };
                let outcome = drive(
                    st.as_mut(),
                    &plan,
                    &mut |t, y| {
                        reported += 1;
                        on_sample(&observe(t, y))
                    },
                    &mut |t, y, _| {
                        on_step(&observe(t, y), &sliding_state(model, y, work));
                        Ok(Control::Continue)
                    },
                )?;
                let last = observe(outcome.t, &outcome.y);
                let y = sliding_state(model, &outcome.y, work);
                let reaction = Reaction::of(&ball, &outcome.y);
                let next = (outcome.stop == Stop::Event && reaction.normal > 0.0).then(|| {
                    transitions.push(Transition {
                        t: outcome.t,
                        kind: "slip",
                    });
                    let reference = unit(&reaction.friction.map(|c| -c));
                    (
                        Phase::Sliding {
                            reference,
                            from_rest: true,
                        },
                        y,
                    )
                });
                let outcome = Outcome {
                    stop: outcome.stop,
                    t: outcome.t,
                    y,
                    stats: outcome.stats,
                };
                (outcome, last, next)
            }
        };
        let (outcome, last, next) = ended;
        stats.steps += outcome.stats.steps;
        stats.rejected += outcome.stats.rejected;
        stats.rhs_evals += outcome.stats.rhs_evals;
        if let Stop::Failed(e) = &outcome.stop {
            let e = match e {
                IntegrateError::TooManySteps { t, .. } => IntegrateError::TooManySteps {
                    max_steps: opts.max_steps(),
                    t: *t,
                },
                other => other.clone(),
            };
            return Err(RouthError::from(e).into());
        }
        match next {
            Some((p, y)) => {
                (phase, t, x) = (p, outcome.t, y);
                if stats.steps >= opts.max_steps() {
                    return Err(RouthError::from(IntegrateError::TooManySteps {
                        max_steps: opts.max_steps(),
                        t,
                    })
                    .into());
                }
            }
            None => {
                return Ok(Ending {
                    outcome: Outcome { stats, ..outcome },
                    last,
                    transitions,
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::Ball;
    use crate::body::Body;
    use crate::contact::sliding::{run, SlidingSummary};
    use crate::contact::Friction;
    use crate::simulate::Settings;
    use crate::state::Normalise;

    fn simulate(
        model: &Sliding,
        y0: [f64; DIM],
        t_end: f64,
        rtol: f64,
    ) -> (SlidingSummary, Vec<Observation>) {
        let settings = Settings::builder()
            .t_end(t_end)
            .tolerances(rtol, rtol)
            .samples(200)
            .build()
            .unwrap();
        let mut seen = Vec::new();
        let summary = run::<RouthError>(model, y0, &settings, &mut |now| {
            seen.push(*now);
            Ok(())
        })
        .unwrap();
        (summary, seen)
    }

    /// A homogeneous ball thrown sliding without spin (v0 = 1, mu = 0.2, G = 9.81): the
    /// friction mu m G slows the centre and spins the ball up until `v = omega R`, at the
    /// textbook time `2 v0 / (7 mu G)` (I = 2/5 m R^2), then it rolls at `5/7 v0` with no
    /// friction needed; the friction's work (as H1, twice) is the kinetic energy lost, `m v0^2
    /// - (7/5) m (5/7 v0)^2 = 2/7 m v0^2`. Tolerances: the stop located to round-off (1e-12
    /// of t, measured 3e-14), the speed and the work at the run's 1e-12 (1e-10). One
    /// transition, `stick`. Negative control: the stop of a ball with I = m R^2,
    /// `v0 / (2 mu G)`, is 1.75x later, far outside the tolerance.
    #[test]
    fn a_ball_thrown_sliding_rolls_at_five_sevenths_of_its_speed() {
        let ball = Ball::new(1.0, 1.0, [0.4; 3], [0.0; 3], 9.81).unwrap();
        let model = Sliding::with_friction(&ball, Friction::Coulomb, 0.2).unwrap();
        let y0 = model
            .initial(
                [0.0, 0.0, -1.0],
                [0.0; 3],
                [1.0, 0.0, 0.0],
                Normalise::Reject,
            )
            .unwrap();
        let (s, seen) = simulate(&model, y0, 1.0, 1e-12);
        let stop = 2.0 / (7.0 * 0.2 * 9.81);
        assert_eq!(s.transitions.len(), 1, "{:?}", s.transitions);
        assert_eq!(s.transitions[0].kind, "stick");
        assert!(
            (s.transitions[0].t - stop).abs() <= 1e-12 * stop,
            "{:?}",
            s.transitions
        );
        let hollow = 1.0 / (2.0 * 0.2 * 9.81);
        assert!((hollow - stop).abs() > 0.5 * stop, "control");
        let v = s.final_state.velocity;
        assert!((dot(&v, &v).sqrt() - 5.0 / 7.0).abs() <= 1e-10);
        assert!(
            (s.final_state.work - 2.0 / 7.0).abs() <= 1e-10,
            "{}",
            s.final_state.work
        );
        assert!(
            s.final_state.slip_speed <= 1e-13 && seen.len() >= 200,
            "{} {}",
            s.final_state.slip_speed,
            seen.len()
        );
        assert!(seen.iter().all(|o| o.t <= stop || o.slip_speed <= 1e-13));
    }

    /// The tippe top of the issue (a = 0.3, I1 = 0.37, I3 = 0.4) spun at 20 from 0.1 rad off its
    /// low position under Coulomb's friction: its small initial slip stops (one `stick`) and it
    /// rolls on: Jellett's integral constant across the switch and in both phases (1e-9; at
    /// rtol 1e-10 measured 1.6e-10), H1 + W constant (1e-9), the energy never increasing
    /// between step ends by more than round-off (1e-12 of H1), the normal force positive.
    /// Rolling keeps H1, so the top cannot invert (its height stays within 0.01 R of R - a):
    /// the inversion needs the contact to slide. mu = 0.1, 0.3 and 1.
    #[test]
    fn the_tippe_top_s_slip_stops_and_it_rolls_with_jellett_kept() {
        let body = Body::new(1.0, 1.0, 0.3, 0.37, 0.37, 0.4, 9.81).unwrap();
        for mu in [0.1, 0.3, 1.0] {
            let model = Sliding::with_friction(&body, Friction::Coulomb, mu).unwrap();
            let tilt = 0.1_f64;
            let y0 = model
                .initial(
                    [tilt.sin(), 0.0, -tilt.cos()],
                    [0.0, 0.0, 20.0],
                    [0.0; 3],
                    Normalise::Reject,
                )
                .unwrap();
            let (s, seen) = simulate(&model, y0, 20.0, 1e-10);
            assert_eq!(
                s.transitions.iter().map(|t| t.kind).collect::<Vec<_>>(),
                ["stick"]
            );
            let b = s.balance;
            assert!(
                b.jellett.unwrap() <= 1e-9 && b.energy_balance <= 1e-9,
                "{b:?}"
            );
            assert!(
                b.energy_increase <= 1e-12 && b.min_normal_force > 0.0,
                "{b:?}"
            );
            assert!(seen.iter().all(|o| (o.height - 0.7).abs() <= 0.01), "{mu}");
        }
    }

    /// The friction that rolling needs per unit of normal force, `|F| / N`, at `y = (gamma, M)`.
    fn needed_ratio(body: &Body, y: &[f64; 6]) -> f64 {
        let reaction = Reaction::of(body, y);
        reaction.friction_size() / reaction.normal
    }

    /// The rolling state at `t` from `y0` by the paper's system alone (Vern9 at 1e-13, no
    /// switch): a second integration, independent of the phases of [`integrate`].
    fn rolled(body: &Body, y0: [f64; 6], t: f64) -> [f64; 6] {
        let settings = Settings::builder()
            .method(Method::Vern9)
            .t_end(t)
            .tolerances(1e-13, 1e-13)
            .samples(0)
            .build()
            .unwrap();
        crate::simulate::integrate_observed::<_, RouthError, 6>(
            body,
            &ReducedSystem(body),
            y0,
            &settings,
            None,
            &mut |_, _| Ok(()),
            &mut |_| {},
        )
        .unwrap()
        .y
    }

    /// The body `(m, R, a, I1, I3, G)` in other units: masses times `mass`, lengths times
    /// `length`, times times `time` (G in length / time^2).
    fn in_units(b: [f64; 6], mass: f64, length: f64, time: f64) -> Body {
        let inertia = mass * length * length;
        Body::new(
            b[0] * mass,
            b[1] * length,
            b[2] * length,
            b[3] * inertia,
            b[3] * inertia,
            b[4] * inertia,
            b[5] * length / (time * time),
        )
        .unwrap()
    }

    /// The slip's onset: the tippe top (a = 0.3, I1 = 0.37, I3 = 0.4) rolling from tilt 0.3
    /// with omega = (0, 2, 1) needs a friction `|F| / N` that grows from 0.061 to 0.20 within
    /// its first 0.3 time units; with mu halfway
    /// between the ratio at t = 0 and its largest value over the first unit of time, the run
    /// starts rolling and its first switch is a `slip` where the ratio reaches mu. That time is
    /// found again from the paper's system alone (a second integration, Vern9 at 1e-13, and
    /// bisection on the ratio to 1e-14 of t): the two agree to 1e-9 of t (the states of two
    /// integrations at 1e-12 and 1e-13 differ by about 1e-11, the ratio's slope is of order
    /// one). Past the onset the ball slides with Jellett's integral and H1 + W kept (1e-9),
    /// the energy rising between step ends by no more than the integration's error while it
    /// rolls (1e-10 of H1: a hundred times the tolerance, either sign, per step).
    /// The same run in other units (masses x 1e12, lengths x 1e-2, times x 1e-3) has the same
    /// switches, of the same kinds, at the same times in its unit of time (1e-9 of t), and the
    /// same relative balances: every threshold of the phases is relative.
    #[test]
    fn the_slip_starts_where_rolling_needs_more_than_mu_n_in_any_units() {
        let b = [1.0, 1.0, 0.3, 0.37, 0.4, 9.81];
        let body = in_units(b, 1.0, 1.0, 1.0);
        let (tilt, omega) = (0.3_f64, [0.0, 2.0, 1.0]);
        let gamma = [tilt.sin(), 0.0, -tilt.cos()];
        let y0 = rolling_of(&body, &gamma, omega);
        let times: Vec<f64> = (0..=200).map(|k| k as f64 / 200.0).collect();
        let mut state = y0;
        let mut ratios = vec![needed_ratio(&body, &y0)];
        for pair in times.windows(2) {
            let step = rolled(&body, state, pair[1] - pair[0]);
            state = step;
            ratios.push(needed_ratio(&body, &state));
        }
        let largest = ratios.iter().cloned().fold(0.0, f64::max);
        assert!(largest > 1.5 * ratios[0], "{ratios:?}");
        let mu = 0.5 * (ratios[0] + largest);
        let above = ratios.iter().position(|&r| r > mu).unwrap();
        let (mut lo, mut hi) = (times[above - 1], times[above]);
        while hi - lo > 1e-14 * hi {
            let mid = 0.5 * (lo + hi);
            if needed_ratio(&body, &rolled(&body, y0, mid)) > mu {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        let onset = 0.5 * (lo + hi);
        let mut runs = Vec::new();
        for (mass, length, time) in [(1.0, 1.0, 1.0), (1e12, 1e-2, 1e-3)] {
            let body = in_units(b, mass, length, time);
            let model = Sliding::with_friction(&body, Friction::Coulomb, mu).unwrap();
            let x0 = sliding_state(
                &model,
                &rolling_of(&body, &gamma, omega.map(|w| w / time)),
                0.0,
            );
            let (s, _) = simulate(&model, x0, 2.0 * time, 1e-12);
            runs.push((s, time));
        }
        let (base, _) = &runs[0];
        assert_eq!(base.transitions[0].kind, "slip", "{:?}", base.transitions);
        assert!(
            (base.transitions[0].t - onset).abs() <= 1e-9 * onset,
            "{} {onset}",
            base.transitions[0].t
        );
        for (s, time) in &runs {
            let bal = s.balance;
            assert!(
                bal.jellett.unwrap() <= 1e-9 && bal.energy_balance <= 1e-9,
                "{bal:?}"
            );
            assert!(bal.energy_increase <= 1e-10, "{bal:?}");
            assert_eq!(
                s.transitions.iter().map(|t| t.kind).collect::<Vec<_>>(),
                base.transitions.iter().map(|t| t.kind).collect::<Vec<_>>()
            );
            for (t, t0) in s.transitions.iter().zip(&base.transitions) {
                assert!((t.t / time - t0.t).abs() <= 1e-9 * t0.t, "{t:?} {t0:?}");
            }
        }
    }

    /// The rolling law's `(gamma, M)` of the ball at `gamma` turning at `omega`.
    fn rolling_of(body: &Body, gamma: &[f64; 3], omega: [f64; 3]) -> [f64; 6] {
        let m = crate::ball::AsBall::ball(body).angular_momentum(gamma, &omega);
        [gamma[0], gamma[1], gamma[2], m[0], m[1], m[2]]
    }

    /// The Taylor method and RK4 are refused under Coulomb's friction, with the reason; auto
    /// runs Vern9.
    #[test]
    fn methods_that_cannot_cross_a_switch_are_refused() {
        for m in [Method::Taylor, Method::Rk4 { steps: 10 }] {
            let message = method(m, 1e-10).unwrap_err().to_string();
            assert!(message.contains("Coulomb's friction"), "{message}");
        }
        assert_eq!(method(Method::Auto, 1e-14).unwrap(), Method::Vern9);
        assert_eq!(method(Method::Dop853, 1e-14).unwrap(), Method::Dop853);
    }
}
