//! Poincaré sections: the crossings of many runs of one autonomous field with a surface
//! `g(y) = 0` in a direction.
//!
//! Each accepted step of each run is shown to a watcher that keeps `g` at the step's start;
//! when `g` changes sign on the step in the surface's [`Direction`], the one event locator
//! [`locate`] finds the zero on the step's dense output (Brent's method to about 2 ulp of
//! `t`), and the state there is the crossing. Nothing stops the run: it goes on to `t_end`,
//! and every crossing is kept (at most one per step: a step is assumed short enough that `g`
//! changes sign once at most on it, as [`locate`] assumes).
//!
//! DOP853 runs in SIMD lanes ([`crate::batch`]: each lane bitwise the one-at-a-time DOP853),
//! the steps of each lane shown to its watcher by the batch's [`Queue`]; Vern9 and RK4 run
//! one at a time through [`crate::drive`], their steps shown by its observer. The watcher is
//! the same in both.

use crate::batch::{self, Field, Job, OneLane, Queue, LANES};
use crate::{
    drive, locate, stepper, Control, Direction, Drive, EventSpec, IntegrateError, Method, Options,
    Outcome, Stats, Stepper, Stop,
};

/// A surface of section `g(y) = 0` and the crossings that count.
#[derive(Clone, Copy)]
pub struct Surface<'g, const N: usize> {
    /// The function whose zeros are the surface.
    pub g: &'g dyn Fn(&[f64; N]) -> f64,
    /// The crossings that count: `Rising` from `g < 0` to `g >= 0`, `Falling` the opposite,
    /// `Either` both.
    pub direction: Direction,
}

/// One crossing of a run with the surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point<const N: usize> {
    /// The index of the run (in the list of initial states).
    pub run: usize,
    /// The time of the crossing.
    pub t: f64,
    /// The state there (the dense output of the step at `t`).
    pub y: [f64; N],
}

/// The crossings of all the runs, ordered by run and time, and the work of the runs.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Section<const N: usize> {
    /// The crossings.
    pub points: Vec<Point<N>>,
    /// The work of all the runs.
    pub stats: Stats,
}

/// One run's watch of the surface: its index and `g` at the start of the next step.
struct Watch {
    run: usize,
    g_start: f64,
}

impl Watch {
    /// The crossing on the last step of `step`, if any, appended to `points`;
    /// [`IntegrateError::NonFinite`] at the step's end when `g` is not finite on it.
    fn observe<const N: usize>(
        &mut self,
        surface: &Surface<'_, N>,
        step: &(impl Stepper<N> + ?Sized),
        points: &mut Vec<Point<N>>,
    ) -> Result<(), IntegrateError> {
        let g_end = (surface.g)(step.y());
        let spec = EventSpec {
            direction: surface.direction,
            terminal: false,
        };
        let found = locate(
            &|t| step.dense(t),
            (step.t_prev(), step.t()),
            &[spec],
            &mut |_, _, y| (surface.g)(y),
            &[self.g_start],
            &[g_end],
        )
        .map_err(|_| IntegrateError::NonFinite { t: step.t() })?;
        points.extend(found.iter().map(|c| Point {
            run: self.run,
            t: c.t,
            y: if c.t == step.t() {
                *step.y()
            } else {
                step.dense(c.t)
            },
        }));
        self.g_start = g_end;
        Ok(())
    }
}

/// The crossings with `surface` of the runs of `field` from each of `starts` over
/// `[0, t_end]`, by `method` with the tolerances and step limit of `opts`: DOP853 in SIMD
/// lanes, Vern9 and RK4 (its `steps` over the whole span) one at a time (see the module's
/// documentation). Errors: [`IntegrateError::Unsupported`] for the Taylor method and `auto`
/// (the field is not recorded here), and the first failure of a run (a step too small, the
/// step limit, a state or a value of `g` not finite).
pub fn section<F: Field<N>, const N: usize>(
    field: &F,
    starts: &[[f64; N]],
    t_end: f64,
    method: Method,
    opts: &Options,
    surface: &Surface<'_, N>,
) -> Result<Section<N>, IntegrateError> {
    let mut section = match method {
        Method::Dop853 => in_lanes(field, starts, t_end, opts, surface),
        Method::Vern9 | Method::Rk4 { .. } => {
            one_at_a_time(field, starts, t_end, method, opts, surface)
        }
        Method::Taylor | Method::Auto => Err(IntegrateError::Unsupported {
            method: if method == Method::Taylor {
                "taylor"
            } else {
                "auto"
            },
            reason: "a section runs DOP853 (in lanes), Vern9 or RK4 on the field as written",
        }),
    }?;
    section
        .points
        .sort_by(|a, b| a.run.cmp(&b.run).then(a.t.total_cmp(&b.t)));
    Ok(section)
}

/// Adds the work of `more` to `stats`.
fn add_work(stats: &mut Stats, more: Stats) {
    stats.steps += more.steps;
    stats.rejected += more.rejected;
    stats.rhs_evals += more.rhs_evals;
}

/// [`section`] with Vern9 or RK4, one run at a time through [`drive`].
fn one_at_a_time<F: Field<N>, const N: usize>(
    field: &F,
    starts: &[[f64; N]],
    t_end: f64,
    method: Method,
    opts: &Options,
    surface: &Surface<'_, N>,
) -> Result<Section<N>, IntegrateError> {
    let system = OneLane(field);
    let mut section = Section::default();
    for (run, y0) in starts.iter().enumerate() {
        let mut watch = Watch {
            run,
            g_start: (surface.g)(y0),
        };
        let mut stepping = stepper(method, &system, 0.0, *y0, t_end, opts)?;
        let points = &mut section.points;
        let outcome = drive::<_, IntegrateError, N>(
            stepping.as_mut(),
            &Drive::default(),
            &mut |_, _| Ok(()),
            &mut |_, _, step| {
                watch.observe(surface, step, points)?;
                Ok(Control::Continue)
            },
        )?
        .into_result()?;
        add_work(&mut section.stats, outcome.stats);
    }
    Ok(section)
}

/// The batch's queue of a section: the runs of `starts` in order, each lane's watch, the
/// crossings, the work and the first failure.
struct Watcher<'a, 'g, const N: usize> {
    starts: &'a [[f64; N]],
    next: usize,
    t_end: f64,
    surface: &'a Surface<'g, N>,
    lanes: [Option<Watch>; LANES],
    section: Section<N>,
    failure: Option<IntegrateError>,
}

impl<const N: usize> Queue<N> for Watcher<'_, '_, N> {
    fn next(&mut self, lane: usize) -> Option<Job<N>> {
        if self.failure.is_some() {
            return None;
        }
        let y0 = *self.starts.get(self.next)?;
        self.lanes[lane] = Some(Watch {
            run: self.next,
            g_start: (self.surface.g)(&y0),
        });
        self.next += 1;
        Some(Job {
            t0: 0.0,
            y0,
            t_end: self.t_end,
        })
    }

    fn step(&mut self, lane: usize, step: &dyn Stepper<N>) {
        if let Some(watch) = self.lanes[lane].as_mut() {
            if let Err(e) = watch.observe(self.surface, step, &mut self.section.points) {
                self.failure.get_or_insert(e);
                self.lanes[lane] = None;
            }
        }
    }

    fn end(&mut self, lane: usize, end: Outcome<N>) {
        add_work(&mut self.section.stats, end.stats);
        self.lanes[lane] = None;
        if let Stop::Failed(e) = end.stop {
            self.failure.get_or_insert(e);
        }
    }
}

/// [`section`] with DOP853 in lanes ([`batch::integrate_in_lanes`]).
fn in_lanes<F: Field<N>, const N: usize>(
    field: &F,
    starts: &[[f64; N]],
    t_end: f64,
    opts: &Options,
    surface: &Surface<'_, N>,
) -> Result<Section<N>, IntegrateError> {
    let mut watcher = Watcher {
        starts,
        next: 0,
        t_end,
        surface,
        lanes: std::array::from_fn(|_| None),
        section: Section::default(),
        failure: None,
    };
    batch::integrate_in_lanes(field, opts, &mut watcher);
    match watcher.failure {
        Some(e) => Err(e),
        None => Ok(watcher.section),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Scalar;

    /// The Hénon–Heiles system (Hénon and Heiles, AJ 69 (1964)) in the order of heyoka's event
    /// benchmark, `(v_x, v_y, x, y)`: `v_x' = -x - 2 x y`, `v_y' = y^2 - y - x^2`, `x' = v_x`,
    /// `y' = v_y`.
    struct HenonHeiles;

    impl Field<4> for HenonHeiles {
        fn eval<D: Scalar>(&self, s: &[D; 4]) -> [D; 4] {
            let (vx, vy, x, y) = (s[0], s[1], s[2], s[3]);
            [-x - x * y * 2.0, y * y - y - x * x, vx, vy]
        }
    }

    /// Its energy `(v_x^2 + v_y^2 + x^2 + y^2) / 2 + x^2 y - y^3 / 3`.
    fn energy(s: &[f64; 4]) -> f64 {
        let (vx, vy, x, y) = (s[0], s[1], s[2], s[3]);
        (vx * vx + vy * vy + x * x + y * y) / 2.0 + x * x * y - y * y * y / 3.0
    }

    /// The initial state of heyoka's event-detection benchmark (heyoka's documentation,
    /// "Benchmarks", "Event detection": the section `x = 0` crossed with `x` increasing,
    /// over t = 2000), on the energy level 0.083333 (to 2e-17: the six digits of an energy
    /// near 1/12 that the benchmark's state was built for).
    const HEYOKA: [f64; 4] = [
        -0.2525875586263492,
        -0.2178423952983717,
        0.0,
        0.2587703282931232,
    ];

    /// The section `x = 0`, `v_x > 0` of the Hénon–Heiles orbit of heyoka's benchmark over
    /// t = 2000, with DOP853 in lanes and with Vern9 one at a time (tolerances 1e-13).
    /// Measured: 306 crossings (about one per period of 2 pi). Each crossing lies on the
    /// surface to round-off: Brent's method locates the time to 2 ulp of t (4.5e-13 at
    /// t = 2000), which moves x by `|v_x|` (below 0.5 on this level) times that: 1e-12 bounds
    /// it (measured 1.3e-13). Each lies on the energy level to 1e-11 (the tolerance times the
    /// steps of the run, some 3e4: measured 1.4e-12). Both methods find the same crossings:
    /// the same number, `v_x > 0` at each, and the same times and points to 1e-8 (the global
    /// error of two runs at 1e-13 over t = 2000, grown by the orbit's shear: measured 3.4e-9).
    /// Negative control: with the direction `Falling` the crossings have `v_x < 0`, and a
    /// start on another energy level (y scaled by 1.1) misses the level by far more
    /// than the tolerance.
    #[test]
    fn henon_heiles_section_of_heyokas_benchmark() {
        let level = energy(&HEYOKA);
        assert!((level - 0.083333).abs() < 1e-15, "{level}");
        let x = |s: &[f64; 4]| s[2];
        let rising = Surface {
            g: &x,
            direction: Direction::Rising,
        };
        let opts = Options::new(1e-13, 1e-13).unwrap();
        let mut other = HEYOKA;
        other[3] *= 1.1;
        let starts = [HEYOKA, other];
        let dop = section(
            &HenonHeiles,
            &starts,
            2000.0,
            Method::Dop853,
            &opts,
            &rising,
        )
        .unwrap();
        let vern = section(&HenonHeiles, &starts, 2000.0, Method::Vern9, &opts, &rising).unwrap();
        let of_run = |s: &Section<4>, run: usize| -> Vec<Point<4>> {
            s.points.iter().filter(|p| p.run == run).copied().collect()
        };
        let (a, b) = (of_run(&dop, 0), of_run(&vern, 0));
        assert!(a.len() > 300, "{}", a.len());
        assert_eq!(a.len(), b.len());
        let on_surface = a.iter().chain(&b).map(|p| p.y[2].abs()).fold(0.0, f64::max);
        let off_level = a
            .iter()
            .chain(&b)
            .map(|p| (energy(&p.y) - level).abs())
            .fold(0.0, f64::max);
        let apart = a
            .iter()
            .zip(&b)
            .map(|(p, q)| {
                (0..4)
                    .map(|i| (p.y[i] - q.y[i]).abs())
                    .fold((p.t - q.t).abs(), f64::max)
            })
            .fold(0.0, f64::max);
        eprintln!(
            "Henon-Heiles: {} crossings, |x| <= {on_surface:e}, |H - H0| <= {off_level:e}, \
             DOP853 - Vern9 <= {apart:e}; work {:?} {:?}",
            a.len(),
            dop.stats,
            vern.stats
        );
        assert!(on_surface < 1e-12);
        assert!(off_level < 1e-11);
        assert!(apart < 1e-8);
        assert!(a.iter().all(|p| p.y[0] > 0.0));
        let other_level = of_run(&dop, 1);
        assert!(!other_level.is_empty());
        assert!(other_level
            .iter()
            .all(|p| (energy(&p.y) - level).abs() > 1e-3));
        let falling = Surface {
            g: &x,
            direction: Direction::Falling,
        };
        let down = section(
            &HenonHeiles,
            &[HEYOKA],
            2000.0,
            Method::Dop853,
            &opts,
            &falling,
        )
        .unwrap();
        assert!(down.points.iter().all(|p| p.y[0] < 0.0));
        assert!(down.points.len().abs_diff(a.len()) <= 1);
    }

    /// The Taylor method and `auto` are refused (the field is not recorded here).
    #[test]
    fn taylor_and_auto_are_refused() {
        let x = |s: &[f64; 4]| s[2];
        let surface = Surface {
            g: &x,
            direction: Direction::Either,
        };
        for method in [Method::Taylor, Method::Auto] {
            let refused = section(
                &HenonHeiles,
                &[HEYOKA],
                1.0,
                method,
                &Options::default(),
                &surface,
            );
            assert!(
                matches!(refused, Err(IntegrateError::Unsupported { .. })),
                "{refused:?}"
            );
        }
    }
}
