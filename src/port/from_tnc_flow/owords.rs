//! Klartext jumps for a target that has loops and conditionals but no
//! jumps (LinuxCNC o-words):
//!
//! * a jump back to a label (`LBL 1` ... `FN 12: IF +Q1 LT +3 GOTO LBL 1`)
//!   → `o1001 do` at the label, `o1001 while [#1 LT 3]` at the jump;
//! * a jump forward (`FN 9: IF +Q1 EQU +2 GOTO LBL 2` ... `LBL 2`) →
//!   `o1002 if [#1 NE 2]` at the jump, `o1002 endif` at the label.
//!
//! * a jump forward to the block just after such a loop, from inside it
//!   (and no other loop), → `o1003 if [c]` `o1001 break` `o1003 endif`
//!   (the form a WHILE ported to Klartext takes).
//!
//! An unconditional jump makes `while [1]` / `if [0]` / a plain `break`. The structures must
//! nest (a jump into or out of another loop's body cannot be written this
//! way: E0622). Labels that only these jumps used go; those a `CALL LBL`
//! uses stay.

use super::shape::{crossing, intervals, loop_exits, pair_else, Jump};
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    Block, CallKind, CallTarget, Decimal, Expr, ExprId, ExprKind, FlowId, JumpTarget, Program,
    Stmt, StmtKind,
};
use crate::span::Span;
use std::collections::{HashMap, HashSet};

/// The shapes are matched pair by pair: a bound keeps that quick.
const MAX_JUMPS: usize = 4000;

pub fn run(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    super::conds::merge_runs(p);
    let called = labels_called(p);
    // Each round merges at least one pair; a few rounds reach the
    // patterns one merge uncovers (an OR inside a CONTINUE).
    for _ in 0..16 {
        if !super::conds::merge_skips(p) {
            break;
        }
        super::conds::drop_unused_labels(p, &called);
    }
    let mut at = HashMap::new();
    for (i, b) in p.blocks.iter().enumerate() {
        if let Some(l) = &b.label {
            at.entry(l.node.to_ascii_uppercase()).or_insert(i);
        }
    }
    let mut jumps = Vec::new();
    for (bi, b) in p.blocks.iter().enumerate() {
        for (si, s) in b.stmts.iter().enumerate() {
            if let StmtKind::Goto {
                target: JumpTarget::Label(l),
                cond,
                ..
            } = &s.kind
            {
                if let Some(&t) = at.get(&l.to_ascii_uppercase()) {
                    jumps.push(Jump {
                        block: bi,
                        stmt: si,
                        target: t,
                        cond: *cond,
                        span: s.span,
                        join: None,
                    });
                }
            }
        }
    }
    if jumps.is_empty() {
        return;
    }
    if jumps.len() > MAX_JUMPS {
        diags.push(
            Diagnostic::new(
                Code::PortJump,
                format!("more than {MAX_JUMPS} jumps to turn into loops and conditionals"),
            )
            .primary(jumps[MAX_JUMPS].span, "this jump")
            .help("split the program, or choose a target with jumps"),
        );
        return;
    }
    // Outer structures first: by opening, the longer first.
    jumps.sort_by_key(|j| (j.open(), std::cmp::Reverse(j.close())));
    let exits = loop_exits(&jumps);
    let mut kept = Vec::new();
    let mut new_index = vec![None; jumps.len()];
    let mut exit_of = Vec::new();
    for (i, (j, e)) in jumps.into_iter().zip(exits).enumerate() {
        match e {
            None => {
                new_index[i] = Some(kept.len());
                kept.push(j);
            }
            Some((l, cont)) => exit_of.push((j, l, cont)),
        }
    }
    // Loops are kept, so each exit's loop has its new index.
    let breaks: Vec<(Jump, usize, bool)> = exit_of
        .into_iter()
        .filter_map(|(j, l, cont)| new_index[l].map(|n| (j, n, cont)))
        .collect();
    let (jumps, elses) = pair_else(kept);
    if let Some(bad) = crossing(&intervals(&jumps, &elses)) {
        diags.push(
            Diagnostic::new(
                Code::PortJump,
                "this jump crosses the loop or conditional another jump makes; the target has no jumps",
            )
            .primary(bad, "this jump")
            .help("make jumps nest like loops and conditionals, or choose a target with jumps"),
        );
        return;
    }
    rebuild(p, &jumps, breaks, elses);
}

fn labels_called(p: &Program) -> HashSet<String> {
    let mut out = HashSet::new();
    for s in p.blocks.iter().flat_map(|b| b.stmts.iter()) {
        match &s.kind {
            StmtKind::Call {
                kind: CallKind::Label,
                target,
                ..
            } => match target {
                CallTarget::Number(n) => {
                    out.insert(n.to_string());
                }
                CallTarget::Name(n) => {
                    out.insert(n.to_ascii_uppercase());
                }
                CallTarget::Computed(_) => {}
            },
            StmtKind::SectionRepeat { start, end, .. } => {
                out.insert(start.to_ascii_uppercase());
                out.extend(end.iter().map(|e| e.to_ascii_uppercase()));
            }
            _ => {}
        }
    }
    out
}

fn number(p: &mut Program, v: i64, span: Span) -> ExprId {
    p.exprs.alloc(Expr {
        kind: ExprKind::Number(Decimal::from_int(v)),
        span,
    })
}

/// `cond` as a while condition, or its negation as an if condition.
fn condition(p: &mut Program, j: &Jump) -> ExprId {
    let Some(c) = j.cond else {
        return number(p, if j.back() { 1 } else { 0 }, j.span);
    };
    if j.back() {
        return c;
    }
    super::conds::negate(p, c)
}

fn rebuild(
    p: &mut Program,
    jumps: &[Jump],
    breaks: Vec<(Jump, usize, bool)>,
    elses: Vec<(usize, usize, usize)>,
) {
    let called = labels_called(p);
    let ids: Vec<FlowId> = (0..jumps.len() + breaks.len())
        .map(|k| FlowId::OWord((1001 + k).to_string()))
        .collect();
    let mut exits: HashMap<(usize, usize), Vec<StmtKind>> = HashMap::new();
    for (n, (j, l, cont)) in breaks.into_iter().enumerate() {
        let id = ids[l].clone();
        let stop = if cont {
            StmtKind::Continue { id }
        } else {
            StmtKind::Break { id }
        };
        let kinds = match j.cond {
            None => vec![stop],
            Some(cond) => {
                let id = ids[jumps.len() + n].clone();
                vec![
                    StmtKind::If {
                        cond,
                        id: id.clone(),
                    },
                    stop,
                    StmtKind::EndIf { id },
                ]
            }
        };
        exits.insert((j.block, j.stmt), kinds);
    }
    let mut at_stmt: HashMap<(usize, usize), StmtKind> = HashMap::new();
    for (j, id) in jumps.iter().zip(&ids) {
        let cond = condition(p, j);
        let id = id.clone();
        let kind = if j.back() {
            StmtKind::DoWhile { cond, id }
        } else {
            StmtKind::If { cond, id }
        };
        at_stmt.insert((j.block, j.stmt), kind);
    }
    for (block, stmt, of) in elses {
        let id = ids[of].clone();
        at_stmt.insert((block, stmt), StmtKind::Else { id });
    }
    // Gap → the structures that close there and those that open there.
    let mut closing: HashMap<usize, Vec<usize>> = HashMap::new();
    let mut opening: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, j) in jumps.iter().enumerate() {
        if j.close() % 2 == 0 {
            closing.entry(j.close()).or_default().push(i);
        }
        if j.open() % 2 == 0 {
            opening.entry(j.open()).or_default().push(i);
        }
    }
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len() + jumps.len());
    for (k, mut b) in blocks.into_iter().enumerate() {
        let gap = 2 * k;
        // Closers first (inner: opened later), then openers (outer first,
        // as `jumps` is sorted).
        let mut ends = closing.remove(&gap).unwrap_or_default();
        ends.sort_by_key(|&i| std::cmp::Reverse(jumps[i].open()));
        for i in ends {
            let s = Stmt::new(StmtKind::EndIf { id: ids[i].clone() }, b.span);
            out.push(piece(&b, s));
        }
        for i in opening.remove(&gap).unwrap_or_default() {
            let s = Stmt::new(StmtKind::Do { id: ids[i].clone() }, b.span);
            out.push(piece(&b, s));
        }
        if b.label
            .as_ref()
            .is_some_and(|l| !called.contains(&l.node.to_ascii_uppercase()))
        {
            b.label = None;
        }
        for (si, s) in b.stmts.iter_mut().enumerate() {
            if let Some(kind) = at_stmt.remove(&(k, si)) {
                s.kind = kind;
            }
        }
        for (si, s) in std::mem::take(&mut b.stmts).into_iter().enumerate() {
            match exits.remove(&(k, si)) {
                Some(kinds) => {
                    for kind in kinds {
                        out.push(piece(&b, Stmt::new(kind, s.span)));
                    }
                }
                None => b.stmts.push(s),
            }
        }
        if !b.stmts.is_empty() || b.label.is_some() || b.number.is_some() {
            out.push(b);
        }
    }
    p.blocks = out;
}

fn piece(like: &Block, s: Stmt) -> Block {
    crate::port::follow_block(like, vec![s])
}
