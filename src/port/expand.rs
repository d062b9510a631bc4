//! `--expand-cycles`: the documented fallback for cycles the target cannot
//! express one-to-one. Every cycle (word-address `G8x` and the position
//! blocks that repeat it, `G80`; named calls such as `CYCLE83`, `POCKET1`,
//! `CYCLE71`, the blocks under `MCALL` and the closing `MCALL`) is replaced
//! by the moves the interpreter makes for it, written by the writer of
//! [`super::expand_range`]: `G0`/`G1 X Y Z` and `G2`/`G3` with their
//! centres in program coordinates, feed changes, dwells and spindle
//! changes. Coordinates are rounded to the target's
//! places (0.001 mm for Fanuc: within the 1 µm `--verify` allows). The
//! cycle's exact-path wrapping (`G61.1` around it) is left out.
//!
//! A cycle statement that runs more than once (in a loop or a subprogram)
//! or whose moves need a call with no statement form (rigid tapping, an
//! oriented spindle stop, arcs of several turns) cannot be expanded:
//! E0610. The program must be in G90 at the cycle.

use super::expand_range::write::Writer;
use crate::canon::{Canon, CanonPlane};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::flow::{NoLoader, Walker};
use crate::interp::{BlockEvent, Options};
use crate::ir::{Program, Stmt, StmtKind};
use crate::span::Span;
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

/// One canonical call with the state it starts from (position, plane,
/// units), as the writer of [`super::expand_range`] follows them.
struct Step {
    call: Canon,
    from: [f64; 6],
    plane: CanonPlane,
    inch: bool,
}

/// The canonical calls of each statement, and statements seen twice.
struct Calls {
    by_span: HashMap<Span, Vec<Step>>,
    repeated: Vec<Span>,
}

fn collect(p: &Program, from: &DialectSpec, to: &DialectSpec) -> Calls {
    let mut by_span: HashMap<Span, Vec<Step>> = HashMap::new();
    let no_statements = HashMap::new();
    let mut follow = Writer::new(&no_statements, to);
    let mut sink = |c: Canon, s: Span| {
        let (from, plane, inch) = (follow.pos, follow.plane, follow.inch);
        follow.follow(&c);
        by_span.entry(s).or_default().push(Step {
            call: c,
            from,
            plane,
            inch,
        });
    };
    let runs = run_counting_blocks(p, from, &mut sink);
    let repeated = p
        .blocks
        .iter()
        .enumerate()
        .filter(|(pc, _)| runs.get(pc).is_some_and(|n| *n > 1))
        .flat_map(|(_, b)| b.stmts.iter().map(|s| s.span))
        .collect();
    Calls { by_span, repeated }
}

/// Runs `p` into `sink` and counts how often each of its blocks ran (a
/// loop body or a subprogram called twice runs more than once, whether or
/// not its other blocks make calls in between).
fn run_counting_blocks(
    p: &Program,
    from: &DialectSpec,
    sink: &mut dyn FnMut(Canon, Span),
) -> HashMap<usize, u32> {
    let runs = Rc::new(RefCell::new(HashMap::<usize, u32>::new()));
    let opts = Options::default();
    let mut sink = sink;
    let mut it = crate::interp::Interp::new(from, &opts, &mut sink);
    let seen = runs.clone();
    it.observer = Some(Box::new(move |e: &BlockEvent, _, _| {
        if e.prog == 0 {
            *seen.borrow_mut().entry(e.pc).or_default() += 1;
        }
    }));
    it.start();
    let _ = Walker::new(Rc::new(p.clone()), &mut NoLoader).run(&mut it);
    drop(it);
    Rc::try_unwrap(runs)
        .map(RefCell::into_inner)
        .unwrap_or_default()
}

/// Is `s` part of a cycle (to expand), or its cancel (to drop)?
/// A Haas G12/G13 circular pocket (kept as an `Aux` code).
fn is_g12(s: &StmtKind, from: &DialectSpec) -> bool {
    matches!(s, StmtKind::Aux { letter, code, .. }
        if crate::interp::haas_pocket::is_circular_pocket(from, *letter, *code))
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
    let calls = collect(p, from, to);
    let mut modal = false;
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut stmts = Vec::new();
        let mut after = Vec::new();
        // Haas G12/G13: the block's X/Y move is part of the cycle's moves.
        let g12 = b.stmts.iter().any(|s| is_g12(&s.kind, from));
        for s in std::mem::take(&mut b.stmts) {
            let pocket_move = g12 && matches!(s.kind, StmtKind::Motion(_));
            if !pocket_move && !is_g12(&s.kind, from) && !in_cycle(&s.kind, &mut modal) {
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

/// The statements of the calls a cycle statement made, written by the
/// expansion writer (its own statements are not reused: a cycle's calls
/// are moves, feeds, dwells and spindle changes).
fn moves(calls: &Calls, span: Span, to: &DialectSpec) -> Result<Vec<Stmt>, String> {
    if calls.repeated.contains(&span) {
        return Err("it runs more than once (loop or subprogram)".into());
    }
    let no_statements = HashMap::new();
    let mut w = Writer::new(&no_statements, to);
    for step in calls.by_span.get(&span).map(Vec::as_slice).unwrap_or(&[]) {
        (w.pos, w.plane, w.inch) = (step.from, step.plane, step.inch);
        w.call(&step.call, span)?;
    }
    Ok(w.out)
}
