//! Siemens 840D semantics in the interpreter: programmable frames, cutting
//! edges, named cycle calls and MCALL modal calls.
//!
//! There is no Siemens oracle: every behaviour here is derived from the
//! documented semantics (`reference/dialects.md` §1, SINUMERIK 840D
//! programming manuals as summarised there); assumptions are marked `[?]`.
//!
//! Coordinate contract with the core:
//! * Canonical positions of Siemens programs are printed in the settable
//!   work offset's frame with the programmable frame applied ("base").
//!   The interpreter's state (`state.pos`) and its own [`MotionHost`]
//!   implementation work in that base frame.
//! * The core maps each programmed target through [`to_base`] (mm in, mm
//!   out; identity when no frame is active) and arcs through [`arc_to_base`];
//!   [`from_base`] gives the programmed position back (for G91 and for
//!   axes not written in a block).
//! * Cycles run here see programmed coordinates through [`FramedHost`].
//!
//! [`MotionHost`]: crate::interp::host::MotionHost

pub(crate) mod arcs;
mod calls;
mod edge;
pub(crate) mod frame;
mod host;
pub(crate) mod milling;
mod tool_data;
mod transform;

#[cfg(test)]
mod tests;

pub use edge::activate_edge;
pub use frame::ProgFrame;
pub use host::FramedHost;
pub use tool_data::assign as assign_tool_data;

use super::{Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, Block, Expr, Stmt, StmtKind, Transform};

/// A modal cycle call (`MCALL CYCLE81(...)`), arguments evaluated when
/// MCALL ran [?: Siemens passes cycle parameters by value at the call].
#[derive(Clone, Debug, PartialEq)]
pub struct ModalCall {
    pub name: String,
    pub args: Vec<Option<f64>>,
    /// A W0510 was already given for this call (it cannot be expanded).
    pub warned: bool,
}

/// The Siemens part of the machine state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SiemensState {
    /// The programmable frame (identity when none).
    pub frame: ProgFrame,
    /// The modal cycle call in force.
    pub modal: Option<ModalCall>,
    /// Direction of the last path move (programmed system), for `CT`.
    pub tangent: Option<[f64; 3]>,
}

/// A programmed point (mm) in the base frame (mm): identity when no
/// programmable frame is active.
pub fn to_base(it: &Interp<'_, '_>, p: [f64; 3]) -> [f64; 3] {
    it.siemens.frame.to_base(p)
}

/// A base point (mm) in programmed coordinates (mm); the point itself when
/// the frame cannot be inverted (a scale factor of 0 is refused when set).
pub fn from_base(it: &Interp<'_, '_>, b: [f64; 3]) -> [f64; 3] {
    it.siemens.frame.from_base(b).unwrap_or(b)
}

/// An arc in the active plane through the frame: end and centre (mm,
/// programmed, x y z), rotation as programmed (+ CCW). Gives the end and
/// centre in the base frame and the rotation to print, or an error when the
/// frame cannot keep the arc a circular arc in the active plane.
pub fn arc_to_base(
    it: &Interp<'_, '_>,
    end: [f64; 3],
    centre: [f64; 3],
    rotation: i64,
) -> Result<([f64; 3], [f64; 3], i64), Diagnostic> {
    let (a, b, n) = crate::interp::host::plane_axes(it.state.plane);
    let f = &it.siemens.frame;
    let flip = f.arc_map(a, b, n).map_err(|why| {
        Diagnostic::new(Code::UnsupportedHere, why)
            .help("program the contour without this frame, or with a uniform SCALE")
    })?;
    Ok((
        f.to_base(end),
        f.to_base(centre),
        if flip { -rotation } else { rotation },
    ))
}

/// Does the programmable frame mirror the active plane (an odd number of
/// mirrored plane axes)? Then G41 acts as G42 and G2 as G3 [K: the 840D
/// swaps them under MIRROR]; the core's radius compensation asks this.
pub fn mirrors_plane(it: &Interp<'_, '_>) -> bool {
    let (a, b, _) = crate::interp::host::plane_axes(it.state.plane);
    it.siemens.frame.mirrors(a, b)
}

/// Runs a frame, cutting-edge, cycle-call or MCALL statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let _ = block;
    match &s.kind {
        StmtKind::Transform(t) => match &**t {
            Transform::Frame {
                op,
                additive,
                axes,
                rpl,
            } => transform::exec(it, *op, *additive, axes, rpl.as_ref(), exprs),
            _ => Err(it.error_at(
                s.span,
                Code::UnsupportedHere,
                "not a Siemens programmable frame",
            )),
        },
        StmtKind::CuttingEdge(v) => edge::exec(it, v, exprs),
        StmtKind::CycleCall(c) => calls::exec(it, c, s.span, exprs),
        StmtKind::ModalCallCancel => {
            it.siemens.modal = None;
            Ok(())
        }
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the Siemens module",
        )),
    }
}

/// Called after every motion statement: a modal call (MCALL) runs its
/// cycle after each block that moves in the active plane [?: the manual
/// says "after each block with path motion"; a move along the tool axis
/// only (retract) does not call the cycle, which is what programs expect].
pub fn after_motion(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let _ = (block, exprs);
    if it.siemens.modal.is_none() {
        return Ok(());
    }
    let StmtKind::Motion(m) = &s.kind else {
        return Ok(());
    };
    let (a, b, _) = crate::interp::host::plane_axes(it.state.plane);
    let letters = ['X', 'Y', 'Z'];
    let in_plane = m.target.get(letters[a]).is_some()
        || m.target.get(letters[b]).is_some()
        || m.polar_angle.is_some()
        || m.polar_radius.is_some();
    if !in_plane {
        return Ok(());
    }
    calls::run_modal(it, s.span)
}
