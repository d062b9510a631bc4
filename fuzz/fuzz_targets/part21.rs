//! Fuzz the STEP-NC Part 21 reader, writer and query paths.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    cncc::stepnc::fuzz_read_write(data);
});
