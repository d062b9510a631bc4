//! A file that is one Siemens `PROC` (the file is the procedure's body:
//! `PROC KONUS(REAL RSTART, REAL ANG)` ... `M17`), for a word-address
//! target, written as that target's own kind of called program:
//!
//! * LinuxCNC (capability `o-words` with `named-parameters`): the
//!   subroutine file `o<konus> sub` ... `o<konus> endsub`, called by
//!   `o<konus> call [..] [..]`. The parameters arrive in `#1`, `#2`, ... in
//!   the order the PROC declares them; the body keeps their names,
//!   `#<rstart> = #1` first.
//! * Fanuc, Haas (`numbered-programs` with Macro B): a macro program
//!   ended by `M99` and called with `G65 P.. A.. B..`. The parameters
//!   become the locals Fanuc's argument letters set, in the order of
//!   argument specification I (`A` = `#1`, `B` = `#2`, `C` = `#3`, `I` =
//!   `#4` ... `Z` = `#26`), in the order the PROC declares them, so a
//!   ported call passes them in that order; a comment after the name says
//!   which letter carries which parameter. The body's own variables on
//!   those locals (its `Rn` are written `#n`) move to free ones. More
//!   than 21 parameters, or a body that reads or sets a variable chosen
//!   at run time, is E0617.
//!
//! A `M17`/`RET` inside the body is the subroutine's return; the last one
//! closes it. Parameters passed by reference (`VAR`) give nothing back on
//! either target: a PROC that declares one is refused.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{CommentStyle, Expr, ExprKind, FlowId, Program, Stmt, StmtKind, Var, VarDecl};
use std::collections::{BTreeSet, HashMap};

/// The locals Fanuc's argument letters reach (argument specification I),
/// in the order a PROC's parameters take them, and each one's letter.
const LETTER_LOCALS: [(u32, char); 21] = [
    (1, 'A'),
    (2, 'B'),
    (3, 'C'),
    (4, 'I'),
    (5, 'J'),
    (6, 'K'),
    (7, 'D'),
    (8, 'E'),
    (9, 'F'),
    (11, 'H'),
    (13, 'M'),
    (17, 'Q'),
    (18, 'R'),
    (19, 'S'),
    (20, 'T'),
    (21, 'U'),
    (22, 'V'),
    (23, 'W'),
    (24, 'X'),
    (25, 'Y'),
    (26, 'Z'),
];

/// The target's kind of called program, if it has one this pass writes.
#[derive(Clone, Copy, PartialEq)]
enum Form {
    OWordSub,
    MacroProgram,
}

fn form_of(to: &DialectSpec) -> Option<Form> {
    if to.has(Capability::StructuredControl) {
        return None;
    }
    if to.has(Capability::OWords) && to.has(Capability::NamedParameters) {
        Some(Form::OWordSub)
    } else if to.has(Capability::NumberedPrograms) && to.has(Capability::MacroB) {
        Some(Form::MacroProgram)
    } else {
        None
    }
}

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let Some(form) = form_of(to) else { return };
    let Some((b, s)) = proc_head(p) else { return };
    let StmtKind::SubStart { name, params, .. } = p.blocks[b].stmts[s].kind.clone() else {
        return;
    };
    let span = p.blocks[b].stmts[s].span;
    let mut names = HashMap::new();
    let head = match form {
        Form::OWordSub => Ok(oword_head(p, &name, &params, &mut names)),
        Form::MacroProgram => macro_head(p, to, &name, &params, &mut names),
    };
    let head = match head {
        Ok(head) => head,
        Err(why) => {
            diags.push(
                Diagnostic::new(
                    Code::PortSubprogram,
                    format!("{} has no macro program for `{name}`: it {why}", to.name),
                )
                .primary(span, "this PROC")
                .help("pass the parameters in common variables set before the call"),
            );
            return;
        }
    };
    let head: Vec<Stmt> = head.into_iter().map(|k| Stmt::new(k, span)).collect();
    let mut blocks = vec![];
    for stmts in head {
        blocks.push(super::follow_block(&p.blocks[b], vec![stmts]));
    }
    p.blocks[b].stmts.remove(s);
    let at = b + 1;
    p.blocks.splice(at..at, blocks);
    super::decls::rename(p, &names);
    match form {
        Form::OWordSub => returns_to_oword(p, &name.to_ascii_lowercase()),
        Form::MacroProgram => returns_to_m99(p),
    }
}

/// Where the file's own PROC is: the first statement that is not layout,
/// a `PROC` the file never closes.
fn proc_head(p: &Program) -> Option<(usize, usize)> {
    let mut head = None;
    for (b, block) in p.blocks.iter().enumerate() {
        for (s, st) in block.stmts.iter().enumerate() {
            match &st.kind {
                StmtKind::SubStart {
                    id: FlowId::Nested, ..
                } if head.is_none() => head = Some((b, s)),
                StmtKind::SubEnd { .. } | StmtKind::SubStart { .. } => return None,
                StmtKind::Comment { .. } | StmtKind::Tape | StmtKind::ProgramStart { .. } => {}
                _ if head.is_none() => return None,
                _ => {}
            }
        }
    }
    head
}

/// `o<name> sub`, then `#<param> = #i` for each parameter.
fn oword_head(
    p: &mut Program,
    name: &str,
    params: &[VarDecl],
    names: &mut HashMap<String, Var>,
) -> Vec<StmtKind> {
    let mut out = vec![StmtKind::SubStart {
        name: name.to_ascii_lowercase(),
        params: vec![],
        id: FlowId::OWord(format!("<{}>", name.to_ascii_lowercase())),
    }];
    for (i, v) in params.iter().enumerate() {
        let var = Var::Named(v.name.to_ascii_lowercase());
        names.insert(v.name.to_ascii_uppercase(), var.clone());
        let value = p.exprs.alloc(Expr {
            kind: ExprKind::Var(Var::Numbered(i as u32 + 1)),
            span: v.span,
        });
        out.push(StmtKind::Assign { var, value });
    }
    out
}

/// The name as a comment, and which letter carries which parameter:
/// the parameters take the letters in order (`A`, `B`, `C`, `I`, ...), as
/// a ported call `L140(1, 2)` → `G65 P140 A1. B2.` passes them. A
/// variable of the body's own (`#n`, or `Rn`, which the port writes `#n`)
/// on one of those locals moves to a free local (`#1`..`#33` are the
/// macro program's own on both controls), else to a free common variable.
fn macro_head(
    p: &mut Program,
    to: &DialectSpec,
    name: &str,
    params: &[VarDecl],
    names: &mut HashMap<String, Var>,
) -> Result<Vec<StmtKind>, String> {
    let mut out = vec![comment(name.to_string())];
    if params.is_empty() {
        return Ok(out);
    }
    if params.len() > LETTER_LOCALS.len() {
        return Err(format!(
            "takes {} parameters, more than the {} argument letters",
            params.len(),
            LETTER_LOCALS.len()
        ));
    }
    let taken: Vec<(u32, char)> = LETTER_LOCALS[..params.len()].to_vec();
    let used = super::free_vars::used(p);
    if used.indirect {
        return Err("picks a variable at run time, which could be an argument's local".into());
    }
    let used = used.numbers;
    let moves = moved_locals(to, &taken, &used)?;
    let mut said = Vec::new();
    for (v, (local, letter)) in params.iter().zip(&taken) {
        names.insert(v.name.to_ascii_uppercase(), Var::Numbered(*local));
        said.push(format!("{letter}={}", v.name));
    }
    renumber(p, &moves);
    out.push(comment(format!("G65 ARGUMENTS {}", said.join(" "))));
    Ok(out)
}

/// Where each of the body's variables on an argument's local goes.
fn moved_locals(
    to: &DialectSpec,
    taken: &[(u32, char)],
    used: &BTreeSet<u32>,
) -> Result<HashMap<u32, u32>, String> {
    let is_taken = |n: u32| taken.iter().any(|(l, _)| *l == n);
    let mut free = (1..=33u32)
        .filter(|n| !used.contains(n))
        .chain(super::free_vars::commons(to, used))
        .filter(|n| !is_taken(*n));
    let mut moves = HashMap::new();
    for &n in used.iter().filter(|n| is_taken(**n)) {
        let Some(m) = free.next() else {
            return Err("uses every variable an argument could move to".into());
        };
        moves.insert(n, m);
    }
    Ok(moves)
}

/// The body's `#n`/`Rn` on an argument's local, renumbered.
fn renumber(p: &mut Program, moves: &HashMap<u32, u32>) {
    if moves.is_empty() {
        return;
    }
    let moved = |v: &Var| match v {
        Var::Numbered(n) => moves.get(n).map(|m| Var::Numbered(*m)),
        Var::R(n) => moves.get(n).map(|m| Var::R(*m)),
        _ => None,
    };
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        if let ExprKind::Var(v) = &p.exprs[id].kind {
            if let Some(nv) = moved(v) {
                p.exprs[id].kind = ExprKind::Var(nv);
            }
        }
    }
    for s in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        if let StmtKind::Assign { var, .. } | StmtKind::For { var, .. } = &mut s.kind {
            if let Some(nv) = moved(var) {
                *var = nv;
            }
        }
    }
}

fn comment(text: String) -> StmtKind {
    StmtKind::Comment {
        text,
        style: CommentStyle::Paren,
    }
}

/// `M17`/`RET` as the o-word subroutine's `return`; one that nothing
/// but comments follows is its `endsub`, else `endsub` is added at the end.
fn returns_to_oword(p: &mut Program, name: &str) {
    let id = FlowId::OWord(format!("<{name}>"));
    let mut last = None;
    for (b, block) in p.blocks.iter_mut().enumerate() {
        for (s, st) in block.stmts.iter_mut().enumerate() {
            if is_return(&st.kind) {
                st.kind = StmtKind::Return {
                    id: id.clone(),
                    value: None,
                };
                last = Some((b, s));
            } else if !matches!(st.kind, StmtKind::Comment { .. } | StmtKind::Tape) {
                last = None;
            }
        }
    }
    let end = StmtKind::SubEnd { id, value: None };
    match last {
        Some((b, s)) => p.blocks[b].stmts[s].kind = end,
        None => {
            let Some(like) = p.blocks.last() else { return };
            let block = super::follow_block(like, vec![Stmt::new(end, like.span)]);
            p.blocks.push(block);
        }
    }
}

/// `RET` as `M99`, the macro program's return.
fn returns_to_m99(p: &mut Program) {
    for st in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        if is_return(&st.kind) {
            st.kind = StmtKind::SubReturn { to: None };
        }
    }
}

fn is_return(k: &StmtKind) -> bool {
    matches!(
        k,
        StmtKind::SubReturn { to: None }
            | StmtKind::Return {
                id: FlowId::Nested,
                value: None
            }
    )
}
