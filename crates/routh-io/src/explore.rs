//! The explorer page of `routh explore`: one self-contained HTML file that computes in the
//! browser. The routh library compiled to WebAssembly (`crates/routh-wasm`, built by `cargo
//! xtask explorer` into [`WASM_PATH`]) is inlined as base64 and runs in a Web Worker; the
//! page's sliders and number fields set the body and the initial state, each change runs the
//! same functions as `routh simulate`, `routh exact`, `routh steady` and `routh diagram`, and
//! the 3D view and charts are those of `routh animate` (`viewer.js`, one script for both).
//! The state is in the URL's hash (`explorer.html#tilt=0.7&spin=6&t_end=20`); a key that is
//! missing takes the value of the built-in default case ([`Defaults`]).

use crate::animate::{base64, fill_viewer_page};
use crate::case::Case;
use crate::error::{AppResult as Result, FileError};
use serde::Serialize;

const TEMPLATE: &str = include_str!("explorer.html");

/// The WebAssembly of `crates/routh-wasm` (`cargo xtask explorer` writes it; `cargo xtask
/// explorer --check`, run by `.ci/run`, fails while it differs from a fresh build).
pub const WASM: &[u8] = include_bytes!("../../../assets/explorer/routh_wasm.wasm");

/// Where [`WASM`] is kept, from the workspace's root.
pub const WASM_PATH: &str = "assets/explorer/routh_wasm.wasm";

/// The page's state when its URL names nothing: the built-in default case's body, its
/// initial gamma = (sin tilt, 0, cos tilt) and omega = (omega1, omega2, spin), and its
/// `[integration]` with `routh simulate`'s default method.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Defaults {
    m: f64,
    #[serde(rename = "R")]
    radius: f64,
    a: f64,
    #[serde(rename = "I1")]
    i1: f64,
    #[serde(rename = "I3")]
    i3: f64,
    #[serde(rename = "G")]
    gravity: f64,
    tilt: f64,
    spin: f64,
    omega1: f64,
    omega2: f64,
    t_end: f64,
    method: String,
    rtol: f64,
    atol: f64,
}

impl Defaults {
    /// The defaults of the built-in default case (a symmetric body with `a`, gamma in the
    /// plane of e1 and e3, its initial omega as written).
    pub fn of_default_case() -> Result<Self> {
        let case = Case::default_case()?;
        let body = case.body("routh explore")?;
        let [gamma1, gamma2, gamma3] = case.initial.gamma();
        let refuse = |message: &str| FileError::Case {
            file: case.source.clone(),
            message: format!("routh explore needs {message}"),
        };
        // omega as written (not M = I_Q omega turned back, which may move its last bits).
        let omega: [f64; 3] = case
            .document
            .get("initial")
            .and_then(|initial| initial.get("omega"))
            .and_then(|omega| omega.as_array())
            .and_then(|omega| {
                omega
                    .iter()
                    .map(|v| v.as_float())
                    .collect::<Option<Vec<_>>>()
            })
            .and_then(|omega| omega.try_into().ok())
            .ok_or_else(|| refuse("omega = [x, y, z] in [initial]"))?;
        if gamma2 != 0.0 {
            return Err(refuse("gamma = (sin tilt, 0, cos tilt)").into());
        }
        if body.i1() != body.i2() {
            return Err(refuse("I1 = I2").into());
        }
        let settings = case.integration;
        Ok(Defaults {
            m: body.m(),
            radius: body.radius(),
            a: body.a(),
            i1: body.i1(),
            i3: body.i3(),
            gravity: body.gravity(),
            tilt: gamma1.atan2(gamma3),
            spin: omega[2],
            omega1: omega[0],
            omega2: omega[1],
            t_end: settings.t_end(),
            method: settings.method().to_string(),
            rtol: settings.rtol(),
            atol: settings.atol(),
        })
    }
}

/// The explorer page.
pub fn html() -> Result<String> {
    let defaults =
        serde_json::to_string(&Defaults::of_default_case()?).map_err(|e| FileError::Case {
            file: "<built-in default>".into(),
            message: format!("cannot embed the defaults: {e}"),
        })?;
    Ok(fill_viewer_page(
        TEMPLATE,
        &[("DEFAULTS", defaults), ("WASM", base64(WASM))],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_default_case() {
        // The default case: gamma = (sin 0.3, 0, cos 0.3), omega = (0.5, 0.2, 8).
        let d = Defaults::of_default_case().unwrap();
        // atan2 of the rounded sine and cosine: within a few ulps of 0.3.
        assert!((d.tilt - 0.3).abs() < 1e-15, "tilt {}", d.tilt);
        // omega as written in the case file, to the bit.
        assert_eq!([d.omega1, d.omega2, d.spin], [0.5, 0.2, 8.0]);
        assert_eq!((d.t_end, d.rtol, d.atol), (100.0, 1e-12, 1e-12));
        assert_eq!(d.method, "dop853");
    }

    #[test]
    fn the_page_holds_the_webassembly_and_no_placeholder() {
        let page = html().unwrap();
        assert!(
            page.contains(&base64(&WASM[..3000])[..4000]),
            "wasm inlined"
        );
        // (three.js itself names a global `__THREE__`, so that key is not looked for.)
        for key in [
            "__VIEWER_STYLE__",
            "__PLAYBACK__",
            "__VIEWER_SCRIPTS__",
            "__VIEWER__",
            "__DEFAULTS__",
            "__WASM__",
        ] {
            assert!(!page.contains(key), "{key} left in the page");
        }
        // The WebAssembly magic number and version 1.
        assert_eq!(&WASM[..8], b"\0asm\x01\0\0\0");
    }
}
