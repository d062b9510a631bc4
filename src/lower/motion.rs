//! Moves and fixed cycles: a motion code (or none: an implicit move) with
//! its axis, arc, polar and corner words; `G81`-style cycles with R Q P,
//! repeats and I J K.

use super::checks::{check_arc_format, check_index, check_not_negative};
use super::words::Words;
use super::Ctx;
use crate::ir::{Axes, CannedCycle, CornerKind, CycleKind, Motion, MotionKind};

/// Arc words are read for arcs and for implicit moves (the modal motion
/// may be an arc).
fn takes_arc_words(kind: MotionKind) -> bool {
    matches!(
        kind,
        MotionKind::Implicit | MotionKind::Arc(_) | MotionKind::ArcThrough | MotionKind::ArcTangent
    )
}

/// Words that make a block without a motion code an implicit move.
pub(super) const MOTION_WORDS: &[&str] = &[
    "I", "J", "K", "R", "CR", "AR", "TURN", "I1", "J1", "K1", "@", "^", "AP", "RP", "CHF", "CHR",
    "RND", "RNDM",
];

/// A move: its kind and the words it takes; `uses` adds the code's extra
/// words (LinuxCNC `P` turns).
pub(super) fn motion(
    kind: MotionKind,
    uses: &[char],
    words: &mut Words,
    ctx: &mut Ctx<'_>,
) -> Box<Motion> {
    // Built in place, in the memory of an earlier move if there is one: a
    // move is large, and lines are many.
    let mut m = match ctx.spare_moves.pop() {
        Some(mut m) => {
            *m = Motion::new(kind);
            m
        }
        None => Box::new(Motion::new(kind)),
    };
    words.take_axes_into(&mut m.target);
    if !words.any_free() {
        // Every lookup below would find nothing.
        return m;
    }
    if takes_arc_words(kind) {
        // A move without a motion code is an arc only if the modal motion
        // is one, which the run knows (it reports the mixed format there):
        // in G0/G1 mode the same words are no arc (E0207 would be wrong).
        if kind != MotionKind::Implicit {
            check_arc_format(words, ctx.diags);
        }
        m.arc.i = words.coord("I");
        m.arc.j = words.coord("J");
        m.arc.k = words.coord("K");
        m.arc.radius = words.value("R").or_else(|| words.value("CR"));
        m.arc.angle = words.value("AR");
        m.arc.turns = words.value("TURN");
        if m.arc.turns.is_none() && uses.contains(&'P') {
            m.arc.turns = words.value("P");
        }
        m.arc.mid = mid_point(words).map(Box::new);
    }
    m.polar_radius = words.value("@").or_else(|| words.value("RP"));
    m.polar_angle = words.value("^").or_else(|| words.value("AP"));
    m.corner = corner(words);
    m
}

/// Siemens `CIP` intermediate point `I1= J1= K1=`.
fn mid_point(words: &mut Words) -> Option<Axes> {
    let mid = Axes {
        x: words.coord("I1"),
        y: words.coord("J1"),
        z: words.coord("K1"),
        ..Default::default()
    };
    (!mid.is_empty()).then_some(mid)
}

fn corner(words: &mut Words) -> Option<(CornerKind, crate::ir::Value)> {
    const KINDS: [(&str, CornerKind); 4] = [
        ("CHF", CornerKind::Chamfer),
        ("CHR", CornerKind::ChamferLeg),
        ("RND", CornerKind::Round),
        ("RNDM", CornerKind::RoundModal),
    ];
    KINDS
        .iter()
        .find_map(|(a, k)| words.value(*a).map(|v| (*k, v)))
}

/// A fixed cycle with its words.
/// A cycle's repeat word that is not a count may be another control's
/// dwell or peck word under the same letter (a GE 1050's `K.4`).
fn repeat_help(spec: &crate::dialect::DialectSpec) -> String {
    format!(
        "in {} `{}` is a canned cycle's repeat count; a control that reads `{}` as a dwell or peck depth is described by a dialect file (`--dialect-file`) that extends this one with another `repeat-letter` and its own cycle codes",
        spec.name, spec.repeat_letter, spec.repeat_letter
    )
}

pub(super) fn cycle(kind: CycleKind, words: &mut Words, ctx: &mut Ctx<'_>) -> CannedCycle {
    let target = words.take_axes();
    let q = words.take("Q");
    if let Some(q) = &q {
        check_not_negative(&q.value, q.span, "peck depth", ctx.diags);
    }
    let repeat = words.take(ctx.spec.repeat_letter);
    if let Some(r) = &repeat {
        let before = ctx.diags.len();
        if check_index(r, "repeat count", None, ctx.diags).is_none() {
            if let Some(d) = ctx.diags.get_mut(before) {
                d.help = Some(repeat_help(ctx.spec));
            }
        }
    }
    CannedCycle {
        kind,
        target,
        r: words.value("R"),
        q: q.map(|w| w.value),
        p: words.value("P"),
        repeat: repeat.map(|w| w.value),
        i: words.value("I"),
        j: words.value("J"),
        k: words.value("K"),
    }
}
