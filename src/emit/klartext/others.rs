//! The Klartext blocks of statements other than moves: program frame,
//! headings, blank, tools, Q parameter formulas, jumps and calls, section
//! repeats, dwell, cycle definitions and patterns.

use super::super::number::NumKind;
use super::super::writer::Writer;
use super::expr::{formula, signed, var};
use super::lines::label;
use super::{unit_word, Out};
use crate::ir::{
    BinaryOp, CallKind, CallTarget, CommentStyle, CycleWord, DwellUnit, ExprKind, JumpTarget, Stmt,
    StmtKind as K, StockCorner, StopKind, ToolRef, Value,
};
use crate::span::Span;

pub(super) fn tool_call(w: &mut Writer<'_>, stmts: &[&Stmt], feed: Option<String>) -> String {
    let mut line = "TOOL CALL".to_string();
    let mut rest = String::new();
    let mut deltas = String::new();
    for s in stmts {
        match &s.kind {
            K::ToolSelect(ToolRef::Number(v)) => match v {
                Value::Number(d) => line.push_str(&format!(" {}", d.format(0, false))),
                Value::Expr(e) => {
                    if let ExprKind::Var(x) = &w.prog.exprs[*e].kind {
                        if let Some(t) = var(w, x, s.span) {
                            line.push_str(&format!(" {t}"));
                        }
                    } else {
                        w.cannot(
                            s.span,
                            "a tool number given by a formula",
                            "compute it into a Q parameter",
                        );
                    }
                }
            },
            K::ToolSelect(ToolRef::Name(n)) => line.push_str(&format!(" \"{n}\"")),
            K::Plane(p) => rest.insert_str(
                0,
                match p {
                    crate::ir::Plane::XY => " Z",
                    crate::ir::Plane::ZX => " Y",
                    crate::ir::Plane::YZ => " X",
                },
            ),
            K::SpindleSpeed(v) => {
                if let Some(t) = signed(w, v, NumKind::Feed, s.span) {
                    rest.push_str(&format!(" S{}", t.trim_start_matches('+')));
                }
            }
            K::ToolOversize { length, radius } => {
                for (a, v) in [("DL", length), ("DR", radius)] {
                    if let Some(t) = v
                        .as_ref()
                        .and_then(|v| signed(w, v, NumKind::Length, s.span))
                    {
                        deltas.push_str(&format!(" {a}{t}"));
                    }
                }
            }
            _ => {}
        }
    }
    if let Some(f) = feed {
        rest.push_str(&format!(" {f}"));
    }
    let change = stmts.iter().find(|s| matches!(s.kind, K::ToolChange));
    let named = stmts.iter().any(|s| matches!(s.kind, K::ToolSelect(_)));
    if let (Some(c), false) = (change, named) {
        // `TOOL CALL` with no tool changes nothing on the TNC.
        w.cannot(
            c.span,
            "a tool change whose tool is not known here (selected on another path)",
            "give the tool in the change block (`T2 M6`)",
        );
    }
    line + &rest + &deltas
}

pub(super) fn other(w: &mut Writer<'_>, out: &mut Out, s: &Stmt) {
    let span = s.span;
    let line = match &s.kind {
        K::ProgramStart { number, name } => {
            let n = super::program_name(*number, name.as_deref()).unwrap_or_else(|| "PGM".into());
            out.lines
                .push(format!("BEGIN PGM {n} {}", unit_word(out.unit)));
            // What the name after BEGIN PGM cannot hold stays as a comment.
            if let Some(text) = name.as_deref().filter(|t| *t != n) {
                let t = w.safe_text(text, crate::dialect::text::TextForm::Semicolon, span);
                out.lines.push(format!("; {t}"));
            }
            if let Some(num) = number.filter(|k| k.to_string() != n) {
                out.lines.push(format!("; program number {num}"));
            }
            None
        }
        K::ProgramEnd { name } => Some(format!(
            "END PGM {} {}",
            super::program_name(None, name.as_deref())
                .or_else(|| super::first_name(w.prog))
                .unwrap_or_else(|| "PGM".into()),
            unit_word(out.unit)
        )),
        K::Comment {
            text,
            style: CommentStyle::Heading,
        } => Some(format!(
            "* {}",
            w.safe_text(text, crate::dialect::text::TextForm::Plain, span)
        )),
        K::Stop(StopKind::Program) => Some("STOP".into()),
        K::Stock {
            corner,
            axis,
            axes: a,
        } => {
            let head = match corner {
                StockCorner::Min => format!("BLK FORM 0.1 {}", axis.unwrap_or('Z')),
                StockCorner::Max => "BLK FORM 0.2".into(),
            };
            super::lines::axes(w, out, a).map(|t| head + &t)
        }
        K::ToolDef {
            tool,
            length,
            radius,
        } => {
            let t = match tool {
                ToolRef::Number(Value::Number(d)) => d.format(0, false),
                ToolRef::Number(_) => "0".into(),
                ToolRef::Name(n) => format!("\"{n}\""),
            };
            let mut l = format!("TOOL DEF {t}");
            for (a, v) in [("L", length), ("R", radius)] {
                if let Some(x) = v.as_ref().and_then(|v| signed(w, v, NumKind::Length, span)) {
                    l.push_str(&format!(" {a}{x}"));
                }
            }
            Some(l)
        }
        K::Raw { dialect, text } if w.spec.answers_to(dialect) => Some(text.clone()),
        K::TncFunction(f) => Some(f.text.clone()),
        K::Assign { var: v, value } if super::expr::is_angle(w, *value) => {
            super::expr::fn13(w, v, *value, span)
        }
        K::Assign { var: v, value } => match (var(w, v, span), formula(w, *value)) {
            (Some(a), Some(b)) => Some(format!("{a} = {b}")),
            _ => None,
        },
        K::Goto {
            target: JumpTarget::Label(l),
            cond,
            ..
        } => goto(w, l, *cond, span),
        K::Call {
            kind: CallKind::Label,
            target,
            repeat: None,
            ..
        } => match target {
            CallTarget::Number(n) => Some(format!("CALL LBL {n}")),
            CallTarget::Name(n) => Some(format!("CALL LBL {}", label(n))),
            CallTarget::Computed(_) => cannot(w, span, "a label call to a computed label"),
        },
        K::Call {
            kind: CallKind::Named | CallKind::Subprogram,
            target,
            repeat: None,
            ..
        } => match target {
            CallTarget::Number(n) => Some(format!("CALL PGM {n}")),
            CallTarget::Name(n) => Some(format!("CALL PGM {n}")),
            CallTarget::Computed(_) => cannot(w, span, "a program call to a computed number"),
        },
        K::SectionRepeat {
            start,
            end: None,
            count,
            single: false,
        } => {
            let n = count.and_then(|c| match w.prog.exprs[c].kind {
                ExprKind::Number(d) => Some(d.format(0, false)),
                _ => None,
            });
            match n {
                Some(n) => Some(format!("CALL LBL {} REP {n}/{n}", label(start))),
                None => cannot(w, span, "a section repeat with a computed count"),
            }
        }
        K::SubReturn { to: None } => Some("LBL 0".into()),
        K::Dwell {
            value,
            unit: DwellUnit::Seconds,
        } => {
            out.lines.push("CYCL DEF 9.0 DWELL TIME".into());
            signed(w, value, NumKind::Plain, span)
                .map(|t| format!("CYCL DEF 9.1 DWELL {}", t.trim_start_matches('+')))
        }
        K::CycleDef(c) => cycle_def(w, c, span),
        K::CycleLine(c) => {
            cycle_words(w, &c.words, span).map(|t| format!("CYCL DEF {}.{}{t}", c.cycle, c.sub))
        }
        K::PatternDef(items) => {
            let mut l = "PATTERN DEF".to_string();
            for i in items {
                let t = cycle_words(w, &i.words, span).unwrap_or_default();
                l.push_str(&format!(" ~\n{} ({})", i.name, t.trim_start()));
            }
            Some(l)
        }
        K::Units { .. } => cannot(w, span, "a change of units inside the program"),
        _ => cannot(
            w,
            span,
            &format!("the statement `{}`", variant_name(&s.kind)),
        ),
    };
    out.lines.extend(line);
}

fn cannot(w: &mut Writer<'_>, span: Span, what: &str) -> Option<String> {
    w.cannot(
        span,
        what,
        "Klartext has no function for it; rewrite this part by hand",
    );
    None
}

fn goto(
    w: &mut Writer<'_>,
    l: &str,
    cond: Option<crate::ir::ExprId>,
    span: Span,
) -> Option<String> {
    let (n, op, a, b) = match cond.map(|c| w.prog.exprs[c].kind.clone()) {
        None => return Some(format!("FN 9: IF +0 EQU +0 GOTO LBL {}", label(l))),
        Some(ExprKind::Binary(op, a, b)) => match op {
            BinaryOp::Eq => (9, "EQU", a, b),
            BinaryOp::Ne => (10, "NE", a, b),
            BinaryOp::Gt => (11, "GT", a, b),
            BinaryOp::Lt => (12, "LT", a, b),
            _ => return cannot(w, span, "a jump condition other than EQU NE GT LT"),
        },
        Some(_) => return cannot(w, span, "a jump condition that is not a comparison"),
    };
    let a = signed(w, &Value::Expr(a), NumKind::Plain, span)?;
    let b = signed(w, &Value::Expr(b), NumKind::Plain, span)?;
    Some(format!("FN {n}: IF {a} {op} {b} GOTO LBL {}", label(l)))
}

fn cycle_def(w: &mut Writer<'_>, c: &crate::ir::CycleDef, span: Span) -> Option<String> {
    let mut l = format!("CYCL DEF {}", c.number);
    if !c.name.is_empty() {
        l.push_str(&format!(" {}", c.name));
    }
    for p in &c.params {
        let v = signed(w, &p.value, NumKind::Plain, span)?;
        l.push_str(&format!(" ~\n  Q{}={v}", p.q));
        if let Some(t) = &p.label {
            l.push_str(&format!(" ;{t}"));
        }
    }
    Some(l)
}

fn cycle_words(w: &mut Writer<'_>, words: &[CycleWord], span: Span) -> Option<String> {
    let mut s = String::new();
    for cw in words {
        match &cw.value {
            // A bare value, or one after a colon (`HSC-MODE:0`): no sign.
            Some(v) if cw.name.is_empty() || cw.name.ends_with(':') => s.push_str(&format!(
                " {}{}",
                cw.name,
                signed(w, v, NumKind::Plain, span)?.trim_start_matches('+')
            )),
            Some(v) => s.push_str(&format!(
                " {}{}",
                cw.name,
                signed(w, v, NumKind::Plain, span)?
            )),
            None => s.push_str(&format!(" {}", cw.name)),
        }
    }
    Some(s)
}

/// `WorkOffset`, `LengthComp`: the statement's kind for messages.
fn variant_name(k: &K) -> String {
    let d = format!("{k:?}");
    d.split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or("")
        .to_string()
}
