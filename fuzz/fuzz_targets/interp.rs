//! Fuzz target: any bytes read and run by the interpreter of every dialect
//! never panic, hang or exhaust memory.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    for d in cncc::fuzzing::DIALECTS {
        cncc::fuzzing::interpret(d, data);
    }
});
