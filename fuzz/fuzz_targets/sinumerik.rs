//! Fuzz target: any bytes through the siemens840d reader and writer never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    cncc::fuzzing::read_and_write("siemens840d", data);
});
