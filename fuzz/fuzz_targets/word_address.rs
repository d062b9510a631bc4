//! Fuzz target: any bytes through the fanuc reader and writer never panic.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for d in ["fanuc", "haas", "linuxcnc"] {
        cncc::fuzzing::read_and_write(d, data);
    }
});
