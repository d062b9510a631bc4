//! `--expand-cycles`: the documented fallback for cycles the target cannot
//! express one-to-one. Every cycle (word-address `G8x` and the position
//! blocks that repeat it, `G80`; named calls such as `CYCLE83`, `POCKET1`,
//! `CYCLE71`, the blocks under `MCALL` and the closing `MCALL`) is replaced
//! by the moves the interpreter makes for it: `G0`/`G1 X Y Z` and XY-plane
//! `G2`/`G3 X Y Z I J` in program coordinates, feed changes, dwells and
//! spindle starts and stops. Coordinates are rounded to the target's
//! places (0.001 mm for Fanuc: within the 1 µm `--verify` allows). The
//! cycle's exact-path wrapping (`G61.1` around it) is left out.
//!
//! A cycle statement that runs more than once (in a loop or a subprogram)
//! or whose moves need a call with no statement form (rigid tapping, an
//! oriented spindle stop, arcs outside XY, several turns) cannot be
//! expanded: E0610. The program must be in G90 at the cycle.

use crate::canon::{Canon, CanonPlane, CanonUnits};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::{flow::NoLoader, Options};
use crate::ir::{
    ArcData, ArcDir, Coord, Decimal, DwellUnit, Motion, MotionKind, Program, SpindleState, Stmt,
    StmtKind, Value,
};
use crate::span::Span;
use std::collections::HashMap;

/// One canonical call with the state it starts from.
struct Step {
    call: Canon,
    from: [f64; 3],
    plane_xy: bool,
    inch: bool,
}

/// The canonical calls of each statement, and statements seen twice.
struct Calls {
    by_span: HashMap<Span, Vec<Step>>,
    repeated: Vec<Span>,
}

fn end_of(c: &Canon, from: [f64; 3]) -> [f64; 3] {
    match c {
        Canon::StraightTraverse(p) | Canon::StraightFeed(p) => [p[0], p[1], p[2]],
        Canon::ArcFeed {
            first_end,
            second_end,
            axis_end,
            ..
        } => [*first_end, *second_end, *axis_end],
        _ => from,
    }
}

fn collect(p: &Program, from: &DialectSpec) -> Calls {
    let mut by_span: HashMap<Span, Vec<Step>> = HashMap::new();
    let mut order: Vec<Span> = Vec::new();
    let (mut pos, mut plane_xy, mut inch) = ([0.0; 3], true, false);
    let mut sink = |c: Canon, s: Span| {
        match &c {
            Canon::SelectPlane(pl) => plane_xy = *pl == CanonPlane::XY,
            Canon::UseLengthUnits(u) => inch = *u == CanonUnits::Inches,
            _ => {}
        }
        if order.last() != Some(&s) {
            order.push(s);
        }
        let next = end_of(&c, pos);
        by_span.entry(s).or_default().push(Step {
            call: c,
            from: pos,
            plane_xy,
            inch,
        });
        pos = next;
    };
    let program = std::rc::Rc::new(p.clone());
    let _ = crate::interp::run(program, from, &Options::default(), &mut NoLoader, &mut sink);
    let mut seen = std::collections::HashSet::new();
    let repeated = order.into_iter().filter(|s| !seen.insert(*s)).collect();
    Calls { by_span, repeated }
}

/// Is `s` part of a cycle (to expand), or its cancel (to drop)?
/// A Haas G12/G13 circular pocket (kept as an `Aux` code).
fn is_g12(s: &StmtKind) -> bool {
    matches!(s, StmtKind::Aux { letter, code, .. }
        if crate::interp::haas_pocket::is_circular_pocket(*letter, *code))
}

fn in_cycle(s: &StmtKind, modal: &mut bool) -> bool {
    match s {
        StmtKind::Cycle(_) => {
            *modal = true;
            true
        }
        StmtKind::CycleCall(c) => {
            *modal = c.modal;
            true
        }
        StmtKind::CycleCancel | StmtKind::ModalCallCancel => {
            *modal = false;
            true
        }
        StmtKind::Motion(_) => *modal,
        // Heidenhain: the definition makes no moves, each call makes the cycle's.
        StmtKind::CycleDef(_) | StmtKind::CycleRun(_) => true,
        _ => false,
    }
}

pub fn expand_unmappable(
    p: &mut Program,
    from: &DialectSpec,
    to: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    let calls = collect(p, from);
    let mut modal = false;
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut stmts = Vec::new();
        let mut after = Vec::new();
        // Haas G12/G13: the block's X/Y move is part of the cycle's moves.
        let g12 = b.stmts.iter().any(|s| is_g12(&s.kind));
        for s in std::mem::take(&mut b.stmts) {
            let pocket_move = g12 && matches!(s.kind, StmtKind::Motion(_));
            if !pocket_move && !is_g12(&s.kind) && !in_cycle(&s.kind, &mut modal) {
                stmts.push(s);
                continue;
            }
            match moves(&calls, s.span, to) {
                Ok(list) => {
                    after.extend(list.into_iter().map(|m| super::follow_block(&b, vec![m])))
                }
                Err(why) => diags.push(
                    Diagnostic::new(
                        Code::PortCycle,
                        format!("this cycle cannot be expanded: {why}"),
                    )
                    .primary(s.span, "cycle")
                    .help("rewrite this part by hand for the target"),
                ),
            }
        }
        b.stmts = stmts;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            p.blocks.push(b);
        }
        p.blocks.extend(after);
    }
}

fn coord(v: f64, places: u8, span: Span) -> Option<Coord> {
    let mut d = Decimal::from_f64(v, places).normalized();
    d.point = true;
    Some(Coord {
        value: Value::Number(d),
        dim: None,
        span,
    })
}

fn moves(calls: &Calls, span: Span, to: &DialectSpec) -> Result<Vec<Stmt>, String> {
    if calls.repeated.contains(&span) {
        return Err("it runs more than once (loop or subprogram)".into());
    }
    let mut out = Vec::new();
    let stmt = |k| Stmt::new(k, span);
    for step in calls.by_span.get(&span).map(Vec::as_slice).unwrap_or(&[]) {
        let places = if step.inch {
            to.numbers.length_places_inch
        } else {
            to.numbers.length_places_mm
        };
        let at = |v: f64| coord(v, places, span);
        let c = &step.call;
        match c {
            Canon::StraightTraverse(p) | Canon::StraightFeed(p) => {
                let rapid = matches!(c, Canon::StraightTraverse(_));
                let mut m = Motion::new(if rapid {
                    MotionKind::Rapid
                } else {
                    MotionKind::Linear
                });
                (m.target.x, m.target.y, m.target.z) = (at(p[0]), at(p[1]), at(p[2]));
                out.push(stmt(StmtKind::Motion(Box::new(m))));
            }
            Canon::ArcFeed {
                first_end,
                second_end,
                first_axis,
                second_axis,
                rotation,
                axis_end,
                ..
            } => {
                if !step.plane_xy || rotation.abs() != 1 {
                    return Err("an arc outside the XY plane or of several turns".into());
                }
                let dir = if *rotation < 0 {
                    ArcDir::Cw
                } else {
                    ArcDir::Ccw
                };
                let mut m = Motion::new(MotionKind::Arc(dir));
                (m.target.x, m.target.y, m.target.z) =
                    (at(*first_end), at(*second_end), at(*axis_end));
                m.arc = ArcData {
                    i: at(first_axis - step.from[0]),
                    j: at(second_axis - step.from[1]),
                    ..ArcData::default()
                };
                out.push(stmt(StmtKind::Motion(Box::new(m))));
            }
            Canon::SetFeedRate(f) => {
                out.push(stmt(StmtKind::Feed(Value::Number(super::decimal(*f)))))
            }
            Canon::Dwell(t) => out.push(stmt(StmtKind::Dwell {
                value: Value::Number(super::decimal(*t)),
                unit: DwellUnit::Seconds,
            })),
            Canon::StopSpindle => out.push(stmt(StmtKind::Spindle(SpindleState::Stop))),
            Canon::SpindleCw => out.push(stmt(StmtKind::Spindle(SpindleState::Cw))),
            Canon::SpindleCcw => out.push(stmt(StmtKind::Spindle(SpindleState::Ccw))),
            Canon::SetMotionControlMode(_)
            | Canon::SetNaivecamTolerance(_)
            | Canon::Comment(_)
            | Canon::SelectPlane(_) => {}
            Canon::DisableFeedOverride
            | Canon::DisableSpeedOverride
            | Canon::EnableFeedOverride
            | Canon::EnableSpeedOverride => {}
            other => {
                return Err(format!(
                    "it makes `{}`, which has no statement form",
                    crate::canon::format_call(other)
                ))
            }
        }
    }
    Ok(out)
}
