//! LinuxCNC's polar words `@` (distance) and `^` (angle): the X Y they
//! give a move, and the polar step of a G91 canned cycle's repeats.

use super::cycle_io::CycleBlock;
use super::motion::{num, run_cycle};
use super::{Interp, Stop};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, Motion};

/// LinuxCNC polar words `@` (distance) and `^` (angle, degrees): the
/// absolute X Y (program units) they give. Under G90 a missing word keeps
/// the current point's distance or angle from the origin; under G91 both
/// are increments to the current point's distance and angle.
pub fn polar(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    exprs: &Arena<Expr>,
) -> Result<Option<(f64, f64)>, Stop> {
    if m.polar_radius.is_none() && m.polar_angle.is_none() {
        return Ok(None);
    }
    if let Some(i) = (0..2).find(|&i| m.target.get(['X', 'Y'][i]).is_some()) {
        return Err(polar_with_xy(it, i));
    }
    let (cx, cy) = (
        it.state.to_prog(it.state.pos[0]),
        it.state.to_prog(it.state.pos[1]),
    );
    let (cr, ca) = (cx.hypot(cy), cy.atan2(cx));
    if !it.state.absolute && cx == 0.0 && cy == 0.0 {
        return Err(it.error_at(
            it.span,
            Code::PolarAtOrigin,
            "G91 motion with polar coordinates is indeterminate when at the origin",
        ));
    }
    let r = num(it, &m.polar_radius, exprs)?;
    let a = num(it, &m.polar_angle, exprs)?.map(f64::to_radians);
    let (r, a) = if it.state.absolute {
        (r.unwrap_or(cr), a.unwrap_or(ca))
    } else {
        (cr + r.unwrap_or(0.0), ca + a.unwrap_or(0.0))
    };
    Ok(Some((r * a.cos(), r * a.sin())))
}

/// Polar words give X and Y: an X or Y word beside them is an error.
fn polar_with_xy(it: &mut Interp<'_, '_>, axis: usize) -> Stop {
    let msg = format!(
        "Cannot specify both polar coordinate and {} word",
        ["X", "Y"][axis]
    );
    it.read_error(it.span, Code::BadWordValue, msg)
}

/// A cycle block with polar words. Under G90 they give the hole's X Y
/// (L repeats drill it again); under G91 they are a step in distance and
/// angle about the program origin that every repeat takes, as LinuxCNC
/// does (the cycle code turns the step into positions).
pub(super) fn polar_cycle(
    it: &mut Interp<'_, '_>,
    mut cb: CycleBlock,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if let Some(i) = (0..2).find(|&i| cb.axes[i].is_some()) {
        return Err(polar_with_xy(it, i));
    }
    if cb.incremental {
        let r = num(it, &m.polar_radius, exprs)?.unwrap_or(0.0);
        let a = num(it, &m.polar_angle, exprs)?.unwrap_or(0.0);
        cb.polar_step = Some((r, a));
    } else if let Some((x, y)) = polar(it, m, exprs)? {
        cb.axes[0] = Some(x);
        cb.axes[1] = Some(y);
    }
    run_cycle(it, cb, block)
}
