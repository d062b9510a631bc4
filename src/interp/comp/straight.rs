//! Straight moves under compensation: the entry move, and later moves with
//! the corner they make with the held-back move (convex: an added arc;
//! concave: the held-back move is cut short where the two offset paths meet).

use super::angle::add_half_pis;
use super::error::CompErrorKind;
use super::queue::Queued;
use super::{MoveKind, RadiusComp};
use crate::canon::{Canon, Pose};
use std::f64::consts::FRAC_PI_2;

/// Corners turning less than this (radians) need no added arc; LinuxCNC's
/// `TOLERANCE_CONCAVE_CORNER`.
pub(super) const SMALL: f64 = 0.05;

impl RadiusComp {
    /// The entry move: ends one radius beside `to`, square to the line
    /// from the tool to `to`.
    pub(super) fn straight_entry(
        &mut self,
        kind: MoveKind,
        from: Pose,
        to: Pose,
    ) -> Result<(), super::CompError> {
        let (cx, cy) = (from[0], from[1]);
        let (px, py) = (to[0], to[1]);
        if self.rules.entry_longer_than_radius && (px - cx).hypot(py - cy) <= self.radius {
            return Err(self.error(CompErrorKind::EntryMoveTooShort, None));
        }
        let k = if self.left() { 1 } else { -1 };
        let alpha = add_half_pis((py - cy).atan2(px - cx), k);
        let end = (
            px + self.radius * alpha.cos(),
            py + self.radius * alpha.sin(),
        );
        self.queue.start = Some((cx, cy));
        let mut p = to;
        p[0] = end.0;
        p[1] = end.1;
        self.queue.push(Queued::Line {
            kind,
            dir: (alpha.cos(), alpha.sin()),
            to: p,
            block: self.block,
        });
        self.first_move = false;
        self.current = [end.0, end.1, to[2]];
        Ok(())
    }

    /// A straight move after the entry move.
    pub(super) fn straight_next(
        &mut self,
        kind: MoveKind,
        from: Pose,
        to: Pose,
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), super::CompError> {
        let [cx, cy, cz] = self.current;
        let (opx, opy) = (from[0], from[1]);
        let (px, py) = (to[0], to[1]);
        if px == opx && py == opy {
            let mut p = to;
            p[0] = cx;
            p[1] = cy;
            self.queue.push(Queued::Line {
                kind,
                dir: (0.0, 0.0),
                to: p,
                block: self.block,
            });
            self.current[2] = to[2];
            return Ok(());
        }
        let r = self.radius;
        let mut theta = (cy - opy).atan2(cx - opx);
        let mut alpha = (py - opy).atan2(px - opx);
        let (beta, gamma) = if self.left() {
            if theta < alpha {
                theta = add_half_pis(theta, 4);
            }
            (add_half_pis(theta - alpha, -1), FRAC_PI_2)
        } else {
            if alpha < theta {
                alpha = add_half_pis(alpha, 4);
            }
            (add_half_pis(alpha - theta, -1), -FRAC_PI_2)
        };
        let normal = alpha + gamma;
        let end = (px + r * normal.cos(), py + r * normal.sin());
        let mid = (opx + r * normal.cos(), opy + r * normal.sin());
        let concave = beta < -SMALL || beta > add_half_pis(SMALL, 2) || self.h_shape(beta);
        if !concave && beta > SMALL {
            self.move_end_and_flush((cx, cy), out)?;
            let abc = [to[3], to[4], to[5]];
            let corner = match kind {
                MoveKind::Feed => {
                    let turn = if self.left() { -1 } else { 1 };
                    Queued::Arc {
                        sweep: 0.0,
                        end: mid,
                        centre: (opx, opy),
                        turn,
                        z: cz,
                        abc,
                        block: self.block,
                    }
                }
                MoveKind::Rapid => Queued::Line {
                    kind,
                    dir: (0.0, 0.0),
                    to: [mid.0, mid.1, cz, abc[0], abc[1], abc[2]],
                    block: self.block,
                },
            };
            self.queue.push(corner);
            self.queue.flush(out);
            self.queue.start = Some(mid);
        } else if concave {
            let p = self.concave_end(beta, theta + gamma, from, to)?;
            self.move_end_and_flush(p, out)?;
        } else {
            self.queue.flush(out);
            self.queue.start = Some((cx, cy));
        }
        let mut p = to;
        p[0] = end.0;
        p[1] = end.1;
        self.queue.push(Queued::Line {
            kind,
            dir: (px - opx, py - opy),
            to: p,
            block: self.block,
        });
        self.current = [end.0, end.1, to[2]];
        Ok(())
    }

    /// The "h" shape: a nearly reversing corner after an arc that turns
    /// towards the tool side is taken as concave.
    fn h_shape(&self, beta: f64) -> bool {
        if beta <= add_half_pis(-SMALL, 2) {
            return false;
        }
        match self.queue.front() {
            Some(Queued::Arc { turn, .. }) => {
                (self.left() && *turn < 0) || (!self.left() && *turn > 0)
            }
            _ => false,
        }
    }

    /// Where the held-back move must end in a concave corner before a line.
    /// `back` is the direction back along the held-back compensated path.
    fn concave_end(
        &self,
        beta: f64,
        back: f64,
        from: Pose,
        to: Pose,
    ) -> Result<(f64, f64), super::CompError> {
        let r = self.radius;
        let [cx, cy, _] = self.current;
        match self.queue.front() {
            Some(Queued::Arc {
                end, centre, turn, ..
            }) => self.arc_to_line_end(*end, *centre, *turn, from, to),
            _ => {
                let half = add_half_pis(beta, 2) / 2.0;
                if half == 0.0 {
                    return Err(self.error(CompErrorKind::ZeroDegreeCorner, None));
                }
                let retreat = r / half.tan();
                Ok((cx + retreat * back.cos(), cy + retreat * back.sin()))
            }
        }
    }

    /// Concave arc-to-line corner: where on the held-back (compensated)
    /// arc the tool meets the offset of the new line.
    fn arc_to_line_end(
        &self,
        end: (f64, f64),
        centre: (f64, f64),
        turn: i64,
        from: Pose,
        to: Pose,
    ) -> Result<(f64, f64), super::CompError> {
        let r = self.radius;
        let (opx, opy) = (from[0], from[1]);
        let oldrad = (centre.1 - end.1).hypot(centre.0 - end.0);
        let base = (to[1] - opy).atan2(to[0] - opx);
        let theta = add_half_pis(base, if turn > 0 { 1 } else { -1 });
        let phi = (centre.1 - opy).atan2(centre.0 - opx);
        let inside = super::angle::tool_inside_arc(self.left(), turn);
        let uncomp = if inside { oldrad + r } else { oldrad - r };
        let d = uncomp * (theta - phi).cos();
        let l = if inside {
            (d - r) / oldrad
        } else {
            (d + r) / oldrad
        };
        if !(-1.0..=1.0).contains(&l) {
            return Err(self.error(CompErrorKind::ArcToStraightGouge, None));
        }
        let sign = if inside == (turn > 0) { -1.0 } else { 1.0 };
        let angle = add_half_pis(sign * l.acos() + theta, 2);
        Ok((
            centre.0 + oldrad * angle.cos(),
            centre.1 + oldrad * angle.sin(),
        ))
    }
}
