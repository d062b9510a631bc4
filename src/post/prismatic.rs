//! Features whose cross-section is not a plain U: slots with a V profile
//! (`VEE_PROFILE`) or a square U with sloped walls, and steps (ISO
//! 14649-10 `STEP`: an open-sided shoulder, its wall a `VEE_PROFILE`).
//! No target has a cycle for them; they are posted as explicit passes
//! along the course of travel, planned on the cross-section
//! ([`super::paths::section`]): levels from the top, each clearing the
//! width the tool can reach there, the level spacing halved until the
//! steps a flat tool leaves on a sloped wall (or a ball's scallops) are
//! within the tolerance. The tolerance is the tightest of the feature's
//! toleranced sizes and the workpiece's global tolerance, else
//! [`DEFAULT_TOL`] [?]. A roughing cut leaves its allowance (normal to the
//! surface) and steps at its axial depth. The last workingstep on the
//! feature must make the section within the tolerance: where its tool
//! cannot (a flat tool in a V's rounded point), the post refuses (E0902,
//! with how much is left and where); earlier cuts leave for later ones.
//!
//! Profile angles: ISO 14649 gives plane angles in degrees, but
//! generators write radians; an angle that is a whole number of degrees
//! once read as radians (and not a whole number itself) is read as
//! radians, with a warning ([`super::angles`]).

use super::angles::read_angle;
use super::frame::Frame;
use super::milling::{spindle_cw, Cut};
use super::paths::section::{self, Pass, Section, ToolShape};
use super::paths::MoveSink;
use super::plan::Step;
use super::validate::Aabb;
use super::{PostError, Writer};
use crate::stepnc::model::*;

/// The feature's its_id, or its workingstep's when the file leaves it
/// empty (so that messages can be located).
fn name<'s>(s: &'s Step<'_>) -> &'s str {
    if s.feature.id.is_empty() {
        &s.ws.id
    } else {
        &s.feature.id
    }
}

/// The tolerance when neither the feature nor the workpiece gives one.
pub const DEFAULT_TOL: f64 = 0.05;

/// How far the passes run out past an open end, beyond the tool radius.
const RUN_OUT: f64 = 2.0;

/// A slot this module posts: a V profile, or a square U whose walls slope.
pub fn is_profiled_slot(k: &FeatureKind) -> bool {
    match k {
        FeatureKind::Slot { swept_shape, .. } => match swept_shape {
            OpenProfile::Vee { .. } => true,
            OpenProfile::SquareU {
                first_angle,
                second_angle,
                ..
            } => !super::slots::upright(*first_angle) || !super::slots::upright(*second_angle),
            _ => false,
        },
        _ => false,
    }
}

/// What the writer of one prismatic feature needs besides the step.
pub struct Context {
    pub tol: f64,
    pub stock: Option<Aabb>,
    /// Another workingstep cuts this feature later.
    pub later: bool,
}

/// A V or sloped-U slot.
pub fn write_slot(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    ctx: &Context,
) -> Result<(), PostError> {
    let FeatureKind::Slot {
        swept_shape,
        end_conditions,
        ..
    } = &s.feature.kind
    else {
        return Err(PostError::unsupported(&s.feature.id, "this feature"));
    };
    let (frame, travel) = super::slots::slot_frame(s)?;
    if !(end_conditions.len() == 2 && end_conditions.iter().all(|e| matches!(e, SlotEnd::Open))) {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a V or sloped-wall slot whose ends are not open (the shape of a closed end under such a profile is not generated; cncc's limit)",
        ));
    }
    let sec = match swept_shape {
        OpenProfile::Vee {
            radius,
            angle,
            tilt_angle,
            ..
        } => {
            let a = read_angle(w, name(s), "VEE_PROFILE profile_angle", *angle);
            let t = read_angle(w, name(s), "VEE_PROFILE tilt_angle", *tilt_angle);
            vee(&s.feature.id, radius.nominal, a, t, s.top, s.bottom)?
        }
        OpenProfile::SquareU {
            width,
            first_radius,
            first_angle,
            second_radius,
            second_angle,
            ..
        } => {
            let r = |v: &Option<Toleranced>| v.as_ref().map_or(0.0, |t| t.nominal);
            let mut ang = |v: Option<f64>, what: &str| {
                v.map_or(0.0, |a| {
                    let d = read_angle(w, name(s), what, a);
                    if super::slots::upright(Some(d)) {
                        0.0
                    } else {
                        d
                    }
                })
            };
            let a1 = ang(*first_angle, "SQUARE_U_PROFILE first_angle");
            let a2 = ang(*second_angle, "SQUARE_U_PROFILE second_angle");
            sloped_u(
                &s.feature.id,
                width.nominal,
                (r(first_radius), a1),
                (r(second_radius), a2),
                s.top,
                s.bottom,
            )?
        }
        _ => return Err(PostError::unsupported(&s.feature.id, "this slot profile")),
    };
    let rt = s.tool.body.dimension.diameter / 2.0;
    let along = (-rt - RUN_OUT, travel + rt + RUN_OUT);
    // The slot's frame has its origin at the middle of the course.
    let placed = frame.then(&Frame {
        origin: [-travel / 2.0, 0.0, 0.0],
        x: [1.0, 0.0, 0.0],
        y: [0.0, 1.0, 0.0],
        z: [0.0, 0.0, 1.0],
    });
    let width = sec.points[sec.points.len() - 1][0] - sec.points[0][0];
    let centres = (-width, width);
    w.comment(&format!(
        "{} slot: explicit passes along the slot, planned on its cross-section (no target has a cycle for it)",
        match swept_shape {
            OpenProfile::Vee { .. } => "V",
            _ => "sloped-wall U",
        }
    ))?;
    cut(w, s, c, ctx, &sec, centres, (along, &[]), &placed)
}

/// A step: the boundary's frame, the floor out to the stock's edge.
pub fn write_step(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    ctx: &Context,
) -> Result<(), PostError> {
    let FeatureKind::Step {
        open_boundary,
        wall_boundary,
        bosses,
    } = &s.feature.kind
    else {
        return Err(PostError::unsupported(&s.feature.id, "this feature"));
    };
    if !bosses.is_empty() {
        return Err(PostError::unsupported(&s.feature.id, "a step with bosses"));
    }
    let TravelPath::Linear {
        placement,
        distance,
        direction,
    } = open_boundary
    else {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a step whose open boundary is not a straight path",
        ));
    };
    let frame = super::slots::line_frame(
        s,
        placement,
        direction,
        0.0,
        "a path that leaves the feature's plane",
    )?;
    let len = distance.nominal;
    let Some(stock) = ctx.stock else {
        return Err(PostError::broken(
            &s.feature.id,
            "a step is open to the workpiece's side, so its width is the stock's: the workpiece gives no BLOCK",
        ));
    };
    // Across: from the boundary (u 0) to the right, out to the stock's
    // edge; the material is on the left (ISO 14649-10).
    let right = frame.rotate([0.0, -1.0, 0.0]);
    let reach = |p: [f64; 3]| exit_distance(&stock, p, right);
    let (p0, p1) = (frame.apply([0.0, 0.0, 0.0]), frame.apply([len, 0.0, 0.0]));
    let width = reach(p0).max(reach(p1));
    if width <= 1e-6 {
        return Err(PostError::outside(
            &s.feature.id,
            "the step's boundary lies on or outside the stock's edge: nothing to remove".into(),
            "check the step's placement and the direction of its open boundary (the material is on its left)".into(),
        ));
    }
    let (wall, radius) = match wall_boundary {
        None => (0.0, 0.0),
        Some(OpenProfile::Vee { radius, angle, .. }) => {
            // The V's sides are the floor and the wall; the angle between
            // them is the removed volume's: 90 is an upright wall.
            let a = read_angle(w, name(s), "VEE_PROFILE profile_angle", *angle);
            if a < 90.0 - 1e-6 {
                return Err(PostError::unsupported(
                    &s.feature.id,
                    &format!("a step whose wall overhangs its floor (profile angle {a}°: under 90° a 3-axis tool cannot reach under the wall)"),
                ));
            }
            (a - 90.0, radius.nominal)
        }
        Some(_) => {
            return Err(PostError::unsupported(
                &s.feature.id,
                "a step whose wall boundary is not a V profile",
            ))
        }
    };
    let sec = step_section(&s.feature.id, width, wall, radius, s.top, s.bottom)?;
    let rt = s.tool.body.dimension.diameter / 2.0;
    // An end on the stock's edge is run out past; one inside the stock
    // stops with the tool's edge on it.
    let inside = |p: [f64; 3]| exit_distance(&stock, p, frame.rotate([-1.0, 0.0, 0.0])) > 1e-6;
    let start = if inside(p0) { rt } else { -rt - RUN_OUT };
    let end_inside = exit_distance(&stock, p1, frame.rotate([1.0, 0.0, 0.0])) > 1e-6;
    let end = if end_inside {
        len - rt
    } else {
        len + rt + RUN_OUT
    };
    if end <= start {
        return Err(PostError::geometry(
            &s.feature.id,
            format!("the step is {len} mm long between material at both ends: shorter than the tool's diameter"),
        ));
    }
    w.comment("step: explicit passes along its open boundary, out to the stock's edge (no target has a cycle for it)")?;
    let mut closed = Vec::new();
    if inside(p0) {
        closed.push(start);
    }
    if end_inside {
        closed.push(end);
    }
    cut(
        w,
        s,
        c,
        ctx,
        &sec,
        (-width, 0.0),
        ((start, end), &closed),
        &frame,
    )
}

/// How far from `p` along `dir` (xy) the stock's box ends (0 when `p`
/// is outside it).
fn exit_distance(b: &Aabb, p: [f64; 3], dir: [f64; 3]) -> f64 {
    let mut t = f64::INFINITY;
    for k in 0..2 {
        if p[k] < b.min[k] - 1e-6 || p[k] > b.max[k] + 1e-6 {
            return 0.0;
        }
        if dir[k] > 1e-12 {
            t = t.min((b.max[k] - p[k]) / dir[k]);
        } else if dir[k] < -1e-12 {
            t = t.min((b.min[k] - p[k]) / dir[k]);
        }
    }
    if t.is_finite() {
        t.max(0.0)
    } else {
        0.0
    }
}

/// The tool as the section sees it.
pub fn tool_shape(w: &mut Writer<'_>, s: &Step<'_>) -> Result<ToolShape, PostError> {
    let dim = &s.tool.body.dimension;
    let r = dim.diameter / 2.0;
    if r <= 0.0 {
        return Err(PostError::broken(
            &s.tool.id,
            "its diameter is not positive",
        ));
    }
    let rc = dim.edge_radius.unwrap_or(0.0).clamp(0.0, r);
    Ok(match &s.tool.body.kind {
        ToolBodyKind::BallEndmill => ToolShape::Ball { r },
        ToolBodyKind::Countersink => match dim.tip_half_angle {
            Some(a) if a > 0.0 => {
                let half = read_angle(w, &s.tool.id, "tool_top_angle", a);
                if !(half > 0.0 && half < 90.0) {
                    return Err(PostError::broken(
                        &s.tool.id,
                        "its tip half angle is not between 0 and 90 degrees",
                    ));
                }
                ToolShape::Vee {
                    r,
                    half_angle: half,
                }
            }
            _ => {
                return Err(PostError::broken(
                    &s.tool.id,
                    "a countersink without its tip angle",
                ))
            }
        },
        ToolBodyKind::TwistDrill
        | ToolBodyKind::TaperedDrill
        | ToolBodyKind::CenterDrill
        | ToolBodyKind::Spotdrill
        | ToolBodyKind::Reamer
        | ToolBodyKind::TaperedReamer
        | ToolBodyKind::Tap => {
            return Err(PostError::geometry(
                &s.feature.id,
                "a drill, reamer or tap cannot mill this profile".into(),
            ))
        }
        _ if rc > 1e-9 => ToolShape::Bull { r, rc },
        _ => ToolShape::Flat { r },
    })
}

/// Plans and writes the passes of one workingstep on a section.
#[allow(clippy::too_many_arguments)]
fn cut(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    ctx: &Context,
    sec: &Section,
    centres: (f64, f64),
    (along, closed): ((f64, f64), &[f64]),
    frame: &Frame,
) -> Result<(), PostError> {
    let tool = tool_shape(w, s)?;
    let allowance = if c.finish {
        0.0
    } else {
        c.allow_side.max(c.allow_bottom).max(0.0)
    };
    let g = sec.grid(tool, allowance, centres);
    if g.lowest() >= sec.top - 1e-6 {
        return Err(PostError::geometry(
            &s.feature.id,
            format!(
                "the tool ({}) does not fit into the profile at all",
                tool.describe()
            ),
        ));
    }
    let d = 2.0 * tool.radius();
    let mut stepover = c.stepover(d).min(0.95 * d);
    if stepover <= 0.0 {
        return Err(PostError::geometry(
            &s.feature.id,
            "the stepover is not positive".into(),
        ));
    }
    let tol = (c.finish).then_some(ctx.tol);
    if let Some(t) = tol {
        stepover = stepover.min(flat_scallop_step(&tool, 0.8 * t));
    }
    let depth = sec.top - g.lowest();
    let first = c.ap.filter(|a| *a > 0.0).unwrap_or(depth);
    let p = section::plan(&g, sec.top, first, stepover, tol);
    let r3 = |v: f64| (v * 1000.0).round() / 1000.0;
    if let Some(t) = tol {
        if p.stepping.0 > t + 1e-9 {
            return Err(PostError::geometry(
                &s.feature.id,
                format!(
                    "the tool ({}) cannot make the profile within {t} mm by stepped passes: {} mm is left",
                    tool.describe(),
                    r3(p.stepping.0)
                ),
            ));
        }
        if !ctx.later && p.form.0 > t + 1e-9 {
            return Err(PostError::geometry(
                &s.feature.id,
                format!(
                    "the tool ({}) cannot make the profile within {t} mm: it leaves {} mm at {} mm across the course (a radius or point smaller than the tool's), and no later workingstep cuts the feature",
                    tool.describe(),
                    r3(p.form.0),
                    r3(p.form.1)
                ),
            ));
        }
    }
    let what = match tol {
        Some(t) => format!(
            "levels {} mm apart, stepover {} mm: within {t} mm of what the tool can make",
            r3(p.step),
            r3(stepover)
        ),
        None => format!(
            "roughing levels {} mm apart, stepover {} mm, allowance {} mm",
            r3(p.step),
            r3(stepover),
            r3(allowance)
        ),
    };
    w.comment(&what)?;
    if tol.is_some() && ctx.later && p.form.0 > ctx.tol {
        w.comment(&format!(
            "this tool leaves up to {} mm for the later workingstep",
            r3(p.form.0)
        ))?;
    }
    if matches!(
        c.strategy,
        Some(Strategy::ContourParallel {
            cutmode: Some(_),
            ..
        }) | Some(Strategy::Unidirectional {
            cutmode: Some(_),
            ..
        })
    ) && spindle_cw(s).is_ok()
    {
        w.not_carried("the strategy's cut mode: the passes run zigzag along the travel, climb and conventional in turn")?;
    }
    super::milling::explicit_moves(w, s, frame, |sink| {
        moves(&p.passes, along, closed, s.clear, s.top + s.sdis, sink)
    })
}

/// The largest stepover whose scallop on a flat floor is within `tol`.
fn flat_scallop_step(t: &ToolShape, tol: f64) -> f64 {
    let cap = |r: f64, flat: f64| 2.0 * flat + 2.0 * (2.0 * r * tol - tol * tol).max(0.0).sqrt();
    match *t {
        ToolShape::Flat { r } => 2.0 * r,
        ToolShape::Ball { r } => cap(r, 0.0),
        ToolShape::Bull { r, rc } => cap(rc, r - rc),
        ToolShape::Vee { half_angle, .. } => 2.0 * tol * half_angle.to_radians().tan(),
    }
}

/// The passes as moves: zigzag along the travel, across at the level
/// within the reachable interval, down to the next level inside it, or
/// up to the R plane and over where the next pass lies elsewhere. At an
/// end closed by material (`closed`: its v) the zigzag's links leave
/// every other gap between passes; after each interval the tool runs
/// along its pass to that end and across the whole interval there.
fn moves(
    passes: &[Pass],
    along: (f64, f64),
    closed: &[f64],
    clear: f64,
    r_plane: f64,
    sink: &mut MoveSink<'_>,
) {
    // Groups of (level, interval), every other level from the other side.
    let mut groups: Vec<Vec<Pass>> = Vec::new();
    for p in passes {
        match groups.last_mut() {
            Some(g) if g[0].level == p.level && g[0].interval == p.interval => g.push(*p),
            _ => groups.push(vec![*p]),
        }
    }
    for g in groups.iter_mut() {
        if g[0].level % 2 == 1 {
            g.reverse();
        }
    }
    let mut k = 0;
    while k < groups.len() {
        // Reverse the order of the intervals on odd levels too.
        let level = groups[k][0].level;
        let mut j = k;
        while j < groups.len() && groups[j][0].level == level {
            j += 1;
        }
        if level % 2 == 1 {
            groups[k..j].reverse();
        }
        k = j;
    }
    let bounds = |g: &[Pass]| {
        g.iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.u), b.max(p.u))
            })
    };
    // Where the tool is: along (v), across (u), z; and the last group's
    // extent and level.
    let mut v_at = along.0;
    let mut cur: Option<(f64, f64, (f64, f64))> = None; // (u, z, bounds)
    for g in &groups {
        for p in g.iter() {
            match cur {
                None => {
                    sink.rapid([v_at, p.u], clear);
                    sink.rapid([v_at, p.u], r_plane);
                    sink.line([v_at, p.u], p.z);
                }
                Some((u, z, (a, b))) if p.u >= a - 1e-9 && p.u <= b + 1e-9 && p.z <= z + 1e-9 => {
                    if (p.u - u).abs() > 1e-9 {
                        sink.line([v_at, p.u], z);
                    }
                    if p.z < z - 1e-9 {
                        sink.line([v_at, p.u], p.z);
                    }
                }
                Some(_) => {
                    sink.rapid(sink.last_xy(), r_plane);
                    sink.rapid([v_at, p.u], r_plane);
                    sink.line([v_at, p.u], p.z);
                }
            }
            let to = if v_at == along.0 { along.1 } else { along.0 };
            sink.line([to, p.u], p.z);
            v_at = to;
            cur = Some((p.u, p.z, bounds(g)));
        }
        let (a, b) = bounds(g);
        let Some((u, z, _)) = cur else { continue };
        let mut u_at = u;
        let mut ends: Vec<f64> = closed.to_vec();
        ends.sort_by(|x, y| (x - v_at).abs().total_cmp(&(y - v_at).abs()));
        for vc in ends {
            if (vc - v_at).abs() > 1e-9 {
                sink.line([vc, u_at], z);
                v_at = vc;
            }
            let other = if (u_at - a).abs() < (u_at - b).abs() {
                b
            } else {
                a
            };
            if (other - u_at).abs() > 1e-9 {
                sink.line([vc, other], z);
                u_at = other;
            }
        }
        cur = Some((u_at, z, (a, b)));
    }
    if cur.is_some() {
        let last = sink.last_xy();
        sink.rapid(last, r_plane);
        sink.rapid(last, clear);
    }
}

/// A V: the sides at `t` (the first, on the left of the course [?]) and
/// `180 - a - t` degrees to the top, blended by `radius` at the bottom,
/// whose lowest point is on the course of travel at the depth.
pub fn vee(
    id: &str,
    radius: f64,
    a: f64,
    t: f64,
    top: f64,
    bottom: f64,
) -> Result<Section, PostError> {
    let t2 = 180.0 - a - t;
    for (side, th) in [("first", t), ("second", t2)] {
        if !(th > 1e-6 && th <= 90.0 + 1e-6) {
            return Err(PostError::unsupported(
                id,
                &format!("a V profile whose {side} side lies at {th}° to the top (a side must rise from the point at more than 0° and at most 90°: otherwise it overhangs, which a 3-axis tool cannot reach)"),
            ));
        }
    }
    if bottom >= top {
        return Err(PostError::outside(
            id,
            "its depth is not below its top".into(),
            "give the depth plane a negative z".into(),
        ));
    }
    let (th1, th2) = (t.min(90.0).to_radians(), t2.min(90.0).to_radians());
    let c = [0.0, bottom + radius];
    // Tangent points of the sides on the blend.
    let p1 = [c[0] + radius * th1.sin(), c[1] - radius * th1.cos()];
    let p2 = [c[0] - radius * th2.sin(), c[1] - radius * th2.cos()];
    let mut pts = Vec::new();
    pts.push(side_top(p2, th2, -1.0, top));
    let n = 64;
    for k in 0..=n {
        // From the second side's tangent point to the first's.
        let ang = -th2 + (th1 + th2) * k as f64 / n as f64;
        let p = [c[0] + radius * ang.sin(), c[1] - radius * ang.cos()];
        if p[1] <= top {
            pts.push(p);
        }
    }
    let _ = (p1, p2);
    pts.push(side_top(p1, th1, 1.0, top));
    Ok(finish(pts, top, Some(top), Some(top)))
}

/// Where a side from `p` rising at `th` (radians, towards `sign` u)
/// meets the top.
fn side_top(p: [f64; 2], th: f64, sign: f64, top: f64) -> [f64; 2] {
    let rise = top - p[1];
    let run = if th.cos().abs() < 1e-12 {
        0.0
    } else {
        rise / th.tan()
    };
    [p[0] + sign * run.max(0.0), top]
}

/// A square U: floor `width` wide between its sharp corners at the
/// depth, walls leaning out by `(radius, angle from the z axis)`, the
/// first on the left [?].
pub fn sloped_u(
    id: &str,
    width: f64,
    first: (f64, f64),
    second: (f64, f64),
    top: f64,
    bottom: f64,
) -> Result<Section, PostError> {
    for (side, (_, a)) in [("first", first), ("second", second)] {
        if !(-1e-9..90.0).contains(&a) {
            return Err(PostError::unsupported(
                id,
                &format!("a U profile whose {side} wall lies at {a}° to the z axis (walls lean outwards, from 0 to under 90°)"),
            ));
        }
    }
    let corner = |(r, a): (f64, f64), sign: f64| -> Vec<[f64; 2]> {
        let a = a.to_radians();
        let k = [sign * width / 2.0, bottom];
        let turn = std::f64::consts::FRAC_PI_2 - a;
        let d = r * (turn / 2.0).tan();
        let f = [k[0] - sign * d, bottom];
        let cc = [f[0], bottom + r];
        let mut pts = Vec::new();
        let n = 48;
        for j in 0..=n {
            let ang = turn * j as f64 / n as f64;
            pts.push([cc[0] + sign * r * ang.sin(), cc[1] - r * ang.cos()]);
        }
        let wall_end = *pts.last().unwrap_or(&k);
        pts.push(side_top(wall_end, turn, sign, top));
        pts
    };
    let mut right = corner(second, -1.0);
    right.reverse();
    let left = corner(first, 1.0);
    let mut pts = right;
    pts.extend(left);
    Ok(finish(pts, top, Some(top), Some(top)))
}

/// A step's section: the floor from the stock's edge (u = -width) to
/// the wall, the wall leaning back by `wall` degrees from the z axis and
/// meeting the top at u 0, blended by `radius`.
pub fn step_section(
    id: &str,
    width: f64,
    wall: f64,
    radius: f64,
    top: f64,
    bottom: f64,
) -> Result<Section, PostError> {
    if bottom >= top {
        return Err(PostError::outside(
            id,
            "its depth is not below its top".into(),
            "give the depth plane a negative z".into(),
        ));
    }
    let a = wall.to_radians();
    let turn = std::f64::consts::FRAC_PI_2 - a;
    // The sharp corner: the wall from (0, top) down at `a` from z.
    let k = [-(top - bottom) * a.tan(), bottom];
    let d = radius * (turn / 2.0).tan();
    let mut pts = vec![[-width, bottom]];
    let cc = [k[0] - d, bottom + radius];
    let n = 48;
    for j in 0..=n {
        let ang = turn * j as f64 / n as f64;
        pts.push([cc[0] + radius * ang.sin(), cc[1] - radius * ang.cos()]);
    }
    pts.push([0.0, top]);
    Ok(finish(pts, top, None, Some(top)))
}

fn finish(mut pts: Vec<[f64; 2]>, top: f64, below: Option<f64>, beyond: Option<f64>) -> Section {
    pts.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    Section {
        points: pts,
        below_first: below,
        beyond_last: beyond,
        top,
    }
}

/// The half width a slot's profile has at its top (`depth` below it).
pub fn top_half_width(p: &OpenProfile, depth: f64) -> Option<f64> {
    let sec = match p {
        OpenProfile::Vee {
            radius,
            angle,
            tilt_angle,
            ..
        } => vee(
            "",
            radius.nominal,
            super::angles::degrees(*angle),
            super::angles::degrees(*tilt_angle),
            0.0,
            -depth,
        )
        .ok()?,
        OpenProfile::SquareU {
            width,
            first_radius,
            first_angle,
            second_radius,
            second_angle,
            ..
        } => {
            let r = |v: &Option<Toleranced>| v.as_ref().map_or(0.0, |t| t.nominal);
            let a = |v: Option<f64>| {
                let d = v.map_or(0.0, super::angles::degrees);
                if super::slots::upright(Some(d)) {
                    0.0
                } else {
                    d
                }
            };
            sloped_u(
                "",
                width.nominal,
                (r(first_radius), a(*first_angle)),
                (r(second_radius), a(*second_angle)),
                0.0,
                -depth,
            )
            .ok()?
        }
        _ => return None,
    };
    let (a, b) = (sec.points[0][0], sec.points[sec.points.len() - 1][0]);
    Some(a.abs().max(b.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_symmetric_vee_rises_at_45_degrees_from_its_blend() {
        let s = vee("v", 3.0, 90.0, 45.0, 0.0, -13.0).unwrap();
        assert!((s.bottom() + 13.0).abs() < 1e-9);
        // Blend centre at z -10; tangent points at +-3 sin 45; the sides
        // reach the top 13 - 3 (1 - cos 45) above them.
        let half = 3.0 * 45f64.to_radians().sin() + (13.0 - 3.0 * (1.0 - 45f64.to_radians().cos()));
        let last = s.points[s.points.len() - 1];
        assert!((last[0] - half).abs() < 1e-9 && last[1] == 0.0, "{last:?}");
        assert!((s.at(5.0) - (s.at(6.0) - 1.0)).abs() < 1e-9);
    }

    #[test]
    fn a_sloped_u_floor_is_its_width_between_sharp_corners() {
        let s = sloped_u("u", 12.0, (0.0, 30.0), (0.0, 30.0), 0.0, -10.0).unwrap();
        assert!((s.at(0.0) + 10.0).abs() < 1e-9);
        let top_half = 6.0 + 10.0 * 30f64.to_radians().tan();
        assert!((s.points[s.points.len() - 1][0] - top_half).abs() < 1e-9);
        // Halfway up the wall.
        let u = 6.0 + 5.0 * 30f64.to_radians().tan();
        assert!((s.at(u) + 5.0).abs() < 1e-6);
    }

    #[test]
    fn an_overhanging_vee_side_is_refused() {
        assert!(vee("v", 0.0, 60.0, 100.0, 0.0, -5.0).is_err());
    }
}
