//! The case parser on arbitrary text: no panic; a case it accepts is finite everywhere.
#![no_main]

#[path = "../../crates/routh/tests/support/properties.rs"]
mod properties;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        properties::case_text(text);
    }
});
