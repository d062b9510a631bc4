//! `--expand-cycles`: the documented fallback for cycles the target cannot
//! express one-to-one. Every drilling cycle (word-address `G8x` and the
//! position blocks that repeat it, `G80`; named `CYCLE8x` calls, the blocks
//! under `MCALL` and the closing `MCALL`) is replaced by the moves
//! the interpreter makes for it: `G0`/`G1 X Y Z` in program coordinates,
//! feed changes, dwells and spindle starts and stops. The cycle's
//! exact-path wrapping (`G61.1` around the cycle) is left out.
//!
//! A cycle statement that runs more than once (in a loop or a subprogram)
//! or whose moves need a call with no statement form (rigid tapping, an
//! oriented spindle stop) cannot be expanded: E0610. The program must be
//! in G90 at the cycle, as the moves are absolute.

use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::{flow::NoLoader, Options};
use crate::ir::{
    Coord, DwellUnit, Motion, MotionKind, Program, SpindleState, Stmt, StmtKind, Value,
};
use crate::span::Span;
use std::collections::HashMap;

/// The canonical calls of each statement, and statements seen twice.
struct Calls {
    by_span: HashMap<Span, Vec<Canon>>,
    repeated: Vec<Span>,
}

fn collect(p: &Program, from: &DialectSpec) -> Calls {
    let mut by_span: HashMap<Span, Vec<Canon>> = HashMap::new();
    let mut order: Vec<Span> = Vec::new();
    let mut sink = |c: Canon, s: Span| {
        if order.last() != Some(&s) {
            order.push(s);
        }
        by_span.entry(s).or_default().push(c);
    };
    let _ = crate::interp::run(
        std::rc::Rc::new(p.clone()),
        from,
        &Options::default(),
        &mut NoLoader,
        &mut sink,
    );
    let mut seen = std::collections::HashSet::new();
    let repeated = order.into_iter().filter(|s| !seen.insert(*s)).collect();
    Calls { by_span, repeated }
}

/// Is `s` part of a cycle (to expand), or its cancel (to drop)?
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
        _ => false,
    }
}

pub fn expand_unmappable(
    p: &mut Program,
    from: &DialectSpec,
    to: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    let _ = to;
    let calls = collect(p, from);
    let mut modal = false;
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut stmts = Vec::new();
        let mut after = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            if !in_cycle(&s.kind, &mut modal) {
                stmts.push(s);
                continue;
            }
            match moves(&calls, s.span) {
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

fn coord(v: f64, span: Span) -> Option<Coord> {
    let d = crate::ir::Decimal::from_f64(v, 4).normalized();
    Some(Coord {
        value: Value::Number(super::decimal(d.to_f64())),
        dim: None,
        span,
    })
}

fn moves(calls: &Calls, span: Span) -> Result<Vec<Stmt>, String> {
    if calls.repeated.contains(&span) {
        return Err("it runs more than once (loop or subprogram)".into());
    }
    let mut out = Vec::new();
    let stmt = |k| Stmt::new(k, span);
    for c in calls.by_span.get(&span).map(Vec::as_slice).unwrap_or(&[]) {
        match c {
            Canon::StraightTraverse(p) | Canon::StraightFeed(p) => {
                let kind = if matches!(c, Canon::StraightTraverse(_)) {
                    MotionKind::Rapid
                } else {
                    MotionKind::Linear
                };
                let mut m = Motion::new(kind);
                m.target.x = coord(p[0], span);
                m.target.y = coord(p[1], span);
                m.target.z = coord(p[2], span);
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
            Canon::SetMotionControlMode(_) | Canon::SetNaivecamTolerance(_) | Canon::Comment(_) => {
            }
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
