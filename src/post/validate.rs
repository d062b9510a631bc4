//! The validator every post runs before writing a word (a posted program
//! runs on a machine): each feature must lie inside the stock, with a
//! positive depth; a profile whose placement repeats its feature's
//! placement is named (ISO 14649-10 places a profile in its feature's
//! frame, so the two add up; some generators write the absolute position
//! twice); feeds that imply an implausible chip load are warned about.
//!
//! The stock is the workpiece's `BLOCK` bounding geometry (ISO 10303-42:
//! a box from the block's placement along its +x, +y, +z), placed by the
//! setup chain like the features. Footprints are taken in the feature's
//! frame and carried to machine coordinates with nalgebra isometries
//! ([`Frame`]).

use super::frame::Frame;
use super::plan::{Item, Step};
use super::PostError;
use crate::diag::{Code, Diagnostic};
use crate::stepnc::model::*;
use nalgebra::{Point3, Vector3};

/// How far (mm) a feature may stand out of the stock before it is an
/// error (rounding in generators' numbers).
pub const TOLERANCE: f64 = 0.01;

/// An axis-aligned box in machine (setup) coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Point3<f64>,
    pub max: Point3<f64>,
}

impl Aabb {
    fn of(points: impl IntoIterator<Item = Point3<f64>>) -> Option<Aabb> {
        let mut it = points.into_iter();
        let first = it.next()?;
        Some(it.fold(
            Aabb {
                min: first,
                max: first,
            },
            |b, p| Aabb {
                min: b.min.inf(&p),
                max: b.max.sup(&p),
            },
        ))
    }

    /// Whether `inner` lies inside (within `tol`), the bottom exempt when
    /// `through` (a through feature breaks out below the stock).
    fn holds(&self, inner: &Aabb, through: bool, tol: f64) -> bool {
        (0..3).all(|k| {
            let low_ok = (through && k == 2) || inner.min[k] >= self.min[k] - tol;
            low_ok && inner.max[k] <= self.max[k] + tol
        })
    }

    /// The eight corners.
    pub fn corners(&self) -> [Point3<f64>; 8] {
        std::array::from_fn(|k| {
            Point3::new(
                if k & 1 == 0 { self.min.x } else { self.max.x },
                if k & 2 == 0 { self.min.y } else { self.max.y },
                if k & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }

    pub fn describe(&self) -> String {
        let r = |v: f64| (v * 1000.0).round() / 1000.0;
        format!(
            "x {}..{}, y {}..{}, z {}..{}",
            r(self.min.x),
            r(self.max.x),
            r(self.min.y),
            r(self.max.y),
            r(self.min.z),
            r(self.max.z)
        )
    }
}

/// The stock of a workpiece in machine coordinates: its BLOCK through the
/// setup frame `base`. `None` when the workpiece gives no block.
pub fn stock(project: &Project, wp: WorkpieceId, base: &Frame) -> Option<Aabb> {
    let w = project.workpieces.get(wp.index())?;
    let raw = w
        .rawpiece
        .and_then(|r| project.workpieces.get(r.index()))
        .and_then(|r| r.bounding.as_ref());
    let Bounding::Block { position, size, .. } = raw.or(w.bounding.as_ref())? else {
        return None;
    };
    let f = base.then(&Frame::from_placement(position));
    let corners = (0..8).map(|k| {
        let c = [
            if k & 1 == 0 { 0.0 } else { size[0] },
            if k & 2 == 0 { 0.0 } else { size[1] },
            if k & 4 == 0 { 0.0 } else { size[2] },
        ];
        Point3::from(f.apply(c))
    });
    Aabb::of(corners)
}

/// The feature's volume as a box in machine coordinates, `None` for
/// kinds whose extent cncc does not compute (faces, steps, open pockets).
pub fn feature_box(s: &Step<'_>) -> Option<Aabb> {
    let (outline, placement) = outline(&s.feature.kind, s.top - s.bottom)?;
    let frame = match placement {
        Some(p) => s.frame.then(&Frame::from_placement(p)),
        None => s.frame,
    };
    // In the working plane, then (tilted) in workpiece coordinates.
    let pts = outline.into_iter().flat_map(|[x, y]| {
        [s.top, s.bottom].map(|z| {
            let mut p = frame.apply([x, y, 0.0]);
            p[2] = z;
            Point3::from(s.tilt.map_or(p, |t| t.apply(p)))
        })
    });
    Aabb::of(pts)
}

type Outline<'a> = (Vec<[f64; 2]>, &'a Option<Axis2Placement>);

/// Points bounding the feature in its profile's plane, and the profile's
/// placement (in the feature's frame).
fn outline(kind: &FeatureKind, depth: f64) -> Option<Outline<'_>> {
    const NONE: &Option<Axis2Placement> = &None;
    match kind {
        FeatureKind::RoundHole { diameter, .. } => Some((square(diameter.nominal / 2.0), NONE)),
        FeatureKind::ClosedPocket { boundary, .. } => match boundary {
            ClosedProfile::Rectangular {
                placement,
                width,
                length,
            } => Some((rect(length.nominal / 2.0, width.nominal / 2.0), placement)),
            ClosedProfile::Circular {
                placement,
                diameter,
            } => Some((square(diameter.nominal / 2.0), placement)),
            ClosedProfile::General { placement, shape } => Some((curve_points(shape), placement)),
            ClosedProfile::Other(_) => None,
        },
        FeatureKind::Slot {
            course_of_travel:
                TravelPath::Linear {
                    placement,
                    distance,
                    direction,
                },
            swept_shape,
            ..
        } => {
            // A V or sloped-wall profile is widest at the top.
            let half = super::prismatic::top_half_width(swept_shape, depth)
                .or_else(|| slot_half_width(swept_shape))?;
            let d = Vector3::from(direction.ratios).try_normalize(1e-12)?;
            let end = d * distance.nominal;
            let n = Vector3::new(-d.y, d.x, 0.0) * half;
            // Along the travel only the course itself: open ends leave
            // the stock where the course meets its side.
            let pts = [Vector3::zeros(), end]
                .iter()
                .flat_map(|p| [p + n, p - n])
                .map(|p| [p.x, p.y])
                .collect();
            Some((pts, placement))
        }
        _ => None,
    }
}

/// Half the width a slot's cross-section sweeps.
pub fn slot_half_width(p: &OpenProfile) -> Option<f64> {
    match p {
        OpenProfile::SquareU { width, .. } | OpenProfile::RoundedU { width, .. } => {
            Some(width.nominal / 2.0)
        }
        OpenProfile::PartialCircular { radius, .. } => Some(radius.nominal),
        _ => None,
    }
}

fn square(r: f64) -> Vec<[f64; 2]> {
    rect(r, r)
}

fn rect(a: f64, b: f64) -> Vec<[f64; 2]> {
    vec![[-a, -b], [a, -b], [a, b], [-a, b]]
}

/// Points of a curve (control points, ends and centres of arcs).
fn curve_points(c: &Curve) -> Vec<[f64; 2]> {
    match c {
        Curve::Polyline { points, .. } => points.iter().map(|p| [p.xyz[0], p.xyz[1]]).collect(),
        Curve::Line { start, end, .. } => vec![xy(start), xy(end)],
        Curve::Arc { circle, radius, .. } => {
            let c = circle.location.xyz;
            square(*radius)
                .into_iter()
                .map(|[x, y]| [c[0] + x, c[1] + y])
                .collect()
        }
        Curve::Composite { segments, .. } => segments
            .iter()
            .flat_map(|s| curve_points(&s.curve))
            .collect(),
        Curve::Other(_) => Vec::new(),
    }
}

fn xy(p: &Point) -> [f64; 2] {
    [p.xyz[0], p.xyz[1]]
}

/// The placement of a feature's profile, when it has one.
fn profile_placement(kind: &FeatureKind) -> Option<&Axis2Placement> {
    match kind {
        FeatureKind::ClosedPocket { boundary, .. } => match boundary {
            ClosedProfile::Rectangular { placement, .. }
            | ClosedProfile::Circular { placement, .. }
            | ClosedProfile::General { placement, .. } => placement.as_ref(),
            ClosedProfile::Other(_) => None,
        },
        FeatureKind::Slot {
            course_of_travel:
                TravelPath::Linear { placement, .. } | TravelPath::General { placement, .. },
            ..
        } => placement.as_ref(),
        _ => None,
    }
}

/// True when the profile's placement repeats the feature's own (a
/// non-zero location written twice): read as ISO 14649-10 says, the
/// profile then sits at twice the distance from the workpiece origin.
pub fn repeats_placement(f: &Feature) -> bool {
    let Some(p) = profile_placement(&f.kind) else {
        return false;
    };
    let a = Vector3::from(p.location.xyz);
    let b = Vector3::from(f.placement.location.xyz);
    b.xy().norm() > TOLERANCE && (a - b).norm() < 1e-6
}

/// What the validator found: errors stop the post, warnings go with it.
#[derive(Default)]
pub struct Findings {
    pub errors: Vec<PostError>,
    pub warnings: Vec<Diagnostic>,
}

/// Checks every workingstep of the plan.
pub fn validate(project: &Project, items: &[Item<'_>], base: &Frame) -> Findings {
    let mut out = Findings::default();
    let mut named: Vec<&Feature> = Vec::new();
    for item in items {
        let Item::Step(s) = item else { continue };
        // Once per feature, however many workingsteps cut it.
        if named.iter().any(|f| std::ptr::eq(*f, s.feature)) {
            if let Some(w) = &s.plane_warning {
                out.warnings.push(w.clone());
            }
            continue;
        }
        named.push(s.feature);
        if repeats_placement(s.feature) {
            out.warnings.push(repeated_placement(s.feature));
        }
        // Holes, pockets and slots go down into the material; a face's or
        // a step's depth plane may sit at its placement, and explicit
        // toolpaths say their own depths.
        let sinks = matches!(
            s.feature.kind,
            FeatureKind::RoundHole { .. }
                | FeatureKind::ClosedPocket { .. }
                | FeatureKind::OpenPocket { .. }
                | FeatureKind::Slot { .. }
                | FeatureKind::Step { .. }
        );
        if s.bottom >= s.top - 1e-9 && sinks {
            out.errors.push(PostError::outside(
                name(s),
                format!(
                    "its depth plane (z {}) is not below its top (z {})",
                    s.bottom, s.top
                ),
                "give the depth plane a negative z in the feature's frame".into(),
            ));
        }
        check_stock(project, s, base, &mut out);
        if let Some(w) = &s.plane_warning {
            out.warnings.push(w.clone());
        }
        if let Some(w) = super::chipload::check(s) {
            out.warnings.push(w);
        }
        if let Some(w) = super::chipload::check_speed(s) {
            out.warnings.push(w);
        }
    }
    out
}

fn check_stock(project: &Project, s: &Step<'_>, base: &Frame, out: &mut Findings) {
    let Some(stock) = stock(project, s.feature.workpiece, base) else {
        if !out.warnings.iter().any(|d| d.code == Code::StockUnknown) {
            let wp = project.workpieces.get(s.feature.workpiece.index());
            out.warnings.push(Diagnostic::new(
                Code::StockUnknown,
                format!(
                    "`{}`: the workpiece gives no BLOCK, so no feature is checked against the stock",
                    wp.map_or("", |w| w.id.as_str())
                ),
            ).help("give the WORKPIECE a BLOCK bounding geometry (its_bounding_geometry)"));
        }
        return;
    };
    let Some(fb) = feature_box(s) else { return };
    if stock.holds(&fb, is_through(&s.feature.kind), TOLERANCE) {
        return;
    }
    let cause = if repeats_placement(s.feature) {
        "its profile's placement repeats the feature's placement (the generator wrote the absolute position in both; ISO 14649-10 places a profile in its feature's frame, so they add up): post with --profiles-absolute to read the profile's placement as the feature's, or correct the file"
    } else if fb.min.z < stock.min.z - TOLERANCE {
        "it is deeper than the stock: check its depth plane and the block's height"
    } else {
        "check the feature's placement against the workpiece setup and the block's placement"
    };
    out.errors.push(PostError::outside(
        name(s),
        format!(
            "the feature ({}) lies outside the stock ({})",
            fb.describe(),
            stock.describe()
        ),
        cause.into(),
    ));
}

/// The feature's its_id, or its workingstep's when the file leaves it
/// empty (so the message can still be located).
fn name<'s>(s: &'s Step<'_>) -> &'s str {
    if s.feature.id.is_empty() {
        &s.ws.id
    } else {
        &s.feature.id
    }
}

/// Features that break through the stock's bottom.
pub fn is_through(k: &FeatureKind) -> bool {
    match k {
        FeatureKind::RoundHole { bottom, .. } => matches!(bottom, HoleBottom::Through),
        FeatureKind::ClosedPocket { pocket, .. } | FeatureKind::OpenPocket { pocket, .. } => {
            matches!(pocket.bottom, PocketBottom::Through)
        }
        _ => false,
    }
}

fn repeated_placement(f: &Feature) -> Diagnostic {
    let l = f.placement.location.xyz;
    Diagnostic::new(
        Code::ProfilePlacementRepeated,
        format!(
            "`{}`: its profile's placement repeats the feature's placement ({}, {}, {})",
            f.id, l[0], l[1], l[2]
        ),
    )
    .help("ISO 14649-10 places a profile in its feature's frame, so cncc adds the two; if the generator meant one absolute position, post with --profiles-absolute")
}

/// `--profiles-absolute`: a profile whose placement repeats its feature's
/// is read as written in workpiece coordinates: it is carried into the
/// feature's frame (the feature's placement inverted, then the profile's,
/// by the geometry kernel). Only such profiles change.
pub fn profiles_absolute(project: &mut Project) {
    for f in &mut project.features {
        if !repeats_placement(f) {
            continue;
        }
        let feature = Frame::from_placement(&f.placement);
        let p = match &mut f.kind {
            FeatureKind::ClosedPocket { boundary, .. } => match boundary {
                ClosedProfile::Rectangular { placement, .. }
                | ClosedProfile::Circular { placement, .. }
                | ClosedProfile::General { placement, .. } => placement.as_mut(),
                ClosedProfile::Other(_) => None,
            },
            FeatureKind::Slot {
                course_of_travel:
                    TravelPath::Linear { placement, .. } | TravelPath::General { placement, .. },
                ..
            } => placement.as_mut(),
            _ => None,
        };
        if let Some(p) = p {
            let Some(r) = feature.relative(&Frame::from_placement(p)) else {
                continue;
            };
            let clean = |v: P3| v.map(|c| if c.abs() < 1e-12 { 0.0 } else { c });
            p.location.xyz = clean(r.origin);
            if let Some(a) = p.axis.as_mut() {
                a.ratios = clean(r.z);
            }
            if let Some(x) = p.ref_direction.as_mut() {
                x.ratios = clean(r.x);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_box_holds_what_is_inside_and_a_through_bottom() {
        let b = Aabb {
            min: Point3::new(0.0, 0.0, 0.0),
            max: Point3::new(100.0, 100.0, 50.0),
        };
        let inner = Aabb {
            min: Point3::new(10.0, 10.0, -2.0),
            max: Point3::new(20.0, 20.0, 50.0),
        };
        assert!(!b.holds(&inner, false, TOLERANCE));
        assert!(b.holds(&inner, true, TOLERANCE));
        let out = Aabb {
            min: Point3::new(70.0, 50.0, 20.0),
            max: Point3::new(150.0, 100.0, 50.0),
        };
        assert!(!b.holds(&out, false, TOLERANCE));
    }
}
