//! A closed pocket with a general boundary (`GENERAL_CLOSED_PROFILE` of
//! a `POLYLINE`, a trimmed line, or a `COMPOSITE_CURVE` of those): no
//! target's cycle takes an arbitrary outline from a STEP-NC plan (the
//! 840D and Heidenhain contour pocket cycles want the contour as a
//! subprogram [?: not declared in the dialect specs]), so every target
//! gets the generated paths of [`super::paths::polygon`]: contour-parallel
//! loops for a convex outline, zigzag inside the finishing contour for a
//! concave one. Arcs of the outline (trimmed circles about the tool axis)
//! are taken as chords within [`ARC_TOLERANCE`] of the arc. An outline
//! the generator cannot offset (a neck narrower than the tool) is a
//! located refusal.

use super::frame::Frame;
use super::milling::{explicit_moves, Cut};
use super::paths::polygon::{self, GeneralPocket, Polygon};
use super::paths::P2;
use super::plan::Step;
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    pocket: &PocketCommon,
    shape: &Curve,
    frame: &Frame,
) -> Result<(), PostError> {
    let mut pts = Vec::new();
    outline(shape, true, &mut pts).map_err(|what| PostError::unsupported(&s.feature.id, what))?;
    let boundary = Polygon::new(&pts).map_err(|e| PostError::broken(&s.feature.id, &e))?;
    let gp = GeneralPocket {
        boundary,
        corner_radius: pocket.orthogonal_radius.as_ref().map_or(0.0, |r| r.nominal),
    };
    let pcut = super::pockets::pocket_cut(s, c)?;
    polygon::check(&gp, &pcut).map_err(|e| PostError::geometry(&s.feature.id, e))?;
    let contour_parallel = matches!(
        c.strategy,
        None | Some(Strategy::ContourParallel { .. }) | Some(Strategy::ContourSpiral { .. })
    );
    if gp.boundary.is_convex() {
        w.comment(&format!(
            "general pocket ({} corners, convex): contour-parallel loops from the inside out",
            gp.boundary.pts.len()
        ))?;
        if !contour_parallel {
            w.not_carried("the operation's strategy: the pocket is cleared contour-parallel")?;
        }
    } else {
        w.comment(&format!(
            "general pocket ({} corners, concave): zigzag inside the finishing contour, then the contour",
            gp.boundary.pts.len()
        ))?;
        if c.strategy.is_some() && contour_parallel {
            w.not_carried("the contour-parallel strategy on a concave outline: cleared zigzag inside the finishing contour")?;
        }
    }
    explicit_moves(w, s, frame, |sink| polygon::moves(&gp, &pcut, sink))
}

/// The outline's corners in the profile's plane, in order; `Err` names
/// what the generator cannot take.
fn outline(c: &Curve, forward: bool, out: &mut Vec<P2>) -> Result<(), &'static str> {
    let mut pts: Vec<P2> = match c {
        Curve::Polyline { points, .. } => points.iter().map(|p| [p.xyz[0], p.xyz[1]]).collect(),
        Curve::Line { start, end, .. } => {
            vec![[start.xyz[0], start.xyz[1]], [end.xyz[0], end.xyz[1]]]
        }
        Curve::Composite { segments, .. } => {
            let mut v = Vec::new();
            for seg in segments {
                outline(&seg.curve, seg.same_sense, &mut v)?;
            }
            v
        }
        Curve::Arc {
            circle,
            radius,
            start,
            end,
            sense,
            ..
        } => arc_points(circle, *radius, start, end, *sense)?,
        Curve::Other(_) => return Err("a pocket whose outline is not a polyline or lines"),
    };
    if !forward {
        pts.reverse();
    }
    out.extend(pts);
    Ok(())
}

/// How far (mm) the chords standing for an arc of the outline may lie
/// from it [?: below any drawing tolerance; the posted path follows the
/// chords, so the wall may deviate by this much either way].
pub const ARC_TOLERANCE: f64 = 0.002;

/// The points of a trimmed circle about an axis along the tool's, from
/// its start to its end in its sense (a full circle when they meet).
fn arc_points(
    circle: &Axis2Placement,
    radius: f64,
    start: &Point,
    end: &Point,
    sense: bool,
) -> Result<Vec<P2>, &'static str> {
    let axis = circle.axis.as_ref().map_or([0.0, 0.0, 1.0], |d| d.ratios);
    let n = (axis[0].powi(2) + axis[1].powi(2) + axis[2].powi(2)).sqrt();
    if radius <= 0.0 || n < 1e-12 || (axis[2] / n).abs() < 1.0 - 1e-9 {
        return Err("a pocket whose outline has an arc not about the tool axis");
    }
    let ccw = sense == (axis[2] > 0.0);
    let c = [circle.location.xyz[0], circle.location.xyz[1]];
    let angle = |p: &Point| (p.xyz[1] - c[1]).atan2(p.xyz[0] - c[0]);
    let (a0, a1) = (angle(start), angle(end));
    let tau = std::f64::consts::TAU;
    let mut sweep = if ccw { a1 - a0 } else { a0 - a1 }.rem_euclid(tau);
    if sweep < 1e-9 {
        sweep = tau;
    }
    let piece = 2.0 * (1.0 - (ARC_TOLERANCE / radius).min(1.0)).acos();
    let k = (sweep / piece.max(1e-3)).ceil().clamp(1.0, 10_000.0) as usize;
    Ok((0..=k)
        .map(|i| {
            let t = sweep * i as f64 / k as f64;
            let a = if ccw { a0 + t } else { a0 - t };
            [c[0] + radius * a.cos(), c[1] + radius * a.sin()]
        })
        .collect())
}
