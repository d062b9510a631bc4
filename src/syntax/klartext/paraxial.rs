//! Paraxial radius compensation in `L` blocks: `L X+10 R+` / `R-` is a
//! [`TncFunctionKind::Paraxial`](crate::ir::TncFunctionKind::Paraxial)
//! next to the move; the block must move one axis and not say RL/RR.

use super::build::Ctx;
use super::token::Kw;
use crate::diag::Code;
use crate::ir::{Axes, CompSide, StmtKind};
use crate::syntax::Item;

/// `R+`/`R-` (paraxial) only in an `L` block moving one axis, without
/// RL/RR; E0128 otherwise.
pub(super) fn fits(
    ctx: &mut Ctx<'_>,
    kw: Kw,
    axes: &Axes,
    out: &[Item],
    l: usize,
    r: usize,
) -> bool {
    let is = |k: &StmtKind| matches!(k, StmtKind::TncFunction(f) if matches!(f.kind, crate::ir::TncFunctionKind::Paraxial(_)));
    let stmts = || {
        out.iter().filter_map(|i| match i {
            Item::Stmt(s) => Some(&s.kind),
            _ => None,
        })
    };
    if !stmts().any(is) {
        return true;
    }
    let comp =
        stmts().any(|k| matches!(k, StmtKind::RadiusComp { side, .. } if *side != CompSide::Off));
    let linear = axes
        .iter()
        .filter(|(a, _)| matches!(a, 'X' | 'Y' | 'Z'))
        .count();
    if kw == Kw::L && linear == 1 && axes.iter().count() == 1 && !comp {
        return true;
    }
    ctx.error(
        Code::KlartextBadParaxial,
        l,
        r,
        "R+/R- (paraxial) needs an L block moving exactly one axis, without RL/RR",
        "write e.g. `L X+10 R+`, or use RL/RR radius compensation",
    );
    false
}
