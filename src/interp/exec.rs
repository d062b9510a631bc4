//! Running one block: its statements in the order NIST's Table 8 gives
//! (comments, feed mode, F, S, T, M6, spindle, coolant, overrides, dwell,
//! plane, units, radius comp, length comp, coordinate system, path mode,
//! distance mode, retract mode, G10/G28/G92, motion, stops), whatever
//! order they were written in.

use super::{modes, motion, offsets, siemens, tools, Interp, Stop};
use crate::ir::{Arena, Block, Expr, Stmt, StmtKind};

/// Where a statement runs within its block (lower first).
pub fn phase(kind: &StmtKind) -> u8 {
    use StmtKind::*;
    match kind {
        Comment { .. } | Message(_) => 1,
        FeedMode(_) => 2,
        Feed(_) => 3,
        SpindleSpeed(_) | SpindleCss { .. } => 4,
        ToolSelect(_) => 5,
        ToolChange => 6,
        Spindle(_) => 7,
        Coolant(_) => 8,
        Aux { .. } | DynamicCode { .. } => 9,
        Dwell { .. } => 10,
        Plane(_) => 11,
        Units { .. } => 12,
        RadiusComp { .. } | CuttingEdge(_) | OffsetRegister { .. } => 13,
        LengthComp { .. } => 14,
        WorkOffset { .. } => 15,
        PathMode { .. } => 16,
        Distance(_) | ArcDistance(_) => 17,
        ReturnToInitial(_) => 18,
        SetData { .. } | RefReturn { .. } | CoordShift { .. } | MachineCoords | Transform(_) => 19,
        Motion(_) | Cycle(_) | CycleCancel | CycleCall(_) | ModalCallCancel => 20,
        Stop(_) => 21,
        // Program content and control flow: the program walker runs these.
        Tape | ProgramStart { .. } | Raw { .. } | Word(_) | Command { .. } => 0,
        Assign { .. } | Declare { .. } | Goto { .. } | IfThen { .. } | If { .. } | ElseIf { .. } | Else { .. }
        | EndIf { .. } | While { .. } | EndWhile { .. } | Do { .. } | DoWhile { .. } | Repeat { .. }
        | EndRepeat { .. } | For { .. } | EndFor | Loop | EndLoop | RepeatUntil | Until { .. } | Case { .. }
        | SectionRepeat { .. } | Break { .. } | Continue { .. } | SubStart { .. } | SubEnd { .. }
        | Return { .. } | Call { .. } | SubReturn { .. } | ModalMacroCancel => 0,
    }
}

/// Runs the machine statements of a block in Table 8 order.
pub fn exec_block(it: &mut Interp<'_, '_>, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let mut order: Vec<&Stmt> = block.stmts.iter().filter(|s| phase(&s.kind) > 0).collect();
    order.sort_by_key(|s| phase(&s.kind));
    for s in order {
        it.span = s.span;
        exec_stmt(it, s, block, exprs)?;
    }
    Ok(())
}

fn exec_stmt(it: &mut Interp<'_, '_>, s: &Stmt, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
    use StmtKind::*;
    match &s.kind {
        Comment { .. } | Message(_) | FeedMode(_) | Feed(_) | SpindleSpeed(_) | SpindleCss { .. } | Spindle(_)
        | Coolant(_) | Aux { .. } | DynamicCode { .. } | Dwell { .. } | Plane(_) | Units { .. } | PathMode { .. }
        | Distance(_) | ArcDistance(_) | ReturnToInitial(_) | Stop(_) => modes::exec(it, s, block, exprs),
        ToolSelect(_) | ToolChange | RadiusComp { .. } | LengthComp { .. } | OffsetRegister { .. } => {
            tools::exec(it, s, block, exprs)
        }
        WorkOffset { .. } | MachineCoords | CoordShift { .. } | SetData { .. } | RefReturn { .. } => {
            offsets::exec(it, s, block, exprs)
        }
        Transform(t) => match **t {
            crate::ir::Transform::Frame { .. } => siemens::exec(it, s, block, exprs),
            _ => offsets::exec(it, s, block, exprs),
        },
        CuttingEdge(_) | CycleCall(_) | ModalCallCancel => siemens::exec(it, s, block, exprs),
        Motion(_) | Cycle(_) | CycleCancel => {
            motion::exec(it, s, block, exprs)?;
            siemens::after_motion(it, s, block, exprs)
        }
        // Run by the program walker (phase 0), never here.
        _ => Ok(()),
    }
}
