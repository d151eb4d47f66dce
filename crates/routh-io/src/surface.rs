//! Surfaces of section as the front ends write them: `NAME = NUMBER`, NAME a component of the
//! reduced state `x = (gamma, M)` named as in `routh simulate`'s CSV
//! ([`STATE_COLUMN_NAMES`]: `gamma1 gamma2 gamma3 M1 M2 M3`), and a direction `up`, `down`
//! or `both`. Parsed once, here, for `routh section` and Python's `routh.section`.

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
}
