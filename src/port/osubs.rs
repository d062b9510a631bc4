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
//! Refused (E0617): named subroutines (`o<name>`; Fanuc programs are
//! numbered), numbers above 9999, returning a value, computed calls, and
//! an argument in `#10`, `#12`, `#14`, `#15`, `#16` or above `#26` (no
//! letter reaches them).

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
    let applies = from.has(Capability::OWords)
        && !to.has(Capability::OWords)
        && to.family != Family::Klartext
        && to.has(Capability::NumberedPrograms)
        && to.code_for(Meaning::MacroCall).is_some();
    if !applies || !has_subs(p) {
        return;
    }
    let mut numbers = Vec::new();
    let (main, subs) = split(p, &mut numbers, diags);
    p.blocks = main;
    for s in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        call(s, &p.exprs, diags);
    }
    number_main(p, &numbers);
    p.blocks.extend(subs);
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

/// The main program's blocks and the subroutines' (as `O n` .. `M99`).
fn split(
    p: &mut Program,
    numbers: &mut Vec<u32>,
    diags: &mut Vec<Diagnostic>,
) -> (Vec<Block>, Vec<Block>) {
    let mut main = Vec::new();
    let mut subs = Vec::new();
    let mut open = false;
    for mut b in std::mem::take(&mut p.blocks) {
        let mut into_sub = open;
        for s in &mut b.stmts {
            match &s.kind {
                StmtKind::SubStart { name, .. } if !open => {
                    open = true;
                    into_sub = true;
                    match name.parse::<u32>() {
                        Ok(n) if (1..=MAX_PROGRAM).contains(&n) => {
                            numbers.push(n);
                            s.kind = StmtKind::ProgramStart {
                                number: Some(n),
                                name: None,
                            };
                        }
                        Ok(n) => diags.push(refusal(s.span, &format!("the subroutine `o{n}`"))),
                        Err(_) => {
                            diags.push(refusal(s.span, &format!("the subroutine `o<{name}>`")))
                        }
                    }
                }
                StmtKind::SubEnd { value, .. } if open => {
                    if value.is_some() {
                        diags.push(refusal(s.span, "a subroutine that returns a value"));
                    }
                    open = false;
                    s.kind = StmtKind::SubReturn { to: None };
                }
                StmtKind::Return { value: Some(_), .. } if open => {
                    diags.push(refusal(s.span, "a subroutine that returns a value"));
                }
                StmtKind::Return { value: None, .. } if open => {
                    s.kind = StmtKind::SubReturn { to: None };
                }
                _ => {}
            }
        }
        if into_sub {
            subs.push(b);
        } else {
            main.push(b);
        }
    }
    (main, subs)
}

/// `o100 call [a] [b]` → `G65 P100 A.. B..`.
fn call(s: &mut Stmt, exprs: &crate::ir::Arena<crate::ir::Expr>, diags: &mut Vec<Diagnostic>) {
    let StmtKind::Call {
        kind: kind @ CallKind::OWord,
        target,
        args,
        repeat: None,
    } = &mut s.kind
    else {
        return;
    };
    if !matches!(target, CallTarget::Number(_)) {
        diags.push(refusal(s.span, "a call of a named or computed subroutine"));
        return;
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
