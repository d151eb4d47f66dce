//! Surfaces of section as the front ends write them: `NAME = NUMBER`, NAME a component of the
//! reduced state `x = (gamma, M)` named as in `routh simulate`'s CSV
//! ([`STATE_COLUMN_NAMES`]: `gamma1 gamma2 gamma3 M1 M2 M3`), and a direction `up`, `down`
//! or `both`; an event of a sweep is both in one text, `NAME = NUMBER [DIRECTION]`
//! ([`parse_event`]). Parsed once, here, for `routh section`, `routh sweep` and Python's
//! `routh.section` and `routh.sweep`.

use crate::error::AppResult as Result;
use crate::integrate::Direction;
use crate::problem::Plane;
use crate::table::STATE_COLUMN_NAMES;
use routh_ball::RouthError;

/// The names of the components of `x = (gamma, M)`, in order: the first six
/// [`STATE_COLUMN_NAMES`].
pub fn component_names() -> &'static [&'static str] {
    &STATE_COLUMN_NAMES[..6]
}

/// The index in `x = (gamma, M)` of the component named `name` (as in the CSV of `routh
/// simulate`, exactly); `None` for any other name (omega is not a component of the state).
pub fn component(name: &str) -> Option<usize> {
    component_names().iter().position(|&n| n == name)
}

/// The plane `NAME = NUMBER` of `text` (spaces around the parts allowed): the component and
/// the value. Refused ([`RouthError::Option`] naming `what`): no `=`, an unknown name, a
/// number that does not parse or is not finite.
pub fn parse_surface(text: &str, what: &'static str) -> Result<Plane> {
    let refused = || RouthError::Option {
        name: what,
        value: format!("{text:?}"),
        rule: "must be NAME = NUMBER, NAME one of gamma1 gamma2 gamma3 M1 M2 M3 and NUMBER \
               finite (e.g. \"gamma1 = 0\")",
    };
    let (name, value) = text.split_once('=').ok_or_else(refused)?;
    let component = component(name.trim()).ok_or_else(refused)?;
    let value: f64 = value.trim().parse().map_err(|_| refused())?;
    Ok(Plane::new(component, value).map_err(|_| refused())?)
}

/// The direction of crossing named `text`: `up` (the component increasing through the
/// value), `down`, or `both`. Anything else is refused ([`RouthError::Option`] naming
/// `what`).
pub fn parse_direction(text: &str, what: &'static str) -> Result<Direction> {
    match text.trim() {
        "up" => Ok(Direction::Rising),
        "down" => Ok(Direction::Falling),
        "both" => Ok(Direction::Either),
        _ => Err(RouthError::Option {
            name: what,
            value: format!("{text:?}"),
            rule: "must be up, down or both",
        }
        .into()),
    }
}

/// A plane of the state and the crossings of it that count: an event of a sweep's runs
/// ([`parse_event`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceEvent {
    /// The plane `x[i] = c`.
    pub plane: Plane,
    /// The crossings that count: `up` (`x[i]` increasing through `c`), `down` or `both`.
    pub direction: Direction,
}

/// The rule of an event's text ([`parse_event`]), as its refusals state it.
pub const EVENT_RULE: &str = "must be NAME = NUMBER with an optional direction up, down or \
                              both (default both), NAME one of gamma1 gamma2 gamma3 M1 M2 M3 \
                              and NUMBER finite (e.g. \"gamma3 = 0.9 up\")";

/// The event `NAME = NUMBER [DIRECTION]` of `text`: a plane as [`parse_surface`] reads it,
/// then, after a space, a direction as [`parse_direction`] reads it (default `both`), such
/// as `"gamma3 = 0.9 up"` or `"M1 = -2.5e-1"`. Refused ([`RouthError::Option`] naming
/// `what`) with the rule of both parts.
pub fn parse_event(text: &str, what: &'static str) -> Result<SurfaceEvent> {
    let refused = || RouthError::Option {
        name: what,
        value: format!("{text:?}"),
        rule: EVENT_RULE,
    };
    let text = text.trim();
    let (surface, direction) = text
        .rsplit_once(char::is_whitespace)
        .and_then(|(surface, word)| Some((surface, parse_direction(word, what).ok()?)))
        .unwrap_or((text, Direction::Either));
    let plane = parse_surface(surface, what).map_err(|_| refused())?;
    Ok(SurfaceEvent { plane, direction })
}

/// The events of `list`, separated by commas (`"gamma3 = 0.9 up,M1 = 0.5"`: a number has
/// no comma), each as [`parse_event`] reads it.
pub fn parse_events(list: &str, what: &'static str) -> Result<Vec<SurfaceEvent>> {
    list.split(',')
        .map(|text| parse_event(text, what))
        .collect()
}

/// The name of `direction` as [`parse_direction`] reads it.
pub fn direction_name(direction: Direction) -> &'static str {
    match direction {
        Direction::Rising => "up",
        Direction::Falling => "down",
        Direction::Either => "both",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surfaces_and_directions_parse_and_malformed_ones_are_refused() {
        assert_eq!(
            parse_surface("gamma1 = 0", "surface").unwrap(),
            Plane::new(0, 0.0).unwrap()
        );
        assert_eq!(
            parse_surface(" M3=-2.5e1 ", "surface").unwrap(),
            Plane::new(5, -25.0).unwrap()
        );
        for bad in [
            "",
            "gamma1",
            "gamma1 = ",
            "= 0",
            "omega1 = 0",
            "gamma4 = 0",
            "gamma1 = x",
            "gamma1 = nan",
            "gamma1 = inf",
            "gamma1 = 0 = 1",
            "Gamma1 = 0",
        ] {
            let refused = parse_surface(bad, "surface").unwrap_err().to_string();
            assert!(refused.contains("surface"), "{bad:?}: {refused}");
        }
        for (name, direction) in [
            ("up", Direction::Rising),
            ("down", Direction::Falling),
            ("both", Direction::Either),
        ] {
            assert_eq!(parse_direction(name, "direction").unwrap(), direction);
            assert_eq!(direction_name(direction), name);
        }
        assert!(parse_direction("sideways", "direction").is_err());
    }

    #[test]
    fn events_parse_with_or_without_a_direction_and_malformed_ones_are_refused() {
        let event = |component, value, direction| SurfaceEvent {
            plane: Plane::new(component, value).unwrap(),
            direction,
        };
        for (text, expected) in [
            ("gamma3 = 0.9", event(2, 0.9, Direction::Either)),
            (" M1 = -2.5e-1 up ", event(3, -0.25, Direction::Rising)),
            ("gamma1=0\tdown", event(0, 0.0, Direction::Falling)),
            ("M3 = 1 both", event(5, 1.0, Direction::Either)),
        ] {
            assert_eq!(parse_event(text, "events").unwrap(), expected, "{text:?}");
        }
        assert_eq!(
            parse_events("gamma3 = 0.9, M1 = -2.5e-1 up", "events").unwrap(),
            [
                event(2, 0.9, Direction::Either),
                event(3, -0.25, Direction::Rising)
            ]
        );
        assert!(parse_events("gamma3 = 0.9,", "events").is_err());
        for bad in [
            "",
            "up",
            "gamma1 = up",
            "gamma1 = 0 sideways",
            "gamma1 = 0up",
            "gamma1 = 0 up down",
            "gamma1 = inf",
            "omega1 = 0",
            "gamma1 = 0:up",
        ] {
            let refused = parse_event(bad, "events").unwrap_err().to_string();
            assert!(
                refused.contains("events") && refused.contains("up, down or both"),
                "{bad:?}: {refused}"
            );
        }
    }
}
