//! `APPR CT`/`APPR LCT` and `DEP CT`/`DEP LCT`: approaching and leaving
//! the contour on an arc tangent to it.
//!
//! Geometry as the TNC manuals describe it (iTNC 530 / TNC 7 user
//! manuals, "contour approach and departure"):
//! * APPR CT: a straight line from the start PS to an auxiliary point PH,
//!   then an arc of radius R and centre angle CCA from PH to the first
//!   contour point PA, tangent there to the first contour element.
//! * APPR LCT: the straight line from PS is itself tangent to that arc
//!   (no CCA): PH is where the line from PS touches the circle.
//! * DEP CT: an arc of radius R and centre angle CCA from the contour end
//!   PE, tangent to the last element; DEP LCT: the arc, then a straight
//!   line tangent to it to the end point PN.
//! * The arc turns counterclockwise for RL with R > 0 and RR with R < 0,
//!   clockwise for RR with R > 0 and RL with R < 0 (the manuals' table);
//!   with R0 the RL rule is used [?: the TNC 7 refuses R0 here].
//!
//! All points are base-frame mm in the working plane's first two axes.

use super::super::comp::MoveKind;
use super::super::machine::pose6;
use super::super::{Interp, Stop};
use crate::ir::CompSide;

type P2 = (f64, f64);

/// How the arc part of an approach or departure is made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcPart {
    /// Radius (mm) as written, with its sign.
    pub radius: f64,
    /// Centre angle in degrees (CT); `None` for LCT.
    pub angle: Option<f64>,
}

/// +1 counterclockwise, -1 clockwise, from the side and the sign of R.
pub fn turn(side: CompSide, radius: f64) -> f64 {
    let left = !matches!(side, CompSide::Right);
    if left == (radius >= 0.0) {
        1.0
    } else {
        -1.0
    }
}

fn rotate(p: P2, c: P2, deg: f64) -> P2 {
    let [x, y] = crate::geom::turn_about([p.0, p.1], [c.0, c.1], deg);
    (x, y)
}

/// The centre of the arc tangent to direction `d` (unit) at `p`.
pub fn centre(p: P2, d: P2, r: f64, s: f64) -> P2 {
    (p.0 - s * r * d.1, p.1 + s * r * d.0)
}

/// The point where a line through `q` touches the circle (`c`, `r`),
/// turning with `s`; `towards`: the line goes from the circle to `q`
/// (departure), else from `q` to the circle (approach). `None` when `q`
/// is inside the circle.
pub fn tangent_point(q: P2, c: P2, r: f64, s: f64, towards: bool) -> Option<P2> {
    let (vx, vy) = (q.0 - c.0, q.1 - c.1);
    let dist = vx.hypot(vy);
    if dist <= r + 1e-9 {
        return None;
    }
    let phi0 = vy.atan2(vx);
    let alpha = (r / dist).acos();
    [phi0 + alpha, phi0 - alpha].into_iter().find_map(|phi| {
        let p = (c.0 + r * phi.cos(), c.1 + r * phi.sin());
        let t = (-s * phi.sin(), s * phi.cos());
        let along = (q.0 - p.0) * t.0 + (q.1 - p.1) * t.1;
        ((along > 0.0) == towards).then_some(p)
    })
}

/// The auxiliary point PH of an approach to `pa` along `d`, from `ps`.
pub fn approach_point(ps: P2, pa: P2, d: P2, arc: ArcPart, s: f64) -> Option<P2> {
    let r = arc.radius.abs();
    let c = centre(pa, d, r, s);
    match arc.angle {
        Some(cca) => Some(rotate(pa, c, -s * cca)),
        None => tangent_point(ps, c, r, s, false),
    }
}

/// The end of a departure's arc from `pe` along `d` (CT: by CCA; LCT:
/// where the line to `pn` leaves it).
pub fn departure_point(pe: P2, pn: Option<P2>, d: P2, arc: ArcPart, s: f64) -> Option<P2> {
    let r = arc.radius.abs();
    let c = centre(pe, d, r, s);
    match (arc.angle, pn) {
        (Some(cca), _) => Some(rotate(pe, c, s * cca)),
        (None, Some(pn)) => tangent_point(pn, c, r, s, true),
        (None, None) => None,
    }
}

/// Sends an arc from the current position to `to` (base, mm) round `c`.
pub fn arc_to(it: &mut Interp<'_, '_>, to: &[f64; 9], c: P2, s: f64) -> Result<(), Stop> {
    if to[..3] == it.state.pos[..3] {
        return Ok(());
    }
    let end = pose6(&it.state, to);
    let centre = (it.state.to_prog(c.0), it.state.to_prog(c.1));
    it.arc_move(end, centre, if s > 0.0 { 1 } else { -1 })?;
    it.state.pos = *to;
    Ok(())
}

/// Sends a straight feed from the current position to `to`.
pub fn line_to(it: &mut Interp<'_, '_>, to: &[f64; 9]) -> Result<(), Stop> {
    if *to == it.state.pos {
        return Ok(());
    }
    let pose = pose6(&it.state, to);
    it.straight_move(MoveKind::Feed, pose)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: P2, b: P2) -> bool {
        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9
    }

    #[test]
    fn appr_ct_rr_half_circle() {
        // The manual's example: PA (10, 20), R+10 RR CCA180, first element
        // towards (20, 35). RR with R > 0 turns clockwise.
        let s = turn(CompSide::Right, 10.0);
        assert_eq!(s, -1.0);
        let d = (10.0 / 325f64.sqrt(), 15.0 / 325f64.sqrt());
        let arc = ArcPart {
            radius: 10.0,
            angle: Some(180.0),
        };
        let ph = approach_point((40.0, 10.0), (10.0, 20.0), d, arc, s).unwrap();
        // PH is the diametrically opposite point: PA + 2R * right normal.
        let n = (d.1, -d.0);
        assert!(close(ph, (10.0 + 20.0 * n.0, 20.0 + 20.0 * n.1)), "{ph:?}");
    }

    #[test]
    fn appr_lct_line_touches_the_circle() {
        // PA (0,0) heading +X, RL R5: centre (0, 5) and PS (-20, 5).
        let s = turn(CompSide::Left, 5.0);
        let arc = ArcPart {
            radius: 5.0,
            angle: None,
        };
        let ph = approach_point((-20.0, 5.0), (0.0, 0.0), (1.0, 0.0), arc, s).unwrap();
        // cos a = R / |PS - C| = 1/4: PH = C + 5 (-1/4, -sin a).
        let sin_a = (1.0f64 - 0.0625).sqrt();
        assert!(close(ph, (-1.25, 5.0 - 5.0 * sin_a)), "{ph:?}");
        // The line PS→PH is perpendicular to the radius at PH.
        let (rx, ry) = (ph.0 - 0.0, ph.1 - 5.0);
        let (lx, ly) = (ph.0 + 20.0, ph.1 - 5.0);
        assert!((rx * lx + ry * ly).abs() < 1e-9);
    }

    #[test]
    fn dep_ct_quarter_turn_left() {
        // PE (0,0) heading +X, RL R+5, CCA 90: ends at (5, 5).
        let s = turn(CompSide::Left, 5.0);
        let arc = ArcPart {
            radius: 5.0,
            angle: Some(90.0),
        };
        let pn = departure_point((0.0, 0.0), None, (1.0, 0.0), arc, s).unwrap();
        assert!(close(pn, (5.0, 5.0)), "{pn:?}");
    }

    #[test]
    fn inside_the_circle_has_no_tangent() {
        assert_eq!(tangent_point((0.0, 1.0), (0.0, 0.0), 5.0, 1.0, false), None);
    }
}
