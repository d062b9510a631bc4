//! Control flow in the form its [`FlowId`] says, if the target has it:
//! LinuxCNC o-words (`o100 if [..]`), Fanuc `WHILE [..] DO1` / `END1`,
//! Siemens structured keywords (`IF`, `WHILE`, `FOR`, `REPEAT`, `CASE`).

use super::writer::{Style, Writer};
use crate::dialect::Capability;
use crate::ir::{CaseArm, ExprId, FlowId, JumpDir, Var, VarDecl};
use crate::span::Span;

/// A condition: bracketed in word-address targets, bare in Siemens.
pub fn cond(w: &mut Writer<'_>, c: ExprId) -> Option<String> {
    let e = w.expr(c)?;
    Some(match w.style {
        Style::Bracket => format!("[{e}]"),
        Style::Sinumerik => e,
    })
}

/// `o100` / `o<name>` for an o-word id.
pub fn oword(name: &str) -> String {
    if name.starts_with('<') || (!name.is_empty() && name.bytes().all(|b| b.is_ascii_digit())) {
        format!("o{name}")
    } else {
        format!("o<{name}>")
    }
}

/// Which syntax the id asks for, if the target offers it; E0601 otherwise.
fn allowed(w: &mut Writer<'_>, id: &FlowId, span: Span, what: &str) -> bool {
    let cap = match id {
        FlowId::Nested => Capability::StructuredControl,
        FlowId::OWord(_) => Capability::OWords,
        FlowId::Do(_) => Capability::MacroB,
    };
    let what = match id {
        FlowId::Nested => format!("a structured {what}"),
        FlowId::OWord(_) => format!("an o-word {what}"),
        FlowId::Do(_) => format!("a Macro B {what}"),
    };
    w.need(cap, span, &what)
}

/// Writes one flow statement: `nested` keyword, o-word keyword, optional
/// condition. `Do` ids are handled by the callers that have a form for them.
pub fn keyword(
    w: &mut Writer<'_>,
    id: &FlowId,
    nested: Option<&str>,
    oword_kw: &str,
    c: Option<ExprId>,
    span: Span,
    words: &mut Vec<String>,
) {
    let what = oword_kw.to_string();
    if !allowed(w, id, span, &what) {
        return;
    }
    let head = match (id, nested) {
        (FlowId::OWord(n), _) => format!("{} {oword_kw}", oword(n)),
        (FlowId::Nested, Some(k)) => k.to_string(),
        (FlowId::Nested, None) | (FlowId::Do(_), _) => {
            return w.cannot(
                span,
                &format!("`{oword_kw}` in this form"),
                "use another loop form",
            );
        }
    };
    let c = match c {
        Some(c) => match cond(w, c) {
            Some(s) => Some(s),
            None => return,
        },
        None => None,
    };
    words.push(head);
    words.extend(c);
}

pub fn while_(w: &mut Writer<'_>, c: ExprId, id: &FlowId, span: Span, words: &mut Vec<String>) {
    if let FlowId::Do(m) = id {
        if allowed(w, id, span, "WHILE loop") {
            if let Some(c) = cond(w, c) {
                words.extend(["WHILE".to_string(), c, format!("DO{m}")]);
            }
        }
        return;
    }
    keyword(w, id, Some("WHILE"), "while", Some(c), span, words);
}

pub fn end_while(w: &mut Writer<'_>, id: &FlowId, span: Span, words: &mut Vec<String>) {
    if let FlowId::Do(m) = id {
        if allowed(w, id, span, "loop end") {
            words.push(format!("END{m}"));
        }
        return;
    }
    keyword(w, id, Some("ENDWHILE"), "endwhile", None, span, words);
}

fn structured(w: &mut Writer<'_>, span: Span, what: &str) -> bool {
    w.need(Capability::StructuredControl, span, what)
}

/// Siemens-only keyword statements with no id (`ENDFOR`, `LOOP`, `REPEAT`).
pub fn bare(w: &mut Writer<'_>, kw: &str, span: Span, words: &mut Vec<String>) {
    if structured(w, span, &format!("`{kw}`")) {
        words.push(kw.to_string());
    }
}

pub fn until(w: &mut Writer<'_>, c: ExprId, span: Span, words: &mut Vec<String>) {
    if structured(w, span, "`UNTIL`") {
        if let Some(c) = cond(w, c) {
            words.extend(["UNTIL".to_string(), c]);
        }
    }
}

pub fn for_(
    w: &mut Writer<'_>,
    var: &Var,
    from: ExprId,
    to: ExprId,
    span: Span,
    words: &mut Vec<String>,
) {
    if !structured(w, span, "a FOR loop") {
        return;
    }
    let v = super::expr::write_var(w, var, span);
    let (f, t) = (w.expr(from), w.expr(to));
    if let (Some(v), Some(f), Some(t)) = (v, f, t) {
        words.extend(["FOR".to_string(), format!("{v}={f}"), "TO".to_string(), t]);
    }
}

pub fn jump_kw(dir: JumpDir) -> &'static str {
    match dir {
        JumpDir::Either => "GOTO",
        JumpDir::Forward => "GOTOF",
        JumpDir::Backward => "GOTOB",
        JumpDir::EitherNoAlarm => "GOTOC",
    }
}

pub fn case(
    w: &mut Writer<'_>,
    sel: ExprId,
    arms: &[CaseArm],
    default: Option<&(String, JumpDir)>,
    span: Span,
    words: &mut Vec<String>,
) {
    if !structured(w, span, "a CASE jump") {
        return;
    }
    let Some(s) = w.expr(sel) else { return };
    let mut out = vec![format!("CASE({s})"), "OF".to_string()];
    for arm in arms {
        let Some(v) = w.expr(arm.value) else { return };
        out.extend([v, jump_kw(arm.dir).to_string(), arm.target.clone()]);
    }
    if let Some((target, dir)) = default {
        out.extend([
            "DEFAULT".to_string(),
            jump_kw(*dir).to_string(),
            target.clone(),
        ]);
    }
    words.extend(out);
}

pub fn section_repeat(
    w: &mut Writer<'_>,
    start: &str,
    end: Option<&str>,
    count: Option<ExprId>,
    single: bool,
    span: Span,
    words: &mut Vec<String>,
) {
    if !structured(w, span, "a section repeat") {
        return;
    }
    words.push(if single { "REPEATB" } else { "REPEAT" }.to_string());
    words.push(start.to_string());
    words.extend(end.map(str::to_string));
    if let Some(c) = count {
        if let Some(c) = w.expr(c) {
            words.push(format!("P={c}"));
        }
    }
}

pub fn sub_start(
    w: &mut Writer<'_>,
    name: &str,
    params: &[VarDecl],
    id: &FlowId,
    span: Span,
    words: &mut Vec<String>,
) {
    if !allowed(w, id, span, "subroutine") {
        return;
    }
    match id {
        FlowId::OWord(n) if params.is_empty() => words.extend([oword(n), "sub".to_string()]),
        FlowId::OWord(_) => w.cannot(
            span,
            "declared subroutine parameters",
            "o-word subroutines take #1..#30",
        ),
        FlowId::Nested => words.push(proc_head(name, params)),
        FlowId::Do(_) => w.cannot(span, "a subroutine with a DO id", "this id is for loops"),
    }
}

/// `PROC NAME(REAL A, REAL B)`: the IR keeps no parameter types, so REAL.
fn proc_head(name: &str, params: &[VarDecl]) -> String {
    if params.is_empty() {
        return format!("PROC {name}");
    }
    let ps: Vec<String> = params.iter().map(|p| format!("REAL {}", p.name)).collect();
    format!("PROC {name}({})", ps.join(", "))
}

/// `o100 endsub [v]`, `o100 return [v]`; Siemens `RET`.
pub fn sub_exit(
    w: &mut Writer<'_>,
    id: &FlowId,
    value: Option<ExprId>,
    oword_kw: &str,
    span: Span,
    words: &mut Vec<String>,
) {
    if !allowed(w, id, span, oword_kw) {
        return;
    }
    match (id, value) {
        (FlowId::OWord(_), _) => keyword(w, id, None, oword_kw, value, span, words),
        (FlowId::Nested, None) => words.push("RET".to_string()),
        (FlowId::Nested, Some(_)) => w.cannot(
            span,
            "a subroutine returning a value",
            "pass the result in a variable",
        ),
        (FlowId::Do(_), _) => w.cannot(span, "a return with a DO id", "this id is for loops"),
    }
}
