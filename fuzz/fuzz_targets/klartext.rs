//! Fuzz target: any bytes through the heidenhain (Klartext) reader and
//! writer never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    cncc::fuzzing::read_and_write("heidenhain", data);
});
