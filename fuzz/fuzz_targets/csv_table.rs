//! The CSV reader of `plot` and `animate` on arbitrary text: no panic; a table it accepts can
//! be drawn (finite, at least two rows, increasing t) and the figures and page are built.
#![no_main]

#[path = "../../crates/routh/tests/support/properties.rs"]
mod properties;

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        properties::csv_text(text);
    }
});
