//! Event location: a bracketing scalar root finder ([`brent`]) and the one event locator
//! ([`locate_into`], and [`locate`] into a new list) that the driver, the sweep, sections
//! and the Python bindings share.

/// Finds a root of `f` in the bracket `[a, b]` (or `[b, a]`) by Brent's method
/// (inverse quadratic interpolation, secant and bisection; R. P. Brent,
/// *Algorithms for Minimization without Derivatives*, 1973, `zeroin`).
///
/// Requires `f(a)` and `f(b)` of opposite signs (or one of them zero). The
/// result `x` satisfies `|x - x*| <= 2 eps |x| + tol / 2` for a root `x*`
/// (`eps` the machine epsilon), so `tol = 0` asks for full precision.
/// Returns `None` if the bracket is invalid, `f` returns NaN, or `max_iter`
/// evaluations do not suffice.
pub fn brent(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    tol: f64,
    max_iter: usize,
) -> Option<f64> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa.is_nan() || fb.is_nan() {
        return None;
    }
    if fa == 0.0 {
        return Some(a);
    }
    if fb == 0.0 {
        return Some(b);
    }
    if (fa > 0.0) == (fb > 0.0) {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..max_iter {
        if (fb > 0.0) == (fc > 0.0) {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol1 || fb == 0.0 {
            return Some(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol1 { d } else { tol1.copysign(m) };
        fb = f(b);
        if fb.is_nan() {
            return None;
        }
    }
    None
}

/// Which sign changes of an event function count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// From negative to zero or positive.
    Rising,
    /// From positive to zero or negative.
    Falling,
    /// Both.
    Either,
}

impl Direction {
    /// Whether a change from `g0` to `g1` is a crossing in this direction (a start at zero
    /// is not one: the zero was met on the step before).
    pub fn crosses(self, g0: f64, g1: f64) -> bool {
        let rising = g0 < 0.0 && g1 >= 0.0;
        let falling = g0 > 0.0 && g1 <= 0.0;
        match self {
            Direction::Rising => rising,
            Direction::Falling => falling,
            Direction::Either => rising || falling,
        }
    }
}

/// How one event function is watched: the crossings that count, and whether one ends the run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EventSpec {
    /// The crossings that count.
    pub direction: Direction,
    /// A crossing ends the run.
    pub terminal: bool,
}

/// A located zero of an event function on a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    /// The index of the event function.
    pub event: usize,
    /// Its time.
    pub t: f64,
    /// Whether it ends the run (its [`EventSpec::terminal`]).
    pub terminal: bool,
}

/// An event function that changed sign on the step `[ta, tb]` but whose zero Brent's method
/// could not find (the function is not finite there).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unlocated {
    /// The index of the event function.
    pub event: usize,
    /// Start of the step.
    pub ta: f64,
    /// End of the step.
    pub tb: f64,
}

/// Most evaluations of Brent's method for one crossing.
const LOCATE_ITERATIONS: usize = 200;

/// The crossings of the event functions `g(i, t, y)` (`i` indexing `specs`) on one step
/// `[ta, tb]` (either direction) whose dense output is `dense`: [`locate_into`] in a new list.
pub fn locate<const N: usize>(
    dense: &dyn Fn(f64) -> [f64; N],
    span: (f64, f64),
    specs: &[EventSpec],
    g: &mut dyn FnMut(usize, f64, &[f64; N]) -> f64,
    g_start: &[f64],
    g_end: &[f64],
) -> Result<Vec<Crossing>, Unlocated> {
    let mut found = vec![];
    locate_into(dense, span, specs, g, g_start, g_end, &mut found)?;
    Ok(found)
}

/// The crossings of the event functions `g(i, t, y)` (`i` indexing `specs`) on one step
/// `[ta, tb]` (either direction) whose dense output is `dense`, written into `found` (cleared
/// first; a caller that keeps the list from step to step allocates nothing once it holds
/// as many crossings as there are events): the one event locator of the driver, the sweep,
/// sections and Python.
///
/// `g_start[i]` and `g_end[i]` are the values of event `i` at the step ends (at `tb` on the
/// state as the step computed it). Every event whose change from `g_start` to `g_end` crosses
/// in its [`Direction`] is located by [`brent`] on `g(i, t, dense(t))` to about 2 ulp of `t`
/// (at `tb` itself when `g_end` is zero); the others cost nothing beyond that test. The
/// crossings come in the order of time (ties in the order of `specs`), and the list ends with
/// the first terminal one. At most one zero of each function is found per step: the step is
/// assumed short enough that the function changes sign at most once on it.
pub fn locate_into<const N: usize>(
    dense: &dyn Fn(f64) -> [f64; N],
    (ta, tb): (f64, f64),
    specs: &[EventSpec],
    g: &mut dyn FnMut(usize, f64, &[f64; N]) -> f64,
    g_start: &[f64],
    g_end: &[f64],
    found: &mut Vec<Crossing>,
) -> Result<(), Unlocated> {
    found.clear();
    let scale = ta.abs().max(tb.abs()).max((tb - ta).abs());
    let tol = 2.0 * f64::EPSILON * scale;
    for (i, spec) in specs.iter().enumerate() {
        if !spec.direction.crosses(g_start[i], g_end[i]) {
            continue;
        }
        let t = if g_end[i] == 0.0 {
            Some(tb)
        } else {
            brent(|s| g(i, s, &dense(s)), ta, tb, tol, LOCATE_ITERATIONS)
        };
        let t = t.ok_or(Unlocated { event: i, ta, tb })?;
        found.push(Crossing {
            event: i,
            t,
            terminal: spec.terminal,
        });
    }
    let dir = if tb >= ta { 1.0 } else { -1.0 };
    // In place (a stable sort may allocate): ties keep the order of `specs`, in which the
    // crossings were pushed.
    found.sort_unstable_by(|a, b| {
        ((a.t - ta) * dir)
            .total_cmp(&((b.t - ta) * dir))
            .then(a.event.cmp(&b.event))
    });
    if let Some(first) = found.iter().position(|c| c.terminal) {
        found.truncate(first + 1);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `y = (sin t, cos t)` exactly, as a dense output; the events are `sin t` (index 0) and
    /// `cos t` (index 1), with zeros at multiples of pi and at pi/2 + k pi.
    fn sine(t: f64) -> [f64; 2] {
        [t.sin(), t.cos()]
    }

    fn run(specs: &[EventSpec], ta: f64, tb: f64) -> Result<Vec<Crossing>, Unlocated> {
        let mut g = |i: usize, _t: f64, y: &[f64; 2]| y[i];
        let (ya, yb) = (sine(ta), sine(tb));
        locate(&sine, (ta, tb), specs, &mut g, &ya, &yb)
    }

    fn spec(direction: Direction, terminal: bool) -> EventSpec {
        EventSpec {
            direction,
            terminal,
        }
    }

    #[test]
    fn locates_sine_and_cosine_zeros_in_time_order() {
        use std::f64::consts::{FRAC_PI_2, PI};
        // On [1, 4]: sin falls through zero at pi, cos falls through zero at pi/2.
        let specs = [
            spec(Direction::Falling, false),
            spec(Direction::Either, false),
        ];
        let found = run(&specs, 1.0, 4.0).unwrap();
        assert_eq!(found.len(), 2);
        assert_eq!((found[0].event, found[1].event), (1, 0));
        // Brent's method to 2 ulp of t, plus the round-off of sin and cos near their zeros.
        assert!((found[0].t - FRAC_PI_2).abs() <= 4.0 * f64::EPSILON * 4.0);
        assert!((found[1].t - PI).abs() <= 4.0 * f64::EPSILON * 4.0);
        // Backwards over the same step: pi comes first.
        let specs_back = [
            spec(Direction::Rising, false),
            spec(Direction::Rising, false),
        ];
        let back = run(&specs_back, 4.0, 1.0).unwrap();
        assert_eq!((back[0].event, back[1].event), (0, 1));
    }

    #[test]
    fn a_direction_that_does_not_match_finds_nothing() {
        // Negative control: sin only falls on [1, 4], cos only falls on it.
        let specs = [spec(Direction::Rising, true), spec(Direction::Rising, true)];
        assert_eq!(run(&specs, 1.0, 4.0).unwrap(), vec![]);
    }

    #[test]
    fn the_first_terminal_crossing_ends_the_list() {
        use std::f64::consts::FRAC_PI_2;
        // cos (terminal) at pi/2 comes before sin at pi, which is dropped.
        let specs = [
            spec(Direction::Either, false),
            spec(Direction::Falling, true),
        ];
        let found = run(&specs, 1.0, 4.0).unwrap();
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].event, 1);
        assert!(found[0].terminal);
        assert!((found[0].t - FRAC_PI_2).abs() <= 4.0 * f64::EPSILON * 4.0);
        // With the later one terminal, both are kept.
        let specs = [
            spec(Direction::Either, true),
            spec(Direction::Falling, false),
        ];
        assert_eq!(run(&specs, 1.0, 4.0).unwrap().len(), 2);
    }

    #[test]
    fn a_function_that_is_not_finite_is_unlocated() {
        let specs = [spec(Direction::Either, true)];
        let mut g = |_: usize, t: f64, _: &[f64; 2]| {
            if t > 1.5 && t < 3.5 {
                f64::NAN
            } else {
                t.sin()
            }
        };
        let err = locate(
            &sine,
            (1.0, 4.0),
            &specs,
            &mut g,
            &[1.0_f64.sin()],
            &[4.0_f64.sin()],
        );
        assert_eq!(
            err,
            Err(Unlocated {
                event: 0,
                ta: 1.0,
                tb: 4.0
            })
        );
    }
}
