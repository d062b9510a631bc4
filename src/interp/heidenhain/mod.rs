//! Heidenhain Klartext semantics in the interpreter (filled in below).

use super::{Interp, Stop};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, Stmt};

/// Runs one Heidenhain-only statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let _ = (block, exprs);
    Err(it.error_at(
        s.span,
        Code::UnsupportedHere,
        "this statement is not run by the interpreter yet",
    ))
}
