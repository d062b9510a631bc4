//! Fuzz target: any bytes read in one dialect (chosen by the first byte)
//! and ported to every other never panic; what is written reads back.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&k, rest)) = data.split_first() else { return };
    let ds = cncc::fuzzing::DIALECTS;
    cncc::fuzzing::port(ds[k as usize % ds.len()], rest);
});
