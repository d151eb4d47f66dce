//! The exact solution (quadrature) on arbitrary f64 bodies and states: no panic, finite
//! turning points, period and states where it accepts the motion.
#![no_main]

#[path = "../../crates/routh/tests/support/properties.rs"]
mod properties;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    properties::numerics(&properties::decode_f64s(data), properties::Parts::Exact);
});
