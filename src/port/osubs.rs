//! LinuxCNC o-word subroutines in the program's own file for a target of
//! numbered programs with macro calls (Fanuc, Haas):
//!
//! * `o100 sub` ... `o100 endsub` becomes the program `O100` ... `M99`,
//!   moved after the main program's end (a tape holding several programs,
//!   as the control loads it into memory); `o100 return` inside it is
//!   `M99` too.
//! * `o100 call [20] [5]` becomes `G65 P100 A20. B5.`: G65 gives the called
//!   program its own local variables, as an o-word call does, and Fanuc's
//!   argument letters put the values in the same locals (`A` = `#1`, `B` =
//!   `#2`, `C` = `#3`, `I` = `#4`, `J` = `#5`, `K` = `#6`, `D` = `#7`, `E` =
//!   `#8`, `F` = `#9`, `H` = `#11`, ... `Z` = `#26`: argument
//!   specification I), so the body reads its arguments unchanged.
//! * The main program needs a number to share its file: it keeps its own
//!   `O` number, or gets the lowest one no subroutine uses.
//!
//! * A subroutine defined by name (`o<drill> sub`) gets a free program
//!   number, the lowest from 1000 up that the file does not use, in the
//!   order they are defined, with its name as a comment: `O1000 (drill)`;
//!   its calls `G65 P1000`.
//!
//! Refused (E0617): a call of a named subroutine in another file (its
//! number would be chosen when that file is ported), numbers above 9999, returning a value, computed calls, and
//! an argument in `#10`, `#12`, `#14`, `#15`, `#16` or above `#26` (no
//! letter reaches them).
//!
//! For Siemens, which keeps subprograms in `.SPF` files of their own (not
//! written by the port), each call is replaced by the subroutine's blocks,
//! its arguments first set in `R1`.. (`#1 = 20` before the body, which
//! [`super::forms`] writes `R1=20`), as Heidenhain label subprograms are
//! ([`super::from_tnc::inline`]). R parameters are global where o-word
//! locals are not, so a main program that uses `#1`..`#30` itself, an
//! argument that reads them, and an early `return` are refused (E0617).

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Family, Meaning};
use crate::ir::{Block, CallArgs, CallKind, CallTarget, ExprKind, Program, Stmt, StmtKind, Value};
use crate::span::Span;

/// Fanuc's argument letters for `#1`..`#26` (argument specification I);
/// `None` where no letter reaches the variable.
const LETTERS: [Option<char>; 26] = [
    Some('A'),
    Some('B'),
    Some('C'),
    Some('I'),
    Some('J'),
    Some('K'),
    Some('D'),
    Some('E'),
    Some('F'),
    None,
    Some('H'),
    None,
    Some('M'),
    None,
    None,
    None,
    Some('Q'),
    Some('R'),
    Some('S'),
    Some('T'),
    Some('U'),
    Some('V'),
    Some('W'),
    Some('X'),
    Some('Y'),
    Some('Z'),
];

/// The highest program number a Fanuc `O` word takes.
const MAX_PROGRAM: u32 = 9999;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if from.has(Capability::OWords) && to.family == Family::Sinumerik && has_subs(p) {
        return inline(p, diags);
    }
    let applies = from.has(Capability::OWords)
        && !to.has(Capability::OWords)
        && to.has(Capability::NumberedPrograms)
        && to.code_for(Meaning::MacroCall).is_some();
    if !applies || !has_subs(p) {
        return;
    }
    let names = name_numbers(p);
    let mut numbers: Vec<u32> = names.iter().map(|(_, n)| *n).collect();
    let (main, subs) = split(p, &names, &mut numbers, diags);
    p.blocks = main;
    number_main(p, &numbers);
    p.blocks.extend(subs);
    for s in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        call(s, &names, &p.exprs, diags);
    }
}

/// The lowest number a named subroutine may get: named ones are numbered
/// from here up, past the numbers the file uses itself, so `O1000 (drill)`
/// stands out from a main program's low number.
const FIRST_FOR_NAMES: u32 = 1000;

/// A free program number for each subroutine defined in the file by name
/// (`o<drill> sub` → 1000), in the order they are defined, skipping the
/// numbers of numbered subroutines and of the main program.
fn name_numbers(p: &Program) -> Vec<(String, u32)> {
    let mut used: Vec<u32> = Vec::new();
    let mut named: Vec<String> = Vec::new();
    for s in p.blocks.iter().flat_map(|b| &b.stmts) {
        match &s.kind {
            StmtKind::SubStart { name, .. } => match name.parse::<u32>() {
                Ok(n) => used.push(n),
                Err(_) if !named.contains(name) => named.push(name.clone()),
                Err(_) => {}
            },
            StmtKind::ProgramStart {
                number: Some(n), ..
            } => used.push(*n),
            _ => {}
        }
    }
    let mut next = FIRST_FOR_NAMES;
    let mut out = Vec::new();
    for name in named {
        while used.contains(&next) {
            next += 1;
        }
        if next > MAX_PROGRAM {
            break;
        }
        used.push(next);
        out.push((name, next));
        next += 1;
    }
    out
}

fn number_of(names: &[(String, u32)], name: &str) -> Option<u32> {
    names.iter().find(|(n, _)| n == name).map(|(_, k)| *k)
}

fn has_subs(p: &Program) -> bool {
    p.blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .any(|s| matches!(s.kind, StmtKind::SubStart { .. }))
}

fn refusal(span: Span, what: &str) -> Diagnostic {
    Diagnostic::new(
        Code::PortSubprogram,
        format!("{what} has no numbered-program form"),
    )
    .primary(span, "here")
    .help("number the subroutine (o100 sub) and pass at most the arguments #1..#9, #11, #13, #17..#26")
}

/// A statement of a subroutine, as [`split_subs`] hands it over.
pub(super) struct SubStmt<'a> {
    pub stmt: &'a mut Stmt,
    /// The block's label (a label subprogram's name goes there).
    pub label: &'a mut Option<Box<crate::span::Spanned<String>>>,
    pub block: Span,
}

/// Splits the blocks into the main program's and the subroutines' (each
/// from its `o.. sub` to its `o.. endsub`, the endsub block included);
/// `each` sees every statement of a subroutine to rewrite it.
pub(super) fn split_subs(
    blocks: Vec<Block>,
    mut each: impl FnMut(SubStmt<'_>),
) -> (Vec<Block>, Vec<Block>) {
    let mut main = Vec::new();
    let mut subs = Vec::new();
    let mut open = false;
    for mut b in blocks {
        let mut into_sub = open;
        let Block {
            stmts, label, span, ..
        } = &mut b;
        for stmt in stmts.iter_mut() {
            let starts = !open && matches!(stmt.kind, StmtKind::SubStart { .. });
            let ends = open && matches!(stmt.kind, StmtKind::SubEnd { .. });
            open |= starts;
            into_sub |= starts;
            if open {
                each(SubStmt {
                    stmt,
                    label,
                    block: *span,
                });
            }
            open &= !ends;
        }
        if into_sub {
            subs.push(b);
        } else {
            main.push(b);
        }
    }
    (main, subs)
}

/// The main program's blocks and the subroutines' (as `O n` .. `M99`).
fn split(
    p: &mut Program,
    names: &[(String, u32)],
    numbers: &mut Vec<u32>,
    diags: &mut Vec<Diagnostic>,
) -> (Vec<Block>, Vec<Block>) {
    split_subs(std::mem::take(&mut p.blocks), |x| {
        let s = x.stmt;
        match &s.kind {
            StmtKind::SubStart { name, .. } => match name.parse::<u32>() {
                Ok(n) if (1..=MAX_PROGRAM).contains(&n) => {
                    numbers.push(n);
                    s.kind = StmtKind::ProgramStart {
                        number: Some(n),
                        name: None,
                    };
                }
                Ok(n) => diags.push(refusal(s.span, &format!("the subroutine `o{n}`"))),
                Err(_) => match number_of(names, name) {
                    Some(n) => {
                        s.kind = StmtKind::ProgramStart {
                            number: Some(n),
                            name: Some(name.clone()),
                        }
                    }
                    None => diags.push(refusal(s.span, &format!("the subroutine `o<{name}>`"))),
                },
            },
            StmtKind::SubEnd { value, .. } | StmtKind::Return { value, .. } => {
                if value.is_some() {
                    diags.push(refusal(s.span, "a subroutine that returns a value"));
                }
                s.kind = StmtKind::SubReturn { to: None };
            }
            _ => {}
        }
    })
}

/// `o100 call [a] [b]` → `G65 P100 A.. B..`.
fn call(
    s: &mut Stmt,
    names: &[(String, u32)],
    exprs: &crate::ir::Arena<crate::ir::Expr>,
    diags: &mut Vec<Diagnostic>,
) {
    let StmtKind::Call {
        kind: kind @ CallKind::OWord,
        target,
        args,
        repeat: None,
    } = &mut s.kind
    else {
        return;
    };
    match target {
        CallTarget::Number(_) => {}
        CallTarget::Name(n) => match number_of(names, n) {
            Some(k) => *target = CallTarget::Number(k),
            None => {
                let what = format!("a call of `o<{n}>`, a subroutine in another file,");
                diags.push(refusal(s.span, &what));
                return;
            }
        },
        CallTarget::Computed(_) => {
            diags.push(refusal(s.span, "a call of a computed subroutine"));
            return;
        }
    }
    let mut letters = Vec::new();
    if let CallArgs::Positional(list) = args {
        for (i, a) in list.iter().enumerate() {
            let Some(e) = a else { continue };
            let Some(letter) = LETTERS.get(i).copied().flatten() else {
                diags.push(refusal(s.span, &format!("the argument #{}", i + 1)));
                return;
            };
            let value = match &exprs[*e].kind {
                ExprKind::Number(d) => Value::Number(*d),
                _ => Value::Expr(*e),
            };
            letters.push((letter, value));
        }
    }
    *kind = CallKind::Macro;
    *args = CallArgs::Letters(letters);
}

/// `O n` for a main program without a number: the lowest no subroutine
/// uses, after a leading `%`.
fn number_main(p: &mut Program, used: &[u32]) {
    let numbered = p.blocks.iter().flat_map(|b| &b.stmts).any(|s| {
        matches!(
            s.kind,
            StmtKind::ProgramStart {
                number: Some(_),
                ..
            }
        )
    });
    if numbered {
        return;
    }
    let n = (1..).find(|n| !used.contains(n)).unwrap_or(1);
    let at = p
        .blocks
        .iter()
        .position(|b| {
            !b.stmts.iter().all(|s| matches!(s.kind, StmtKind::Tape)) || b.stmts.is_empty()
        })
        .unwrap_or(0);
    let like = p.blocks.get(at).or(p.blocks.first());
    let span = like.map(|b| b.span).unwrap_or_default();
    let start = Stmt::new(
        StmtKind::ProgramStart {
            number: Some(n),
            name: None,
        },
        span,
    );
    let block = match like {
        Some(b) => crate::port::follow_block(b, vec![start]),
        None => return,
    };
    p.blocks.insert(at, block);
}

fn inline_refusal(span: Span, what: &str) -> Diagnostic {
    Diagnostic::new(
        Code::PortSubprogram,
        format!("{what} cannot be carried into a Siemens program with the subroutines inlined"),
    )
    .primary(span, "here")
    .help("Siemens keeps subprograms in .SPF files of their own; write this one as a PROC by hand, or simplify it in the source")
}

/// The highest o-word argument (`#30`).
const ARGS: u32 = 30;

/// Siemens: the subroutines as label subprograms after the end, their
/// calls as argument assignments and a label call, then inlined.
fn inline(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    let (main, mut subs) = split_subs(std::mem::take(&mut p.blocks), |x| {
        let s = x.stmt;
        match &s.kind {
            StmtKind::SubStart { name, .. } => {
                *x.label = Some(Box::new(crate::span::Spanned {
                    node: name.clone(),
                    span: s.span,
                }));
            }
            StmtKind::SubEnd { value, .. } => {
                if value.is_some() {
                    diags.push(inline_refusal(s.span, "a subroutine that returns a value"));
                }
                s.kind = StmtKind::SubReturn { to: None };
            }
            StmtKind::Return { .. } => {
                diags.push(inline_refusal(
                    s.span,
                    "a return before the subroutine's end",
                ));
            }
            _ => {}
        }
    });
    for b in &mut subs {
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::SubStart { .. }));
    }
    let sub_spans: Vec<Span> = subs.iter().map(|b| b.span).collect();
    main_locals(p, &sub_spans, diags);
    locals_after_calls(p, &subs, diags);
    p.blocks = main;
    p.blocks.extend(subs);
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut stmts = Vec::with_capacity(b.stmts.len());
        for s in std::mem::take(&mut b.stmts) {
            stmts.extend(label_call(s, &p.exprs, diags));
        }
        b.stmts = stmts;
        p.blocks.push(b);
    }
    super::from_tnc::inline::run(p, diags);
}

/// `o100 call [a] [b]` → `#1 = a`, `#2 = b`, `CALL LBL 100`.
fn label_call(
    s: Stmt,
    exprs: &crate::ir::Arena<crate::ir::Expr>,
    diags: &mut Vec<Diagnostic>,
) -> Vec<Stmt> {
    let StmtKind::Call {
        kind: CallKind::OWord,
        target,
        args,
        repeat: None,
    } = &s.kind
    else {
        return vec![s];
    };
    if matches!(target, CallTarget::Computed(_)) {
        diags.push(inline_refusal(s.span, "a call of a computed subroutine"));
        return vec![s];
    }
    let mut out = Vec::new();
    if let CallArgs::Positional(list) = args {
        for (i, a) in list.iter().enumerate() {
            let Some(value) = a else { continue };
            let n = i as u32 + 1;
            if n > ARGS || reads_locals(*value, exprs) {
                diags.push(inline_refusal(
                    s.span,
                    &format!("the argument #{n}, which reads the caller's #1..#30,"),
                ));
                return vec![s];
            }
            // At the argument's place: the inliner takes the call's span
            // to find the call.
            out.push(Stmt::new(
                StmtKind::Assign {
                    var: crate::ir::Var::Numbered(n),
                    value: *value,
                },
                exprs[*value].span,
            ));
        }
    }
    out.push(Stmt::new(
        StmtKind::Call {
            kind: CallKind::Label,
            target: target.clone(),
            args: CallArgs::None,
            repeat: None,
        },
        s.span,
    ));
    out
}

/// Whether an expression reads `#1`..`#30`.
fn reads_locals(e: crate::ir::ExprId, exprs: &crate::ir::Arena<crate::ir::Expr>) -> bool {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        use crate::ir::Var;
        match &exprs[e].kind {
            ExprKind::Var(Var::Numbered(n)) if (1..=ARGS).contains(n) => return true,
            ExprKind::Var(Var::Indirect(i) | Var::RIndirect(i)) => stack.push(*i),
            ExprKind::Var(Var::User(_, idx)) => stack.extend(idx),
            ExprKind::Unary(_, a) | ExprKind::Dimension(_, a) => stack.push(*a),
            ExprKind::Binary(_, a, b) | ExprKind::AtanSlash(a, b) => stack.extend([*a, *b]),
            ExprKind::ExistsNumbered(a) => stack.push(*a),
            ExprKind::Call(_, args) | ExprKind::Query(_, args) => stack.extend(args),
            ExprKind::Number(_)
            | ExprKind::Str(_)
            | ExprKind::Bool(_)
            | ExprKind::Var(_)
            | ExprKind::Exists(_) => {}
        }
    }
    false
}

/// The main program's own `#1`..`#30` (outside the subroutines' blocks)
/// would share `R1`..`R30` with the arguments.
fn main_locals(p: &Program, subs: &[Span], diags: &mut Vec<Diagnostic>) {
    let inside = |sp: Span| {
        subs.iter()
            .any(|b| sp.file == b.file && sp.start >= b.start && sp.end <= b.end)
    };
    for (_, e) in p.exprs.iter() {
        if let ExprKind::Var(crate::ir::Var::Numbered(n)) = e.kind {
            if (1..=ARGS).contains(&n) && !inside(e.span) {
                diags.push(inline_refusal(
                    e.span,
                    "a main program's own #1..#30 next to subroutine arguments in R1..R30",
                ));
                return;
            }
        }
    }
}

/// A subroutine that calls another and reads `#1`..`#30` after the call:
/// inlined, the callee's arguments would overwrite them (they are one set
/// of R parameters).
fn locals_after_calls(p: &Program, subs: &[Block], diags: &mut Vec<Diagnostic>) {
    let mut start = 0;
    while start < subs.len() {
        let end = subs[start + 1..]
            .iter()
            .position(|b| b.label.is_some())
            .map_or(subs.len(), |k| start + 1 + k);
        let body = &subs[start..end];
        start = end;
        let call = body
            .iter()
            .flat_map(|b| &b.stmts)
            .find_map(|s| match s.kind {
                StmtKind::Call {
                    kind: CallKind::OWord,
                    ..
                } => Some(s.span),
                _ => None,
            });
        let Some(call) = call else { continue };
        let last = body.last().map_or(call, |b| b.span);
        let read = p.exprs.iter().find_map(|(_, e)| match e.kind {
            ExprKind::Var(crate::ir::Var::Numbered(n))
                if (1..=ARGS).contains(&n)
                    && e.span.file == call.file
                    && e.span.start >= call.end
                    && e.span.end <= last.end =>
            {
                Some(e.span)
            }
            _ => None,
        });
        if let Some(span) = read {
            diags.push(inline_refusal(
                span,
                "a subroutine's own #1..#30 read after it calls another",
            ));
        }
    }
}
