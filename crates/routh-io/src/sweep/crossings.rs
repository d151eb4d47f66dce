//! The events of a sweep's runs: the functions of the state watched on every accepted step
//! of a run, whose sign changes are located on the step's dense output by the integrator's
//! one event locator ([`crate::integrate::locate_into`]), in the lanes as one at a time. They
//! are the tilt rate, whose zeros are the turning points of the nutation
//! ([`super::turning`]), and the user's events, planes `x[i] = c` of the state crossed in a
//! direction (`[sweep] events = ["gamma3 = 0.9", "M1 = 0.5 up"]`, `routh sweep --events`,
//! Python's `events=`; [`crate::surface::parse_event`]), counted with the time of the first
//! crossing. The events do not end a run: it goes on to t_end.

use super::spec::{refuse, texts, Refusal};
use super::turning::{tilt_rate, NutationEvents, TurningPoints};
use crate::body::Body;
use crate::integrate::{locate_into, Crossing, Direction, EventSpec, Stepper};
use crate::surface::{parse_event, SurfaceEvent};

/// The crossings of one user event along a run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Crossings {
    /// How many, in `(0, t_end]` (a start on the plane is not one).
    pub count: u64,
    /// The time of the first (None without one).
    pub first_t: Option<f64>,
}

/// The user events of the `[sweep]` table's key `events = ["gamma3 = 0.9", "M1 = 0.5 up"]`.
pub fn from_toml(listed: &toml::Value) -> Result<Vec<SurfaceEvent>, Refusal> {
    let listed = texts(
        "events",
        listed,
        "must be a list of events NAME = NUMBER [up|down|both], such as [\"gamma3 = 0.9\", \
         \"M1 = 0.5 up\"]",
    )?;
    listed
        .into_iter()
        .map(|text| {
            parse_event(text, "events")
                .map_err(|_| refuse("events", format!("{text:?}"), crate::surface::EVENT_RULE))
        })
        .collect()
}

/// The events watched along the runs of one body, one run after another: its buffers are
/// allocated once (per lane of a batch) and reused by every run, each begun by
/// [`Watch::start`].
#[derive(Debug, Clone)]
pub struct Watch<'a> {
    body: &'a Body,
    /// The turning points, when watched (then event 0 is the tilt rate).
    turning: Option<TurningPoints>,
    /// The user's events, events `first..` of `specs`.
    events: &'a [SurfaceEvent],
    first: usize,
    specs: Vec<EventSpec>,
    /// The event functions at the start and at the end of the step.
    at_start: Vec<f64>,
    at_end: Vec<f64>,
    /// The crossings located on the step.
    found: Vec<Crossing>,
    crossings: Vec<Crossings>,
}

impl<'a> Watch<'a> {
    /// The events of runs of `body`: the turning points of the tilt when `turning`, and the
    /// user's `events` (none, or some, may be watched alone).
    pub fn new(body: &'a Body, turning: bool, events: &'a [SurfaceEvent]) -> Self {
        let first = usize::from(turning);
        let specs: Vec<EventSpec> = turning
            .then_some(Direction::Either)
            .into_iter()
            .chain(events.iter().map(|e| e.direction))
            .map(|direction| EventSpec {
                direction,
                terminal: false,
            })
            .collect();
        let n = specs.len();
        Watch {
            body,
            turning: turning.then(|| TurningPoints::new(&[0.0; 6])),
            events,
            first,
            specs,
            at_start: vec![0.0; n],
            at_end: vec![0.0; n],
            found: Vec::with_capacity(n),
            crossings: vec![Crossings::default(); events.len()],
        }
    }

    /// Event function `i` at `x`.
    fn value(body: &Body, events: &[SurfaceEvent], first: usize, i: usize, x: &[f64; 6]) -> f64 {
        match i.checked_sub(first) {
            Some(k) => events[k].plane.level(x),
            None => tilt_rate(body, x),
        }
    }

    /// Start a run at `x0 = (gamma, M)`, forgetting the last.
    pub fn start(&mut self, x0: &[f64; 6]) {
        let (body, events, first) = (self.body, self.events, self.first);
        for (i, g) in self.at_start.iter_mut().enumerate() {
            *g = Self::value(body, events, first, i, x0);
        }
        if let Some(turning) = self.turning.as_mut() {
            *turning = TurningPoints::new(x0);
        }
        self.crossings.fill(Crossings::default());
    }

    /// Look at one accepted step: the event functions at its end, and every sign change in
    /// an event's direction located on its dense output. A step on which a function that
    /// changed sign is not finite (its run then fails) counts no crossing.
    pub fn observe(&mut self, step: &dyn Stepper<6>) {
        let (body, events, first) = (self.body, self.events, self.first);
        let y1 = step.y();
        for (i, g) in self.at_end.iter_mut().enumerate() {
            *g = Self::value(body, events, first, i, y1);
        }
        let located = locate_into(
            &|t| step.dense(t),
            (step.t_prev(), step.t()),
            &self.specs,
            &mut |i, _, x| Self::value(body, events, first, i, x),
            &self.at_start,
            &self.at_end,
            &mut self.found,
        );
        if located.is_ok() {
            for crossing in &self.found {
                match crossing.event.checked_sub(first) {
                    Some(k) => {
                        let c = &mut self.crossings[k];
                        c.count += 1;
                        c.first_t.get_or_insert(crossing.t);
                    }
                    None => {
                        if let Some(turning) = self.turning.as_mut() {
                            let x = step.dense(crossing.t);
                            turning.turn(crossing.t, &x, self.at_start[0] < 0.0);
                        }
                    }
                }
            }
        }
        if let Some(turning) = self.turning.as_mut() {
            turning.step_end(y1);
        }
        std::mem::swap(&mut self.at_start, &mut self.at_end);
    }

    /// What the turning points say about the nutation of the run (None when not watched).
    pub fn nutation(&self) -> Option<NutationEvents> {
        self.turning.as_ref().map(TurningPoints::summary)
    }

    /// The crossings of each user event along the run, in the order of the events.
    pub fn crossings(&self) -> &[Crossings] {
        &self.crossings
    }
}
