//! G2/G3: the centre from I J K (incremental, or absolute under G90.1) or
//! from R (negative R: the long way round), full circles, P turns,
//! helices, in all three planes; checked with LinuxCNC's tolerances and
//! messages. Inverse-time feeds become a per-minute rate for the arc.

use super::host::{plane_axes, MotionHost};
use super::machine::pose6;
use super::motion::check_feed;
use super::target::{target, Frame};
use super::{Interp, Stop};
use crate::canon::{Canon, CanonPlane, CanonUnits, Pose};
use crate::diag::Code;
use crate::ir::{ArcDir, Arena, Block, Coord, Expr, FeedMode, Motion};
use std::f64::consts::PI;

/// LinuxCNC's tolerance for the two radii of a centre-format arc
/// (absolute, in program units) and its relative tolerance. rs274 scales
/// its 0.002 in / 0.02 mm by sqrt(2) (`CENTER_ARC_RADIUS_TOLERANCE_*`): its
/// `good/` and `bad/` arc tests sit on both sides of 0.002 * sqrt(2) * 100.
fn radius_tolerance(units: CanonUnits) -> f64 {
    let base = match units {
        CanonUnits::Inches => 0.002,
        CanonUnits::Mm => 0.02,
    };
    base * std::f64::consts::SQRT_2
}
const RELATIVE_TOLERANCE: f64 = 0.001;
const TINY: f64 = 1e-12;

/// The letters of the first and second centre words in a plane, and the
/// letters of the plane's first and second axes (for messages).
fn plane_letters(plane: CanonPlane) -> (char, char, char, char) {
    match plane {
        CanonPlane::XY => ('I', 'J', 'X', 'Y'),
        CanonPlane::XZ => ('K', 'I', 'Z', 'X'),
        CanonPlane::YZ => ('J', 'K', 'Y', 'Z'),
    }
}

fn centre_word(m: &Motion, letter: char) -> Option<&Coord> {
    match letter {
        'I' => m.arc.i.as_ref(),
        'J' => m.arc.j.as_ref(),
        _ => m.arc.k.as_ref(),
    }
}

pub fn arc(
    it: &mut Interp<'_, '_>,
    dir: ArcDir,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let plane = it.state.plane;
    let (ci, cj, _, _) = plane_letters(plane);
    let (wi, wj) = (centre_word(m, ci), centre_word(m, cj));
    let has_centre = wi.is_some() || wj.is_some();
    if m.arc.radius.is_some() && has_centre {
        return Err(it.error_at(
            it.span,
            Code::ArcBadWords,
            "Mixed radius ijk format for arc",
        ));
    }
    if m.arc.radius.is_none() && !has_centre {
        let code = if dir == ArcDir::Cw { "G2" } else { "G3" };
        return Err(Stop::Error(
            crate::diag::Diagnostic::new(
                Code::ArcBadWords,
                format!("R i j k words all missing for arc: this block moves on a {code} arc with neither a centre ({ci} {cj}) nor a radius (R)"),
            )
            .primary(it.span, format!("{code} arc without a centre"))
            .help(format!("give the centre with {ci}/{cj} or the radius with R, or program G1 if this move is meant to be straight")),
        ));
    }
    let turns = match &m.arc.turns {
        Some(v) => it.value(v, exprs)?,
        None => 1.0,
    };
    if turns < 1.0 || turns.fract() != 0.0 {
        return Err(it.error_at(
            it.span,
            Code::BadWordValue,
            "P value not an integer with G2 or G3",
        ));
    }
    let from = MotionHost::position(it);
    let to = target(it, &m.target, exprs, Frame::Program)?;
    let to = pose6(&it.state, &to);
    let (a, b, _) = plane_axes(plane);
    let (s, e) = ((from[a], from[b]), (to[a], to[b]));
    let centre = match &m.arc.radius {
        Some(r) => {
            let r = it.value(r, exprs)?;
            centre_from_radius(it, dir, s, e, r)?
        }
        None => {
            let oi = match wi {
                Some(c) => it.value(&c.value, exprs)?,
                None => 0.0,
            };
            let oj = match wj {
                Some(c) => it.value(&c.value, exprs)?,
                None => 0.0,
            };
            let c = if it.state.arc_absolute {
                (oi, oj)
            } else {
                (s.0 + oi, s.1 + oj)
            };
            check_radii(it, s, c, e)?;
            c
        }
    };
    check_feed(
        it,
        block,
        "Cannot make arc with zero feed rate",
        "F word missing with inverse time arc move",
    )?;
    let turns = turns as i64;
    let rotation = if dir == ArcDir::Ccw { turns } else { -turns };
    if it.state.feed_mode == FeedMode::InverseTime {
        let rate = arc_length(plane, &from, &to, centre, rotation) * it.state.feed;
        it.out(Canon::SetFeedRate(rate));
    }
    it.arc_move(to, centre, rotation)
}

/// The centre of an R-format arc (LinuxCNC's construction).
fn centre_from_radius(
    it: &Interp<'_, '_>,
    dir: ArcDir,
    s: (f64, f64),
    e: (f64, f64),
    r: f64,
) -> Result<(f64, f64), Stop> {
    if s == e {
        return Err(it.error_at(
            it.span,
            Code::ArcBadWords,
            "Current point same as end point of arc",
        ));
    }
    let abs_r = r.abs();
    let mid = ((s.0 + e.0) / 2.0, (s.1 + e.1) / 2.0);
    let mut half = (mid.0 - e.0).hypot(mid.1 - e.1);
    if abs_r == 0.0 || half / abs_r > 1.0 + TINY {
        return Err(it.error_at(
            it.span,
            Code::ArcRadiusTooSmall,
            "Arc radius too small to reach end point",
        ));
    }
    if half / abs_r > 1.0 - TINY {
        half = abs_r;
    }
    let chord = (e.1 - s.1).atan2(e.0 - s.0);
    let theta = if (dir == ArcDir::Cw && r > 0.0) || (dir == ArcDir::Ccw && r < 0.0) {
        chord - PI / 2.0
    } else {
        chord + PI / 2.0
    };
    let offset = abs_r * (half / abs_r).asin().cos();
    Ok((mid.0 + offset * theta.cos(), mid.1 + offset * theta.sin()))
}

pub(crate) fn check_radii(
    it: &Interp<'_, '_>,
    s: (f64, f64),
    c: (f64, f64),
    e: (f64, f64),
) -> Result<(), Stop> {
    let r1 = (s.0 - c.0).hypot(s.1 - c.1);
    let r2 = (e.0 - c.0).hypot(e.1 - c.1);
    let abs_err = (r1 - r2).abs();
    let rel_err = abs_err / r1.max(r2);
    let tol = radius_tolerance(MotionHost::units(it));
    if abs_err > tol * 100.0 || (abs_err > tol && rel_err > RELATIVE_TOLERANCE) {
        let (_, _, x, y) = plane_letters(it.state.plane);
        let msg = format!(
            "Radius to end of arc differs from radius to start: start=({x}{:.4},{y}{:.4}) center=({x}{:.4},{y}{:.4}) end=({x}{:.4},{y}{:.4}) r1={r1:.4} r2={r2:.4} abs_err={} rel_err={:.4}%",
            s.0, s.1, c.0, c.1, e.0, e.1, g4(abs_err), rel_err * 100.0
        );
        return Err(it.error_at(it.span, Code::ArcEndNotOnCircle, msg));
    }
    Ok(())
}

/// C's `%.4g`, for the magnitudes arc errors have.
fn g4(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let exp = v.abs().log10().floor() as i32;
    if !(-4..4).contains(&exp) {
        return format!("{v:.3e}");
    }
    let s = format!("{:.*}", (3 - exp).max(0) as usize, v);
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// The helical length of an arc (for inverse-time feeds).
fn arc_length(plane: CanonPlane, from: &Pose, to: &Pose, c: (f64, f64), rotation: i64) -> f64 {
    let (a, b, n) = plane_axes(plane);
    let r = (from[a] - c.0).hypot(from[b] - c.1);
    let a0 = (from[b] - c.1).atan2(from[a] - c.0);
    let a1 = (to[b] - c.1).atan2(to[a] - c.0);
    let mut sweep = if rotation > 0 { a1 - a0 } else { a0 - a1 };
    if sweep <= 0.0 {
        sweep += 2.0 * PI;
    }
    sweep += (rotation.abs() - 1) as f64 * 2.0 * PI;
    (r * sweep).hypot(to[n] - from[n])
}
