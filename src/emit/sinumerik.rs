//! What only the Siemens 840D writer says its own way: `MSG("..")`,
//! `%_N_NAME_MPF`, keyword commands, named cycle calls with their empty
//! slots kept (`MCALL CYCLE83(10,0,5,,20,,4)`), DEF, GOTOF/GOTOB and
//! subprogram calls `L123 P2` / `NAME(args)`.

use super::flow;
use super::number::NumKind;
use super::writer::Writer;
use crate::ir::{
    Arg, CallArgs, CallKind, CallTarget, CycleCall, ExprId, JumpDir, JumpTarget, Value, VarDecl,
    VarType,
};
use crate::span::Span;

pub fn message(w: &mut Writer<'_>, text: Option<&str>, span: Span, words: &mut Vec<String>) {
    match text {
        None => words.push("MSG()".to_string()),
        Some(t) => {
            let t = w.safe_message(t, crate::dialect::text::TextForm::Quoted, span);
            words.push(format!("MSG(\"{t}\")"))
        }
    }
}

pub fn program_start(
    w: &mut Writer<'_>,
    number: Option<u32>,
    name: Option<&str>,
    span: Span,
    words: &mut Vec<String>,
) {
    // A file name: letters, digits and `_` only.
    let base = match (name, number) {
        (Some(n), _) => n
            .chars()
            .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
            .collect(),
        (None, Some(n)) => format!("O{n}"),
        (None, None) => {
            return w.cannot(span, "a program start without a name", "name the program")
        }
    };
    let upper = base.to_ascii_uppercase();
    if upper.ends_with("_MPF") || upper.ends_with("_SPF") {
        words.push(format!("%_N_{base}"));
    } else {
        words.push(format!("%_N_{base}_MPF"));
    }
}

/// Positional arguments, empty slots kept: `10,0,5,,20`.
fn args_text(w: &mut Writer<'_>, args: impl Iterator<Item = Option<ExprId>>) -> Option<String> {
    let mut parts = Vec::new();
    let mut ok = true;
    for a in args {
        match a.map(|e| w.expr(e)) {
            None => parts.push(String::new()),
            Some(Some(s)) => parts.push(s),
            Some(None) => ok = false,
        }
    }
    ok.then(|| parts.join(","))
}

pub fn command(w: &mut Writer<'_>, name: &str, args: Option<&[Arg]>, words: &mut Vec<String>) {
    match args {
        None => words.push(name.to_string()),
        Some(a) => {
            if let Some(t) = args_text(w, a.iter().map(|a| a.value)) {
                words.push(format!("{name}({t})"));
            }
        }
    }
}

pub fn cycle_call(w: &mut Writer<'_>, c: &CycleCall, words: &mut Vec<String>) {
    let Some(t) = args_text(w, c.args.iter().map(|a| a.value)) else {
        return;
    };
    let call = format!("{}({t})", c.name);
    words.push(if c.modal {
        format!("MCALL {call}")
    } else {
        call
    });
}

fn type_name(ty: VarType) -> &'static str {
    match ty {
        VarType::Real => "REAL",
        VarType::Int => "INT",
        VarType::Bool => "BOOL",
        VarType::Char => "CHAR",
        VarType::String => "STRING",
        VarType::Axis => "AXIS",
        VarType::Frame => "FRAME",
    }
}

/// `DEF REAL A, B=2.5, T[3,4]`; `DEF STRING[32] S`.
pub fn declare(w: &mut Writer<'_>, ty: VarType, vars: &[VarDecl], words: &mut Vec<String>) {
    let mut head = format!("DEF {}", type_name(ty));
    let string_len = ty == VarType::String;
    if string_len {
        if let Some(v) = vars.first().filter(|v| !v.dims.is_empty()) {
            head.push_str(&format!("[{}]", v.dim_text(0)));
        }
    }
    let mut parts = Vec::new();
    for v in vars {
        let mut s = v.name.clone();
        // A STRING's first "dimension" is its length, written after DEF.
        let first = string_len as usize;
        if v.dims.len() > first {
            let dims: Vec<String> = (first..v.dims.len()).map(|i| v.dim_text(i)).collect();
            s.push_str(&format!("[{}]", dims.join(",")));
        }
        if let Some(init) = v.init {
            let Some(e) = w.expr(init) else { return };
            s.push_str(&format!("={e}"));
        }
        parts.push(s);
    }
    words.push(format!("{head} {}", parts.join(", ")));
}

pub fn goto(
    w: &mut Writer<'_>,
    target: &JumpTarget,
    dir: JumpDir,
    cond: Option<ExprId>,
    span: Span,
    words: &mut Vec<String>,
) {
    let dest = match target {
        JumpTarget::Label(l) => l.clone(),
        JumpTarget::Sequence(Value::Number(d)) => match w.num(*d, NumKind::Int, span) {
            Some(n) => format!("N{n}"),
            None => return,
        },
        JumpTarget::Sequence(Value::Expr(_)) => {
            return w.cannot(span, "a jump to a computed block number", "jump to a label");
        }
    };
    let mut out = Vec::new();
    if let Some(c) = cond {
        let Some(c) = flow::cond(w, c) else { return };
        out.extend(["IF".to_string(), c]);
    }
    out.extend([flow::jump_kw(dir).to_string(), dest]);
    words.extend(out);
}

/// `L123 P2`, `L140(2)`, `NAME(1,,3)`, `NAME P3`.
pub fn call(
    w: &mut Writer<'_>,
    kind: CallKind,
    target: &CallTarget,
    args: &CallArgs,
    repeat: Option<&Value>,
    span: Span,
    words: &mut Vec<String>,
) {
    match kind {
        CallKind::Subprogram | CallKind::Named | CallKind::OWord => {}
        CallKind::Local | CallKind::Macro | CallKind::ModalMacro | CallKind::Label => {
            let what = format!("a {kind:?} call");
            return w.cannot(span, &what, "call a subprogram by name (PROC) instead");
        }
    }
    let name = match target {
        CallTarget::Number(n) => format!("L{n}"),
        CallTarget::Name(n) => n.clone(),
        CallTarget::Computed(_) => {
            return w.cannot(
                span,
                "a call to a computed program number",
                "call the subprogram by name",
            )
        }
    };
    let call = match args {
        CallArgs::None => name,
        CallArgs::Positional(list) => match args_text(w, list.iter().copied()) {
            Some(t) => format!("{name}({t})"),
            None => return,
        },
        CallArgs::Letters(_) => {
            return w.cannot(
                span,
                "letter arguments (G65 style)",
                "declare the parameters in a PROC and pass them positionally",
            )
        }
    };
    words.push(call);
    if let Some(r) = repeat {
        w.push_word(words, "P", r, NumKind::Int, span);
    }
}
