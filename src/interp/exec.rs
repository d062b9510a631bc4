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
        Comment { .. } | Message(_) | Stock { .. } => 1,
        FeedMode(_) => 2,
        Feed(_) => 3,
        SpindleSpeed(_) | SpindleCss { .. } => 4,
        ToolSelect(_) => 5,
        ToolChange | ToolDef { .. } => 6,
        ToolOversize { .. } | ToolPreselect(_) => 7,
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
        Pole(_) | Corner { .. } | Approach(_) | CycleDef(_) | CycleLine(_) | PatternDef(_) => 20,
        CycleRun(_) | TncFunction(_) => 20,
        Stop(_) | ProgramEnd { .. } => 21,
        // Program content and control flow: the program walker runs these.
        Tape | ProgramStart { .. } | Raw { .. } | Word(_) | Command { .. } => 0,
        Assign { .. }
        | Declare { .. }
        | Goto { .. }
        | IfThen { .. }
        | If { .. }
        | ElseIf { .. }
        | Else { .. }
        | EndIf { .. }
        | While { .. }
        | EndWhile { .. }
        | Do { .. }
        | DoWhile { .. }
        | Repeat { .. }
        | EndRepeat { .. }
        | For { .. }
        | EndFor
        | Loop
        | EndLoop
        | RepeatUntil
        | Until { .. }
        | Case { .. }
        | SectionRepeat { .. }
        | Break { .. }
        | Continue { .. }
        | SubStart { .. }
        | SubEnd { .. }
        | Return { .. }
        | Call { .. }
        | SubReturn { .. }
        | ModalMacroCancel => 0,
    }
}

/// Runs the machine statements of a block in Table 8 order.
pub fn exec_block(it: &mut Interp<'_, '_>, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
    // The phases present, as bits; each is run in turn, its statements in
    // written order (no allocation, as a stable sort would give).
    use crate::dialect::Capability;
    if it.spec.has(Capability::PolePaths) {
        super::heidenhain::flush_before(it, block, exprs)?;
    }
    let late = it.spec.has(Capability::OffFunctionsAfterMove);
    let spec = it.spec;
    let phase = |k: &StmtKind| phase_of(k, late, spec);
    let mut present = 0u32;
    for s in &block.stmts {
        present |= 1 << phase(&s.kind);
    }
    present &= !1;
    if present.count_ones() <= 1 || in_phase_order(&block.stmts, late, spec) {
        return run_phase(it, block, exprs, late, |p| p > 0);
    }
    while present != 0 {
        let p = present.trailing_zeros() as u8;
        present &= present - 1;
        run_phase(it, block, exprs, late, |q| q == p)?;
    }
    Ok(())
}

/// The phase of a statement in `spec`: a kept code that is a motion runs
/// with the motions; with `late` (capability `off-functions-after-move`),
/// spindle stop and coolant off (and with them M0/M2/M30) run after the
/// block's move.
fn phase_of(kind: &StmtKind, late: bool, spec: &crate::dialect::DialectSpec) -> u8 {
    use crate::ir::{Coolant, SpindleState};
    match kind {
        StmtKind::Spindle(SpindleState::Stop) | StmtKind::Coolant(Coolant::Off) if late => 20,
        StmtKind::Aux { letter, code, .. } if super::aux::is_motion_aux(spec, *letter, *code) => 20,
        k => phase(k),
    }
}

/// Are the statements already in phase order?
fn in_phase_order(stmts: &[Stmt], late: bool, spec: &crate::dialect::DialectSpec) -> bool {
    stmts
        .windows(2)
        .all(|w| phase_of(&w[0].kind, late, spec) <= phase_of(&w[1].kind, late, spec))
}

/// Runs, in written order, the statements whose phase `keep` accepts.
fn run_phase(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
    late: bool,
    keep: impl Fn(u8) -> bool,
) -> Result<(), Stop> {
    for s in &block.stmts {
        if keep(phase_of(&s.kind, late, it.spec)) {
            it.span = s.span;
            exec_stmt(it, s, block, exprs)?;
        }
    }
    Ok(())
}

fn exec_stmt(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    use StmtKind::*;
    match &s.kind {
        Aux {
            letter,
            code,
            words,
        } if super::aux::is_motion_aux(it.spec, *letter, *code) => {
            super::aux::exec_motion(it, *letter, *code, words, block, exprs)
        }
        Comment { .. }
        | Message(_)
        | FeedMode(_)
        | Feed(_)
        | SpindleSpeed(_)
        | SpindleCss { .. }
        | Spindle(_)
        | Coolant(_)
        | Aux { .. }
        | DynamicCode { .. }
        | Dwell { .. }
        | Plane(_)
        | Units { .. }
        | PathMode { .. }
        | Distance(_)
        | ArcDistance(_)
        | ReturnToInitial(_)
        | Stop(_) => modes::exec(it, s, block, exprs),
        // Heidenhain TOOL CALL: the new tool's length (and radius) are active.
        ToolChange
            if it
                .spec
                .has(crate::dialect::Capability::ToolCallActivatesOffsets) =>
        {
            tools::exec(it, s, block, exprs)?;
            super::heidenhain::tool_change(it, block, exprs)
        }
        // Heidenhain RL/RR: the radius with the TOOL CALL's DR.
        RadiusComp { .. } if it.spec.has(crate::dialect::Capability::CompWithoutRegister) => {
            super::heidenhain::radius_comp(it, s, block, exprs)
        }
        ToolSelect(_)
        | ToolChange
        | ToolPreselect(_)
        | RadiusComp { .. }
        | LengthComp { .. }
        | OffsetRegister { .. } => tools::exec(it, s, block, exprs),
        WorkOffset { .. }
        | MachineCoords
        | CoordShift { .. }
        | SetData { .. }
        | RefReturn { .. } => offsets::exec(it, s, block, exprs),
        Transform(t) => match **t {
            crate::ir::Transform::Frame { .. } => siemens::exec(it, s, block, exprs),
            _ => offsets::exec(it, s, block, exprs),
        },
        CuttingEdge(_) | CycleCall(_) | ModalCallCancel => siemens::exec(it, s, block, exprs),
        Motion(m) if it.spec.has(crate::dialect::Capability::PolePaths) => {
            super::heidenhain::motion(it, s, m, block, exprs)
        }
        Motion(_) | Cycle(_) | CycleCancel => {
            motion::exec(it, s, block, exprs)?;
            siemens::after_motion(it, s, block, exprs)
        }
        ProgramEnd { .. }
        | Stock { .. }
        | ToolDef { .. }
        | ToolOversize { .. }
        | Pole(_)
        | Corner { .. }
        | Approach(_)
        | CycleDef(_)
        | CycleLine(_)
        | CycleRun(_)
        | PatternDef(_)
        | TncFunction(_) => super::heidenhain::exec(it, s, block, exprs),
        // Run by the program walker (phase 0), never here.
        _ => Ok(()),
    }
}
