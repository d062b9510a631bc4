//! Program, tool and blank blocks to items: `BEGIN PGM`/`END PGM`,
//! `TOOL CALL`, `TOOL DEF`, `BLK FORM`, `STOP`, and blocks of M functions
//! alone.

use super::build::{Ctx, WordNode};
use super::path::{read_words, AXES};
use crate::diag::Code;
use crate::ir::{LengthUnit, Plane, StmtKind, StockCorner, ToolRef};
use crate::syntax::Item;

/// `TOOL CALL 1 Z S3000 F500 DL+0.1 DR-0.05`: tool select and change, the
/// plane from the tool axis, speed, feed and oversizes.
pub fn tool_call(
    ctx: &mut Ctx<'_>,
    tool: Option<ToolRef>,
    words: &[WordNode],
    l: usize,
    r: usize,
) -> Vec<Item> {
    let mut out = Vec::new();
    if let Some(t) = tool {
        out.push(ctx.stmt(StmtKind::ToolSelect(t), l, r));
        out.push(ctx.stmt(StmtKind::ToolChange, l, r));
    }
    let (mut dl, mut dr) = (None, None);
    for w in words {
        let v = ctx.word_value(w);
        let plane = match w.name.as_str() {
            "Z" => Some(Plane::XY),
            "Y" => Some(Plane::ZX),
            "X" => Some(Plane::YZ),
            _ => None,
        };
        match (w.name.as_str(), v, plane) {
            (_, None, Some(p)) => out.push(ctx.stmt(StmtKind::Plane(p), w.l, w.r)),
            ("S", Some(v), _) => out.push(ctx.stmt(StmtKind::SpindleSpeed(v), w.l, w.r)),
            ("F", Some(v), _) => out.push(ctx.stmt(StmtKind::Feed(v), w.l, w.r)),
            ("DL", Some(v), _) => dl = Some(v),
            ("DR", Some(v), _) => dr = Some(v),
            (n, _, _) => ctx.error(
                Code::KlartextWordNotAllowed,
                w.l,
                w.r,
                format!("TOOL CALL does not take `{n}` here"),
                "TOOL CALL takes the tool, its axis (Z), S, F, DL and DR",
            ),
        }
    }
    if dl.is_some() || dr.is_some() {
        let k = StmtKind::ToolOversize {
            length: dl,
            radius: dr,
        };
        out.push(ctx.stmt(k, l, r));
    }
    out
}

/// `TOOL DEF 1 L+0 R+5`.
pub fn tool_def(
    ctx: &mut Ctx<'_>,
    tool: Option<ToolRef>,
    words: &[WordNode],
    l: usize,
    r: usize,
) -> Vec<Item> {
    let Some(tool) = tool else {
        ctx.error(
            Code::KlartextMissingWord,
            l,
            r,
            "TOOL DEF needs the tool number or name",
            "write `TOOL DEF 1 L+0 R+5`",
        );
        return Vec::new();
    };
    let (mut length, mut radius) = (None, None);
    for w in words {
        match (w.name.as_str(), ctx.word_value(w)) {
            ("L", Some(v)) => length = Some(v),
            ("R", Some(v)) => radius = Some(v),
            (n, _) => ctx.error(
                Code::KlartextWordNotAllowed,
                w.l,
                w.r,
                format!("TOOL DEF does not take `{n}`"),
                "TOOL DEF takes L (length) and R (radius)",
            ),
        }
    }
    // `TOOL DEF 2` alone: the preselection of the next tool (the tool
    // table holds its sizes), the meaning of a word-address `T2`.
    if length.is_none() && radius.is_none() {
        return vec![ctx.stmt(StmtKind::ToolSelect(tool), l, r)];
    }
    vec![ctx.stmt(
        StmtKind::ToolDef {
            tool,
            length,
            radius,
        },
        l,
        r,
    )]
}

/// `BLK FORM 0.1 Z X.. Y.. Z..` / `BLK FORM 0.2 X.. Y.. Z..`.
pub fn blk_form(
    ctx: &mut Ctx<'_>,
    which: crate::ir::Decimal,
    words: &[WordNode],
    l: usize,
    r: usize,
) -> Vec<Item> {
    let corner = match which.format(1, true).as_str() {
        "0.1" => StockCorner::Min,
        "0.2" => StockCorner::Max,
        _ => {
            ctx.error(
                Code::KlartextWordNotAllowed,
                l,
                r,
                "only BLK FORM 0.1 and 0.2 are read",
                "give the blank as BLK FORM 0.1 (minimum point) and 0.2 (maximum point)",
            );
            return Vec::new();
        }
    };
    let mut axis = None;
    let mut rest = Vec::new();
    for (i, w) in words.iter().enumerate() {
        if i == 0
            && corner == StockCorner::Min
            && w.value.is_none()
            && w.sign.is_none()
            && AXES[..3].contains(&w.name.as_str())
        {
            axis = w.name.chars().next();
        } else {
            rest.push(w.clone());
        }
    }
    let s = read_words(ctx, &rest, &[], true);
    let k = StmtKind::Stock {
        corner,
        axis,
        axes: Box::new(s.axes),
    };
    vec![ctx.stmt(k, l, r)]
}

/// `STOP` (with M functions).
pub fn stop(ctx: &mut Ctx<'_>, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let mut s = read_words(ctx, words, &["M"], false);
    let mut out = vec![ctx.stmt(StmtKind::Stop(crate::ir::StopKind::Program), l, r)];
    out.append(&mut s.items);
    out
}

/// A block of M functions alone (`M3 M8`); anything else there is an
/// unknown block.
pub fn bare(ctx: &mut Ctx<'_>, words: &[WordNode]) -> Vec<Item> {
    if let Some(w) = words.first().filter(|w| w.name != "M") {
        if w.name == "CYCLE"
            && words
                .get(1)
                .is_some_and(|d| d.name == "DEF" || d.name == "CALL")
        {
            let d = &words[1];
            ctx.error(
                Code::KlartextUnknownBlock,
                w.l,
                d.r,
                format!("`CYCLE {}` is not Klartext: the keyword is `CYCL {}`", d.name, d.name),
                &format!(
                    "write `CYCL {}` (no E), as in `CYCL DEF 9.0 DWELL TIME` / `CYCL DEF 9.1 DWELL 5`",
                    d.name
                ),
            );
            return Vec::new();
        }
        let hint = suggestion(&w.name);
        ctx.error(
            Code::KlartextUnknownBlock,
            w.l,
            w.r,
            format!("`{}` does not start a Klartext block", w.name),
            &hint,
        );
        return Vec::new();
    }
    let mut s = read_words(ctx, words, &["M"], false);
    std::mem::take(&mut s.items)
}

fn suggestion(name: &str) -> String {
    const KNOWN: &[&str] = &[
        "CYCL", "TOOL", "CALL", "LBL", "BLK", "PATTERN", "APPR", "DEP", "STOP", "RND", "CHF",
        "PLANE",
    ];
    match KNOWN.iter().find(|k| name.starts_with(*k) || k.starts_with(name)) {
        Some(k) => format!("did you mean `{k}`?"),
        None => "a block starts with L, C, CC, CR, CT, LP, CP, CTP, RND, CHF, APPR, DEP, LBL, CALL, FN, CYCL, TOOL, BLK FORM, PATTERN DEF, PLANE, STOP, an FK function (FL, FC, FPOL ...), Qn = or M".into(),
    }
}

/// `BEGIN PGM name MM` / `END PGM name MM`: the name and the unit.
pub fn pgm_line(ctx: &mut Ctx<'_>, end: bool, from: usize, l: usize, r: usize) -> Vec<Item> {
    let text = ctx.slice(from, ctx.end()).trim().to_string();
    let (name, unit) = match text.rsplit_once(char::is_whitespace) {
        Some((n, u)) => (n.trim().to_string(), u.trim().to_ascii_uppercase()),
        None => (String::new(), text.to_ascii_uppercase()),
    };
    let unit = match unit.as_str() {
        "MM" => Some(LengthUnit::Mm),
        "INCH" => Some(LengthUnit::Inch),
        _ => None,
    };
    let (name, unit) = match unit {
        Some(u) => (name, Some(u)),
        None => (text.clone(), None),
    };
    let name = (!name.is_empty()).then_some(name);
    let mut out = Vec::new();
    if end {
        out.push(ctx.stmt(StmtKind::ProgramEnd { name }, l, r));
        return out;
    }
    out.push(ctx.stmt(StmtKind::ProgramStart { number: None, name }, l, r));
    match unit {
        Some(unit) => out.push(ctx.stmt(
            StmtKind::Units {
                unit,
                with_feeds: true,
            },
            l,
            r,
        )),
        None => missing_unit(ctx, &text, l, r),
    }
    out
}

/// E0123 for a `BEGIN PGM` without its unit: the TNC writes `MM` or
/// `INCH` and nothing else [K]; an `IN` (as some NX posts write) is named.
fn missing_unit(ctx: &mut Ctx<'_>, text: &str, l: usize, r: usize) {
    let last = text.rsplit(char::is_whitespace).next().unwrap_or("");
    if last.eq_ignore_ascii_case("IN") && text.split_whitespace().count() > 1 {
        ctx.error(
            Code::KlartextMissingWord,
            l,
            r,
            "BEGIN PGM gives the unit `IN`: the TNC's inch unit is `INCH`",
            "write `BEGIN PGM NAME INCH` (the TNC knows MM and INCH only; the post wrote IN)",
        );
        return;
    }
    ctx.error(
        Code::KlartextMissingWord,
        l,
        r,
        "BEGIN PGM needs the unit MM or INCH",
        "write `BEGIN PGM NAME MM`: the TNC does not take a program without its unit",
    );
}
