//! What two matching operations ran with: feeds, spindle speeds and
//! dwells (a run of matching operations with the same two values is one
//! difference, named where it starts), and the rapids that led to them
//! (listed, never fatal).

use super::align::{close, differ, Aligner};
use super::describe::{self, num};
use super::ops::OpKind;
use super::{DiffKind, MAX_LISTED};
use crate::toolpath::P3;

impl Aligner<'_> {
    /// Compares what two matching operations ran with.
    pub(super) fn matched(&mut self, i: usize, j: usize) {
        if self.opts.compare_rapids {
            self.rapids(i, j);
        }
        let (Some(x), Some(y)) = (self.a.get(i), self.b.get(j)) else {
            return;
        };
        if !self.opts.compare_feeds || matches!(x.kind, OpKind::Tool(_)) {
            return;
        }
        let checks = [
            (DiffKind::Feed, x.feed, y.feed),
            (DiffKind::Spindle, x.spindle, y.spindle),
            (DiffKind::Dwell, x.dwell as f64, y.dwell as f64),
        ];
        let mut found = None;
        for (kind, p, q) in checks {
            let off = match kind {
                DiffKind::Feed | DiffKind::Spindle => super::align::rates_differ(p, q),
                _ => differ(p, q),
            };
            if off {
                found = Some((kind, p, q));
                break;
            }
        }
        let Some((kind, p, q)) = found else {
            self.open_tech = None;
            return;
        };
        if let Some((k, op, oq)) = self.open_tech {
            if let Some(last) = self.out.differences.last_mut() {
                if k == kind && !differ(op, p) && !differ(oq, q) && last.a_ops.end == i {
                    last.a_ops.end = i + 1;
                    last.b_ops.end = j + 1;
                    return;
                }
            }
        }
        self.open_tech = Some((kind, p, q));
        let what = match kind {
            DiffKind::Feed => format!(
                "feed: A {}; B {} ({})",
                describe::feed(x),
                describe::feed(y),
                describe::op(x)
            ),
            DiffKind::Spindle => format!(
                "spindle: A S{}; B S{} ({})",
                num(p),
                num(q),
                describe::op(x)
            ),
            _ => format!(
                "dwell: A {} s; B {} s (after {})",
                num(p),
                num(q),
                describe::op(x)
            ),
        };
        let pts: Vec<P3> = describe::end_of(x).into_iter().collect();
        let d = self.difference(kind, what, i..i + 1, j..j + 1, pts);
        self.out.differences.push(d);
    }

    /// Lists rapids before two matching operations that differ.
    fn rapids(&mut self, i: usize, j: usize) {
        let (Some(x), Some(y)) = (self.a.get(i), self.b.get(j)) else {
            return;
        };
        let (ra, rb) = (self.a.rapids(&x.rapids), self.b.rapids(&y.rapids));
        let tol = self.opts.tolerance_mm;
        let same = ra.len() == rb.len() && ra.iter().zip(rb).all(|(p, q)| close(p.0, q.0, tol));
        if same || self.out.rapid_differences.len() >= MAX_LISTED {
            return;
        }
        let via = |r: &[(P3, crate::span::Span)]| {
            if r.is_empty() {
                "none".to_string()
            } else {
                r.iter()
                    .map(|p| describe::point(p.0))
                    .collect::<Vec<_>>()
                    .join(", ")
            }
        };
        let what = format!(
            "rapids before {}: A via {}; B via {}",
            describe::op(x),
            via(ra),
            via(rb)
        );
        let pts: Vec<P3> = ra.iter().chain(rb).map(|p| p.0).collect();
        let mut d = self.difference(DiffKind::Rapids, what, i..i + 1, j..j + 1, pts);
        // Name the first rapid that differs (or the last one, where one
        // side has more).
        let k = ra
            .iter()
            .zip(rb)
            .position(|(p, q)| !close(p.0, q.0, tol))
            .unwrap_or(ra.len().min(rb.len()));
        let at = |r: &[(P3, crate::span::Span)]| r.get(k).or(r.last()).map(|p| p.1);
        d.a = at(ra).or(d.a);
        d.b = at(rb).or(d.b);
        self.out.rapid_differences.push(d);
    }
}
