//! Running the motion statements of a block (see [`super::exec`] for which):
//! G0/G1 (absolute, incremental, G53), implicit moves in the modal motion,
//! G2/G3 (see [`super::arcs`]), G38.x probing, canned cycles G73..G89
//! through [`super::cycles::run_cycle`], G80. Every move goes through
//! cutter compensation ([`Interp::straight_move`], [`Interp::arc_move`]).

use super::comp::MoveKind;
use super::cycle_io::CycleBlock;
use super::machine::pose6;
use super::state::ModalMotion;
use super::target::{target, written, Frame};
use super::{arcs, aux, Interp, Stop};
use crate::canon::{Canon, Pose};
use crate::diag::{Code, Diagnostic};
use crate::dialect::Capability;
use crate::ir::{
    Arena, Axes, Block, CannedCycle, CoordShift, CycleKind, DwellUnit, Expr, FeedMode, Motion,
    MotionKind, Stmt, StmtKind, Value,
};

pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.begin_block(block);
    let keeps_nurbs = matches!(&s.kind, StmtKind::Motion(m) if m.kind == MotionKind::Implicit);
    if !keeps_nurbs {
        super::splines::leaving_nurbs(it);
    }
    match &s.kind {
        StmtKind::Motion(m) => motion(it, m, block, exprs),
        StmtKind::Cycle(c) => {
            let cb = cycle_block(it, c, block, exprs)?;
            if let Some(StmtKind::Motion(m)) = block
                .stmts
                .iter()
                .map(|s| &s.kind)
                .find(|k| matches!(k, StmtKind::Motion(_)))
            {
                if m.polar_radius.is_some() || m.polar_angle.is_some() {
                    return super::polar::polar_cycle(it, cb, m, block, exprs);
                }
            }
            run_cycle(it, cb, block)
        }
        StmtKind::CycleCancel => {
            it.cycles.cancel();
            it.splines.no_motion_code = false;
            if let Some(k) = motion_after_cancel(it) {
                it.state.motion = ModalMotion::Move(k);
                return Ok(());
            }
            it.state.motion = ModalMotion::None;
            it.out(Canon::Comment(
                "interpreter: motion mode set to none".into(),
            ));
            Ok(())
        }
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the interpreter yet",
        )),
    }
}

fn has(block: &Block, f: impl Fn(&StmtKind) -> bool) -> bool {
    block.stmts.iter().any(|s| f(&s.kind))
}

/// Axis words the reader attached to a G92.1/G92.2/G92.3 in the block
/// (those codes take none): they belong to the block's motion.
fn stray_axes(block: &Block) -> Option<&Axes> {
    block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::CoordShift { kind, axes }
            if !matches!(kind, CoordShift::Set | CoordShift::Local) && !axes.is_empty() =>
        {
            Some(&**axes)
        }
        _ => None,
    })
}

fn motion(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if m.target.is_empty() {
        if let Some(axes) = stray_axes(block) {
            let mut m2 = m.clone();
            m2.target = axes.clone();
            return motion_inner(it, &m2, block, exprs);
        }
    }
    motion_inner(it, m, block, exprs)
}

fn motion_inner(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    // Polar words beside a cycle's G code belong to that cycle, which the
    // cycle statement of the block runs.
    if m.kind == MotionKind::Implicit && has(block, |k| matches!(k, StmtKind::Cycle(_))) {
        return Ok(());
    }
    // So do the words of a spline block (G5 .. G5.3), and a G5.2
    // continuation block gives a control point.
    if m.kind == MotionKind::Implicit
        && has(
            block,
            |k| matches!(k, StmtKind::Aux { letter, code, .. } if super::aux::is_motion_aux(it.spec, *letter, *code)),
        )
    {
        return Ok(());
    }
    if m.kind == MotionKind::Implicit && super::splines::in_nurbs_mode(it) {
        return super::splines::continuation(it, m, block, exprs);
    }
    if m.kind == MotionKind::Implicit && super::threading::is_modal(it) && !m.target.is_empty() {
        it.comp_block(block.span);
        return super::threading::exec(it, &[], block, exprs);
    }
    let kind = match m.kind {
        MotionKind::Implicit => match it.state.motion {
            _ if m.target.is_empty()
                && m.arc.is_empty()
                && m.polar_radius.is_none()
                && m.polar_angle.is_none() =>
            {
                return Ok(())
            }
            ModalMotion::Move(k) => k,
            ModalMotion::Cycle(kind) => return implicit_cycle(it, kind, m, block, exprs),
            ModalMotion::None if has(block, |k| matches!(k, StmtKind::CycleCancel)) => {
                return Err(it.error_at(
                    it.span,
                    Code::BadWordValue,
                    "Cannot use axis values with g80",
                ))
            }
            ModalMotion::None => {
                return Err(it.error_at(
                    it.span,
                    Code::BadWordValue,
                    "Cannot use axis values without a g code that uses them",
                ))
            }
        },
        k => {
            it.cycles.cancel();
            it.state.motion = ModalMotion::Move(k);
            // A bare `G2`/`G3` only sets the mode where a bare motion code
            // does not move (Fanuc, Haas, Siemens): the block that moves
            // in it is the one that must give the centre.
            let bare = m.target.is_empty()
                && m.arc.is_empty()
                && m.polar_radius.is_none()
                && m.polar_angle.is_none();
            if bare
                && matches!(k, MotionKind::Arc(_))
                && !it.spec.has(crate::dialect::Capability::BareMotionCodeMoves)
            {
                return Ok(());
            }
            k
        }
    };
    if m.kind == MotionKind::Implicit
        && matches!(kind, MotionKind::Rapid | MotionKind::Linear)
        && !it.spec.has(crate::dialect::Capability::StrictWords)
    {
        if let Some(d) = arc_words_without_arc(it.span, m) {
            it.diags.push(d);
        }
    }
    it.comp_block(block.span);
    let sinumerik = it.spec.has(crate::dialect::Capability::FrameArcs);
    match kind {
        MotionKind::Rapid | MotionKind::Linear if sinumerik => {
            let from = it.state.pos;
            straight(it, kind, m, block, exprs)?;
            super::siemens::arcs::note_straight(it, from);
            Ok(())
        }
        MotionKind::Rapid | MotionKind::Linear => straight(it, kind, m, block, exprs),
        MotionKind::Arc(_) | MotionKind::ArcThrough | MotionKind::ArcTangent if sinumerik => {
            super::siemens::arcs::arc(it, kind, m, block, exprs)
        }
        MotionKind::Arc(dir) => arcs::arc(it, dir, m, block, exprs),
        MotionKind::Probe { error, .. } => probe(it, &m.target, error, exprs),
        MotionKind::Other(code) if sync_motion(it, code).is_some() => {
            let rigid = sync_motion(it, code) == Some(true);
            spindle_sync(it, rigid, &m.target, exprs)
        }
        MotionKind::Implicit
        | MotionKind::ArcThrough
        | MotionKind::ArcTangent
        | MotionKind::Other(_) => Err(it.error_at(
            it.span,
            Code::UnsupportedHere,
            "this motion is not run by the interpreter yet",
        )),
    }
}

/// W0597: a block without a motion code moves straight in G0/G1 mode, so
/// its centre or radius words belong to no arc (a lost G2/G3, or words
/// meant as M98 arguments). Dialects with `strict-words` refuse them when
/// the block is read instead.
fn arc_words_without_arc(span: crate::span::Span, m: &Motion) -> Option<Diagnostic> {
    let a = &m.arc;
    let words: Vec<&str> = [
        (a.i.is_some(), "I"),
        (a.j.is_some(), "J"),
        (a.k.is_some(), "K"),
        (a.radius.is_some(), "R"),
    ]
    .iter()
    .filter(|(on, _)| *on)
    .map(|(_, w)| *w)
    .collect();
    if words.is_empty() {
        return None;
    }
    Some(
        Diagnostic::new(
            Code::ArcWordsWithoutArc,
            format!("{} in a block that moves straight: not used", words.join(" ")),
        )
        .primary(span, "no G2/G3 is in force here")
        .help("write the arc's G2/G3 if this move is meant to be an arc, or remove the words (M98 passes no arguments; G65 does)"),
    )
}

/// Is the modal G code a spindle-synchronised motion (`Some(rigid)`)?
fn sync_motion(it: &Interp<'_, '_>, code: crate::ir::Decimal) -> Option<bool> {
    match super::aux::machine_fn(it.spec, 'G', code)? {
        crate::dialect::MachineFn::SpindleSync { rigid } => Some(rigid),
        _ => None,
    }
}

fn straight(
    it: &mut Interp<'_, '_>,
    kind: MotionKind,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let axes = &m.target;
    let machine = has(block, |k| it.spec.in_machine_coords(k));
    let mut to = target(
        it,
        axes,
        exprs,
        if machine {
            Frame::Machine
        } else {
            Frame::Program
        },
    )?;
    let polar = super::polar::polar(it, m, exprs)?;
    if let Some((x, y)) = polar {
        to[0] = it.state.to_mm(x);
        to[1] = it.state.to_mm(y);
    }
    let to = pose6(&it.state, &to);
    // An explicit G0/G1 without axis words moves to where the tool is
    // where the spec says so (rs274 prints it); elsewhere it only sets
    // the mode (a Fanuc `G1` alone needs no F). An implicit one was
    // dropped by the caller.
    if axes.is_empty() && polar.is_none() && !it.spec.has(Capability::BareMotionCodeMoves) {
        return Ok(());
    }
    if kind == MotionKind::Rapid {
        return it.straight_move(MoveKind::Rapid, to);
    }
    check_feed(
        it,
        block,
        "Cannot do g1 with zero feed rate",
        "F word missing with inverse time g1 move",
    )?;
    if it.state.feed_mode == FeedMode::InverseTime {
        let from = super::host::MotionHost::position(it);
        let rate = straight_length(&from, &to) * it.state.feed;
        it.out(Canon::SetFeedRate(rate));
    }
    it.straight_move(MoveKind::Feed, to)
}

/// Errors for a feed move without a usable feed rate.
pub fn check_feed(
    it: &Interp<'_, '_>,
    block: &Block,
    zero: &str,
    inverse: &str,
) -> Result<(), Stop> {
    if it.state.feed_mode == FeedMode::InverseTime {
        if !has(block, |k| matches!(k, StmtKind::Feed(_))) {
            return Err(it.error_at(it.span, Code::NoFeedRate, inverse));
        }
    } else if it.state.feed == 0.0 {
        if it.from_outside {
            // A subprogram checked alone cuts at its caller's feed. [?] An
            // explicit F0 in the file is taken the same way.
            return Err(it.from_outside_at(it.span, "F"));
        }
        return Err(it.error_at(it.span, Code::NoFeedRate, zero));
    }
    Ok(())
}

/// The length of a straight move as rs274 measures it for inverse time:
/// X Y Z if any moves, else A B C.
pub fn straight_length(from: &Pose, to: &Pose) -> f64 {
    let d = |r: std::ops::Range<usize>| r.map(|i| (to[i] - from[i]).powi(2)).sum::<f64>().sqrt();
    let xyz = d(0..3);
    if xyz > 0.0 {
        xyz
    } else {
        d(3..6)
    }
}

/// G38.x: the simulated probe reaches the programmed point.
fn probe(
    it: &mut Interp<'_, '_>,
    axes: &Axes,
    error: bool,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let to = target(it, axes, exprs, Frame::Program)?;
    let to = pose6(&it.state, &to);
    {
        let span = it.span;
        let sink = &mut it.sink;
        it.comp.flush(&mut |c| sink.call(c, span));
    }
    let from = super::host::MotionHost::position(it);
    if it.state.feed == 0.0 {
        return Err(it.error_at(
            it.span,
            Code::NoFeedRate,
            "Cannot probe with zero feed rate",
        ));
    }
    // Only the probes that fail on no contact (G38.2/G38.4) check (rs274).
    if error && straight_length(&from, &to) < it.state.to_prog(0.254) {
        return Err(it.error_at(
            it.span,
            Code::BadWordValue,
            "Start point too close to probe point",
        ));
    }
    it.out(Canon::TurnProbeOn);
    it.out(Canon::StraightProbe(to));
    it.out(Canon::TurnProbeOff);
    // The simulated probe trips at the programmed point and the tool ends
    // 0.254 mm (0.010 in) back along the move, as rs274 reports it.
    let back = it.state.to_prog(0.254);
    let len = straight_length(&from, &to);
    let mut at = to;
    if len > 0.0 {
        for i in 0..3 {
            at[i] -= (to[i] - from[i]) / len * back;
        }
    }
    it.set_position(&at);
    for (i, v) in to.iter().enumerate() {
        it.params.set_numbered(5061 + i as u32, Some(*v));
    }
    it.params.set_numbered(5070, Some(0.0));
    Ok(())
}

pub(super) fn num(
    it: &mut Interp<'_, '_>,
    v: &Option<Value>,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match v {
        Some(v) => Ok(Some(it.value(v, exprs)?)),
        None => Ok(None),
    }
}

fn dwell_unit(it: &Interp<'_, '_>) -> DwellUnit {
    it.spec
        .code_for(crate::dialect::Meaning::Dwell)
        .and_then(|c| {
            c.dwell_units
                .iter()
                .find(|(l, _)| *l == 'P')
                .map(|(_, u)| *u)
        })
        .unwrap_or(DwellUnit::Seconds)
}

fn base_block(
    it: &mut Interp<'_, '_>,
    kind: CycleKind,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<CycleBlock, Stop> {
    let w = written(it, axes, exprs)?;
    Ok(CycleBlock {
        kind,
        axes: [w[0], w[1], w[2], w[3], w[4], w[5]],
        r: None,
        q: None,
        p: None,
        p_unit: dwell_unit(it),
        repeat: None,
        i: None,
        j: None,
        k: None,
        incremental: !it.state.absolute,
        return_initial: it.state.retract_initial,
        words_required: it.spec.has(crate::dialect::Capability::CycleWordsRequired),
        r_above_bottom: it.spec.has(crate::dialect::Capability::CycleRAboveBottom),
        rotary_refused: it
            .spec
            .has(crate::dialect::Capability::CycleRotaryWordsRefused),
        code_in_block: false,
        polar_step: None,
        shift: it
            .spec
            .code_for(crate::dialect::Meaning::Cycle(kind))
            .and_then(|c| c.shift),
        span: it.span,
    })
}

fn cycle_block(
    it: &mut Interp<'_, '_>,
    c: &CannedCycle,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<CycleBlock, Stop> {
    let _ = block;
    let mut cb = base_block(it, c.kind, &c.target, exprs)?;
    cb.r = num(it, &c.r, exprs)?;
    cb.q = num(it, &c.q, exprs)?;
    cb.p = num(it, &c.p, exprs)?;
    cb.repeat = num(it, &c.repeat, exprs)?;
    cb.i = num(it, &c.i, exprs)?;
    cb.j = num(it, &c.j, exprs)?;
    cb.k = num(it, &c.k, exprs)?;
    cb.code_in_block = true;
    Ok(cb)
}

fn implicit_cycle(
    it: &mut Interp<'_, '_>,
    kind: CycleKind,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let mut cb = base_block(it, kind, &m.target, exprs)?;
    cb.r = match num(it, &m.arc.radius, exprs)? {
        Some(r) => Some(r),
        None => aux::block_word(it, block, 'R', exprs)?,
    };
    cb.q = aux::block_word(it, block, 'Q', exprs)?;
    cb.p = aux::block_word(it, block, 'P', exprs)?;
    cb.repeat = match aux::block_word(it, block, 'L', exprs)? {
        Some(l) => Some(l),
        None => aux::block_word(it, block, 'K', exprs)?,
    };
    cb.i = aux::block_word(it, block, 'I', exprs)?;
    cb.j = aux::block_word(it, block, 'J', exprs)?;
    cb.k = aux::block_word(it, block, 'K', exprs)?;
    if m.polar_radius.is_some() || m.polar_angle.is_some() {
        return super::polar::polar_cycle(it, cb, m, block, exprs);
    }
    run_cycle(it, cb, block)
}

pub(super) fn run_cycle(
    it: &mut Interp<'_, '_>,
    cb: CycleBlock,
    block: &Block,
) -> Result<(), Stop> {
    it.comp_block(block.span);
    if let ModalMotion::Move(k) = it.state.motion {
        it.state.motion_before_cycle = Some(k);
    }
    it.state.motion = ModalMotion::Cycle(cb.kind);
    let mark = it.diags.len();
    let mut mem = std::mem::take(&mut it.cycles);
    super::cycles::run_cycle(it, &mut mem, &cb);
    it.cycles = mem;
    it.take_error(mark)
}

/// G33 (a synchronised feed) and G33.1 (rigid tapping: in and back out,
/// so the position does not change).
fn spindle_sync(
    it: &mut Interp<'_, '_>,
    rigid: bool,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if axes.is_empty() {
        return Ok(());
    }
    let to = target(it, axes, exprs, Frame::Program)?;
    let to = pose6(&it.state, &to);
    let pitch = it.state.sync_pitch;
    it.out(Canon::StartSpeedFeedSync {
        pitch,
        velocity_mode: false,
    });
    if rigid {
        it.out(Canon::RigidTap {
            x: to[0],
            y: to[1],
            z: to[2],
        });
    } else {
        it.straight_move(MoveKind::Feed, to)?;
    }
    it.out(Canon::StopSpeedFeedSync);
    Ok(())
}

/// Where the cycle cancel is a code of another modal group than G00/G01
/// (Fanuc: group 09 beside group 01), the motion in force before the cycle
/// stays; where it is a motion code itself (LinuxCNC), none does.
fn motion_after_cancel(it: &Interp<'_, '_>) -> Option<MotionKind> {
    use crate::dialect::Meaning;
    let cancel = it.spec.code_for(Meaning::CycleCancel)?;
    let rapid = it.spec.code_for(Meaning::Motion(MotionKind::Rapid))?;
    if cancel.group == rapid.group {
        return None;
    }
    match it.state.motion {
        ModalMotion::Move(k) => Some(k),
        _ => it.state.motion_before_cycle,
    }
}
