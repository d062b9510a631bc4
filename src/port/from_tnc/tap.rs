//! Heidenhain tapping cycles for a word-address target (see
//! [`super`] for the rules): 207 RIGID TAPPING → G84 / G74 with
//! F = |Q239| × S, 206 TAPPING with a floating holder → G84 / G74 by the
//! spindle's direction with F = Q206 and P = Q211.

use super::{coord, plain_cycle, Mapped, Pass};
use crate::ir::{CycleDef, CycleKind, Value};
use crate::span::Span;

impl Pass<'_> {
    /// 207 → G84 / G74 with F = pitch × S.
    pub(super) fn map_tap(&mut self, d: &CycleDef, span: Span) -> Result<Mapped, String> {
        let q = |n: u32| d.param(n).and_then(Value::number).map(|v| v.to_f64());
        let need = |n: u32| q(n).ok_or(format!("Q{n} is not a number known here"));
        let (top, sdis, depth, pitch) = (need(203)?, need(200)?.abs(), need(201)?, need(239)?);
        if pitch == 0.0 {
            return Err("a thread pitch Q239 of 0".into());
        }
        let speed = self
            .modal
            .speed
            .as_ref()
            .and_then(Value::number)
            .map(|v| v.to_f64())
            .filter(|s| *s > 0.0)
            .ok_or("tapping without a spindle speed known here (F = Q239 x S)")?;
        let left = pitch < 0.0;
        if self.modal.ccw != left {
            return Err(format!(
                "a {} tap with the spindle turning {}: {} needs {}",
                if left { "left-hand" } else { "right-hand" },
                if self.modal.ccw { "M4" } else { "M3" },
                if left { "G74" } else { "G84" },
                if left { "M4" } else { "M3" },
            ));
        }
        let kind = if left {
            CycleKind::TapLeft
        } else {
            CycleKind::Tap
        };
        self.target_has(kind)?;
        let (r, rtp) = (top + sdis, top + q(204).unwrap_or(0.0).abs());
        let mut c = plain_cycle(kind, r);
        c.target.z = Some(coord(top + depth, span));
        Ok(Mapped {
            cycle: c,
            r,
            rtp,
            feed: pitch.abs() * speed,
        })
    }

    /// 206 (floating tap holder) → G84 / G74 by the spindle's direction,
    /// F = Q206, P = Q211.
    pub(super) fn map_float_tap(&mut self, d: &CycleDef, span: Span) -> Result<Mapped, String> {
        let q = |n: u32| d.param(n).and_then(Value::number).map(|v| v.to_f64());
        let need = |n: u32| q(n).ok_or(format!("Q{n} is not a number known here"));
        let (top, sdis, depth, feed) = (need(203)?, need(200)?.abs(), need(201)?, need(206)?);
        let kind = if self.modal.ccw {
            CycleKind::TapLeft
        } else {
            CycleKind::Tap
        };
        self.target_has(kind)?;
        let (r, rtp) = (top + sdis, top + q(204).unwrap_or(0.0).abs());
        let mut c = plain_cycle(kind, r);
        c.target.z = Some(coord(top + depth, span));
        let dwell = q(211).unwrap_or(0.0);
        if dwell > 0.0 {
            c.p = Some(Value::Number(self.dwell_word(dwell)?));
        }
        Ok(Mapped {
            cycle: c,
            r,
            rtp,
            feed,
        })
    }
}
