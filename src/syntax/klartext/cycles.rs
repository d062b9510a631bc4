//! Cycles to items: `CYCL DEF` (numbered cycles with their
//! `Qnnn=value ;LABEL` lines, checked against the spec's cycle table, and
//! old-style sub-numbered lines), `CYCL CALL [POS|PAT]`, `PATTERN DEF`.

use super::build::{Ctx, Operand, WordNode};
use super::lexer::Spanned3;
use super::token::Tok;
use crate::diag::{Code, Diagnostic};
use crate::ir::{CycleDef, CycleLine, CycleRunKind, PatternItem, QParam, StmtKind, Var};
use crate::syntax::Item;

/// `CYCL DEF ...` from the tokens at `from`.
pub fn cycl_def(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let Some((nl, Tok::Num(num), nr)) = toks.first().cloned() else {
        ctx.error(
            Code::KlartextBadCycle,
            l,
            r,
            "CYCL DEF without a cycle number",
            "write `CYCL DEF 200 DRILLING` or `CYCL DEF 7.0 DATUM SHIFT`",
        );
        return Vec::new();
    };
    let mut text = ctx.slice(nl, nr).to_string();
    let mut toks = toks;
    // `CYCL DEF9 .0` (a post's spacing): the sub-number after a space.
    if let Some((_, Tok::Num(_), sr)) = toks.get(1).cloned() {
        let sub = ctx.slice(toks[1].0, sr).to_string();
        if !text.contains('.') && sub.starts_with('.') {
            text.push_str(&sub);
            toks.remove(1);
        }
    }
    if let Some((c, sub)) = text.split_once('.') {
        let (Ok(cycle), Ok(sub)) = (c.parse::<u32>(), sub.parse::<u32>()) else {
            ctx.error(
                Code::KlartextBadCycle,
                nl,
                nr,
                format!("`{text}` is not a cycle number"),
                "old-style cycles are numbered n.m (7.0, 7.1)",
            );
            return Vec::new();
        };
        return match ctx.cycle_words(&toks[1..]) {
            Some(words) => {
                let k = StmtKind::CycleLine(Box::new(CycleLine { cycle, sub, words }));
                vec![ctx.stmt(k, l, r)]
            }
            None => vec![kept(ctx, l, r)],
        };
    }
    let number = num.as_int().unwrap_or(0).clamp(0, 99_999) as u32;
    // The name runs up to the first parameter (`TAPPING W/ CHIP BRKG`).
    let mut i = 1;
    while i < toks.len() && !matches!(toks[i].1, Tok::Q(..)) {
        i += 1;
    }
    let name_end = toks.get(i).map(|t| t.0).unwrap_or(ctx.end());
    let name: Vec<String> = ctx
        .slice(nr, name_end)
        .split_whitespace()
        .map(String::from)
        .collect();
    let mut params = Vec::new();
    while i < toks.len() {
        let Some(p) = q_param(ctx, &toks, &mut i) else {
            let (a, _, b) = toks[i].clone();
            ctx.error(
                Code::KlartextBadCycle,
                a,
                b,
                "expected a cycle parameter `Qnnn=value`",
                "write one `Qnnn=value` per parameter",
            );
            break;
        };
        params.push(p);
    }
    missing_params(ctx, number, &params, l, r);
    let def = CycleDef {
        number,
        name: name.join(" "),
        params,
    };
    vec![ctx.stmt(StmtKind::CycleDef(Box::new(def)), l, r)]
}

/// E0320: the parameters the spec lists for the cycle that are not given.
fn missing_params(ctx: &mut Ctx<'_>, number: u32, params: &[QParam], l: usize, r: usize) {
    let Some(sig) = ctx.spec.cycle(&number.to_string()) else {
        ctx.diags.push(
            Diagnostic::new(Code::CannotExpandCycle, format!("cycle {number} is not in the dialect's cycle table"))
                .primary(ctx.span(l, r), "kept with its parameters, not checked")
                .help("its Q parameters are kept as written; it cannot be run or mapped to another control"),
        );
        return;
    };
    let missing: Vec<String> = sig
        .params
        .iter()
        .filter(|p| !params.iter().any(|q| format!("Q{}", q.q) == p.name))
        .map(|p| format!("{} ({})", p.name, p.doc))
        .collect();
    if !missing.is_empty() && params.is_empty() && !sig.params.is_empty() {
        // None at all: the parameter lines were not joined to the block.
        let d = Diagnostic::new(
            Code::KlartextCycleMissingParameter,
            format!("CYCL DEF {number} has none of its parameters: its line does not end with `~`"),
        )
        .primary(ctx.span(l, r), "the block ends here")
        .help(format!(
            "a CYCL DEF goes on over the next lines only when each line but its last ends with `~` (`CYCL DEF {number} ... ~`, then `Q200=2 ;... ~`); without it the Q lines after it are separate blocks and cycle {number} lacks {}",
            sig.params.iter().map(|p| p.name.as_str()).collect::<Vec<_>>().join(" ")
        ));
        ctx.diags.push(d);
        return;
    }
    if !missing.is_empty() {
        let d = Diagnostic::new(
            Code::KlartextCycleMissingParameter,
            format!(
                "CYCL DEF {number} lacks {}",
                if missing.len() == 1 {
                    "a parameter"
                } else {
                    "parameters"
                }
            ),
        )
        .primary(ctx.span(l, r), format!("missing: {}", missing.join(", ")))
        .help(format!(
            "cycle {number} takes {}; add one `Qnnn=value` line for each (a parameter line belongs to the block only when the line before it ends with `~`)",
            sig.params
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>()
                .join(" ")
        ));
        ctx.diags.push(d);
    }
}

/// `Q200=+2 ;SET-UP CLEARANCE`, `Q206=Q2`.
fn q_param(ctx: &mut Ctx<'_>, toks: &[Spanned3], i: &mut usize) -> Option<QParam> {
    let (l, Tok::Q(crate::ir::QBank::Q, q), _) = toks.get(*i).cloned()? else {
        return None;
    };
    if toks.get(*i + 1).map(|t| &t.1) != Some(&Tok::Eq) {
        return None;
    }
    let mut j = *i + 2;
    let sign = match toks.get(j).map(|t| &t.1) {
        Some(Tok::Plus) => Some('+'),
        Some(Tok::Minus) => Some('-'),
        _ => None,
    };
    if sign.is_some() {
        j += 1;
    }
    let (a, t, b) = toks.get(j).cloned()?;
    let op = match t {
        Tok::Num(d) => Operand::Num(d, a, b),
        Tok::Q(bank, n) => Operand::Expr(ctx.var(Var::Q(bank, n), a, b)),
        _ => return None,
    };
    *i = j + 1;
    let value = ctx.value(&(sign, op));
    let next = toks.get(*i).map(|t| t.0).unwrap_or(usize::MAX);
    let label = ctx
        .comments
        .iter()
        .position(|c| c.start >= b && c.start < next)
        .map(|k| {
            ctx.used_comments.push(k);
            ctx.comments[k].text.clone()
        });
    Some(QParam {
        q,
        value,
        label,
        span: ctx.span(l, b),
    })
}

/// A block kept as text, with a W0005 warning.
pub(super) fn kept(ctx: &mut Ctx<'_>, l: usize, r: usize) -> Item {
    let text = ctx.slice(l, r).trim().to_string();
    ctx.diags.push(
        Diagnostic::new(Code::KeptAsText, format!("`{text}` is kept as text"))
            .primary(ctx.span(l, r), "not understood, only kept")
            .help("it is written back unchanged to Heidenhain and cannot be run or translated"),
    );
    ctx.stmt(
        StmtKind::Raw {
            dialect: ctx.spec.id.clone(),
            text,
        },
        l,
        r,
    )
}

/// `CYCL CALL`, `CYCL CALL POS X.. Y.. Z..`, `CYCL CALL PAT`, with F and M.
pub fn cycl_call(ctx: &mut Ctx<'_>, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let mut out = Vec::new();
    let mut how = CycleRunKind::Call;
    let mut axes = crate::ir::Axes::default();
    let mut pos = false;
    let mut pat = false;
    let mut rapid = false;
    for w in words {
        let v = ctx.word_value(w);
        match (w.name.as_str(), v) {
            ("POS", None) => pos = true,
            ("PAT", None) => pat = true,
            // Positioning between the points at rapid (the interpreter
            // positions at rapid either way) [?: the TNC manuals show F and
            // FMAX here; without either the control's default applies].
            ("FMAX", None) if pos || pat => rapid = true,
            ("F", Some(v)) => out.push(ctx.stmt(StmtKind::Feed(v), w.l, w.r)),
            ("M", Some(v)) => out.extend(super::path::m_function(ctx, w, v)),
            (n, Some(v)) if pos && n.len() == 1 && "XYZABCUVW".contains(n) => {
                let c = crate::ir::Coord {
                    value: v,
                    dim: None,
                    span: ctx.span(w.l, w.r),
                };
                if let Some(s) = axes.slot_mut(n.chars().next().unwrap_or('X')) {
                    *s = Some(c);
                }
            }
            (n, _) => ctx.error(
                Code::KlartextWordNotAllowed,
                w.l,
                w.r,
                format!("CYCL CALL does not take `{n}` here"),
                "CYCL CALL takes POS with axes, PAT, F (FMAX with POS or PAT) and M",
            ),
        }
    }
    if pos {
        how = CycleRunKind::Pos {
            axes: Box::new(axes),
            rapid,
        };
    } else if pat {
        how = CycleRunKind::Pattern { rapid };
    }
    out.insert(0, ctx.stmt(StmtKind::CycleRun(how), l, r));
    out
}

/// `PATTERN DEF ~ POS1 (X+25 Y+33.5 Z+0) ~ ...`.
pub fn pattern_def(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let mut items = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (a, Tok::Name(n), _) = toks[i].clone() else {
            return vec![kept(ctx, l, r)];
        };
        let mut name = n;
        i += 1;
        if let Some((_, Tok::Num(d), _)) = toks.get(i) {
            name.push_str(&d.format(0, false));
            i += 1;
        }
        if toks.get(i).map(|t| &t.1) != Some(&Tok::LParen) {
            return vec![kept(ctx, l, r)];
        }
        let Some(close) = toks[i..]
            .iter()
            .position(|t| t.1 == Tok::RParen)
            .map(|k| k + i)
        else {
            return vec![kept(ctx, l, r)];
        };
        let Some(words) = ctx.cycle_words(&toks[i + 1..close]) else {
            return vec![kept(ctx, l, r)];
        };
        let b = toks[close].2;
        items.push(PatternItem {
            name,
            words,
            span: ctx.span(a, b),
        });
        i = close + 1;
    }
    vec![ctx.stmt(StmtKind::PatternDef(items), l, r)]
}

/// `TCH PROBE 417 DATUM IN TS AXIS ~ Q263=-22.5 ;.. ~ ...` (and the old
/// `TCH PROBE 0.0 REF. PLANE Z+`): a touch probe cycle, kept with its text
/// (written back as read); its number must follow `PROBE`.
pub fn tch_probe(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let (number, nr) = match (toks.first(), toks.get(1)) {
        (Some((_, Tok::Name(p), _)), Some((nl, Tok::Num(_), nr))) if p == "PROBE" => {
            (ctx.slice(*nl, *nr).to_string(), *nr)
        }
        _ => {
            ctx.error(
                Code::KlartextBadCycle,
                l,
                r,
                "TCH without `PROBE` and a cycle number",
                "write `TCH PROBE 417 DATUM IN TS AXIS` with its Q parameters",
            );
            return Vec::new();
        }
    };
    // The name runs up to the first parameter, as in CYCL DEF.
    let mut i = 2;
    while i < toks.len() && !matches!(toks[i].1, Tok::Q(..)) {
        i += 1;
    }
    let name_end = toks.get(i).map(|t| t.0).unwrap_or(r);
    let mut text = format!("TCH PROBE {number}");
    for w in ctx.slice(nr, name_end).split_whitespace() {
        text.push(' ');
        text.push_str(w);
    }
    // Each `Qnnn=value ;label` on a line of its own, `~` between them.
    while i < toks.len() {
        let start = toks[i].0;
        let Some(p) = q_param(ctx, &toks, &mut i) else {
            let (a, _, b) = toks[i].clone();
            ctx.error(
                Code::KlartextBadCycle,
                a,
                b,
                "expected a probing cycle parameter `Qnnn=value`",
                "write one `Qnnn=value` per parameter",
            );
            return Vec::new();
        };
        let end = toks[i - 1].2;
        text.push_str(&format!(" ~\n  {}", ctx.slice(start, end).replace(' ', "")));
        if let Some(t) = &p.label {
            text.push_str(&format!(" ;{t}"));
        }
    }
    let f = crate::ir::TncFunction {
        text,
        kind: crate::ir::TncFunctionKind::TouchProbe(number),
    };
    vec![ctx.stmt(StmtKind::TncFunction(Box::new(f)), l, r)]
}
