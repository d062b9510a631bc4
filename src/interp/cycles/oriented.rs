//! Oriented boring in the Fanuc manner: fine boring (Fanuc/Haas G76) and
//! back boring (Fanuc G87, Haas G77), for codes whose dialect spec gives a
//! `shift` direction. Sources: Fanuc 0i-MF / 30i operator's manuals
//! ("fine boring cycle", "back boring cycle"; 15i: "Q is modal information
//! in a canned cycle, and is also used as the depth of cut of G73/G83"),
//! Haas mill manual (G76/G77: Q always incremental, direction by setting
//! 27; without Q the optional I and J give the shift).
//!
//! [?] Whether G80 clears the retained Q is not settled (the 0i manual says
//! G80 clears "other drilling data"); the run keeps Q across cycles, as it
//! keeps the peck depth.

use super::body::{orient_mode, start, turning, Levels};
use super::frame::Frame;
use super::memory::CycleMemory;
use super::word::Params;
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::cycle_io::CycleBlock;
use crate::interp::host::MotionHost;
use crate::ir::CycleKind;

/// The shift of one oriented-boring block, resolved.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Shift {
    /// The Q written in this block (kept as the cycles' Q).
    pub q: Option<f64>,
    /// The shift in plane terms (first, second positioning axis).
    pub by: (f64, f64),
    /// The I J words that gave the shift (Haas), kept for later blocks.
    pub ij: Option<[f64; 3]>,
}

/// The shift of a fine or back boring block whose code has a `shift`
/// direction; None for any other block. Q in the block wins; then I/J
/// written in the block; then what the last oriented block used (its I/J)
/// or the retained Q (0 at power-on: no shift).
pub(super) fn resolve(mem: &CycleMemory, block: &CycleBlock, f: Frame) -> Option<Shift> {
    if !matches!(block.kind, CycleKind::FineBore | CycleKind::BackBore) {
        return None;
    }
    let dir = block.shift?;
    if let Some(q) = block.q {
        return Some(Shift {
            q: Some(q),
            by: dir.vector(q),
            ij: None,
        });
    }
    let ij = if block.i.is_some() || block.j.is_some() {
        Some([block.i.unwrap_or(0.0), block.j.unwrap_or(0.0), 0.0])
    } else if mem.shift_ij {
        Some(mem.ijk)
    } else {
        None
    };
    let by = match ij {
        Some(v) => (v[f.a], v[f.b]),
        None => dir.vector(mem.q),
    };
    Some(Shift { q: None, by, ij })
}

/// Keeps what an oriented block used for the blocks after it.
pub(super) fn remember(mem: &mut CycleMemory, shift: &Shift) {
    if let Some(ij) = shift.ij {
        mem.ijk = ij;
        mem.shift_ij = true;
    } else if shift.q.is_some() {
        mem.shift_ij = false;
    }
}

/// W0520 when an oriented boring cycle shifts by nothing: the tool's edge
/// drags up the bored wall (fine boring) or cannot enter below the part
/// (back boring). The control runs it.
pub(super) fn no_shift_note(h: &mut dyn MotionHost, p: &Params, block: &CycleBlock) {
    let Some(s) = p.shift else { return };
    if s.by != (0.0, 0.0) || !block.code_in_block {
        return;
    }
    let what = if p.kind == CycleKind::BackBore {
        "the tool goes down through the hole with its edge out"
    } else {
        "the edge drags up the bored wall on the way out"
    };
    h.report(
        Diagnostic::new(Code::BoreNoShift, "oriented boring with no shift")
            .primary(block.span, "no Q here and none before: shift 0")
            .note(what)
            .help("give the shift away from the tool tip with Q (a positive distance)"),
    );
}

/// W0521 for R above Z in back boring: R is where the tool enters below the
/// part and Z the top of the back bore, so the cycle feeds downwards. The
/// control runs it as written [?: no alarm is documented for it].
pub(super) fn downward_note(h: &mut dyn MotionHost, r: f64, top: f64, block: &CycleBlock) {
    if r <= top || !block.code_in_block {
        return;
    }
    let msg = format!("back boring from R {r:.4} down to Z {top:.4}");
    h.report(
        Diagnostic::new(Code::BackBoreDownward, msg)
            .primary(block.span, "R above Z in back boring")
            .note("in back boring R is the level below the part where the tool enters, and Z the top of the bore it cuts upwards; this one feeds down")
            .help("give R below the part and Z above it (R < Z)"),
    );
}

/// Fanuc G87 / Haas G77 at one hole, from the initial level: orient,
/// shift, rapid down to R, shift back, spindle on, feed up to Z, dwell,
/// orient, shift, rapid out to the initial level, shift back, spindle on.
/// `l.bottom` is Z (the top of the bore), `l.clear` the initial level.
pub(super) fn back_bore(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let dir = turning(h, block)?;
    let s = p.shift.map(|s| s.by).unwrap_or((0.0, 0.0));
    let off = (l.at.0 + s.0, l.at.1 + s.1);
    let orient = Canon::OrientSpindle {
        angle: 0.0,
        mode: orient_mode(dir),
    };
    h.emit(Canon::StopSpindle);
    h.emit(orient.clone());
    f.rapid(h, off, l.clear);
    f.rapid(h, off, l.r);
    f.rapid(h, l.at, l.r);
    h.emit(start(dir));
    f.feed(h, l.at, l.bottom);
    if p.dwell > 0.0 {
        h.dwell(p.dwell);
    }
    h.emit(Canon::StopSpindle);
    h.emit(orient);
    f.rapid(h, off, l.bottom);
    f.rapid(h, off, l.clear);
    f.rapid(h, l.at, l.clear);
    h.emit(start(dir));
    Ok(())
}
