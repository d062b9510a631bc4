//! Haas G12 (clockwise) / G13 (counter-clockwise) circular pocket
//! milling, run where the spec gives a code the meaning
//! `pocket.circular-cw` / `pocket.circular-ccw`, expanded into moves
//! about the tool's position.
//!
//! Words (Haas mill manual [K]): I radius of the first circle (the
//! finished radius when there is no K), K radius of the finished circle,
//! Q radial step from I out to K (needed with K), Z depth (absolute in
//! G90; in G91 an increment from the start, repeated L times), L number
//! of depth passes, D the offset whose tool radius the circles are
//! compensated by (absent or D0: the radii are the tool centre's). F is
//! the block's own feed word. X and Y in the block move to the centre
//! first (a rapid at the current height [?]); a Z among the block's axis
//! words is the cycle's depth, not a move.
//!
//! The path is not specified in our references; what is built here, each
//! point [?]:
//! * per depth pass: feed down to the level at the centre; for each
//!   radius from I by Q up to K (K last): feed straight out along +X to
//!   the circle, cut the full circle as two half arcs (G12 clockwise,
//!   G13 counter-clockwise); then feed back to the centre;
//! * the cycle ends at the centre, at the last depth (the Haas examples
//!   follow it with a `G0 Z` retract);
//! * in G90 with L > 1 the same depth is cut L times (Haas intends L
//!   with G91);
//! * D n takes tool n's diameter from the tool table (our reading of the
//!   Haas D offset; the control reads its diameter offset register).
//!
//! Not run: another plane than G17, or cutter compensation already on
//! (the cycle compensates itself); I not beyond the tool radius, K less
//! than or equal to I (the Haas reference: I more than the tool radius,
//! less than K), K without a positive Q. Each is an error with its own
//! code.

use super::host::MotionHost;
use super::machine::pose6;
use super::state::MM_PER_INCH;
use super::target::{target, Frame};
use super::{Interp, Stop};
use crate::canon::{CanonPlane, Pose};
use crate::diag::Code;
use crate::dialect::{DialectSpec, MachineFn};
use crate::ir::{Arena, Block, Decimal, Expr, LengthUnit, StmtKind, Word};

/// Most circles (rings × depth passes) one call may cut.
const MAX_CIRCLES: f64 = 100_000.0;

/// Is this code a circular pocket in `spec` (its meaning `pocket.circular-cw`
/// or `-ccw`)?
pub fn is_circular_pocket(spec: &DialectSpec, letter: char, code: Decimal) -> bool {
    matches!(
        super::aux::machine_fn(spec, letter, code),
        Some(MachineFn::CircularPocket { .. })
    )
}

/// The cycle's words, resolved and checked.
struct Pocket {
    clockwise: bool,
    /// Tool-centre radii of the circles, first to last.
    radii: Vec<f64>,
    /// Depth of each pass (program frame Z).
    levels: Vec<f64>,
}

fn word(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match words
        .iter()
        .find(|w| w.letter.eq_ignore_ascii_case(&letter))
    {
        Some(w) => Ok(Some(it.value(&w.value, exprs)?)),
        None => Ok(None),
    }
}

fn fail(it: &Interp<'_, '_>, code: Code, msg: String) -> Stop {
    it.error_at(it.span, code, msg)
}

/// The radius the circles are compensated by: D n's tool, in program units.
fn d_radius(it: &mut Interp<'_, '_>, d: Option<f64>) -> Result<f64, Stop> {
    let t = match d {
        None => return Ok(0.0),
        Some(v) if v.fract() != 0.0 || v < 0.0 => {
            return Err(fail(
                it,
                Code::CycleBadArgument,
                format!("G12/G13: D{v} is not an offset number"),
            ))
        }
        Some(v) => v as i64,
    };
    if t == 0 {
        return Ok(0.0);
    }
    crate::interp::tools::known_tool(it, t)?;
    let Some(tool) = it.tool_table.get(t) else {
        return Err(fail(
            it,
            Code::ToolNotInTable,
            format!("G12/G13: D{t}: tool {t} is not in the tool table"),
        ));
    };
    let scale = match it.opts.machine_units {
        LengthUnit::Inch => MM_PER_INCH,
        LengthUnit::Mm => 1.0,
    };
    Ok(it.state.to_prog(tool.diameter * scale) / 2.0)
}

fn read(
    it: &mut Interp<'_, '_>,
    g: &str,
    clockwise: bool,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<Pocket, Stop> {
    if it.state.plane != CanonPlane::XY {
        return Err(fail(
            it,
            Code::UnsupportedHere,
            format!("{g} runs in the G17 (XY) plane only"),
        ));
    }
    if it.comp.is_on() {
        return Err(fail(
            it,
            Code::CircularPocketComp,
            format!("{g} with cutter compensation on: the cycle compensates by its D word itself"),
        ));
    }
    let Some(i) = word(it, words, 'I', exprs)? else {
        return Err(fail(
            it,
            Code::CycleMissingWord,
            format!("{g} needs I (radius of the first circle)"),
        ));
    };
    let k = word(it, words, 'K', exprs)?;
    let q = word(it, words, 'Q', exprs)?;
    let d = word(it, words, 'D', exprs)?;
    let r = d_radius(it, d)?;
    if i <= r + 1e-6 {
        return Err(fail(
            it,
            Code::CircularPocketRadius,
            format!("{g}: I{i} is not beyond the tool radius {r}"),
        ));
    }
    let mut radii = vec![i];
    if let Some(k) = k {
        if k <= i {
            return Err(fail(
                it,
                Code::CircularPocketRadius,
                format!("{g}: K{k} is not more than I{i}"),
            ));
        }
        let q = match q {
            Some(q) if q > 0.0 => q,
            _ => {
                return Err(fail(
                    it,
                    Code::CircularPocketStep,
                    format!("{g}: K needs a positive Q (the radial step from I to K)"),
                ))
            }
        };
        if (k - i) / q > MAX_CIRCLES {
            return Err(fail(
                it,
                Code::LimitExceeded,
                format!("{g}: more than {MAX_CIRCLES} circles"),
            ));
        }
        let mut next = i + q;
        while next < k - 1e-9 {
            radii.push(next);
            next += q;
        }
        radii.push(k);
    }
    let radii = radii.into_iter().map(|x| x - r).collect();
    let levels = levels(it, g, words, exprs, radii_len(k, i, q))?;
    Ok(Pocket {
        clockwise,
        radii,
        levels,
    })
}

fn radii_len(k: Option<f64>, i: f64, q: Option<f64>) -> f64 {
    match (k, q) {
        (Some(k), Some(q)) if q > 0.0 => ((k - i) / q).ceil() + 1.0,
        _ => 1.0,
    }
}

/// The depth of each pass: Z (absolute in G90, an increment per pass in
/// G91), L passes; no Z: at the current height.
fn levels(
    it: &mut Interp<'_, '_>,
    g: &str,
    words: &[Word],
    exprs: &Arena<Expr>,
    rings: f64,
) -> Result<Vec<f64>, Stop> {
    let start = MotionHost::position(it)[2];
    let z = word(it, words, 'Z', exprs)?;
    let l = word(it, words, 'L', exprs)?.unwrap_or(1.0);
    if l < 1.0 || l.fract() != 0.0 || l * rings > MAX_CIRCLES {
        return Err(fail(
            it,
            Code::CycleBadRepeat,
            format!(
                "{g}: L{l} is not a number of passes from 1 (at most {MAX_CIRCLES} circles in all)"
            ),
        ));
    }
    let n = l as usize;
    Ok((1..=n)
        .map(|p| match z {
            None => start,
            Some(z) if it.state.absolute => z,
            Some(dz) => start + dz * p as f64,
        })
        .collect())
}

/// The pocket's centre: the block's X/Y words (a rapid there at the
/// current height [?]), else the current position.
fn centre(it: &mut Interp<'_, '_>, block: &Block, exprs: &Arena<Expr>) -> Result<Pose, Stop> {
    let axes = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Motion(m) if !m.target.is_empty() => Some(&m.target),
        _ => None,
    });
    let here = MotionHost::position(it);
    let Some(axes) = axes else {
        return Ok(here);
    };
    let to = target(it, axes, exprs, Frame::Program)?;
    let mut to = pose6(&it.state, &to);
    to[2] = here[2];
    if to != here {
        MotionHost::rapid(it, to);
    }
    Ok(to)
}

/// Runs G12/G13: the block's X/Y (the centre), then the circles.
pub fn exec(
    it: &mut Interp<'_, '_>,
    letter: char,
    code: Decimal,
    clockwise: bool,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let g = format!("{letter}{}", code.format(0, false));
    let p = read(it, &g, clockwise, words, exprs)?;
    if it.state.feed <= 0.0 {
        return Err(fail(
            it,
            Code::NoFeedRate,
            "G12/G13 with no feed rate (F)".into(),
        ));
    }
    let c: Pose = centre(it, block, exprs)?;
    let at = |x: f64, y: f64, z: f64| -> Pose {
        let mut q = c;
        q[0] = x;
        q[1] = y;
        q[2] = z;
        q
    };
    let turn = if p.clockwise { -1 } else { 1 };
    for z in &p.levels {
        MotionHost::feed(it, at(c[0], c[1], *z));
        for rho in &p.radii {
            MotionHost::feed(it, at(c[0] + rho, c[1], *z));
            MotionHost::arc(it, at(c[0] - rho, c[1], *z), (c[0], c[1]), turn);
            MotionHost::arc(it, at(c[0] + rho, c[1], *z), (c[0], c[1]), turn);
        }
        MotionHost::feed(it, at(c[0], c[1], *z));
    }
    Ok(())
}
