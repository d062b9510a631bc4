//! Hole groups and patterns: consecutive workingsteps that make the same
//! hole with the same operation at different places are posted as one
//! cycle call with several positions; positions that form a row, a
//! circle or an axis-parallel grid become the target's pattern cycle
//! (840D `HOLES1`, `HOLES2`, `CYCLE801`) where it has one.

use super::paths::P2;
use super::plan::{Item, Step};
use crate::stepnc::model::{FeatureKind, TravelPath};

const EPS: f64 = 1e-6;

/// What the program writes, in order: one item, or a group of holes.
pub enum Unit<'a, 'p> {
    Item(&'a Item<'p>),
    Holes(Vec<&'a Step<'p>>),
    /// Consecutive alike slots (same size, depth, tool and operation).
    Slots(Vec<&'a Step<'p>>),
}

/// Groups consecutive equal hole operations.
pub fn units<'a, 'p>(items: &'a [Item<'p>]) -> Vec<Unit<'a, 'p>> {
    let mut out: Vec<Unit<'a, 'p>> = Vec::new();
    for item in items {
        let Item::Step(s) = item else {
            out.push(Unit::Item(item));
            continue;
        };
        if matches!(s.feature.kind, FeatureKind::Slot { .. }) {
            match out.last_mut() {
                Some(Unit::Slots(g)) if same_slot_op(g[0], s) => g.push(s),
                _ => out.push(Unit::Slots(vec![s])),
            }
            continue;
        }
        // A milled hole is a pocket of its own, never a cycle position.
        if !matches!(s.feature.kind, FeatureKind::RoundHole { .. }) || super::plan::is_milling(s.op)
        {
            out.push(Unit::Item(item));
            continue;
        }
        if let Some(Unit::Holes(g)) = out.last_mut() {
            if same_hole_op(g[0], s) && !g.iter().any(|o| same_place(o, s)) {
                g.push(s);
                continue;
            }
        }
        out.push(Unit::Holes(vec![s]));
    }
    out
}

fn same_hole_op(a: &Step<'_>, b: &Step<'_>) -> bool {
    let blank = |s: &Step<'_>| {
        let mut op = s.op.clone();
        op.id.clear();
        op
    };
    let (fa, fb) = (&a.feature.kind, &b.feature.kind);
    a.tilt.is_none()
        && b.tilt.is_none()
        && a.tool_no == b.tool_no
        && blank(a) == blank(b)
        && fa == fb
        && (a.top - b.top).abs() < EPS
        && (a.bottom - b.bottom).abs() < EPS
        && (a.clear - b.clear).abs() < EPS
}

/// Slots alike but for where they lie (the course of travel's direction
/// and placement may differ).
fn same_slot_op(a: &Step<'_>, b: &Step<'_>) -> bool {
    let size = |s: &Step<'_>| match &s.feature.kind {
        FeatureKind::Slot {
            course_of_travel: TravelPath::Linear { distance, .. },
            swept_shape,
            end_conditions,
        } => Some((
            distance.clone(),
            swept_shape.clone(),
            end_conditions.clone(),
        )),
        _ => None,
    };
    let blank = |s: &Step<'_>| {
        let mut op = s.op.clone();
        op.id.clear();
        op
    };
    a.tilt.is_none()
        && b.tilt.is_none()
        && size(a).is_some()
        && size(a) == size(b)
        && a.tool_no == b.tool_no
        && blank(a) == blank(b)
        && a.roughed_by == b.roughed_by
        && (a.top - b.top).abs() < EPS
        && (a.bottom - b.bottom).abs() < EPS
        && (a.clear - b.clear).abs() < EPS
}

fn same_place(a: &Step<'_>, b: &Step<'_>) -> bool {
    dist(xy(a), xy(b)) < EPS
}

/// A hole's position in the plane.
pub fn xy(s: &Step<'_>) -> P2 {
    [s.frame.origin[0], s.frame.origin[1]]
}

fn dist(a: P2, b: P2) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// A regular arrangement of positions.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// From `start`, `num` holes `spacing` apart at `angle` degrees.
    Row {
        start: P2,
        angle: f64,
        spacing: f64,
        num: usize,
    },
    /// `num` holes on a circle, the first at `start` degrees, each
    /// `index` degrees on (positive counter-clockwise).
    Circle {
        centre: P2,
        radius: f64,
        start: f64,
        index: f64,
        num: usize,
    },
    /// `nx` x `ny` holes from the lower-left `origin`, axis-parallel.
    Grid {
        origin: P2,
        dx: f64,
        dy: f64,
        nx: usize,
        ny: usize,
    },
}

/// The pattern the positions form, if any (three holes at least).
pub fn pattern(p: &[P2]) -> Option<Pattern> {
    if p.len() < 3 {
        return None;
    }
    row(p).or_else(|| circle(p)).or_else(|| grid(p))
}

fn row(p: &[P2]) -> Option<Pattern> {
    let d = [p[1][0] - p[0][0], p[1][1] - p[0][1]];
    let spacing = dist(p[0], p[1]);
    let ok = p
        .iter()
        .enumerate()
        .all(|(k, q)| dist(*q, [p[0][0] + d[0] * k as f64, p[0][1] + d[1] * k as f64]) < EPS);
    ok.then(|| Pattern::Row {
        start: p[0],
        angle: d[1].atan2(d[0]).to_degrees(),
        spacing,
        num: p.len(),
    })
}

fn circle(p: &[P2]) -> Option<Pattern> {
    let centre = circumcentre(p[0], p[1], p[2])?;
    let radius = dist(centre, p[0]);
    let ang = |q: P2| (q[1] - centre[1]).atan2(q[0] - centre[0]).to_degrees();
    let start = ang(p[0]);
    let index = wrap(ang(p[1]) - start);
    let ok = p.iter().enumerate().all(|(k, q)| {
        (dist(*q, centre) - radius).abs() < EPS
            && wrap(ang(*q) - start - index * k as f64).abs() < 1e-6
    });
    (ok && index.abs() > 1e-6 && index.abs() * ((p.len() - 1) as f64) < 360.0 - 1e-6).then_some(
        Pattern::Circle {
            centre,
            radius,
            start,
            index,
            num: p.len(),
        },
    )
}

fn grid(p: &[P2]) -> Option<Pattern> {
    let xs = distinct(p.iter().map(|q| q[0]));
    let ys = distinct(p.iter().map(|q| q[1]));
    let (nx, ny) = (xs.len(), ys.len());
    if nx < 2 || ny < 2 || nx * ny != p.len() {
        return None;
    }
    let even = |v: &[f64]| {
        v.windows(2)
            .all(|w| ((w[1] - w[0]) - (v[1] - v[0])).abs() < EPS)
    };
    let all = xs.iter().all(|x| {
        ys.iter()
            .all(|y| p.iter().any(|q| dist(*q, [*x, *y]) < EPS))
    });
    (even(&xs) && even(&ys) && all).then(|| Pattern::Grid {
        origin: [xs[0], ys[0]],
        dx: xs[1] - xs[0],
        dy: ys[1] - ys[0],
        nx,
        ny,
    })
}

fn distinct(v: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = v.collect();
    v.sort_by(|a, b| a.total_cmp(b));
    v.dedup_by(|a, b| (*a - *b).abs() < EPS);
    v
}

fn wrap(a: f64) -> f64 {
    let r = (a + 180.0).rem_euclid(360.0) - 180.0;
    if (r + 180.0).abs() < 1e-9 {
        180.0
    } else {
        r
    }
}

fn circumcentre(a: P2, b: P2, c: P2) -> Option<P2> {
    let d = 2.0 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
    if d.abs() < 1e-9 {
        return None;
    }
    let sq = |p: P2| p[0] * p[0] + p[1] * p[1];
    Some([
        (sq(a) * (b[1] - c[1]) + sq(b) * (c[1] - a[1]) + sq(c) * (a[1] - b[1])) / d,
        (sq(a) * (c[0] - b[0]) + sq(b) * (a[0] - c[0]) + sq(c) * (b[0] - a[0])) / d,
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_of_equally_spaced_holes() {
        let p = [[10.0, 10.0], [20.0, 20.0], [30.0, 30.0], [40.0, 40.0]];
        match pattern(&p) {
            Some(Pattern::Row {
                angle,
                spacing,
                num,
                ..
            }) => {
                assert!((angle - 45.0).abs() < 1e-9);
                assert!((spacing - 200f64.sqrt()).abs() < 1e-9);
                assert_eq!(num, 4);
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(pattern(&[[0.0, 0.0], [10.0, 0.0], [25.0, 0.0]]), None);
    }

    #[test]
    fn a_bolt_circle() {
        let p: Vec<P2> = (0..4)
            .map(|k| {
                let a = (30.0 + 90.0 * k as f64).to_radians();
                [50.0 + 20.0 * a.cos(), 40.0 + 20.0 * a.sin()]
            })
            .collect();
        match pattern(&p) {
            Some(Pattern::Circle {
                centre,
                radius,
                start,
                index,
                num,
            }) => {
                assert!(dist(centre, [50.0, 40.0]) < 1e-9 && (radius - 20.0).abs() < 1e-9);
                assert!((start - 30.0).abs() < 1e-9 && (index - 90.0).abs() < 1e-9);
                assert_eq!(num, 4);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_grid_in_any_order() {
        let p = [
            [0.0, 0.0],
            [10.0, 5.0],
            [0.0, 5.0],
            [10.0, 0.0],
            [20.0, 0.0],
            [20.0, 5.0],
        ];
        assert_eq!(
            pattern(&p),
            Some(Pattern::Grid {
                origin: [0.0, 0.0],
                dx: 10.0,
                dy: 5.0,
                nx: 3,
                ny: 2
            })
        );
        assert_eq!(pattern(&p[..5]), None);
    }
}
