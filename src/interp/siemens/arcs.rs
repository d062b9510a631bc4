//! Siemens 840D circles in the interpreter: `G2`/`G3` with a centre
//! (`I J K`, incremental, or `I=AC(..)` absolute), with `CR=` (negative: more
//! than 180°), with `AR=` (opening angle, with a centre or with an end
//! point), `TURN=` extra full turns (helix), `CIP` (through an intermediate
//! point `I1= J1= K1=`, incremental or absolute as the end point) and `CT`
//! (tangent to the previous path element), in the three planes.
//!
//! The geometry is computed in the programmed system (mm) and mapped to the
//! base frame through [`super::arc_to_base`]. The direction of the previous
//! move (programmed system) is kept in [`super::SiemensState::tangent`].
//! Sources: SINUMERIK 840D programming manual "Circular interpolation" as
//! summarised in `reference/dialects.md`; `[?]` marks assumptions.

use crate::canon::Canon;
use crate::diag::Code;
use crate::interp::host::plane_axes;
use crate::interp::machine::pose6;
use crate::interp::motion::check_feed;
use crate::interp::target::{target, Frame};
use crate::interp::{Interp, Stop};
use crate::ir::{ArcDir, Arena, Block, Coord, DimMode, Expr, FeedMode, Motion, MotionKind};

type P2 = (f64, f64);
/// Start and end (programmed, mm, x y z) and the end in the base frame.
type Ends = ([f64; 3], [f64; 3], [f64; 9]);
const EPS: f64 = 1e-9;

/// The centre of the arc from `s` to `e` with opening angle `deg`
/// (0 < deg < 360) turning `ccw`.
pub fn centre_from_angle(s: P2, e: P2, deg: f64, ccw: bool) -> Option<P2> {
    let (dx, dy) = (e.0 - s.0, e.1 - s.1);
    let d = dx.hypot(dy);
    if d < EPS || !(deg > 0.0 && deg < 360.0) {
        return None;
    }
    // Distance of the centre from the chord's midpoint, to the left of
    // s->e for a CCW arc under 180° (negative beyond 180°).
    let h = (d / 2.0) / (deg.to_radians() / 2.0).tan();
    let h = if ccw { h } else { -h };
    let (nx, ny) = (-dy / d, dx / d);
    Some(((s.0 + e.0) / 2.0 + h * nx, (s.1 + e.1) / 2.0 + h * ny))
}

/// The centre of the arc from `s` to `e` of radius `r` (CR=; negative:
/// the long way round) turning `ccw`.
pub fn centre_from_radius(s: P2, e: P2, r: f64, ccw: bool) -> Option<P2> {
    let d = (e.0 - s.0).hypot(e.1 - s.1);
    if d < EPS || r.abs() < d / 2.0 - EPS {
        return None;
    }
    let half = (d / 2.0).min(r.abs());
    let deg = 2.0 * (half / r.abs()).asin().to_degrees();
    let deg = if r < 0.0 { 360.0 - deg } else { deg };
    if deg >= 360.0 - EPS {
        return None;
    }
    centre_from_angle(s, e, deg.max(EPS), ccw)
}

/// The end of the arc from `s` round `c` through `deg` turning `ccw`.
pub fn end_from_angle(s: P2, c: P2, deg: f64, ccw: bool) -> P2 {
    let a = if ccw {
        deg.to_radians()
    } else {
        -deg.to_radians()
    };
    let (x, y) = (s.0 - c.0, s.1 - c.1);
    (
        c.0 + x * a.cos() - y * a.sin(),
        c.1 + x * a.sin() + y * a.cos(),
    )
}

/// The circle through `s`, `m`, `e`: its centre and whether the path
/// s->m->e turns CCW. None when the points are collinear.
pub fn circle_through(s: P2, m: P2, e: P2) -> Option<(P2, bool)> {
    let (bx, by) = (m.0 - s.0, m.1 - s.1);
    let (cx, cy) = (e.0 - s.0, e.1 - s.1);
    let d = 2.0 * (bx * cy - by * cx);
    if d.abs() < EPS {
        return None;
    }
    let (b2, c2) = (bx * bx + by * by, cx * cx + cy * cy);
    let ux = (cy * b2 - by * c2) / d;
    let uy = (bx * c2 - cx * b2) / d;
    Some(((s.0 + ux, s.1 + uy), d > 0.0))
}

/// The arc from `s` to `e` leaving `s` along direction `t`: its centre and
/// whether it turns CCW. None when `e` lies on the tangent line (a straight).
pub fn tangent_circle(s: P2, t: P2, e: P2) -> Option<(P2, bool)> {
    let tl = t.0.hypot(t.1);
    if tl < EPS {
        return None;
    }
    let (nx, ny) = (-t.1 / tl, t.0 / tl);
    let (vx, vy) = (e.0 - s.0, e.1 - s.1);
    let side = nx * vx + ny * vy;
    if side.abs() < EPS {
        return None;
    }
    let k = (vx * vx + vy * vy) / (2.0 * side);
    Some(((s.0 + k * nx, s.1 + k * ny), side > 0.0))
}

/// The direction of travel at the end of an arc round `c` ending at `e`.
pub fn end_direction(c: P2, e: P2, ccw: bool) -> P2 {
    let (x, y) = (e.0 - c.0, e.1 - c.1);
    if ccw {
        (-y, x)
    } else {
        (y, -x)
    }
}

fn centre_word(m: &Motion, index: usize) -> Option<&Coord> {
    [m.arc.i.as_ref(), m.arc.j.as_ref(), m.arc.k.as_ref()][index]
}

fn mid_word(m: &Motion, index: usize) -> Option<&Coord> {
    m.arc
        .mid
        .as_ref()
        .and_then(|a| a.get(['X', 'Y', 'Z'][index]))
}

/// The programmed point (mm) of a Siemens arc's start, end (x y z).
fn ends(it: &mut Interp<'_, '_>, m: &Motion, exprs: &Arena<Expr>) -> Result<Ends, Stop> {
    let p = it.state.pos;
    let s = super::from_base(it, [p[0], p[1], p[2]]);
    let base = target(it, &m.target, exprs, Frame::Program)?;
    let e = super::from_base(it, [base[0], base[1], base[2]]);
    Ok((s, e, base))
}

/// A value of a centre or intermediate-point word, mm, absolute in the
/// programmed system: `AC()` or (for I1= under G90) absolute, else
/// relative to the start.
fn point_value(
    it: &mut Interp<'_, '_>,
    c: &Coord,
    start: f64,
    absolute: bool,
    exprs: &Arena<Expr>,
) -> Result<f64, Stop> {
    let v = it.value(&c.value, exprs)?;
    let v = it.state.to_mm(v);
    let abs = c.dim.map(|d| d == DimMode::Absolute).unwrap_or(absolute);
    Ok(if abs { v } else { start + v })
}

/// Runs a Siemens arc: `G2`/`G3` (any form), `CIP` or `CT`.
pub fn arc(
    it: &mut Interp<'_, '_>,
    kind: MotionKind,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let (a, b, _) = plane_axes(it.state.plane);
    let (s3, mut e3, mut base) = ends(it, m, exprs)?;
    let mut e = (e3[a], e3[b]);
    let Some((centre, ccw)) = centre_of(it, kind, m, s3, &mut e, exprs)? else {
        return tangent_straight(it, base, e3, s3);
    };
    e3[a] = e.0;
    e3[b] = e.1;
    let mut turns = match &m.arc.turns {
        Some(v) => it.value(v, exprs)?,
        None => 0.0,
    };
    // 840D programming manual: TURN= is the number of additional full
    // circles, 0 to 999.
    if !(0.0..=999.0).contains(&turns) || turns.fract() != 0.0 {
        let d = crate::diag::Diagnostic::new(
            Code::BadWordValue,
            format!("TURN={turns} is not a whole number of full circles from 0 to 999"),
        )
        .primary(it.span, "this helix")
        .help("TURN= counts the full circles added to the arc; the part of a circle comes from the end point (a half turn is TURN=0 with the end opposite the start)");
        if !it.opts.keep_going || it.recovered >= super::super::MAX_RECOVERED {
            return Err(Stop::Error(d));
        }
        // The end point is sound: the run goes on from it, so the blocks
        // after are checked from where the program meant to be.
        it.recovered += 1;
        it.diags.push(
            d.note("the run went on with the arc alone (TURN=0), to the end point the block gives"),
        );
        turns = 0.0;
    }
    check_feed(
        it,
        block,
        "Cannot make arc with zero feed rate",
        "F word missing with inverse time arc move",
    )?;
    let r = 1 + turns as i64;
    let mut c3 = s3;
    c3[a] = centre.0;
    c3[b] = centre.1;
    let (eb, cb, rot) = super::arc_to_base(it, e3, c3, if ccw { r } else { -r })
        .map_err(|d| Stop::Error(d.primary(it.span, "this arc")))?;
    base[..3].copy_from_slice(&eb);
    let to = pose6(&it.state, &base);
    let centre_prog = (it.state.to_prog(cb[a]), it.state.to_prog(cb[b]));
    let d = end_direction(centre, e, ccw);
    let mut t = [0.0; 3];
    t[a] = d.0;
    t[b] = d.1;
    it.siemens.tangent = Some(t);
    if it.state.feed_mode == FeedMode::InverseTime {
        let len = helix_length(s3, e3, c3, (a, b), if ccw { r } else { -r });
        it.out(Canon::SetFeedRate(it.state.to_prog(len) * it.state.feed));
    }
    it.arc_move(to, centre_prog, rot)
}

/// The length (mm) of an arc from `s` to `e` round `c` (programmed, mm)
/// with `rotation` turns as printed (+ CCW), the helix rise included.
pub fn helix_length(
    s: [f64; 3],
    e: [f64; 3],
    c: [f64; 3],
    (a, b): (usize, usize),
    rotation: i64,
) -> f64 {
    let n = 3 - a - b;
    let r = (s[a] - c[a]).hypot(s[b] - c[b]);
    let a0 = (s[b] - c[b]).atan2(s[a] - c[a]);
    let a1 = (e[b] - c[b]).atan2(e[a] - c[a]);
    let tau = 2.0 * std::f64::consts::PI;
    let mut sweep = if rotation > 0 { a1 - a0 } else { a0 - a1 };
    if sweep <= 1e-12 {
        sweep += tau;
    }
    sweep += (rotation.unsigned_abs().max(1) - 1) as f64 * tau;
    (r * sweep).hypot(e[n] - s[n])
}

/// The centre and direction of a Siemens arc (None: a `CT` along the
/// tangent, a straight); `e` is the end in the plane, which `AR=` with a
/// centre sets.
fn centre_of(
    it: &mut Interp<'_, '_>,
    kind: MotionKind,
    m: &Motion,
    s3: [f64; 3],
    e: &mut P2,
    exprs: &Arena<Expr>,
) -> Result<Option<(P2, bool)>, Stop> {
    let (a, b, _) = plane_axes(it.state.plane);
    let s = (s3[a], s3[b]);
    let found = match kind {
        MotionKind::ArcThrough => {
            let mut mp = s3;
            for (i, v) in mp.iter_mut().enumerate() {
                if let Some(c) = mid_word(m, i) {
                    *v = point_value(it, c, s3[i], it.state.absolute, exprs)?;
                }
            }
            circle_through(s, (mp[a], mp[b]), *e).ok_or_else(|| {
                it.error_at(
                    it.span,
                    Code::ArcBadWords,
                    "CIP: start, intermediate and end points lie on a line",
                )
            })?
        }
        MotionKind::ArcTangent => {
            let t = it.siemens.tangent.unwrap_or([0.0; 3]);
            match tangent_circle(s, (t[a], t[b]), *e) {
                Some(c) => c,
                None if (t[a], t[b]) != (0.0, 0.0) => return Ok(None),
                None => {
                    return Err(it.error_at(
                        it.span,
                        Code::ArcBadWords,
                        "CT: no previous path direction to be tangent to",
                    ))
                }
            }
        }
        MotionKind::Arc(dir) => {
            let ccw = dir == ArcDir::Ccw;
            (g2g3_centre(it, m, s3, e, (a, b), ccw, exprs)?, ccw)
        }
        _ => return Err(it.error_at(it.span, Code::UnsupportedHere, "not a Siemens arc")),
    };
    Ok(Some(found))
}

/// After a straight move from `from` (base, mm): keeps its direction in
/// the programmed system for a following `CT`.
pub fn note_straight(it: &mut Interp<'_, '_>, from: [f64; 9]) {
    let p = it.state.pos;
    let s = super::from_base(it, [from[0], from[1], from[2]]);
    let e = super::from_base(it, [p[0], p[1], p[2]]);
    let d = [e[0] - s[0], e[1] - s[1], e[2] - s[2]];
    if d.iter().any(|v| v.abs() > EPS) {
        it.siemens.tangent = Some(d);
    }
}

/// CT to a point on the tangent line: a straight feed.
fn tangent_straight(
    it: &mut Interp<'_, '_>,
    base: [f64; 9],
    e3: [f64; 3],
    s3: [f64; 3],
) -> Result<(), Stop> {
    let to = pose6(&it.state, &base);
    it.siemens.tangent = Some([e3[0] - s3[0], e3[1] - s3[1], e3[2] - s3[2]]);
    it.straight_move(crate::interp::comp::MoveKind::Feed, to)
}

/// The centre of a G2/G3: centre words, CR=, or AR= (which with a centre
/// and no end point in the plane gives the end point).
fn g2g3_centre(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    s3: [f64; 3],
    e: &mut P2,
    (a, b): (usize, usize),
    ccw: bool,
    exprs: &Arena<Expr>,
) -> Result<P2, Stop> {
    let s = (s3[a], s3[b]);
    let has_centre = centre_word(m, a).is_some() || centre_word(m, b).is_some();
    let angle = match &m.arc.angle {
        Some(v) => Some(it.value(v, exprs)?),
        None => None,
    };
    let letters = ['X', 'Y', 'Z'];
    let end_written = m.target.get(letters[a]).is_some() || m.target.get(letters[b]).is_some();
    if has_centre {
        let mut c = [s3[0], s3[1], s3[2]];
        for i in [a, b] {
            if let Some(w) = centre_word(m, i) {
                c[i] = point_value(it, w, s3[i], false, exprs)?;
            }
        }
        let c = (c[a], c[b]);
        if let (Some(deg), false) = (angle, end_written) {
            *e = end_from_angle(s, c, deg, ccw);
            return Ok(c);
        }
        check_radii(it, s, c, *e)?;
        return Ok(c);
    }
    if let Some(deg) = angle {
        return centre_from_angle(s, *e, deg, ccw).ok_or_else(|| {
            it.error_at(
                it.span,
                Code::ArcBadWords,
                "AR= needs an end point away from the start and an angle between 0 and 360",
            )
        });
    }
    if let Some(r) = &m.arc.radius {
        let r = it.value(r, exprs)?;
        let r = it.state.to_mm(r);
        return centre_from_radius(s, *e, r, ccw).ok_or_else(|| {
            it.error_at(
                it.span,
                Code::ArcRadiusTooSmall,
                "Arc radius too small to reach end point",
            )
        });
    }
    Err(it.error_at(
        it.span,
        Code::ArcBadWords,
        "circle without centre, CR= or AR=",
    ))
}

/// The end point must lie on the circle (0.02 mm or 0.1 % [?: the 840D's
/// machine data; LinuxCNC's tolerance used]).
fn check_radii(it: &Interp<'_, '_>, s: P2, c: P2, e: P2) -> Result<(), Stop> {
    let r1 = (s.0 - c.0).hypot(s.1 - c.1);
    let r2 = (e.0 - c.0).hypot(e.1 - c.1);
    let err = (r1 - r2).abs();
    if err > 2.0 || (err > 0.02 && err / r1.max(r2) > 0.001) {
        let msg = format!("end point not on the circle: r1={r1:.4} r2={r2:.4} (mm)");
        return Err(it.error_at(it.span, Code::ArcEndNotOnCircle, msg));
    }
    Ok(())
}

#[cfg(test)]
#[path = "arcs_tests.rs"]
mod tests;
