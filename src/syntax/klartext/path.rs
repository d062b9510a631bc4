//! Path blocks to items: `L`, `C`, `CC`, `CR`, `CT`, `LP`, `CP`, `CTP`,
//! `RND`, `CHF`, `APPR`/`DEP`, and the words every block shares.
//!
//! `L` is a linear move, or a rapid with `FMAX`; `C` an arc round the pole
//! (no centre words: the interpreter takes the pole); `CR` an arc by
//! radius; `CT`/`CTP` tangent arcs; `LP`/`CP` polar (`PR`/`PA`, with `I`:
//! incremental, kept as `IC(..)` around the value). `RL`/`RR`/`R0` become
//! radius compensation, `F` a feed, `M` words go to the shared lowering
//! (the spec's code table); `M99`/`M89` are cycle calls.

use super::build::{Ctx, Signed, WordNode};
use super::token::Kw;
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    ApproachKind, ArcDir, Axes, CompSide, Coord, CornerKind, CycleRunKind, DimMode, ExprKind,
    Motion, MotionKind, SpindleState, StmtKind, Value,
};
use crate::syntax::Item;

pub(super) const AXES: [&str; 9] = ["X", "Y", "Z", "A", "B", "C", "U", "V", "W"];

/// What the words of a path block said besides axes.
#[derive(Default)]
pub(super) struct Said {
    pub(super) axes: Axes,
    rapid: bool,
    dir: Option<ArcDir>,
    pub(super) radius: Option<Value>,
    polar_r: Option<Value>,
    polar_a: Option<Value>,
    pub(super) len: Option<Value>,
    pub(super) cca: Option<Value>,
    pub(super) kind: Option<ApproachKind>,
    pos: bool,
    pat: bool,
    pub(super) items: Vec<Item>,
}

/// Reads a block's words; `allowed` lists the non-axis words it takes.
pub(super) fn read_words(
    ctx: &mut Ctx<'_>,
    words: &[WordNode],
    allowed: &[&str],
    axes_ok: bool,
) -> Said {
    let mut s = Said::default();
    let mut i = 0;
    while i < words.len() {
        let w = &words[i];
        i += 1;
        let n = w.name.as_str();
        if n == "MB" && allowed.contains(&"M") {
            // `MB` belongs to the M function written just before it.
            let m = match s.items.last() {
                Some(Item::Word(m)) if m.address.as_bytes() == b"M" => Some(m.span.range().start),
                _ => None,
            };
            if m.is_some() {
                s.items.pop();
            }
            let (item, used) = super::functions::retract(ctx, words, i - 1, m);
            s.items.extend(item);
            i += used - 1;
            continue;
        }
        let incr = n.len() == 2 && n.starts_with('I') && AXES.contains(&&n[1..]);
        if axes_ok && (AXES.contains(&n) || incr) {
            let Some(v) = ctx.word_value(w) else {
                ctx.error(
                    Code::KlartextAxisWithoutValue,
                    w.l,
                    w.r,
                    format!("the axis word `{n}` has no coordinate"),
                    "write the coordinate after the axis letter: `X+10`, `IZ-2`",
                );
                continue;
            };
            let letter = n.chars().last().unwrap_or('X');
            let c = Coord {
                value: v,
                dim: incr.then_some(DimMode::Incremental),
                span: ctx.span(w.l, w.r),
            };
            if let Some(slot) = s.axes.slot_mut(letter) {
                *slot = Some(c);
            }
            continue;
        }
        if axes_ok && not_a_number(ctx, w) {
            continue;
        }
        let r_word = n == "R" && allowed.contains(&"R0");
        if !allowed.contains(&n) && !r_word {
            ctx.error(
                Code::KlartextWordNotAllowed,
                w.l,
                w.r,
                format!("`{n}` is not a word this block takes"),
                "remove the word or move it to a block that takes it",
            );
            continue;
        }
        word(ctx, w, n, &mut s, allowed.contains(&"R"));
    }
    s
}

/// `Xnan`, `Yinf`: a post that computed no coordinate wrote the float's
/// text; a located E0121 naming it (true when reported).
fn not_a_number(ctx: &mut Ctx<'_>, w: &WordNode) -> bool {
    let n = w.name.as_str();
    let Some(bad) = ["NAN", "INF", "INFINITY"].into_iter().find(|b| {
        n.strip_suffix(b)
            .is_some_and(|a| AXES.contains(&a.trim_start_matches('I')))
    }) else {
        return false;
    };
    let axis = &n[..n.len() - bad.len()];
    ctx.error(
        Code::KlartextAxisWithoutValue,
        w.l,
        w.r,
        format!("the coordinate of `{axis}` is `{}`: not a number", bad.to_ascii_lowercase()),
        "the post-processor computed no value here and wrote its float's text; regenerate the program (check the operation's geometry in the CAM system)",
    );
    true
}

fn word(ctx: &mut Ctx<'_>, w: &WordNode, n: &str, s: &mut Said, radius_ok: bool) {
    let v = ctx.word_value(w);
    let (l, r) = (w.l, w.r);
    let comp = |side| StmtKind::RadiusComp {
        side,
        register: None,
        diameter: false,
    };
    match (n, v) {
        // `R0`: compensation off (a radius is never 0 and unsigned).
        ("R", Some(Value::Number(d))) if d.as_int() == Some(0) && w.sign.is_none() => {
            s.items.push(ctx.stmt(comp(CompSide::Off), l, r))
        }
        ("R", Some(v)) if radius_ok => s.radius = Some(v),
        // `R+`/`R-`: paraxial (the block's axis checked in [`path`]).
        ("R", None) if w.sign.is_some() && !radius_ok => {
            let f = crate::ir::TncFunction {
                text: format!("R{}", w.sign.unwrap_or('+')),
                kind: crate::ir::TncFunctionKind::Paraxial(w.sign == Some('+')),
            };
            s.items
                .push(ctx.stmt(StmtKind::TncFunction(Box::new(f)), l, r))
        }
        ("R", Some(_)) => ctx.error(
            Code::KlartextWordNotAllowed,
            l,
            r,
            "`R` with a value is not a word this block takes",
            "radius compensation is R0, RL or RR; paraxial R+/R- blocks are not supported",
        ),
        ("RL", None) => s.items.push(ctx.stmt(comp(CompSide::Left), l, r)),
        ("RR", None) => s.items.push(ctx.stmt(comp(CompSide::Right), l, r)),
        ("R0", _) => s.items.push(ctx.stmt(comp(CompSide::Off), l, r)),
        ("F", Some(v)) => s.items.push(ctx.stmt(StmtKind::Feed(v), l, r)),
        ("FMAX", None) => s.rapid = true,
        ("FAUTO", None) => {
            fauto_kept(ctx, l, r);
            s.items.push(ctx.stmt(
                StmtKind::Raw {
                    dialect: ctx.spec.id.clone(),
                    text: "FAUTO".into(),
                },
                l,
                r,
            ));
        }
        ("M", Some(v)) => match v.number().and_then(|d| d.as_int()) {
            Some(99) => s
                .items
                .push(ctx.stmt(StmtKind::CycleRun(CycleRunKind::Block), l, r)),
            Some(89) => s
                .items
                .push(ctx.stmt(StmtKind::CycleRun(CycleRunKind::Modal), l, r)),
            _ => s.items.extend(m_function(ctx, w, v)),
        },
        ("DR", None) => {
            s.dir = Some(if w.sign == Some('-') {
                ArcDir::Cw
            } else {
                ArcDir::Ccw
            })
        }
        ("PR", Some(v)) => s.polar_r = Some(v),
        ("IPR", Some(v)) => s.polar_r = Some(incremental(ctx, v, l, r)),
        ("PA", Some(v)) => s.polar_a = Some(v),
        ("IPA", Some(v)) => s.polar_a = Some(incremental(ctx, v, l, r)),
        ("LEN", Some(v)) => s.len = Some(v),
        ("CCA", Some(v)) => s.cca = Some(v),
        ("LT", None) => s.kind = Some(ApproachKind::LineTangent),
        ("LN", None) => s.kind = Some(ApproachKind::LineNormal),
        ("CT", None) => s.kind = Some(ApproachKind::ArcTangent),
        ("LCT", None) => s.kind = Some(ApproachKind::LineArcTangent),
        ("POS", None) => s.pos = true,
        ("PAT", None) => s.pat = true,
        (n, v) => {
            let what = if v.is_some() {
                format!("`{n}` takes no value here")
            } else {
                format!("`{n}` needs a value")
            };
            ctx.error(
                Code::KlartextWordNotAllowed,
                l,
                r,
                what,
                "check the word against the block's function",
            );
        }
    }
}

/// An M function: `M13`/`M14` are spindle on with coolant (two
/// statements); the others go to the shared lowering.
pub fn m_function(ctx: &mut Ctx<'_>, w: &WordNode, v: Value) -> Vec<Item> {
    let (l, r) = (w.l, w.r);
    match v.number().and_then(|d| d.as_int()) {
        Some(c @ (13 | 14)) => {
            let dir = if c == 13 {
                SpindleState::Cw
            } else {
                SpindleState::Ccw
            };
            vec![
                ctx.stmt(StmtKind::Spindle(dir), l, r),
                ctx.stmt(StmtKind::Coolant(crate::ir::Coolant::Flood), l, r),
            ]
        }
        _ => vec![ctx.m_word(w, v)],
    }
}

/// `IPA+45`: an incremental value, as `IC(45)`.
fn incremental(ctx: &mut Ctx<'_>, v: Value, l: usize, r: usize) -> Value {
    let e = ctx.expr_of(&v, l, r);
    let span = ctx.span(l, r);
    Value::Expr(ctx.exprs.alloc(crate::ir::Expr {
        kind: ExprKind::Dimension(DimMode::Incremental, e),
        span,
    }))
}

const MOVE_WORDS: &[&str] = &["R0", "RL", "RR", "F", "FMAX", "FAUTO", "M"];

/// `L`, `C`, `CC`, `CR`, `CT`, `LP`, `CP`, `CTP`, `RND`, `CHF` (without value).
pub fn path(ctx: &mut Ctx<'_>, kw: Kw, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let (allowed, axes_ok): (&[&str], bool) = match kw {
        Kw::L | Kw::Ct => (MOVE_WORDS, true),
        Kw::C => (&["R0", "RL", "RR", "F", "FMAX", "FAUTO", "M", "DR"], true),
        Kw::Cr => (
            &["R", "R0", "RL", "RR", "F", "FMAX", "FAUTO", "M", "DR"],
            true,
        ),
        Kw::Cc => (&[], true),
        Kw::Lp | Kw::Ctp => (
            &[
                "PR", "IPR", "PA", "IPA", "R0", "RL", "RR", "F", "FMAX", "FAUTO", "M",
            ],
            true,
        ),
        Kw::Cp => (
            &[
                "PA", "IPA", "R0", "RL", "RR", "F", "FMAX", "FAUTO", "M", "DR",
            ],
            true,
        ),
        Kw::Rnd => (&["R", "F"], false),
        _ => (&["F"], false),
    };
    let mut s = read_words(ctx, words, allowed, axes_ok);
    let mut out = std::mem::take(&mut s.items);
    if !super::paraxial::fits(ctx, kw, &s.axes, &out, l, r) {
        return Vec::new();
    }
    let need = |ctx: &mut Ctx<'_>, what: &str, help: &str| {
        ctx.error(Code::KlartextMissingWord, l, r, what.to_string(), help)
    };
    let kind = match kw {
        Kw::Cc => {
            out.insert(0, ctx.stmt(StmtKind::Pole(Box::new(s.axes)), l, r));
            return out;
        }
        Kw::Rnd | Kw::Chf => {
            let Some(size) = s.radius.take() else {
                need(ctx, "RND needs its radius `R`", "write `RND R5`");
                return out;
            };
            let corner = StmtKind::Corner {
                kind: CornerKind::Round,
                size,
            };
            out.insert(0, ctx.stmt(corner, l, r));
            return out;
        }
        Kw::L | Kw::Lp if s.rapid => MotionKind::Rapid,
        Kw::L | Kw::Lp => MotionKind::Linear,
        Kw::Ct | Kw::Ctp => MotionKind::ArcTangent,
        _ => match s.dir {
            Some(d) => MotionKind::Arc(d),
            None => {
                need(
                    ctx,
                    "a circle needs its direction `DR+` or `DR-`",
                    "add DR+ (counter-clockwise) or DR- (clockwise)",
                );
                MotionKind::Arc(ArcDir::Ccw)
            }
        },
    };
    if kw == Kw::Cr && s.radius.is_none() {
        need(
            ctx,
            "CR needs its radius `R`",
            "write `CR X.. Y.. R+20 DR-`",
        );
    }
    if matches!(kw, Kw::Lp | Kw::Ctp) && s.polar_r.is_none() && s.polar_a.is_none() {
        need(
            ctx,
            "a polar block needs PR or PA",
            "write `LP PR+40 PA+30`",
        );
    }
    let mut m = Motion::new(kind);
    m.target = s.axes;
    m.arc.radius = s.radius;
    m.polar_radius = s.polar_r;
    m.polar_angle = s.polar_a;
    out.insert(0, ctx.stmt(StmtKind::Motion(Box::new(m)), l, r));
    out
}

/// `CHF 2` (with optional `F`).
pub fn chamfer(
    ctx: &mut Ctx<'_>,
    size: &Signed,
    words: &[WordNode],
    l: usize,
    r: usize,
) -> Vec<Item> {
    let size = ctx.value(size);
    let mut s = read_words(ctx, words, &["F"], false);
    let mut out = std::mem::take(&mut s.items);
    let kind = StmtKind::Corner {
        kind: CornerKind::Chamfer,
        size,
    };
    out.insert(0, ctx.stmt(kind, l, r));
    out
}

/// W0005 for `FAUTO` (`F AUTO`): the feed of the last TOOL CALL, which
/// cncc does not run yet; the run keeps the feed in force.
fn fauto_kept(ctx: &mut Ctx<'_>, l: usize, r: usize) {
    ctx.diags.push(
        Diagnostic::new(Code::KeptAsText, "`FAUTO` is kept as text")
            .primary(ctx.span(l, r), "the TOOL CALL's feed: not run, the feed in force is used")
            .help("FAUTO moves at the feed of the last TOOL CALL; cncc keeps it for Heidenhain but runs the block at the feed in force, so the run's times and the proof of a port may differ: write the TOOL CALL's F value instead"),
    );
}
