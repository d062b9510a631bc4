//! Arcs under compensation: the entry arc, and later arcs with the corner
//! they make with the held-back move.

use super::angle::{add_half_pis, find_turn, tool_inside_arc};
use super::error::{CompError, CompErrorKind};
use super::queue::Queued;
use super::straight::SMALL;
use super::RadiusComp;
use crate::canon::{Canon, Pose};

/// LinuxCNC's `TOLERANCE_EQUAL`.
const TOLERANCE_EQUAL: f64 = 0.0001;

impl RadiusComp {
    /// The entry arc: a new arc from the tool to one radius beside the
    /// programmed end, whose centre keeps it tangent there.
    pub(super) fn arc_entry(
        &mut self,
        from: Pose,
        to: Pose,
        centre: (f64, f64),
        turn: i64,
    ) -> Result<(), CompError> {
        let r = self.radius;
        let (cx, cy) = (from[0], from[1]);
        let (ex, ey) = (to[0], to[1]);
        if self.rules.entry_longer_than_radius && (ex - cx).hypot(ey - cy) <= r {
            return Err(self.error(CompErrorKind::EntryArcTooShort, None));
        }
        let gamma = if tool_inside_arc(self.left(), turn) {
            (centre.1 - ey).atan2(centre.0 - ex)
        } else {
            (ey - centre.1).atan2(ex - centre.0)
        };
        let end = (ex + r * gamma.cos(), ey + r * gamma.sin());
        let b_len = (cy - end.1).hypot(cx - end.0) / 2.0;
        let ab = (centre.1 - end.1).atan2(centre.0 - end.0);
        let a = (cy - end.1).atan2(cx - end.0) - ab;
        if a.cos().abs() < TOLERANCE_EQUAL {
            return Err(self.error(CompErrorKind::ToolRadiusNotLessThanArcRadius, None));
        }
        let c_len = b_len / a.cos();
        let c = (end.0 + c_len * ab.cos(), end.1 + c_len * ab.sin());
        let sweep = find_turn((cx, cy), c, turn, end);
        let abc = [to[3], to[4], to[5]];
        self.queue.push(Queued::Arc {
            sweep,
            end,
            centre: c,
            turn,
            z: to[2],
            abc,
            block: self.block,
        });
        self.first_move = false;
        self.current = [end.0, end.1, to[2]];
        Ok(())
    }

    /// An arc after the entry move.
    pub(super) fn arc_next(
        &mut self,
        from: Pose,
        to: Pose,
        centre: (f64, f64),
        turn: i64,
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), CompError> {
        let r = self.radius;
        let left = self.left();
        let [cx, cy, cz] = self.current;
        let op = (from[0], from[1]);
        let (ex, ey) = (to[0], to[1]);
        let arc_radius = (centre.0 - ex).hypot(centre.1 - ey);
        let theta = add_half_pis((cy - op.1).atan2(cx - op.0), if left { -1 } else { 1 });
        let mut delta = (centre.1 - op.1).atan2(centre.0 - op.0);
        let alpha = add_half_pis(delta, if turn > 0 { -1 } else { 1 });
        let beta = normalize(if left { theta - alpha } else { alpha - theta });
        let inside = tool_inside_arc(left, turn);
        let gamma = if inside {
            if arc_radius <= r {
                return Err(self.error(CompErrorKind::ToolRadiusNotLessThanArcRadius, None));
            }
            (centre.1 - ey).atan2(centre.0 - ex)
        } else {
            delta = add_half_pis(delta, 2);
            (ey - centre.1).atan2(ex - centre.0)
        };
        let new_end = (ex + r * gamma.cos(), ey + r * gamma.sin());
        let abc = [to[3], to[4], to[5]];
        let main = Queued::Arc {
            sweep: find_turn(op, centre, turn, (ex, ey)),
            end: new_end,
            centre,
            turn,
            z: to[2],
            abc,
            block: self.block,
        };
        let pi = add_half_pis(0.0, 2);
        let concave = beta < -SMALL
            || beta > add_half_pis(SMALL, 2)
            || ((beta - pi).abs() < SMALL && !inside);
        if concave {
            let mid = match self.queue.front() {
                Some(Queued::Arc {
                    end,
                    centre: pc,
                    turn: pt,
                    ..
                }) => self.arc_to_arc_end(*end, *pc, *pt, centre, turn, arc_radius)?,
                _ => self.line_to_arc_end(beta, theta, centre, turn, arc_radius)?,
            };
            self.move_end_and_flush(mid, out)?;
        } else if beta > SMALL {
            let mid = (op.0 + r * delta.cos(), op.1 + r * delta.sin());
            self.queue.flush(out);
            let t = if left { -1 } else { 1 };
            self.queue.push(Queued::Arc {
                sweep: 0.0,
                end: mid,
                centre: op,
                turn: t,
                z: cz,
                abc,
                block: self.block,
            });
            self.queue.flush(out);
            self.queue.start = Some(mid);
        } else {
            self.queue.flush(out);
            self.queue.start = Some((cx, cy));
        }
        self.queue.push(main);
        self.current = [new_end.0, new_end.1, to[2]];
        Ok(())
    }

    /// Concave line-to-arc corner: where the held-back line must end.
    fn line_to_arc_end(
        &self,
        beta: f64,
        theta: f64,
        centre: (f64, f64),
        turn: i64,
        arc_radius: f64,
    ) -> Result<(f64, f64), CompError> {
        let r = self.radius;
        let y = arc_radius * add_half_pis(beta, -1).sin();
        let inside = tool_inside_arc(self.left(), turn);
        let (dist, toward) = if inside {
            (arc_radius - r, y + r)
        } else {
            (arc_radius + r, y - r)
        };
        let l = toward / dist;
        if !(-1.0..=1.0).contains(&l) {
            return Err(self.error(CompErrorKind::ArcGouge, None));
        }
        let angle = match (inside, turn > 0) {
            (true, true) => theta + l.asin(),
            (true, false) => theta - l.asin(),
            (false, true) => add_half_pis(theta, 2) - l.asin(),
            (false, false) => add_half_pis(theta, 2) + l.asin(),
        };
        Ok((centre.0 + dist * angle.cos(), centre.1 + dist * angle.sin()))
    }

    /// Concave arc-to-arc corner: where the two compensated arcs cross.
    fn arc_to_arc_end(
        &self,
        pend: (f64, f64),
        pc: (f64, f64),
        pturn: i64,
        centre: (f64, f64),
        turn: i64,
        arc_radius: f64,
    ) -> Result<(f64, f64), CompError> {
        let r = self.radius;
        let oldrad = (pc.1 - pend.1).hypot(pc.0 - pend.0);
        let newrad = if tool_inside_arc(self.left(), turn) {
            arc_radius - r
        } else {
            arc_radius + r
        };
        let cc = (pc.1 - centre.1).hypot(pc.0 - centre.0);
        if oldrad == 0.0 || cc == 0.0 {
            return Err(self.error(CompErrorKind::ArcsSameCentre, None));
        }
        let a = (oldrad * oldrad + cc * cc - newrad * newrad) / (2.0 * oldrad * cc);
        if !(-1.0..=1.0).contains(&a) {
            return Err(self.error(CompErrorKind::ArcToArcGouge, None));
        }
        let pullback = a.acos();
        let cc_dir = (centre.1 - pc.1).atan2(centre.0 - pc.0);
        let plus = tool_inside_arc(self.left(), pturn) == (turn > 0);
        let dir = if plus {
            cc_dir + pullback
        } else {
            cc_dir - pullback
        };
        Ok((pc.0 + oldrad * dir.cos(), pc.1 + oldrad * dir.sin()))
    }
}

/// Brings an angle into (-pi/2, 3pi/2], as LinuxCNC normalizes `beta`.
fn normalize(beta: f64) -> f64 {
    if beta > add_half_pis(0.0, 3) {
        add_half_pis(beta, -4)
    } else if beta < add_half_pis(0.0, -1) {
        add_half_pis(beta, 4)
    } else {
        beta
    }
}
