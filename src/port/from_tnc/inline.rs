//! Heidenhain label subprograms for a Siemens target, in one file: Siemens
//! keeps a subprogram in a `.SPF` file of its own, which the port does not
//! write, so each `CALL LBL n` is replaced by the subprogram's blocks
//! (`LBL n` ... `LBL 0` after the program's end, without the `LBL 0`), and
//! the subprograms after the end go. A program-section repeat (`LBL 2` ...
//! `CALL LBL 2 REP 1`) is the Siemens one with the same reach (from the
//! label up to the `REPEAT` block, run again k times): `LBL2:` ...
//! `REPEAT LBL2 P=1`, the label made an identifier.
//!
//! Subprograms that call subprograms are inlined up to [`DEPTH`] levels,
//! and all the inlined copies together add at most [`MAX_BLOCKS`] blocks
//! (every copy is charged, nested ones too: eight levels of ten calls
//! would otherwise make a hundred million blocks); a call past either
//! limit, or of a label that is not a subprogram, is E0617.

use super::subprograms::refusal;
use crate::diag::Diagnostic;
use crate::ir::{Block, CallKind, CallTarget, Program, StmtKind, StopKind};
use std::collections::HashMap;

/// How deep inlined subprograms may call others.
const DEPTH: usize = 8;
/// How many blocks the inlined subprograms may add in all.
const MAX_BLOCKS: usize = 100_000;

pub fn run(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    let subs = take_bodies(p);
    let blocks = std::mem::take(&mut p.blocks);
    let mut budget = MAX_BLOCKS;
    p.blocks = expand(blocks, &subs, 0, &mut budget, diags);
    let starts: Vec<String> = p
        .blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .filter_map(|s| match &s.kind {
            StmtKind::SectionRepeat { start, .. } => Some(start.clone()),
            _ => None,
        })
        .collect();
    for b in &mut p.blocks {
        if let Some(l) = &mut b.label {
            if starts.contains(&l.node) && l.node.parse::<u32>().is_ok() {
                l.node = format!("LBL{}", l.node);
            }
        }
        for s in &mut b.stmts {
            if let StmtKind::SectionRepeat { start, .. } = &mut s.kind {
                if start.parse::<u32>().is_ok() {
                    *start = format!("LBL{start}");
                }
            }
        }
    }
}

/// Removes the subprograms after the program's end; their blocks by label.
fn take_bodies(p: &mut Program) -> HashMap<String, Vec<Block>> {
    let mut subs: HashMap<String, Vec<Block>> = HashMap::new();
    let mut ended = false;
    let mut open: Option<String> = None;
    let mut kept = Vec::new();
    for mut b in std::mem::take(&mut p.blocks) {
        if ended && open.is_none() {
            if let Some(l) = b.label.take() {
                open = Some(l.node);
            }
        }
        let Some(name) = open.clone() else {
            ended |= b
                .stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::Stop(StopKind::End | StopKind::EndRewind)));
            kept.push(b);
            continue;
        };
        let closes = b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::SubReturn { to: None }));
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::SubReturn { to: None }));
        if closes {
            open = None;
        }
        if !b.stmts.is_empty() {
            subs.entry(name).or_default().push(b);
        }
    }
    p.blocks = kept;
    subs
}

fn expand(
    blocks: Vec<Block>,
    subs: &HashMap<String, Vec<Block>>,
    depth: usize,
    budget: &mut usize,
    diags: &mut Vec<Diagnostic>,
) -> Vec<Block> {
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        let call = b.stmts.iter().find_map(|s| match &s.kind {
            StmtKind::Call {
                kind: CallKind::Label,
                target,
                ..
            } => Some((target.clone(), s.span)),
            _ => None,
        });
        let Some((target, span)) = call else {
            out.push(b);
            continue;
        };
        let name = match &target {
            CallTarget::Number(n) => n.to_string(),
            CallTarget::Name(n) => n.clone(),
            CallTarget::Computed(_) => String::new(),
        };
        let Some(body) = subs.get(&name) else {
            diags.push(refusal(
                span,
                format!("`CALL LBL {name}`: no subprogram after the program's end"),
            ));
            out.push(b);
            continue;
        };
        if depth >= DEPTH {
            diags.push(refusal(
                span,
                format!("subprograms nested more than {DEPTH} deep"),
            ));
            out.push(b);
            continue;
        }
        if body.len() > *budget {
            diags.push(refusal(
                span,
                format!("inlining the subprograms would add more than {MAX_BLOCKS} blocks"),
            ));
            out.push(b);
            continue;
        }
        *budget -= body.len();
        let mut rest = b;
        rest.stmts.retain(|s| s.span != span);
        let keep_rest = !rest.stmts.is_empty() || rest.label.is_some();
        let mut body = body.clone();
        if keep_rest && rest.label.is_some() {
            // The section label stays on the first inlined block's place.
            out.push(crate::port::follow_block(&rest, Vec::new()));
            if let Some(last) = out.last_mut() {
                last.label = rest.label.take();
            }
        }
        if !rest.stmts.is_empty() {
            out.push(rest);
        }
        body = expand(body, subs, depth + 1, budget, diags);
        out.extend(body);
    }
    out
}
