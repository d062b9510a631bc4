//! Drilling canned cycles expanded into canonical moves, as the
//! controllers expand them.
//!
//! * [`run_cycle`]: word-address cycles G73..G89 (and Fanuc's G74/G76),
//!   exactly as LinuxCNC 2.9's interpreter expands them (checked against
//!   `rs274`; see `tests.rs`). The core keeps one [`CycleMemory`] per
//!   program run, calls [`CycleMemory::cancel`] on G80 or any other motion
//!   code, and calls `run_cycle` for every block that runs a cycle.
//!   `run_cycle` owns the whole expansion, including LinuxCNC's wrapper
//!   `SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)` … restore of the mode from
//!   [`MotionHost::path_mode`](super::host::MotionHost::path_mode): the core
//!   must not add it.
//! * [`run_named_drill_cycle`]: Siemens CYCLE81..CYCLE89.
//! * [`pattern_positions`]: Siemens HOLES1, HOLES2, CYCLE801.

mod body;
mod float_tap;
mod frame;
mod memory;
mod oriented;
mod patterns;
mod siemens;
mod word;

#[cfg(test)]
mod testhost;
#[cfg(test)]
mod tests;

pub use memory::CycleMemory;
pub use patterns::pattern_positions;
pub use siemens::run_named_drill_cycle;
pub use word::run_cycle;
