//! LinuxCNC's rules on mixing subroutine styles (the dialect capability
//! `strict-sub-styles`, rs274 2.9; its m98m99 tests 06 and 11): a Fanuc
//! `O1 ... M99` program is called by `M98` only, an `O1 sub` by `O1 call`
//! only, and normal flow reaching a sub definition rs274 has already
//! recorded (by a call that searched forward to it, or by passing it
//! before, as in a loop) is "sub found in illegal location". The M99
//! inside an `O1 sub` is a structure check (`check::structure`).

use super::{Interp, Stop};
use crate::diag::Code;
use crate::dialect::Capability;
use crate::ir::{Block, CallKind, FlowId, StmtKind};

/// A call of `kind` entering the definition `def` (the block holding the
/// `O1` or `O1 sub`): rs274's error at the definition when the styles
/// differ.
pub fn check_call(it: &Interp<'_, '_>, kind: CallKind, def: Option<&Block>) -> Result<(), Stop> {
    if !it.spec.has(Capability::StrictSubStyles) {
        return Ok(());
    }
    let Some(def) = def else { return Ok(()) };
    for s in &def.stmts {
        let msg = match (&s.kind, kind) {
            (
                StmtKind::ProgramStart {
                    number: Some(_), ..
                },
                CallKind::OWord,
            ) => "Fanuc 'O....' subroutine must be called with 'M98'",
            (
                StmtKind::SubStart {
                    id: FlowId::OWord(_),
                    ..
                },
                CallKind::Subprogram,
            ) => "'O.... sub' subroutine must be called with 'O.... call'",
            _ => continue,
        };
        return Err(it.error_at(s.span, Code::ControlOutsideSub, msg));
    }
    Ok(())
}

/// Normal flow reaching the o-word sub definition in `block`: an error when
/// rs274 has it recorded already (`known` says whether it was; the caller
/// records it from now on).
pub fn check_reached(it: &Interp<'_, '_>, block: &Block, known: bool) -> Result<(), Stop> {
    if !known || !it.spec.has(Capability::StrictSubStyles) {
        return Ok(());
    }
    for s in &block.stmts {
        if let StmtKind::SubStart {
            id: FlowId::OWord(o),
            ..
        } = &s.kind
        {
            return Err(it.error_at(
                s.span,
                Code::ControlOutsideSub,
                format!("sub: o|{o}| found in illegal location"),
            ));
        }
    }
    Ok(())
}
