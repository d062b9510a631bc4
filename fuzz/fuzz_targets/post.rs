//! Fuzz target: any bytes read as STEP-NC and posted to every dialect
//! never panic; every posted program reads back.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    cncc::fuzzing::post(data);
});
