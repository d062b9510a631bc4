//! Haas G150 general purpose pocket milling, where the spec gives a code
//! the meaning `pocket.general`: read and kept, not expanded.
//!
//! G150 takes its pocket's outline from a subprogram (P, or a local
//! sequence number) and clears it with the control's own roughing passes
//! (Q stepover, Z depth, R plane, I/J/K and D finishing allowances and
//! offsets, G41/G42 side). How the control orders the passes, plunges
//! and joins them is not described in our references [?], so the run
//! reports W0510 (cycle-not-expanded) and goes on as if the cycle cut
//! nothing; the statement is kept in the program and written back.
//! Axis words in the block still move the tool with the modal motion.

use super::{Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, MachineFn};
use crate::ir::Decimal;

/// Is this code a general pocket in `spec` (meaning `pocket.general`)?
pub fn is_general_pocket(spec: &DialectSpec, letter: char, code: Decimal) -> bool {
    super::aux::machine_fn(spec, letter, code) == Some(MachineFn::GeneralPocket)
}

/// Notes that the cycle is not expanded (W0510); the run goes on.
pub fn exec(it: &mut Interp<'_, '_>, name: &str) -> Result<(), Stop> {
    let span = it.span;
    it.diags.push(
        Diagnostic::new(
            Code::CannotExpandCycle,
            format!("{name} (general pocket) is not expanded into moves: its cuts are left out"),
        )
        .primary(span, "not expanded")
        .note("the pocket's outline is a subprogram and the control's roughing path is not documented well enough to reproduce")
        .help("the run goes on after the block as if the cycle cut nothing; the block is kept in the program"),
    );
    Ok(())
}
