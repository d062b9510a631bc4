//! FN 14..20 function blocks, `PLANE` and the FK free contour blocks to
//! [`TncFunction`] statements (their meaning, and their text for the
//! Klartext writer).
//!
//! * `FN 14: ERROR= n` → `Error`; `FN 15: PRINT` items → `Print`;
//!   `FN 16: F-PRINT mask/output` → `FormattedPrint`;
//!   `FN 18: SYSREAD Qn = IDg NRn IDXi` → `SysRead`;
//!   `FN 17: SYSWRITE`, `FN 19: PLC`, `FN 20: WAIT FOR` → `MachineOnly`.
//!   Other FN numbers (table functions 26..28, ...) stay kept text.
//! * `PLANE RESET|SPATIAL|PROJECTED|EULER|VECTOR|POINTS|RELATIV|AXIAL`
//!   with its values and `MOVE|TURN|STAY` → `Plane`.
//! * `FL`, `FLT`, `FC`, `FCT`, `FPOL`, `FSELECT` → `FreeContour`.
//!
//! Sources: `reference/dialects.md` §2.5/2.6; the FN 18 data numbers
//! from the TNC technical manuals' system data table.

use super::build::{Ctx, WordNode};
use super::cycles::kept;
use super::lexer::Spanned3;
use super::token::Tok;
use crate::diag::Code;
use crate::ir::{
    Decimal, PrintItem, StmtKind, TiltPlane, TncFunction, TncFunctionKind, Value, Var,
};
use crate::syntax::Item;

/// The FK free contour keywords.
pub(super) const FREE_CONTOUR: [&str; 7] = ["FL", "FLT", "FC", "FCT", "FPOL", "FSELECT", "FLN"];

/// `PLANE`, `FUNCTION` and the FK keywords start blocks the grammar reads
/// as words.
pub(super) fn starts_block(name: &str) -> bool {
    name == "PLANE" || name == "FUNCTION" || FREE_CONTOUR.contains(&name)
}

fn item(ctx: &Ctx<'_>, kind: TncFunctionKind, l: usize, r: usize) -> Item {
    let text = ctx.slice(l, r).trim().to_string();
    let f = TncFunction { text, kind };
    ctx.stmt(StmtKind::TncFunction(Box::new(f)), l, r)
}

fn bad(ctx: &mut Ctx<'_>, l: usize, r: usize, n: u32, form: &str) -> Vec<Item> {
    ctx.error(
        Code::KlartextBadFunction,
        l,
        r,
        format!("this is not the form of FN {n}"),
        &format!("write `{form}`"),
    );
    Vec::new()
}

/// `FN 14..20: ...`; `at` is where the part after the colon starts.
pub fn fn_other(ctx: &mut Ctx<'_>, n: Decimal, at: usize, l: usize, r: usize) -> Vec<Item> {
    let n = n.as_int().unwrap_or(-1);
    let toks: Vec<Spanned3> = ctx.toks_from(at).to_vec();
    let kw = match toks.first() {
        Some((_, Tok::Name(k), _)) => k.clone(),
        _ => String::new(),
    };
    let kind = match (n, kw.as_str()) {
        (14, "ERROR") => error(ctx, &toks[1..]),
        (15, "PRINT") => Some(print(ctx, &toks[1..])),
        (16, "F") if matches!(toks.get(2), Some((_, Tok::Name(p), _)) if p == "PRINT") => {
            let from = toks[2].2;
            let spec = ctx.slice(from, ctx.end()).trim().to_string();
            Some(TncFunctionKind::FormattedPrint { spec })
        }
        (18, "SYSREAD") => sysread(ctx, &toks[1..]),
        (17, "SYSWRITE") | (19, "PLC") | (20, "WAIT") => {
            Some(TncFunctionKind::MachineOnly(n as u32))
        }
        (14..=20, _) => None,
        _ => return vec![kept(ctx, l, r)],
    };
    match kind {
        Some(k) => vec![item(ctx, k, l, r)],
        None => {
            let form = match n {
                14 => "FN 14: ERROR= n",
                15 => "FN 15: PRINT +Q1 \"text\"",
                16 => "FN 16: F-PRINT mask/output",
                17 => "FN 17: SYSWRITE ID.. NR.. IDX.. = value",
                18 => "FN 18: SYSREAD Q1 = ID270 NR1 IDX3",
                19 => "FN 19: PLC= value/value",
                _ => "FN 20: WAIT FOR ...",
            };
            bad(ctx, l, r, n as u32, form)
        }
    }
}

/// A signed number or Q parameter at the start of `toks`: the value and
/// how many tokens it took.
fn operand(ctx: &mut Ctx<'_>, toks: &[Spanned3]) -> Option<(Value, usize)> {
    let (neg, skip) = match toks.first() {
        Some((_, Tok::Minus, _)) => (true, 1),
        Some((_, Tok::Plus, _)) => (false, 1),
        _ => (false, 0),
    };
    let v = match toks.get(skip) {
        Some((_, Tok::Num(d), _)) => Value::Number(if neg { d.neg() } else { *d }),
        Some((a, Tok::Q(bank, q), b)) => {
            let e = ctx.var(Var::Q(*bank, *q), *a, *b);
            let e = if neg {
                ctx.unary(crate::ir::UnaryOp::Neg, e, *a, *b)
            } else {
                e
            };
            Value::Expr(e)
        }
        _ => return None,
    };
    Some((v, skip + 1))
}

/// `ERROR= n`.
fn error(ctx: &mut Ctx<'_>, toks: &[Spanned3]) -> Option<TncFunctionKind> {
    let rest = match toks.first() {
        Some((_, Tok::Eq, _)) => &toks[1..],
        _ => toks,
    };
    let (v, used) = operand(ctx, rest)?;
    (used == rest.len()).then_some(TncFunctionKind::Error(v))
}

/// `PRINT +Q1 "text" 5`: texts, numbers and Q parameters.
fn print(ctx: &mut Ctx<'_>, toks: &[Spanned3]) -> TncFunctionKind {
    let mut items = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        if let Tok::Str(s) = &toks[i].1 {
            items.push(PrintItem::Text(s.clone()));
            i += 1;
            continue;
        }
        match operand(ctx, &toks[i..]) {
            Some((v, used)) => {
                items.push(PrintItem::Value(v));
                i += used;
            }
            None => {
                // Separators and words: kept as the text they are.
                let (a, _, b) = toks[i];
                items.push(PrintItem::Text(ctx.slice(a, b).to_string()));
                i += 1;
            }
        }
    }
    TncFunctionKind::Print(items)
}

/// `Q23 = ID270 NR1 IDX3`.
fn sysread(ctx: &mut Ctx<'_>, toks: &[Spanned3]) -> Option<TncFunctionKind> {
    let var = match toks.first() {
        Some((_, Tok::Q(bank, n), _)) => Var::Q(*bank, *n),
        _ => return None,
    };
    if !matches!(toks.get(1), Some((_, Tok::Eq, _))) {
        return None;
    }
    let (mut id, mut nr, mut idx) = (None, None, None);
    let mut i = 2;
    while i < toks.len() {
        let Tok::Name(name) = &toks[i].1 else {
            return None;
        };
        let name = name.clone();
        let (v, used) = operand(ctx, &toks[i + 1..])?;
        i += 1 + used;
        let whole = |v: &Value| match v {
            Value::Number(d) => d.as_int().and_then(|n| u32::try_from(n).ok()),
            Value::Expr(_) => None,
        };
        match name.as_str() {
            "ID" => id = Some(whole(&v)?),
            "NR" => nr = Some(whole(&v)?),
            "IDX" => idx = Some(v),
            _ => return None,
        }
    }
    Some(TncFunctionKind::SysRead {
        var,
        id: id?,
        nr: nr?,
        idx,
    })
}

/// The definition words each PLANE kind takes.
fn plane_words(how: &str) -> Option<&'static [&'static str]> {
    Some(match how {
        "RESET" => &[],
        "SPATIAL" | "RELATIV" => &["SPA", "SPB", "SPC"],
        "PROJECTED" => &["PROPR", "PROMIN", "PROROT", "ROT"],
        "EULER" => &["EULPR", "EULNU", "EULROT"],
        "VECTOR" => &["BX", "BY", "BZ", "NX", "NY", "NZ"],
        "AXIAL" => &["A", "B", "C"],
        // [?] P1X.. P3Z are read as words whose values are not kept.
        "POINTS" => &["P", "X", "Y", "Z"],
        _ => return None,
    })
}

/// Positioning words that may follow: how, speed, order.
const PLANE_TAIL: [&str; 12] = [
    "MOVE", "TURN", "STAY", "MB", "MAX", "FMAX", "F", "DIST", "SEQ", "TABLE", "COORD", "ROT",
];

/// `PLANE ...`, or an FK block: a block the grammar read as words.
pub fn word_block(ctx: &mut Ctx<'_>, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let first = words[0].name.clone();
    if first == "FUNCTION" {
        return function(ctx, words, l, r);
    }
    if first != "PLANE" {
        return vec![item(ctx, TncFunctionKind::FreeContour(first), l, r)];
    }
    let Some(how) = words
        .get(1)
        .filter(|w| w.value.is_none() && w.sign.is_none())
    else {
        ctx.error(
            Code::KlartextBadPlane,
            l,
            r,
            "PLANE needs how the plane is defined",
            "write `PLANE RESET STAY` or `PLANE SPATIAL SPA+0 SPB+0 SPC+0 STAY`",
        );
        return Vec::new();
    };
    let Some(takes) = plane_words(&how.name) else {
        let (a, b) = (how.l, how.r);
        ctx.error(
            Code::KlartextBadPlane,
            a,
            b,
            format!("`PLANE {}` is not a PLANE function", how.name),
            "PLANE RESET, SPATIAL, PROJECTED, EULER, VECTOR, POINTS, RELATIV or AXIAL",
        );
        return Vec::new();
    };
    let mut plane = TiltPlane {
        how: how.name.clone(),
        values: Vec::new(),
        positioning: None,
    };
    let mut ok = true;
    for w in &words[2..] {
        let n = w.name.as_str();
        if matches!(n, "MOVE" | "TURN" | "STAY") {
            plane.positioning = Some(n.to_string());
        } else if takes.contains(&n) && w.value.is_some() && plane.positioning.is_none() {
            if let Some(v) = ctx.word_value(w) {
                plane.values.push((n.to_string(), v));
            }
        } else if !PLANE_TAIL.contains(&n) {
            ctx.error(
                Code::KlartextBadPlane,
                w.l,
                w.r,
                format!("`{n}` is not a word of PLANE {}", plane.how),
                "give the plane's values, then MOVE, TURN or STAY (with MB, FMAX/F, DIST, SEQ)",
            );
            ok = false;
        }
    }
    if !ok {
        return Vec::new();
    }
    vec![item(ctx, TncFunctionKind::Plane(Box::new(plane)), l, r)]
}

/// `FUNCTION TCPM ...`, `FUNCTION RESET TCPM`, `FUNCTION MODE MILL` ...:
/// kept with its words; the run decides what it can do with them.
fn function(ctx: &mut Ctx<'_>, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let Some(second) = words.get(1) else {
        ctx.error(
            Code::KlartextMissingWord,
            l,
            r,
            "FUNCTION needs the function it selects",
            "write `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS` or `FUNCTION RESET TCPM`",
        );
        return Vec::new();
    };
    let what = ctx.slice(second.l, r);
    let what = what.split_whitespace().collect::<Vec<_>>().join(" ");
    vec![item(
        ctx,
        TncFunctionKind::Function(what.to_ascii_uppercase()),
        l,
        r,
    )]
}

/// `M140 MB MAX` / `M140 MB+50`, with the `F` that follows: the retract
/// in the tool axis. `at` is the index of `MB` in `words`, `m` where the
/// M function before it starts (it is part of the item); returns the
/// item and how many words it took.
pub(super) fn retract(
    ctx: &mut Ctx<'_>,
    words: &[WordNode],
    at: usize,
    m: Option<usize>,
) -> (Option<Item>, usize) {
    let mb = &words[at];
    let mut used = 1;
    let distance = match (ctx.word_value(mb), words.get(at + 1)) {
        (Some(v), _) => Some(v),
        (None, Some(w)) if w.name == "MAX" && w.value.is_none() => {
            used += 1;
            None
        }
        _ => {
            ctx.error(
                Code::KlartextMissingWord,
                mb.l,
                mb.r,
                "`MB` needs the retract distance or MAX",
                "write `M140 MB MAX` (to the end of travel) or `M140 MB 50`",
            );
            return (None, 1);
        }
    };
    let mut r = words[at + used - 1].r;
    if let Some(f) = words
        .get(at + used)
        .filter(|w| w.name == "F" || w.name == "FMAX")
    {
        used += 1;
        r = f.r;
    }
    let kind = TncFunctionKind::Retract(distance);
    (Some(item(ctx, kind, m.unwrap_or(mb.l), r)), used)
}
