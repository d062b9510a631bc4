//! `APPR`/`DEP` blocks to an [`Approach`] statement: the kind (LT, LN,
//! CT, LCT), the contour point, LEN, R and CCA; CT needs R and CCA, LCT R.

use super::build::{Ctx, WordNode};
use super::path::read_words;
use crate::diag::Code;
use crate::ir::{Approach, ApproachKind, StmtKind};
use crate::syntax::Item;

/// `APPR LT X.. Y.. LEN10 RR F300`, `DEP CT CCA90 R+5 F..`.
pub fn approach(
    ctx: &mut Ctx<'_>,
    depart: bool,
    words: &[WordNode],
    l: usize,
    r: usize,
) -> Vec<Item> {
    let allowed = [
        "LT", "LN", "CT", "LCT", "LEN", "CCA", "R", "R0", "RL", "RR", "F", "FMAX", "M",
    ];
    let mut s = read_words(ctx, words, &allowed, true);
    let mut out = std::mem::take(&mut s.items);
    let Some(kind) = s.kind else {
        ctx.error(
            Code::KlartextMissingWord,
            l,
            r,
            "APPR/DEP needs its kind: LT, LN, CT or LCT",
            "write e.g. `APPR LT X+0 Y+0 LEN10 RL`",
        );
        return out;
    };
    let needs: &[(&str, bool)] = match kind {
        ApproachKind::ArcTangent => &[("R", s.radius.is_some()), ("CCA", s.cca.is_some())],
        ApproachKind::LineArcTangent => &[("R", s.radius.is_some())],
        ApproachKind::LineTangent | ApproachKind::LineNormal => &[],
    };
    for (word, given) in needs {
        if !given {
            ctx.error(
                Code::KlartextMissingWord,
                l,
                r,
                format!("APPR/DEP CT and LCT need the arc's {word}"),
                "write e.g. `APPR CT X+10 Y+20 CCA180 R+10 RR` or `DEP LCT X+0 Y+0 R8`",
            );
        }
    }
    let a = Approach {
        depart,
        kind,
        target: s.axes,
        len: s.len,
        radius: s.radius,
        angle: s.cca,
    };
    out.insert(0, ctx.stmt(StmtKind::Approach(Box::new(a)), l, r));
    out
}
