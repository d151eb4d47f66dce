//! The model's numerical entry points (field, integrals, steady motions) on arbitrary f64
//! bodies and states: no panic, no NaN in what an accepted input gives.
#![no_main]

#[path = "../../crates/routh/tests/support/properties.rs"]
mod properties;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    properties::numerics(&properties::decode_f64s(data), properties::Parts::Model);
});
