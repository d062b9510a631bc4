//! A planar face: CYCLE71 or CYCL DEF 232 where the target has it
//! (`face.j2`; a cycle that cannot turn the face, as 232, only for a face
//! along the axes), else explicit zigzag toolpaths. The face is the rectangle swept by the
//! course of travel (a linear path, normally along the feature's y) over
//! the removal boundary's length (a linear profile along its x), or the
//! same turned a quarter: a course along x, the profile along y.

use super::frame::Frame;
use super::milling::{explicit_moves, layers, Cut};
use super::paths::face::{self, FaceArea, FaceCut};
use super::plan::Step;
use super::step::feed;
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(w: &mut Writer<'_>, s: &Step<'_>, c: &Cut<'_>) -> Result<(), PostError> {
    let FeatureKind::PlanarFace {
        course_of_travel,
        removal_boundary,
        face_boundary,
        bosses,
    } = &s.feature.kind
    else {
        return Err(PostError::unsupported(&s.feature.id, "this feature"));
    };
    let unsupported = || {
        PostError::unsupported(&s.feature.id, "a planar face not given by a linear path and a linear profile at the feature's origin, at right angles,")
    };
    let (
        TravelPath::Linear {
            placement: None,
            distance,
            direction,
        },
        OpenProfile::Linear {
            placement: None,
            length,
        },
    ) = (course_of_travel, removal_boundary)
    else {
        return Err(unsupported());
    };
    if !bosses.is_empty() {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a planar face with bosses",
        ));
    }
    if face_boundary.is_some() {
        w.not_carried("the face boundary: the whole travel x width rectangle is milled")?;
    }
    let u = direction.ratios;
    let n = (u[0] * u[0] + u[1] * u[1]).sqrt();
    let (along_x, along_y) = ((u[0] / n.max(1e-300)).abs(), (u[1] / n.max(1e-300)).abs());
    if n < 1e-9 || (along_x > 1e-9 && along_y > 1e-9) {
        return Err(unsupported());
    }
    let (width, along) = (length.value, distance.nominal);
    // The rectangle swept in the feature's plane: the course along y (the
    // profile along x), or along x (the profile along y, as raised from a
    // program that faced along X).
    let (size, corner_local, travel) = if along_x <= 1e-9 {
        let y0 = if u[1] > 0.0 { 0.0 } else { -along };
        ([width, along], [0.0, y0, 0.0], [0.0, u[1].signum()])
    } else {
        let x0 = if u[0] > 0.0 { 0.0 } else { -along };
        ([along, width], [x0, 0.0, 0.0], [u[0].signum(), 0.0])
    };
    let corner = s.frame.apply(corner_local);
    let (feed_dir, left_step) = pass_direction(c.strategy, travel);
    let passes_along_y = feed_dir[0].abs() < 1e-9;
    let d = s.tool.body.dimension.diameter;
    let overlap = c.overlap().unwrap_or(0.1);
    let stepover = d * (1.0 - overlap);
    let roughed = s.roughed_by.is_some();
    let bottom_allowance = if c.finish { 0.0 } else { c.allow_bottom };
    if stepover <= 0.0 || stepover > d {
        return Err(PostError::geometry(
            &s.feature.id,
            format!("the overlap {overlap} gives no usable stepover"),
        ));
    }
    let turned = s.frame.angle_deg().abs() > 1e-9;
    if w.post.has("face.j2") && !(turned && w.post.ignores("face.j2", "angle")) {
        if passes_along_y && w.post.ignores("face.j2", "vari") {
            w.not_carried("the pass direction along Y: the face cycle mills along X")?;
        }
        if c.finish && !roughed {
            w.comment(
                "nothing roughed before: the face is machined whole down to the depth plane",
            )?;
        }
        let units = if c.finish && roughed { 2 } else { 1 };
        let bidirectional = !matches!(c.strategy, Some(Strategy::Unidirectional { .. }));
        let tens = match (bidirectional, passes_along_y) {
            (false, false) => 1,
            (false, true) => 2,
            (true, false) => 3,
            (true, true) => 4,
        };
        let v = Vals::new()
            .set("clear", w.fmt.len(s.clear))
            .set("top", w.fmt.len(s.top))
            .set("sdis", w.fmt.len(s.sdis))
            .set("bottom", w.fmt.len(s.bottom))
            .set("pa", w.fmt.len(corner[0]))
            .set("po", w.fmt.len(corner[1]))
            .set("leng", w.fmt.len(size[0]))
            .set("wid", w.fmt.len(size[1]))
            .set("angle", w.fmt.angle(s.frame.angle_deg()))
            .set("mid", w.fmt.len(c.ap.unwrap_or(s.top - s.bottom)))
            .set("mida", w.fmt.len(stepover))
            .set("fdp", w.fmt.len(d / 2.0))
            .set("fald", w.fmt.len(bottom_allowance))
            .set("feed", w.fmt.feed(feed(s)?))
            .set("vari", (tens * 10 + units).to_string())
            .set("fdp1", w.fmt.len(overlap * d))
            .set_derived("strategy", if bidirectional { "0" } else { "2" })
            .set_derived("overlap_factor", w.fmt.plain(stepover / (d / 2.0), 4))
            .set_derived("clear_inc", w.fmt.len(s.clear - s.top));
        return w.emit("face.j2", v);
    }
    // Explicit zigzag in a frame whose y axis is the pass direction.
    let base = s.frame.then(&Frame {
        origin: corner_local,
        ..Frame::identity()
    });
    let (frame, area) = if passes_along_y {
        (
            base,
            FaceArea {
                across: size[0],
                along: size[1],
            },
        )
    } else {
        let swapped = Frame {
            origin: base.origin,
            x: base.y,
            y: base.x,
            z: base.z,
        };
        (
            swapped,
            FaceArea {
                across: size[1],
                along: size[0],
            },
        )
    };
    // Step towards the left of the feed direction: from the high side
    // when left points down the across axis.
    let across_dir = if passes_along_y {
        [1.0, 0.0]
    } else {
        [0.0, 1.0]
    };
    let left = [-feed_dir[1], feed_dir[0]];
    let towards_left = left[0] * across_dir[0] + left[1] * across_dir[1];
    let from_high_side = match left_step {
        Some(true) => towards_left < 0.0,
        Some(false) => towards_left > 0.0,
        None => false,
    };
    let cut = FaceCut {
        tool_radius: d / 2.0,
        stepover,
        overhang: overlap * d,
        from_high_side,
        levels: layers(s, c, bottom_allowance),
        clear: s.clear,
        r_plane: s.top + s.sdis,
        run_out: d / 2.0 + s.sdis,
    };
    explicit_moves(w, s, &frame, |sink| face::moves(&area, &cut, sink))
}

/// The pass direction (feature plane) and whether stepover goes left
/// (`Some(true)`), right, or is not said.
fn pass_direction(st: Option<&Strategy>, travel: [f64; 2]) -> ([f64; 2], Option<bool>) {
    let (dir, side) = match st {
        Some(Strategy::Bidirectional {
            feed_direction,
            stepover_direction,
            ..
        }) => (feed_direction.as_ref(), *stepover_direction),
        Some(Strategy::Unidirectional { feed_direction, .. }) => (feed_direction.as_ref(), None),
        _ => (None, None),
    };
    let d = dir
        .map(|d| {
            if d.ratios[0].abs() >= d.ratios[1].abs() {
                [d.ratios[0].signum(), 0.0]
            } else {
                [0.0, d.ratios[1].signum()]
            }
        })
        .unwrap_or(travel);
    (d, side.map(|s| s == LeftOrRight::Left))
}
