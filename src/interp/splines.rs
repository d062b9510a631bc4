//! LinuxCNC's splines, run as rs274 2.9 runs them: G5 (cubic) and G5.1
//! (quadratic) become one NURBS_FEED each, the Bezier control polygon from
//! the start point; G5.2 blocks gather weighted control points that G5.3
//! sends as one NURBS_FEED. Splines lie in the XY plane; Z and the rotary
//! axes may not move.
//!
//! Behaviour pinned with the live rs274 (tests/programs/linuxcnc/oracle):
//! - G5 and G5.1 leave the modal motion as it was; G5.2 makes it modal
//!   (continuation blocks give `X Y P`); G5.3 leaves no motion mode (rs274
//!   reads `#<_motion_mode>` -1 there, as cncc does until a G80).
//! - G5 without I J starts in the direction the previous G5 ended (I J =
//!   the negated P Q of the last G5, 0 0 at first). rs274 keeps these in
//!   the same setting as the canned cycles' I J [?]: cncc keeps them apart.
//! - The NURBS order is 3 unless an L above 3 is given; leaving G5.2 for
//!   another motion drops the gathered points without a call (cncc warns,
//!   E0514). rs274 keeps a dropped list until the next G5.2 block, whose
//!   weight checks then see it: cncc does the same.

mod nurbs;

pub use nurbs::leaving_nurbs;

use super::polar::polar as polar_xy;
use super::state::ModalMotion;
use super::target::{target, Frame};
use super::{Interp, Stop};
use crate::canon::{Canon, CanonPlane, NurbsPoint};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, FeedMode, Motion, MotionKind, StmtKind, Word};

/// Spline state that outlives a block.
#[derive(Clone, Debug, Default)]
pub struct Splines {
    /// G5.2's gathered control points (the start point first).
    points: Vec<NurbsPoint>,
    order: u32,
    /// The block span that started the gathered points.
    started: Option<crate::span::Span>,
    /// G5's default I J: the negated P Q of the last G5.
    next_ij: (f64, f64),
    /// G5.3 left no motion mode (until G80 sets "none" proper).
    pub no_motion_code: bool,
}

/// Is the modal motion the NURBS control-point code (G5.2: continuation
/// blocks are control points)?
pub fn in_nurbs_mode(it: &Interp<'_, '_>) -> bool {
    matches!(it.state.motion, ModalMotion::Move(MotionKind::Other(code))
        if super::aux::machine_fn(it.spec, 'G', code) == Some(crate::dialect::MachineFn::Spline(2)))
}

/// The words of a block's spline code, with the block's motion words.
struct Words<'b> {
    kind: u8,
    words: &'b [Word],
    motion: Option<&'b Motion>,
}

fn value(
    it: &mut Interp<'_, '_>,
    w: &Words<'_>,
    block: &Block,
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    super::aux::word_or_loose(it, w.words, block, letter, exprs)
}

fn fail(it: &Interp<'_, '_>, msg: impl Into<String>) -> Stop {
    it.error_at(it.span, Code::BadWordValue, msg)
}

/// Runs a spline statement (in the motion phase): `code` 0 cubic (G5),
/// 1 quadratic (G5.1), 2 NURBS control point (G5.2), 3 NURBS end (G5.3).
pub fn exec(
    it: &mut Interp<'_, '_>,
    code: u8,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let motion = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Motion(m) => Some(&**m),
        _ => None,
    });
    let w = Words {
        kind: code,
        words,
        motion,
    };
    match code {
        0 | 1 => spline(it, &w, block, exprs),
        2 => nurbs::nurbs_point(it, &w, block, exprs),
        _ => nurbs::nurbs_end(it),
    }
}

/// A continuation block of G5.2: one more control point.
pub fn continuation(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let w = Words {
        kind: 2,
        words: &[],
        motion: Some(m),
    };
    nurbs::nurbs_point(it, &w, block, exprs)
}

/// The end point of the block's motion words (program units), and
/// whether X and Y were written.
fn end_xy(
    it: &mut Interp<'_, '_>,
    w: &Words<'_>,
    exprs: &Arena<Expr>,
) -> Result<((f64, f64), bool, bool), Stop> {
    let Some(m) = w.motion else {
        let p = super::host::MotionHost::position(it);
        return Ok(((p[0], p[1]), false, false));
    };
    let has = |c| m.target.get(c).is_some();
    let (hx, hy) = (has('X'), has('Y'));
    if ['Z', 'A', 'B', 'C'].iter().any(|c| has(*c)) && w.kind < 2 {
        return Err(fail(it, "Splines may not have motion in Z, A, B, or C"));
    }
    let to = target(it, &m.target, exprs, Frame::Program)?;
    let mut xy = (it.state.to_prog(to[0]), it.state.to_prog(to[1]));
    if let Some(p) = polar_xy(it, m, exprs)? {
        xy = p;
    }
    let polar = m.polar_radius.is_some() || m.polar_angle.is_some();
    Ok((xy, hx || polar, hy || polar))
}

/// G5 / G5.1: one NURBS_FEED from the start point.
fn spline(
    it: &mut Interp<'_, '_>,
    w: &Words<'_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if it.comp.is_on() {
        return Err(fail(
            it,
            "Cannot convert spline with cutter radius compensation",
        ));
    }
    match it.state.feed_mode {
        FeedMode::PerMinute if it.state.feed == 0.0 => {
            return Err(it.error_at(
                it.span,
                Code::NoFeedRate,
                "Cannot make arc with zero feed rate",
            ))
        }
        FeedMode::InverseTime
            if !block
                .stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::Feed(_))) =>
        {
            return Err(it.error_at(
                it.span,
                Code::NoFeedRate,
                "F word missing with inverse time arc move",
            ))
        }
        _ => {}
    }
    if it.state.plane != CanonPlane::XY {
        return Err(fail(it, "Splines must be in the XY plane"));
    }
    let start = super::host::MotionHost::position(it);
    let (x0, y0) = (start[0], start[1]);
    let i = value(it, w, block, 'I', exprs)?;
    let j = value(it, w, block, 'J', exprs)?;
    let pt = |x, y| NurbsPoint { x, y, w: 1.0 };
    let points = if w.kind == 1 {
        let (Some(i), Some(j)) = (i, j) else {
            return Err(fail(it, "Must specify both I and J with G5.1"));
        };
        let ((x2, y2), _, _) = end_xy(it, w, exprs)?;
        vec![pt(x0, y0), pt(x0 + i, y0 + j), pt(x2, y2)]
    } else {
        let (i, j) = match (i, j) {
            (Some(i), Some(j)) => (i, j),
            (None, None) => it.splines.next_ij,
            _ => return Err(fail(it, "Must specify both I and J, or neither")),
        };
        let ((x3, y3), _, _) = end_xy(it, w, exprs)?;
        let p = value(it, w, block, 'P', exprs)?;
        let q = value(it, w, block, 'Q', exprs)?;
        let (Some(p), Some(q)) = (p, q) else {
            return Err(fail(it, "Must specify both P and Q with G5"));
        };
        it.splines.next_ij = (-p, -q);
        vec![
            pt(x0, y0),
            pt(x0 + i, y0 + j),
            pt(x3 + p, y3 + q),
            pt(x3, y3),
        ]
    };
    let order = points.len() as u32;
    feed(it, points, order);
    Ok(())
}

/// Emits the curve and moves the tool to its last control point.
fn feed(it: &mut Interp<'_, '_>, points: Vec<NurbsPoint>, order: u32) {
    let mut end = super::host::MotionHost::position(it);
    if let Some(last) = points.last() {
        end[0] = last.x;
        end[1] = last.y;
    }
    it.out(Canon::NurbsFeed { points, order });
    it.set_position(&end);
}
