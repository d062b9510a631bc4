//! Reference returns between the two forms controllers have:
//!
//! * through an intermediate point (Fanuc, Haas, LinuxCNC `G28`): the
//!   axes given are first moved to the point written (in the distance mode
//!   in force), then home;
//! * straight home along named machine axes (Siemens `G74 Z1=0`: the
//!   values are not read).
//!
//! `G91 G28 Z0` (the intermediate point is where the tool is) becomes
//! `G74 Z1=0`; an intermediate point that is a move of its own (`G90 G28
//! Z5`, `G91 G28 Z10`) is refused (E0601): write the move, then the return.
//! Back, `G74 Z1=0` becomes `G91 G28 Z0`, followed by `G90` when the
//! program was in absolute mode (a straight walk of the blocks, as
//! [`super::levels`] follows them).
//!
//! A target with neither form but with moves in machine coordinates
//! (Heidenhain `M91`) gets a rapid to the machine datum on the named axes:
//! `G91 G28 Z0` is `L Z+0 R0 FMAX M91`. That takes the reference position
//! to be the machine zero, as the interpreter does (#5161.. start at 0)
//! and as a Fanuc reference position usually is [?: a machine parameter].

use super::follow_block;
use super::levels::Modal;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{Axes, Coord, Decimal, DimMode, Program, Stmt, StmtKind, Value};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let has = |direct| {
        to.code_for(Meaning::RefReturn {
            index: 1,
            store: false,
            direct,
        })
        .is_some()
    };
    let (via, direct) = (has(false), has(true));
    if !via && !direct && to.code_for(Meaning::MachineCoords).is_some() {
        return machine_datum(p, from, to, diags);
    }
    if via == direct {
        return;
    }
    let mut modal = Modal::new(from);
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        see_distance_first(&mut modal, &b);
        // A direct return written under G90: G91 for it, G90 after.
        let mut absolute = false;
        for s in &mut b.stmts {
            if let StmtKind::RefReturn {
                index: 1,
                store: false,
                direct: from_direct,
                axes,
            } = &mut s.kind
            {
                if *from_direct && via {
                    *from_direct = false;
                    zero(axes);
                    absolute |= modal.absolute;
                } else if !*from_direct && direct {
                    if !stays_put(axes, modal.absolute) {
                        diags.push(through_a_point(s.span, to));
                    }
                    // Converted either way: the error above, not the
                    // writer's, says what is wrong.
                    *from_direct = true;
                    zero(axes);
                }
            }
            modal.see(s);
        }
        if !absolute {
            p.blocks.push(b);
            continue;
        }
        let span = b.span;
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::Distance(DimMode::Absolute)));
        let i = b
            .stmts
            .iter()
            .position(|s| matches!(s.kind, StmtKind::RefReturn { .. }))
            .unwrap_or(0);
        let g91 = Stmt::new(StmtKind::Distance(DimMode::Incremental), span);
        b.stmts.insert(i, g91);
        let g90 = Stmt::new(StmtKind::Distance(DimMode::Absolute), span);
        let after = follow_block(&b, vec![g90]);
        p.blocks.push(b);
        p.blocks.push(after);
    }
}

/// `G28` / `G74` as a rapid to the machine datum on the named axes, in
/// machine coordinates (the G28 through a point of its own refused).
fn machine_datum(
    p: &mut Program,
    from: &DialectSpec,
    to: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    let mut modal = Modal::new(from);
    for b in &mut p.blocks {
        see_distance_first(&mut modal, b);
        let mut i = 0;
        while i < b.stmts.len() {
            modal.see(&b.stmts[i]);
            let s = &b.stmts[i];
            let StmtKind::RefReturn {
                index: 1,
                store: false,
                direct,
                axes,
            } = &s.kind
            else {
                i += 1;
                continue;
            };
            if !*direct && !stays_put(axes, modal.absolute) {
                diags.push(through_a_point(s.span, to));
            }
            let mut target = (**axes).clone();
            zero(&mut target);
            for a in crate::ir::AXIS_LETTERS {
                if let Some(Some(c)) = target.slot_mut(a) {
                    c.dim = Some(DimMode::Absolute);
                }
            }
            let mut rapid = crate::ir::Motion::new(crate::ir::MotionKind::Rapid);
            rapid.target = target;
            let span = s.span;
            b.stmts[i] = Stmt::new(StmtKind::Motion(Box::new(rapid)), span);
            b.stmts.insert(i, Stmt::new(StmtKind::MachineCoords, span));
            i += 2;
        }
    }
}

/// A block's G90/G91 applies before its motion, wherever it is written
/// (`G28 G91 Z0.` is `G91 G28 Z0.`), as the control applies it.
fn see_distance_first(modal: &mut Modal, b: &crate::ir::Block) {
    for s in &b.stmts {
        if matches!(s.kind, StmtKind::Distance(_)) {
            modal.see(s);
        }
    }
}

/// The intermediate point is where the tool is: incremental zeros (and at
/// least one axis named: `G74` needs one).
fn stays_put(axes: &Axes, absolute: bool) -> bool {
    axes.iter().next().is_some()
        && axes.iter().all(|(_, c)| {
            let incremental = match c.dim {
                Some(d) => d == DimMode::Incremental,
                None => !absolute,
            };
            incremental && c.value.number().is_some_and(|v| v == Decimal::ZERO)
        })
}

/// Every named axis at the value 0 (both forms read only which axes).
fn zero(axes: &mut Axes) {
    for a in crate::ir::AXIS_LETTERS {
        if let Some(Some(c)) = axes.slot_mut(a) {
            *c = Coord {
                value: Value::Number(Decimal::ZERO),
                dim: None,
                span: c.span,
            };
        }
    }
}

fn through_a_point(span: crate::span::Span, to: &DialectSpec) -> Diagnostic {
    Diagnostic::new(
        Code::CannotExpress,
        format!(
            "{} returns to the reference point along machine axes only, not through a point",
            to.name
        ),
    )
    .primary(span, "a reference return through an intermediate point")
    .help("move to the intermediate point first, then return from there (`G91 G28 Z0`)")
}
