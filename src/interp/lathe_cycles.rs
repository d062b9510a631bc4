//! LinuxCNC 2.9's lathe profile cycles (the spec's `cycle.lathe-finish`,
//! `cycle.lathe-rough*`, `cycle.lathe-face*`: G70, G71, G72 and their
//! .1/.2), run in three steps so that canonical calls match rs274's:
//!
//! 1. [`exec`], in the motion phase of the cycle's block: the checks
//!    rs274 makes first (Q given, no cutter compensation for roughing,
//!    the XZ plane), the block's words, and a rapid to the start point
//!    (the block's X Z, else the current point). The walker is then asked to call the
//!    contour subroutine Q ([`LatheCycles::take_call`]).
//! 2. While that subroutine runs, its blocks only add to the contour
//!    ([`super::lathe_profile::record`]).
//! 3. When it returns, [`finish`] makes the passes on the geometry kernel
//!    ([`crate::geom::turning`]) and emits them as moves.
//!
//! Words: Q contour sub, D finishing allowance (G70: of the first pass), E
//! allowance of the last G70 pass, P number of G70 passes, I depth of cut
//! (> 0), R retract, U W shift of the contour. Each move sets the motion
//! mode as a programmed one would (rs274 makes them as G0/G1/G2/G3
//! blocks): the contour is read in G0 (after the rapid to the start), and
//! the last move of the cycle leaves its mode in force.

use super::comp::MoveKind;
use super::host::{plane_axes, MotionHost};
use super::lathe_profile::Contour;
use super::state::ModalMotion;
use super::target::{target, Frame};
use super::{Interp, Stop};
use crate::canon::{CanonPlane, Pose};
use crate::diag::Code;
use crate::dialect::meaning::LatheProfile;
use crate::geom::turning::{Finish, Motion, Pockets, Profile, Pt, Rough, TurnError};
use crate::ir::{ArcDir, Arena, Block, Decimal, Expr, MotionKind, StmtKind, Word};
use crate::span::Span;

/// A cycle between its block and the end of its contour.
#[derive(Clone, Debug)]
pub struct Running {
    kind: LatheProfile,
    /// The words D E I P R U W as given (`None`: the default).
    words: [Option<f64>; 7],
    start: Pt,
    /// The cycle's block.
    span: Span,
    pub contour: Contour,
}

/// The cycles' state in the interpreter.
#[derive(Clone, Debug, Default)]
pub struct LatheCycles {
    call: Option<u32>,
    pub running: Option<Box<Running>>,
    /// The contour's point while one of its blocks is read (the contour is
    /// then out of `running`).
    pub reading_at: Option<Pt>,
}

impl LatheCycles {
    /// The contour subroutine the walker must call now, if a cycle began.
    pub fn take_call(&mut self) -> Option<u32> {
        self.call.take()
    }

    /// Is a contour being read (its blocks add geometry, they do not run)?
    pub fn reading(&self) -> bool {
        self.running.is_some() && self.call.is_none()
    }

    /// The current point (Z, X) while a contour is read: rs274 2.9 moves
    /// its current position along the contour as it reads it, so that
    /// `#<_x>`, `#<_z>` (#5420, #5422) give the contour's last point (from
    /// the cycle's start point on), not where the tool is. Under G7
    /// (diameter mode) X is the contour's radius, as read [?].
    pub fn contour_point(&self) -> Option<Pt> {
        if self.call.is_some() {
            return None;
        }
        self.reading_at
            .or_else(|| self.running.as_ref().map(|r| r.contour.at))
    }
}

const LETTERS: [char; 7] = ['D', 'E', 'I', 'P', 'R', 'U', 'W'];

/// `G71.1`, `G70.0`: the code as rs274 names it in messages.
fn name(code: Decimal) -> String {
    let v = code.to_f64();
    format!(
        "G{}.{}",
        v.trunc() as i64,
        ((v.fract() * 10.0).round()) as i64
    )
}

fn fail(it: &Interp<'_, '_>, code: Code, msg: impl Into<String>) -> Stop {
    it.error_at(it.span, code, msg)
}

/// Step 1: the cycle's block.
pub fn exec(
    it: &mut Interp<'_, '_>,
    kind: LatheProfile,
    code: Decimal,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let w = |it: &mut Interp<'_, '_>, c| super::aux::word_or_loose(it, words, block, c, exprs);
    let name = name(code);
    let Some(q) = w(it, 'Q')? else {
        return Err(fail(it, Code::CycleMissingWord, "G7x.x  requires a Q word"));
    };
    if it.comp.is_on() && kind != LatheProfile::Finish {
        return Err(fail(
            it,
            Code::CompStateChange,
            format!("{name} cannot be used with cutter compensation enabled"),
        ));
    }
    if it.state.plane != CanonPlane::XZ {
        return Err(fail(
            it,
            Code::LatheProfileFailed,
            format!("{name} can only be used in XZ plane (G18)"),
        ));
    }
    let mut vals = [None; 7];
    for (v, c) in vals.iter_mut().zip(LETTERS) {
        *v = w(it, c)?;
    }
    let to = start_point(it, block, exprs)?;
    // rs274 first goes to the start at rapid (cutter compensation, if on
    // for G70, applies).
    it.straight_move(MoveKind::Rapid, to)?;
    it.lathe.running = Some(Box::new(Running {
        kind,
        words: vals,
        start: Pt::new(to[2], to[0]),
        span: it.span,
        contour: Contour {
            at: Pt::new(to[2], to[0]),
            motion: Some(MotionKind::Rapid),
            incremental: !it.state.absolute,
            arc_incremental: !it.state.arc_absolute,
            ..Contour::default()
        },
    }));
    it.lathe.call = Some(q.round().max(0.0) as u32);
    Ok(())
}

/// The block's X Z (program frame), else the current point.
fn start_point(it: &mut Interp<'_, '_>, block: &Block, exprs: &Arena<Expr>) -> Result<Pose, Stop> {
    let axes = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Motion(m) => Some(&m.target),
        _ => None,
    });
    match axes {
        Some(a) => {
            let to = target(it, a, exprs, Frame::Program)?;
            Ok(super::machine::pose6(&it.state, &to))
        }
        None => Ok(MotionHost::position(it)),
    }
}

/// Step 3: the contour is read; the passes.
pub fn finish(it: &mut Interp<'_, '_>) -> Result<(), Stop> {
    let Some(run) = it.lathe.running.take() else {
        return Ok(());
    };
    let Running {
        kind,
        words,
        start,
        span,
        contour,
    } = *run;
    // rs274 has read the contour's last line when it makes the passes: its
    // errors show that line (the cycle's block is named beside it).
    let end_span = it.span;
    it.state.motion = match contour.motion {
        Some(k) => ModalMotion::Move(k),
        None => ModalMotion::None,
    };
    let segs = contour.segs;
    if segs.len() <= 1 {
        return Ok(());
    }
    let get = |i: usize, d: f64| words[i].unwrap_or(d);
    let (d, e, depth, p, r, u, w) = (
        get(0, 0.0),
        get(1, 0.0),
        get(2, 1.0),
        get(3, 1.0),
        get(4, 0.5),
        get(5, 0.0),
        get(6, 0.0),
    );
    if depth <= 0.0 {
        return Err(fail(
            it,
            Code::LatheProfileFailed,
            "G7X error: I must be greater than zero.",
        ));
    }
    let mut out = Emit {
        it,
        base: None,
        err: None,
        last: None,
    };
    let result = match kind {
        LatheProfile::Finish => {
            let c = Finish {
                start,
                first: d,
                last: e,
                passes: p,
            };
            let profile = Profile {
                segs,
                ..Profile::default()
            };
            profile.finish(&c, &mut out)
        }
        LatheProfile::Rough { facing, part } => {
            let c = Rough {
                start,
                shift: Pt::new(w, u),
                allowance: d,
                depth,
                retract: r,
                pockets: match part {
                    1 => Pockets::None,
                    2 => Pockets::Only,
                    _ => Pockets::All,
                },
                facing,
            };
            let profile = Profile {
                segs,
                ..Profile::default()
            };
            profile.rough(&c, &mut out)
        }
    };
    let sink = out.err.take();
    if let Some(k) = out.last {
        it.state.motion = ModalMotion::Move(k);
    }
    result.map_err(|e| match turn_error(it, e, sink) {
        Stop::Error(d) if span != end_span => {
            Stop::Error(d.secondary(span, "the cycle whose contour this is"))
        }
        other => other,
    })
}

fn turn_error(it: &Interp<'_, '_>, e: TurnError, sink: Option<Stop>) -> Stop {
    match e {
        TurnError::Geometry(m) => fail(it, Code::LatheProfileFailed, format!("G7X error: {m}")),
        TurnError::Corner(p) => fail(
            it,
            Code::LatheProfileFailed,
            format!("G7X error: Corner finish failed at ({},{})", p.re, p.im),
        ),
        TurnError::Endless => fail(
            it,
            Code::LimitExceeded,
            "G7X: the roughing passes never end (LinuxCNC 2.9 loops for ever on this contour)",
        ),
        TurnError::Sink => sink.unwrap_or_else(|| fail(it, Code::LatheProfileFailed, "G7X error")),
    }
}

/// The kernel's moves as the interpreter's (X and Z of the current pose).
struct Emit<'i, 'a, 's> {
    it: &'i mut Interp<'a, 's>,
    base: Option<Pose>,
    /// The interpreter's own error that stopped the moves.
    err: Option<Stop>,
    /// The kind of the last move made (the motion mode it leaves).
    last: Option<MotionKind>,
}

impl Emit<'_, '_, '_> {
    fn pose(&mut self, to: Pt) -> Pose {
        let mut p = self.base.unwrap_or_else(|| MotionHost::position(self.it));
        p[0] = to.im;
        p[2] = to.re;
        self.base = Some(p);
        p
    }

    fn keep(&mut self, r: Result<(), Stop>) -> Result<(), TurnError> {
        r.map_err(|e| {
            self.err = Some(e);
            TurnError::Sink
        })
    }
}

impl Motion for Emit<'_, '_, '_> {
    fn rapid(&mut self, to: Pt) -> Result<(), TurnError> {
        let p = self.pose(to);
        self.last = Some(MotionKind::Rapid);
        let r = self.it.straight_move(MoveKind::Rapid, p);
        self.keep(r)
    }

    fn feed(&mut self, to: Pt) -> Result<(), TurnError> {
        let p = self.pose(to);
        self.last = Some(MotionKind::Linear);
        let r = feed_check(self.it).and_then(|_| self.it.straight_move(MoveKind::Feed, p));
        self.keep(r)
    }

    fn arc(&mut self, ccw: bool, center: Pt, to: Pt) -> Result<(), TurnError> {
        let from = MotionHost::position(self.it);
        let p = self.pose(to);
        // rs274 makes no arc to where the tool already is.
        if (from[0] - p[0]).abs() < 1e-4 && (from[2] - p[2]).abs() < 1e-4 {
            return Ok(());
        }
        self.last = Some(MotionKind::Arc(if ccw { ArcDir::Ccw } else { ArcDir::Cw }));
        let (a, b, _) = plane_axes(self.it.state.plane);
        let mut c = [0.0; 6];
        c[0] = center.im;
        c[2] = center.re;
        let r = feed_check(self.it)
            .and_then(|_| {
                super::arcs::check_radii(self.it, (from[a], from[b]), (c[a], c[b]), (p[a], p[b]))
            })
            .and_then(|_| self.it.arc_move(p, (c[a], c[b]), if ccw { 1 } else { -1 }));
        self.keep(r)
    }
}

fn feed_check(it: &Interp<'_, '_>) -> Result<(), Stop> {
    if it.state.feed == 0.0 {
        return Err(fail(
            it,
            Code::NoFeedRate,
            "Cannot do G1 with zero feed rate",
        ));
    }
    Ok(())
}
