//! Siemens 840D semantics in the interpreter: programmable frames, cutting
//! edges, named cycle calls and MCALL modal calls.

use super::{Interp, Stop};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, Stmt};

/// Runs a frame, cutting-edge, cycle-call or MCALL statement.
pub fn exec(it: &mut Interp<'_, '_>, s: &Stmt, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let _ = (block, exprs);
    Err(it.error_at(s.span, Code::UnsupportedHere, "this statement is not run by the interpreter yet"))
}

/// Called after every motion statement: a modal call (MCALL) runs its
/// cycle after each positioning move.
pub fn after_motion(it: &mut Interp<'_, '_>, s: &Stmt, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let _ = (it, s, block, exprs);
    Ok(())
}
