//! Explicit (CC1) toolpaths posted as they are: an operation's
//! `its_toolpath` (a `FREEFORM_OPERATION` of a `TOOLPATH_FEATURE`, or any
//! operation that carries its own path) and a `RAPID_MOVEMENT` with a
//! toolpath become the target's rapid, line, arc and helix blocks through
//! `rapid.j2`, `line.j2`, `arc.j2` and `helix.j2`.
//!
//! Trajectories whose speed is `SPEED_NAME(.RAPID.)` are rapids; the others
//! feed at the operation's feed times their `POSITIVE_RATIO_MEASURE` (or at
//! their own technology's feed). Curves are polylines, trimmed lines,
//! arcs of circles about the tool axis (in the XY plane), composite curves
//! of those, and the curves the reader keeps raw that [`super::raw_curves`]
//! reads (NIST `HELIX`, a trimmed line with a contradictory sense). Points
//! are in the feature's frame (ISO 14649: a workingstep tied to a feature).
//! What cannot be posted (a dwell `FEEDSTOP`, a tool axis or surface
//! normal curve: 3-axis posts; other curves) is an error naming the
//! toolpath's operation.

use super::frame::Frame;
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::{Curve, Point, Toolpath, ToolpathSpeed};

/// One move of an explicit toolpath in workpiece coordinates; `feed` is
/// None for a rapid. An arc whose end z differs from its start is one
/// piece (at most half a turn) of a helix, written through `helix.j2`.
#[derive(Clone, Debug, PartialEq)]
pub enum PathMove {
    Straight {
        to: [f64; 3],
        feed: Option<f64>,
    },
    Arc {
        to: [f64; 3],
        centre: [f64; 2],
        ccw: bool,
        feed: f64,
    },
}

/// Points closer than this (mm) are one point: repeated polyline points
/// make no move.
const SAME: f64 = 1e-9;

/// The moves of `paths` placed by `frame`, fed at `feed` (mm/min) unless a
/// trajectory says otherwise; `rapid_only` for a `RAPID_MOVEMENT`; `top`:
/// the feature's top, below which the way to the first point is fed.
pub fn moves(
    frame: &Frame,
    paths: &[Toolpath],
    feed: Option<f64>,
    (rapid_only, top): (bool, Option<f64>),
    owner: &str,
) -> Result<Vec<PathMove>, PostError> {
    let mut out = Vec::new();
    for p in paths {
        let (base, curve, extra) = match p {
            Toolpath::CutterLocation {
                base,
                basic_curve,
                tool_axis,
                surface_normal,
                ..
            } => (
                base,
                basic_curve,
                tool_axis.is_some() || surface_normal.is_some(),
            ),
            Toolpath::Feedstop { .. } => {
                return Err(PostError::unsupported(
                    owner,
                    "a dwell (FEEDSTOP) in an explicit toolpath",
                ))
            }
            Toolpath::Other(raw) => {
                return Err(PostError::unsupported(
                    owner,
                    &format!("a toolpath {}", raw.entity),
                ))
            }
        };
        if extra {
            return Err(PostError::unsupported(
                owner,
                "a toolpath with its own tool axis or surface normal (3-axis posts only)",
            ));
        }
        let rapid =
            rapid_only || matches!(&base.speed, Some(ToolpathSpeed::Named(n)) if n == "RAPID");
        let speed = if rapid {
            None
        } else {
            // A toolpath's own feed of 0 is no feed: the operation's holds.
            let own = base.technology.as_ref().and_then(|t| t.feed);
            let f = own.filter(|f| *f > 0.0).or(feed).filter(|f| *f > 0.0);
            let ratio = match &base.speed {
                Some(ToolpathSpeed::Ratio(r)) => *r,
                _ => 1.0,
            };
            Some(
                f.map(|f| f * ratio)
                    .ok_or_else(|| PostError::broken(owner, "its technology gives no feed"))?,
            )
        };
        curve_moves(frame, curve, speed, owner, &mut out)?;
    }
    // The path starts at its first point: the tool gets there by
    // positioning, not by cutting, unless the point is below the
    // feature's top (then it feeds down to it).
    if let Some(PathMove::Straight { to, feed }) = out.first_mut() {
        if top.is_none_or(|t| to[2] >= t - SAME) {
            *feed = None;
        }
    }
    Ok(out)
}

fn curve_moves(
    frame: &Frame,
    curve: &Curve,
    feed: Option<f64>,
    owner: &str,
    out: &mut Vec<PathMove>,
) -> Result<(), PostError> {
    let at = |p: &Point| frame.apply(p.xyz);
    match curve {
        Curve::Polyline { points, .. } => {
            for p in points {
                out.push(PathMove::Straight { to: at(p), feed });
            }
        }
        Curve::Line { start, end, .. } => {
            out.push(PathMove::Straight {
                to: at(start),
                feed,
            });
            out.push(PathMove::Straight { to: at(end), feed });
        }
        Curve::Arc {
            circle,
            start,
            end,
            sense,
            ..
        } => {
            let Some(f) = feed else {
                return Err(PostError::unsupported(owner, "a rapid along an arc"));
            };
            let (s, e) = (at(start), at(end));
            let axis = circle.axis.as_ref().map_or([0.0, 0.0, 1.0], |d| d.ratios);
            let normal = frame.rotate(axis);
            if normal[0].abs() > 1e-9 || normal[1].abs() > 1e-9 || (s[2] - e[2]).abs() > 1e-6 {
                return Err(PostError::unsupported(
                    owner,
                    "an arc outside the XY plane or a helix in an explicit toolpath",
                ));
            }
            let c = frame.apply(circle.location.xyz);
            out.push(PathMove::Straight { to: s, feed });
            out.push(PathMove::Arc {
                to: e,
                centre: [c[0], c[1]],
                ccw: *sense == (normal[2] > 0.0),
                feed: f,
            });
        }
        Curve::Composite { segments, .. } => {
            for seg in segments {
                if !seg.same_sense {
                    return Err(PostError::unsupported(
                        owner,
                        "a composite curve segment run against its sense",
                    ));
                }
                curve_moves(frame, &seg.curve, feed, owner, out)?;
            }
        }
        Curve::Other(raw) => super::raw_curves::moves(frame, raw, feed, owner, out)?,
    }
    Ok(())
}

/// The centre's offset from the arc's start as the target writes it: the
/// difference of the two written (rounded) values, so the centre the
/// program states is the centre rounded, wherever the start was rounded.
fn offset(w: &Writer<'_>, centre: f64, start: f64) -> String {
    let written = |v: f64| w.fmt.len(v).parse::<f64>().unwrap_or(v);
    w.fmt.len(written(centre) - written(start))
}

/// The signed angle (degrees, + counter-clockwise) an arc about `centre`
/// turns from `from` to `to` in its direction, in (0, 360].
fn turn_deg(centre: &[f64; 2], from: [f64; 3], to: [f64; 3], ccw: bool) -> f64 {
    let a0 = (from[1] - centre[1]).atan2(from[0] - centre[0]);
    let a1 = (to[1] - centre[1]).atan2(to[0] - centre[0]);
    let mut d = if ccw { a1 - a0 } else { a0 - a1 };
    while d <= 1e-12 {
        d += std::f64::consts::TAU;
    }
    while d > std::f64::consts::TAU {
        d -= std::f64::consts::TAU;
    }
    let deg = d.to_degrees();
    if ccw {
        deg
    } else {
        -deg
    }
}

/// The first point a list of moves goes to.
pub fn first_point(moves: &[PathMove]) -> Option<[f64; 3]> {
    moves.first().map(|m| match m {
        PathMove::Straight { to, .. } | PathMove::Arc { to, .. } => *to,
    })
}

/// Writes the moves from `from` (where the tool is), leaving out those
/// that go nowhere; returns where the tool ends.
pub(crate) fn write(
    w: &mut Writer<'_>,
    moves: &[PathMove],
    from: [f64; 3],
) -> Result<[f64; 3], PostError> {
    let mut at = from;
    for m in moves {
        match m {
            PathMove::Straight { to, feed } => {
                if (0..3).all(|i| (to[i] - at[i]).abs() < SAME) {
                    continue;
                }
                let v = Vals::new()
                    .set("x", w.fmt.len(to[0]))
                    .set("y", w.fmt.len(to[1]))
                    .set("z", w.fmt.len(to[2]));
                match feed {
                    None => w.emit("rapid.j2", v)?,
                    Some(f) => w.emit("line.j2", v.set("f", w.fmt.feed(*f)))?,
                }
                at = *to;
            }
            PathMove::Arc {
                to,
                centre,
                ccw,
                feed,
            } => {
                let v = Vals::new()
                    .set("g", if *ccw { "3" } else { "2" })
                    .set("x", w.fmt.len(to[0]))
                    .set("y", w.fmt.len(to[1]))
                    .set("i", offset(w, centre[0], at[0]))
                    .set("j", offset(w, centre[1], at[1]))
                    .set("f", w.fmt.feed(*feed));
                if (to[2] - at[2]).abs() < SAME {
                    w.emit("arc.j2", v)?;
                } else {
                    let turn = turn_deg(centre, at, *to, *ccw);
                    let v = v
                        .set("z", w.fmt.len(to[2]))
                        .set("ipa", w.fmt.angle(turn))
                        .set("iz", w.fmt.len(to[2] - at[2]));
                    w.emit("helix.j2", v)?;
                }
                at = *to;
            }
        }
    }
    Ok(at)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stepnc::model::ToolpathType;

    fn polyline(points: &[[f64; 3]]) -> Toolpath {
        let points = points
            .iter()
            .map(|p| Point {
                name: String::new(),
                xyz: *p,
            })
            .collect();
        let curve = Curve::Polyline {
            name: String::new(),
            points,
        };
        crate::raise::ops::trajectory(curve, None, ToolpathType::TrajectoryPath)
    }

    /// The way to the first point is a rapid above the feature's top and
    /// a feed below it (the tool would plunge into the material).
    #[test]
    fn the_start_is_reached_at_rapid_only_above_the_top() {
        let f = Frame::identity();
        let above = [polyline(&[[0.0, 0.0, 5.0], [0.0, 0.0, -1.0]])];
        let m = moves(&f, &above, Some(300.0), (false, Some(0.0)), "op").unwrap();
        assert_eq!(
            m[0],
            PathMove::Straight {
                to: [0.0, 0.0, 5.0],
                feed: None
            }
        );
        assert_eq!(
            m[1],
            PathMove::Straight {
                to: [0.0, 0.0, -1.0],
                feed: Some(300.0)
            }
        );
        let below = [polyline(&[[0.0, 0.0, -2.0], [10.0, 0.0, -2.0]])];
        let m = moves(&f, &below, Some(300.0), (false, Some(0.0)), "op").unwrap();
        assert_eq!(
            m[0],
            PathMove::Straight {
                to: [0.0, 0.0, -2.0],
                feed: Some(300.0)
            }
        );
    }
}
