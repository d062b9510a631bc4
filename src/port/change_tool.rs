//! `change-names-tool` targets (Klartext `TOOL CALL 2`): a word-address
//! change that names no tool (`T2` in one block, `M6` later) loads the
//! tool selected before it. The port writes that number into the change
//! block, so the change is `TOOL CALL 2` and the selection alone is the
//! preselection `TOOL DEF 2`.
//!
//! The selection is followed in program order through straight-line code
//! only: a label, a jump, a call, a loop or a conditional between the
//! selection and the change (where the run could come from elsewhere)
//! leaves the change as it is, and the writer refuses a change whose tool
//! it does not know.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, Stmt, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if !to.has(Capability::ChangeNamesTool) {
        return;
    }
    let mut selected: Option<Stmt> = None;
    for b in &mut p.blocks {
        if b.label.is_some() {
            selected = None;
        }
        let changes = b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ToolChange));
        let own = b
            .stmts
            .iter()
            .find(|s| matches!(s.kind, StmtKind::ToolSelect(_)));
        match (changes, own, &selected) {
            (true, None, Some(sel)) => {
                let at = b
                    .stmts
                    .iter()
                    .position(|s| matches!(s.kind, StmtKind::ToolChange))
                    .unwrap_or(0);
                let mut s = sel.clone();
                s.span = b.stmts[at].span;
                b.stmts.insert(at, s);
            }
            (_, Some(own), _) => selected = Some(own.clone()),
            _ => {}
        }
        // `T1 T2 M6`: the next change loads T2.
        if let Some(next) = b.stmts.iter().find_map(|s| match &s.kind {
            StmtKind::ToolPreselect(t) => Some(Stmt::new(StmtKind::ToolSelect(t.clone()), s.span)),
            _ => None,
        }) {
            selected = Some(next);
        }
        if b.stmts.iter().any(|s| ends_straight_run(&s.kind)) {
            selected = None;
        }
    }
}

/// A statement after which the next block may be reached from elsewhere,
/// or run more than once: the selection before it is not followed.
fn ends_straight_run(k: &StmtKind) -> bool {
    use StmtKind as K;
    match k {
        K::Goto { .. }
        | K::IfThen { .. }
        | K::If { .. }
        | K::ElseIf { .. }
        | K::Else { .. }
        | K::EndIf { .. }
        | K::While { .. }
        | K::EndWhile { .. }
        | K::Do { .. }
        | K::DoWhile { .. }
        | K::Repeat { .. }
        | K::EndRepeat { .. }
        | K::For { .. }
        | K::EndFor { .. }
        | K::Loop { .. }
        | K::EndLoop { .. }
        | K::RepeatUntil { .. }
        | K::Until { .. }
        | K::Case { .. }
        | K::SectionRepeat { .. }
        | K::Break { .. }
        | K::Continue { .. }
        | K::SubStart { .. }
        | K::SubEnd { .. }
        | K::Return { .. }
        | K::Call { .. }
        | K::SubReturn { .. }
        | K::ModalMacroCancel { .. }
        | K::ProgramStart { .. }
        | K::ProgramEnd { .. } => true,
        K::Comment { .. }
        | K::Message { .. }
        | K::Tape { .. }
        | K::Stock { .. }
        | K::ToolDef { .. }
        | K::ToolOversize { .. }
        | K::Raw { .. }
        | K::Word { .. }
        | K::Units { .. }
        | K::Plane { .. }
        | K::Distance { .. }
        | K::ArcDistance { .. }
        | K::FeedMode { .. }
        | K::Feed { .. }
        | K::SpindleSpeed { .. }
        | K::SpindleCss { .. }
        | K::Spindle { .. }
        | K::Coolant { .. }
        | K::ToolSelect { .. }
        | K::ToolChange { .. }
        | K::ToolPreselect { .. }
        | K::CuttingEdge { .. }
        | K::RadiusComp { .. }
        | K::LengthComp { .. }
        | K::OffsetRegister { .. }
        | K::WorkOffset { .. }
        | K::MachineCoords { .. }
        | K::CoordShift { .. }
        | K::SetData { .. }
        | K::RefReturn { .. }
        | K::PathMode { .. }
        | K::ReturnToInitial { .. }
        | K::Transform { .. }
        | K::Dwell { .. }
        | K::Stop { .. }
        | K::Aux { .. }
        | K::DynamicCode { .. }
        | K::Command { .. }
        | K::Motion { .. }
        | K::Pole { .. }
        | K::Corner { .. }
        | K::Approach { .. }
        | K::CycleDef { .. }
        | K::CycleLine { .. }
        | K::CycleRun { .. }
        | K::PatternDef { .. }
        | K::TncFunction { .. }
        | K::Cycle { .. }
        | K::CycleCancel { .. }
        | K::CycleCall { .. }
        | K::ModalCallCancel { .. }
        | K::Assign { .. }
        | K::Declare { .. } => false,
    }
}
