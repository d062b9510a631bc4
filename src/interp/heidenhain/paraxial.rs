//! Paraxial radius compensation `L X+10 R+` / `R-` [K]: the one-axis move
//! is lengthened (`R+`) or shortened (`R-`) by the active tool radius
//! (with the TOOL CALL's DR), along the direction it moves. The front
//! end has checked that the block moves one axis without RL/RR.

use super::super::target::{target, Frame};
use super::super::{siemens, Interp, Stop};
use crate::ir::{Arena, Block, Expr, Motion, StmtKind, TncFunctionKind};
use std::borrow::Cow;

/// The move with its end point moved by the tool radius, when the block
/// says `R+`/`R-`.
pub fn apply<'m>(
    it: &mut Interp<'_, '_>,
    block: &Block,
    mut m: Cow<'m, Motion>,
    exprs: &Arena<Expr>,
) -> Result<Cow<'m, Motion>, Stop> {
    let Some(lengthen) = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::TncFunction(f) => match f.kind {
            TncFunctionKind::Paraxial(l) => Some(l),
            _ => None,
        },
        _ => None,
    }) else {
        return Ok(m);
    };
    let Some((letter, _)) = m.target.iter().next() else {
        return Ok(m);
    };
    let i = match letter {
        'X' => 0,
        'Y' => 1,
        'Z' => 2,
        _ => return Ok(m),
    };
    let p = it.state.pos;
    let from = siemens::from_base(it, [p[0], p[1], p[2]]);
    let t = target(it, &m.target, exprs, Frame::Program)?;
    let to = siemens::from_base(it, [t[0], t[1], t[2]]);
    let delta = to[i] - from[i];
    // [?] a move of length 0 has no direction: left as written.
    if delta.abs() < 1e-9 {
        return Ok(m);
    }
    let r = it.state.comp_radius;
    let sign = if lengthen { 1.0 } else { -1.0 };
    let end = to[i] + sign * r * delta.signum();
    let span = it.span;
    let coord = super::paths::abs_coord(end, it, span);
    if let Some(slot) = m.to_mut().target.slot_mut(letter) {
        *slot = Some(coord);
    }
    Ok(m)
}
