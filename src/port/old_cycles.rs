//! Old-style Heidenhain cycles that act when defined, in the target's own
//! form where that is exact (the target lacks `cycle-definitions`, the
//! family of `CYCL DEF n.m` lines):
//!
//! * Datum shift `CYCL DEF 7.0` with `7.1 X..`, `7.2 Y..`, `7.3 Z..` in
//!   the blocks that follow: when the group gives all three axes, absolute
//!   and without the datum table (`#n`), the shift does not depend on the
//!   one before, and is the target's local shift: Siemens `TRANS X Y Z`
//!   (capability `frames`; it replaces the programmable frame, so only
//!   where the program has no rotation, mirror or scaling cycle 8, 10, 11
//!   or 26), or the code meaning `coord-shift.local` (Fanuc, Haas,
//!   LinuxCNC `G52 X Y Z`, relative to the work offset as the Heidenhain
//!   shift is relative to the preset).
//! * Dwell `CYCL DEF 9.0` with `9.1 V.ZEIT t` (seconds): the dwell
//!   statement (`G4`), which the writer gives its unit.
//!
//! Other groups stay as they are, and the writer names them (E0601).

use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{
    Axes, Block, Coord, CoordShift, CycleLine, DwellUnit, FrameOp, Program, Stmt, StmtKind,
    Transform, Value,
};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if to.has(Capability::CycleDefinitions) || !has_old_lines(p) {
        return;
    }
    let frames = to.has(Capability::Frames) && !has_other_frames(p);
    let local = to
        .code_for(Meaning::CoordShift(CoordShift::Local))
        .is_some();
    let mut i = 0;
    while i < p.blocks.len() {
        let Some(head) = line(&p.blocks[i]) else {
            i += 1;
            continue;
        };
        let (cycle, sub) = (head.cycle, head.sub);
        let end = group_end(&p.blocks, i, cycle);
        if sub == 0 {
            let kind = match cycle {
                7 => shift(&p.blocks[i + 1..end], frames, local),
                9 => dwell(&p.blocks[i + 1..end]),
                _ => None,
            };
            if let Some(kind) = kind {
                let span = p.blocks[i].span;
                let block = crate::port::follow_block(&p.blocks[i], vec![Stmt::new(kind, span)]);
                let number = p.blocks[i].number.take();
                let label = p.blocks[i].label.take();
                p.blocks.splice(
                    i..end,
                    [Block {
                        number,
                        label,
                        ..block
                    }],
                );
            }
        }
        i += 1;
    }
}

fn has_old_lines(p: &Program) -> bool {
    p.blocks.iter().any(|b| line(b).is_some())
}

/// Cycles 8 (mirror), 10 (rotation), 11 and 26 (scaling).
fn has_other_frames(p: &Program) -> bool {
    p.blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .any(|s| match &s.kind {
            StmtKind::CycleLine(l) => matches!(l.cycle, 8 | 10 | 11 | 26),
            StmtKind::Transform(_) => true,
            _ => false,
        })
}

/// The block's old-style cycle line, when it holds only that.
fn line(b: &Block) -> Option<&CycleLine> {
    match b.stmts.as_slice() {
        [s] => match &s.kind {
            StmtKind::CycleLine(l) => Some(l),
            _ => None,
        },
        _ => None,
    }
}

/// The index after the `n.1`, `n.2`.. blocks that follow `n.0` at `i`.
fn group_end(blocks: &[Block], i: usize, cycle: u32) -> usize {
    let mut j = i + 1;
    while j < blocks.len() {
        match line(&blocks[j]) {
            Some(l) if l.cycle == cycle && l.sub > 0 && blocks[j].label.is_none() => j += 1,
            _ => break,
        }
    }
    j
}

/// `7.1 X+20`, `7.2 Y+Q7`, `7.3 Z+0` → the shift by all three axes.
fn shift(lines: &[Block], frames: bool, local: bool) -> Option<StmtKind> {
    if !frames && !local {
        return None;
    }
    let mut axes = Axes::default();
    for b in lines {
        for w in &line(b)?.words {
            let axis = match w.name.as_str() {
                "X" => &mut axes.x,
                "Y" => &mut axes.y,
                "Z" => &mut axes.z,
                _ => return None,
            };
            let value: Value = w.value.clone()?;
            *axis = Some(Coord {
                value,
                dim: None,
                span: w.span,
            });
        }
    }
    if axes.x.is_none() || axes.y.is_none() || axes.z.is_none() {
        return None;
    }
    Some(if frames {
        StmtKind::Transform(Box::new(Transform::Frame {
            op: FrameOp::Trans,
            additive: false,
            axes,
            rpl: None,
        }))
    } else {
        StmtKind::CoordShift {
            kind: CoordShift::Local,
            axes: Box::new(axes),
        }
    })
}

/// `9.1 V.ZEIT 1.5` → a dwell of 1.5 s.
fn dwell(lines: &[Block]) -> Option<StmtKind> {
    let [b] = lines else { return None };
    let words = &line(b)?.words;
    let value = words.iter().find_map(|w| w.value.clone())?;
    Some(StmtKind::Dwell {
        value,
        unit: DwellUnit::Seconds,
    })
}
