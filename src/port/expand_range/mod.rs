//! The port's last resort before a refusal: a construct the target has no
//! form for (and no exact rewrite gave one) is written as what it does.
//! The program is run once ([`trace`]); around each construct the port
//! refused, the smallest part of the main program that runs as one piece
//! and starts and ends in a plain modal state is found ([`ranges`]) and
//! replaced by the moves and state changes the run made in it
//! ([`write`]), then the modes and variables it leaves. A construct in a
//! subprogram is replaced at each call and the definition goes. The port
//! is then tried again; what still fails, or depends on values known only
//! while the machine runs, stays refused.

mod dead;
mod ranges;
mod trace;
pub(super) mod write;

use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::flow::ProgramLoader;
use crate::interp::params::OuterVar;
use crate::interp::state::ModalMotion;
use crate::ir::{Block, ExprKind, MotionKind, Program, Stmt, StmtKind, Var};
use crate::span::Span;
use ranges::{Range, Structure};
use std::collections::HashSet;
use trace::Trace;

/// A part of the program that was written as the moves it makes.
#[derive(Clone, Debug)]
pub struct Replaced {
    /// The construct the target could not express, and why.
    pub at: Span,
    pub why: String,
    /// How many blocks of the source the moves replace.
    pub blocks: usize,
}

/// Tries `attempt` (port, write, read back) on `p`, and while it refuses
/// constructs, replaces them by what they do and tries again. Returns
/// the successful attempt's result and what was replaced, or the errors
/// that remain (each with a note on why it could not be expanded).
pub fn legalize<T>(
    p: &Program,
    source: &str,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &crate::interp::Options,
    loader: &mut dyn ProgramLoader,
    errors: Vec<Diagnostic>,
    mut attempt: impl FnMut(&Program) -> Result<T, Vec<Diagnostic>>,
) -> Result<(T, Vec<Diagnostic>), Vec<Diagnostic>> {
    let (mut cur, mut errors) = (p.clone(), errors);
    let mut notes: Vec<Diagnostic> = Vec::new();
    let mut seen: HashSet<Vec<(Code, Option<Span>)>> = HashSet::new();
    for _ in 0..8 {
        if !seen.insert(places(&errors)) {
            // Writing it as moves gave the same refusals: the construct is
            // a state the target has no form for, not a path.
            return Err(errors
                .into_iter()
                .map(|e| {
                    e.note("writing it as the moves it makes does not help: the target has no form for what it sets")
                })
                .collect());
        }
        let trace = trace::record(&cur, from, opts, loader);
        let (next, done) = plan_and_apply(&cur, source, &trace, (from, to), &errors)?;
        notes.extend(done);
        cur = next;
        match attempt(&cur) {
            Ok(t) => return Ok((t, notes)),
            Err(e) => errors = e,
        }
    }
    Err(errors)
}

/// Replaces the parts around every error, or returns the errors with
/// why each could not be replaced.
fn plan_and_apply(
    p: &Program,
    source: &str,
    t: &Trace,
    (from, to): (&DialectSpec, &DialectSpec),
    errors: &[Diagnostic],
) -> Result<(Program, Vec<Diagnostic>), Vec<Diagnostic>> {
    let st = Structure::of(p);
    let mut ranges: Vec<Range> = Vec::new();
    let mut definitions: Vec<(usize, usize)> = Vec::new();
    let mut dead: Vec<(usize, usize)> = Vec::new();
    let mut notes = Vec::new();
    let mut refused = Vec::new();
    // The blocks of the main file that ran, built once if a never-called
    // subprogram needs them.
    let ran = std::cell::OnceCell::new();
    for e in errors.iter().filter(|d| d.is_error()) {
        let found = block_of(p, e).ok_or_else(|| "it is not in this file".to_string());
        match found.and_then(|j| targets(p, &st, t, &ran, j)) {
            Ok(Target::Moves(rs, def)) => {
                ranges.extend(rs);
                definitions.extend(def);
                notes.push(note_for(e));
            }
            Ok(Target::Dead(d)) => {
                if !dead.contains(&d) {
                    dead.push(d);
                    notes.push(dead::note(p, d));
                }
            }
            Err(why) => refused.push(e.clone().note(format!(
                "it cannot be written as the moves it makes either: {why}"
            ))),
        }
    }
    if !refused.is_empty() {
        return Err(refused);
    }
    let all_refused = |why: String| -> Vec<Diagnostic> {
        errors
            .iter()
            .map(|e| {
                e.clone()
                    .note(format!("it cannot be written as the moves it makes: {why}"))
            })
            .collect()
    };
    let ranges = merge(t, &st, ranges).map_err(all_refused)?;
    // Moves are written in work coordinates: a block that moves in
    // machine coordinates (G53, SUPA) would lose where it goes.
    let machine = |r: &Range| {
        p.blocks[r.a..=r.b]
            .iter()
            .flat_map(|b| &b.stmts)
            .any(|s| from.in_machine_coords(&s.kind))
    };
    if ranges.iter().any(machine) {
        return Err(all_refused(
            "it moves in machine coordinates, which moves written in work coordinates cannot carry"
                .into(),
        ));
    }
    let parts = Parts {
        ranges: &ranges,
        defs: &definitions,
        dead: &dead,
    };
    let out = apply(p, t, to, &parts, source).map_err(all_refused)?;
    Ok((out, notes))
}

fn places(errors: &[Diagnostic]) -> Vec<(Code, Option<Span>)> {
    let mut v: Vec<(Code, Option<Span>)> = errors
        .iter()
        .map(|e| (e.code, e.labels.first().map(|l| l.span)))
        .collect();
    v.sort_by_key(|(c, s)| (*c, s.map(|s| (s.file.0, s.start))));
    v
}

fn note_for(e: &Diagnostic) -> Diagnostic {
    let mut d = Diagnostic::new(
        Code::PortExpanded,
        format!("written as the moves it makes: {}", e.message),
    );
    if let Some(l) = e.labels.iter().find(|l| l.primary).or(e.labels.first()) {
        d = d.primary(l.span, "the target has no form for this");
    }
    d
}

/// The block of `p` that holds the error's primary place.
fn block_of(p: &Program, e: &Diagnostic) -> Option<usize> {
    let l = e.labels.iter().find(|l| l.primary).or(e.labels.first())?;
    let sp = l.span;
    p.blocks
        .iter()
        .position(|b| {
            b.span.file == sp.file
                && b.span.start <= sp.start
                && sp.start <= b.span.end.max(b.span.start)
        })
        .or_else(|| {
            p.blocks.iter().position(|b| {
                b.stmts.iter().any(|s| {
                    s.span.file == sp.file && s.span.start <= sp.start && sp.start < s.span.end
                })
            })
        })
}

/// What replaces the place of an error.
enum Target {
    /// The parts to write as moves, and the subprogram definition that
    /// goes with them.
    Moves(Vec<Range>, Option<(usize, usize)>),
    /// A subprogram definition the program never calls (first and last
    /// block), carried as comments.
    Dead((usize, usize)),
}

/// What replaces the place of an error at block `j`.
fn targets(
    p: &Program,
    st: &Structure,
    t: &Trace,
    ran: &std::cell::OnceCell<HashSet<usize>>,
    j: usize,
) -> Result<Target, String> {
    let at_top = t.steps.iter().any(|s| s.pc == j);
    match t.deep.get(&j) {
        Some(calls) if !at_top => {
            let mut out = Vec::new();
            let mut seen = HashSet::new();
            for &k in calls {
                let pc = t.steps[k].pc;
                if seen.insert(pc) {
                    out.push(ranges::grow(t, st, pc, pc)?);
                }
            }
            let def = ranges::definition(p, st, t, j);
            Ok(Target::Moves(out, def))
        }
        _ => {
            let sub =
                ranges::definition(p, st, t, j).filter(|d| d.0 > 0 && starts_sub(&p.blocks[d.0]));
            if let Some(d) = sub.filter(|_| !at_top && !t.deep.contains_key(&j)) {
                // A subprogram the run never calls: it has no moves to
                // write, and dropping it would lose it.
                let ran = ran.get_or_init(|| t.visits.iter().map(|v| v.1).collect());
                return match dead::definition(p, t, ran, d) {
                    true => Ok(Target::Dead(d)),
                    // Not reached because the run stopped first.
                    false if t.stopped.is_some() => Err("the run stops before it reaches it (at a value known only while the machine runs, or an error)".into()),
                    false => Err("it is in a subprogram this program never calls, so there are no moves to write it as".into()),
                };
            }
            Ok(Target::Moves(vec![ranges::grow(t, st, j, j)?], None))
        }
    }
}

/// A block that opens a subprogram: `O1000`, `o100 sub`, `PROC`, a label.
fn starts_sub(b: &Block) -> bool {
    b.label.is_some()
        || b.stmts.iter().any(|s| {
            matches!(
                s.kind,
                StmtKind::ProgramStart { .. } | StmtKind::SubStart { .. }
            )
        })
}

/// Sorts the ranges and joins the ones that overlap (grown again).
fn merge(t: &Trace, st: &Structure, mut rs: Vec<Range>) -> Result<Vec<Range>, String> {
    rs.sort_by_key(|r| (r.a, r.b));
    let mut out: Vec<Range> = Vec::new();
    for r in rs {
        match out.last_mut() {
            Some(last) if r.a <= last.b + 1 => {
                if r.b > last.b {
                    *last = ranges::grow(t, st, last.a, r.b)?;
                }
            }
            _ => out.push(r),
        }
    }
    Ok(out)
}

/// What [`apply`] replaces: parts written as moves, the definitions that
/// go with them, and never-called definitions carried as comments.
struct Parts<'a> {
    ranges: &'a [Range],
    defs: &'a [(usize, usize)],
    dead: &'a [(usize, usize)],
}

fn apply(
    p: &Program,
    t: &Trace,
    to: &DialectSpec,
    parts: &Parts<'_>,
    source: &str,
) -> Result<Program, String> {
    let (rs, defs) = (parts.ranges, parts.defs);
    let by_span = write::statements_by_span(p);
    let mut out = p.clone();
    let read = vars_read_outside(p, rs, defs);
    let mut blocks = Vec::new();
    let mut i = 0;
    while i < p.blocks.len() {
        if let Some(r) = rs.iter().find(|r| r.a == i) {
            blocks.extend(expansion(&mut out, p, t, to, &by_span, r, &read)?);
            i = r.b + 1;
        } else if let Some(&d) = parts.dead.iter().find(|d| d.0 == i) {
            blocks.extend(dead::as_comments(p, source, d));
            i = d.1 + 1;
        } else if let Some(&(_, e)) = defs.iter().find(|d| d.0 == i) {
            // The definition goes; a program end in it stays.
            blocks.extend(p.blocks[i..=e].iter().filter(|b| ends(b)).cloned());
            i = e + 1;
        } else {
            blocks.push(p.blocks[i].clone());
            i += 1;
        }
    }
    out.blocks = blocks;
    forget_removed_exprs(&mut out, p, parts, &read);
    Ok(out)
}

/// The expressions of the blocks that went stay in the arena; passes that
/// scan the arena (which variables a program uses) must not find them, so
/// they become the number 0. Statements kept from a replaced part keep
/// theirs.
fn forget_removed_exprs(out: &mut Program, p: &Program, parts: &Parts<'_>, read: &Reads) {
    let mut gone: Vec<Span> = Vec::new();
    let mut kept_spans: Vec<Span> = Vec::new();
    let regions = parts
        .ranges
        .iter()
        .map(|r| (r.a, r.b))
        .chain(parts.defs.iter().copied())
        .chain(parts.dead.iter().copied());
    for (a, b) in regions {
        for blk in &p.blocks[a..=b] {
            gone.push(blk.span);
            kept_spans.extend(blk.stmts.iter().filter(|s| kept(s, read)).map(|s| s.span));
        }
    }
    let inside = |x: Span, r: &Span| x.file == r.file && r.start <= x.start && x.end <= r.end;
    let handles: Vec<_> = out
        .exprs
        .iter()
        .filter(|(_, e)| {
            gone.iter().any(|g| inside(e.span, g)) && !kept_spans.iter().any(|k| inside(e.span, k))
        })
        .map(|(h, _)| h)
        .collect();
    for h in handles {
        out.exprs[h].kind = ExprKind::Number(crate::ir::Decimal::from_int(0));
    }
}

fn ends(b: &Block) -> bool {
    b.stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::ProgramEnd { .. }))
}

/// Statements a replaced part keeps where they were: the program's start
/// and tape marks, and the declarations of variables the rest reads.
fn kept(s: &Stmt, read: &Reads) -> bool {
    match &s.kind {
        StmtKind::ProgramStart { .. } | StmtKind::Tape => true,
        StmtKind::Declare { vars, .. } => vars
            .iter()
            .any(|v| read.user.contains(&v.name.to_ascii_uppercase())),
        _ => false,
    }
}

fn expansion(
    out: &mut Program,
    p: &Program,
    t: &Trace,
    to: &DialectSpec,
    by_span: &std::collections::HashMap<Span, Stmt>,
    r: &Range,
    read: &Reads,
) -> Result<Vec<Block>, String> {
    let like = &p.blocks[r.a];
    let mut blocks: Vec<Block> = Vec::new();
    for b in &p.blocks[r.a..=r.b] {
        let keep: Vec<Stmt> = b.stmts.iter().filter(|s| kept(s, read)).cloned().collect();
        if !keep.is_empty() {
            blocks.push(super::follow_block(b, keep));
        }
    }
    let before = &t.steps[r.first].before;
    let mut w = write::Writer::new(by_span, to);
    let start = t.steps[r.first].first;
    for (c, _) in &t.calls[..start] {
        w.follow(c);
    }
    (w.plane, w.inch) = (before.plane, before.inch);
    w.begin();
    let mut head = vec![Stmt::new(
        StmtKind::Comment {
            text: "cncc: written as the moves it makes".into(),
            style: crate::ir::CommentStyle::Paren,
        },
        like.span,
    )];
    if !before.absolute {
        head.push(Stmt::new(
            StmtKind::Distance(crate::ir::DimMode::Absolute),
            like.span,
        ));
    }
    if before.arc_absolute {
        head.push(Stmt::new(
            StmtKind::ArcDistance(crate::ir::DimMode::Incremental),
            like.span,
        ));
    }
    w.out.extend(head);
    write_calls(&mut w, p, t, r)?;
    if w.g92 != w.g92_base {
        return Err("it leaves a G92/G52 shift other than the one it started in".into());
    }
    let after = t.after(r.last).ok_or("the run ended inside it")?;
    restore(&mut w, out, after, before, read, like.span)?;
    for b in &p.blocks[r.a..=r.b] {
        if ends(b) {
            blocks.push(b.clone());
        }
    }
    let body = group(like, std::mem::take(&mut w.out));
    let split = blocks.iter().position(ends).unwrap_or(blocks.len());
    blocks.splice(split..split, body);
    Ok(blocks)
}

/// The calls of the range, with each visited block's comments before the
/// calls it made.
fn write_calls(w: &mut write::Writer<'_>, p: &Program, t: &Trace, r: &Range) -> Result<(), String> {
    let from = t.steps[r.first].visit;
    let to = t.steps.get(r.last + 1).map_or(t.visits.len(), |s| s.visit);
    let end = t.steps.get(r.last + 1).map_or(t.calls.len(), |s| s.first);
    let mut cursor = t.steps[r.first].first;
    for &(first, pc) in &t.visits[from..to] {
        for (c, sp) in &t.calls[cursor..first.max(cursor)] {
            w.call(c, *sp)?;
        }
        cursor = cursor.max(first);
        for s in &p.blocks[pc].stmts {
            if said_not_run(s) {
                w.out.push(s.clone());
            }
        }
    }
    for (c, sp) in &t.calls[cursor..end] {
        w.call(c, *sp)?;
    }
    Ok(())
}

/// What a block says that makes no canonical call but must not be lost:
/// comments, and machine functions cncc passes through (a builder's M
/// code). If the target cannot hold one, the port refuses again.
fn said_not_run(s: &Stmt) -> bool {
    matches!(s.kind, StmtKind::Comment { .. })
        || (matches!(s.kind, StmtKind::Aux { .. } | StmtKind::Command { .. }) && write::literal(s))
}

/// The modes and variables the replaced part leaves for what follows.
fn restore(
    w: &mut write::Writer<'_>,
    out: &mut Program,
    after: &trace::Modes,
    before: &trace::Modes,
    read: &Reads,
    span: Span,
) -> Result<(), String> {
    let push = |w: &mut write::Writer<'_>, k| w.out.push(Stmt::new(k, span));
    if after.plane != w.plane {
        push(w, StmtKind::Plane(write::plane_of(after.plane)));
    }
    if !after.absolute {
        push(w, StmtKind::Distance(crate::ir::DimMode::Incremental));
    }
    if after.arc_absolute {
        push(w, StmtKind::ArcDistance(crate::ir::DimMode::Absolute));
    }
    // A target without motion codes (Klartext: each block has its path
    // function) has no modal motion to give back.
    let modal =
        w.to.code_for(crate::dialect::Meaning::Motion(MotionKind::Rapid))
            .is_some();
    if let ModalMotion::Move(k @ (MotionKind::Rapid | MotionKind::Linear)) = after.motion {
        if modal && w.last_motion != Some(k) {
            push(w, StmtKind::Motion(Box::new(crate::ir::Motion::new(k))));
        }
    }
    let mut changed: Vec<(&OuterVar, f64)> = after
        .vars
        .iter()
        .filter(|(k, v)| before.vars.get(*k) != Some(*v) && read.wants(k))
        .map(|(k, v)| (k, *v))
        .collect();
    changed.sort_by(|a, b| format!("{:?}", a.0).cmp(&format!("{:?}", b.0)));
    for (k, v) in changed {
        let Some(var) = var_of(k) else { continue };
        if !v.is_finite() {
            // Unknown at check time (a system datum, a probe): a number
            // written in its place would be a value the machine never had.
            return Err(format!(
                "it leaves {} with a value known only while the machine runs",
                var_name(k)
            ));
        }
        let value = super::number_expr(out, super::decimal(v), span);
        push(w, StmtKind::Assign { var, value });
    }
    Ok(())
}

fn var_name(k: &OuterVar) -> String {
    match k {
        OuterVar::Numbered(n) => format!("`#{n}`"),
        OuterVar::R(n) => format!("`R{n}`"),
        OuterVar::Q(b, n) => format!("`{b:?}{n}`"),
        OuterVar::Named(s) => format!("`#<{s}>`"),
        OuterVar::User(s) => format!("`{s}`"),
    }
}

fn var_of(k: &OuterVar) -> Option<Var> {
    Some(match k {
        OuterVar::Numbered(n) => Var::Numbered(*n),
        OuterVar::R(n) => Var::R(*n),
        OuterVar::Q(b, n) => Var::Q(*b, *n),
        OuterVar::Named(s) => Var::Named(s.clone()),
        OuterVar::User(s) if !s.contains('[') => Var::User(s.clone(), Vec::new()),
        OuterVar::User(_) => return None,
    })
}

/// Statements in blocks: a feed goes on the move after it, the rest one
/// to a block.
fn group(like: &Block, stmts: Vec<Stmt>) -> Vec<Block> {
    let mut out: Vec<Block> = Vec::new();
    let mut pending: Vec<Stmt> = Vec::new();
    for s in stmts {
        let is_feed = matches!(s.kind, StmtKind::Feed(_));
        let is_move = matches!(s.kind, StmtKind::Motion(_));
        if is_move {
            // The move first, its feed after it: `G1 X10 F400`.
            pending.insert(0, s);
            out.push(super::follow_block(like, std::mem::take(&mut pending)));
        } else if is_feed {
            if !pending.is_empty() {
                out.push(super::follow_block(like, std::mem::take(&mut pending)));
            }
            pending.push(s);
        } else {
            if !pending.is_empty() {
                out.push(super::follow_block(like, std::mem::take(&mut pending)));
            }
            out.push(super::follow_block(like, vec![s]));
        }
    }
    if !pending.is_empty() {
        out.push(super::follow_block(like, pending));
    }
    out
}

/// Variables read by the part of the program that stays.
struct Reads {
    numbered: HashSet<u32>,
    any_numbered: bool,
    r: HashSet<u32>,
    any_r: bool,
    q: HashSet<(crate::ir::QBank, u32)>,
    named: HashSet<String>,
    user: HashSet<String>,
}

impl Reads {
    fn wants(&self, k: &OuterVar) -> bool {
        match k {
            OuterVar::Numbered(n) => self.any_numbered || self.numbered.contains(n),
            OuterVar::R(n) => self.any_r || self.r.contains(n),
            OuterVar::Q(b, n) => self.q.contains(&(*b, *n)),
            OuterVar::Named(s) => self.named.contains(&s.to_ascii_lowercase()),
            OuterVar::User(s) => self.user.contains(&s.to_ascii_uppercase()),
        }
    }
}

fn vars_read_outside(p: &Program, rs: &[Range], defs: &[(usize, usize)]) -> Reads {
    let span_of = |a: usize, b: usize| (p.blocks[a].span.start, p.blocks[b].span.end);
    let gone: Vec<(u32, u32)> = rs
        .iter()
        .map(|r| span_of(r.a, r.b))
        .chain(defs.iter().map(|&(a, b)| span_of(a, b)))
        .collect();
    let inside = |s: Span| gone.iter().any(|&(a, b)| a <= s.start && s.end <= b);
    let mut r = Reads {
        numbered: HashSet::new(),
        any_numbered: false,
        r: HashSet::new(),
        any_r: false,
        q: HashSet::new(),
        named: HashSet::new(),
        user: HashSet::new(),
    };
    for (_, e) in p.exprs.iter() {
        if e.span.file != p.file || inside(e.span) {
            continue;
        }
        if let ExprKind::Var(v) = &e.kind {
            match v {
                Var::Numbered(n) => {
                    r.numbered.insert(*n);
                }
                Var::Indirect(_) => r.any_numbered = true,
                Var::Named(s) => {
                    r.named.insert(s.to_ascii_lowercase());
                }
                Var::R(n) => {
                    r.r.insert(*n);
                }
                Var::RIndirect(_) => r.any_r = true,
                Var::User(s, _) => {
                    r.user.insert(s.to_ascii_uppercase());
                }
                Var::System(..) => {}
                Var::Q(b, n) => {
                    r.q.insert((*b, *n));
                }
            }
        }
    }
    r
}
