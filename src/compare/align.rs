//! Walks two operation lists side by side. Where they part, it looks
//! ahead for the nearest place both go on the same way (a few operations
//! matching in a row) and reports what lies between as one difference, so
//! one changed block gives one difference, not a cascade. On operations
//! that match it compares the technology (feeds, speeds, dwells) and the
//! rapids that led to them ([`super::technology`]).

use super::describe;
use super::ops::{Op, OpKind};
use super::window::OpWindow;
use super::{CompareOptions, Comparison, DiffKind, Difference};
use crate::toolpath::P3;
use std::ops::Range;

/// How far ahead (operations, on each side) a resynchronisation looks.
const WINDOW: usize = 256;
/// How many operations must match in a row to count as back in step.
const RUN: usize = 3;
/// Differences reported before the comparison stops.
pub const MAX_DIFFERENCES: usize = 1000;

/// How many operations past the current one the walk may read.
const AHEAD: usize = 2 * WINDOW + RUN + 2;

pub(super) struct Aligner<'a> {
    pub(super) a: OpWindow<'a>,
    pub(super) b: OpWindow<'a>,
    pub(super) opts: &'a CompareOptions,
    pub(super) out: Comparison,
    /// The open technology difference (kind, A value, B value), which
    /// following matched operations with the same values extend.
    pub(super) open_tech: Option<(DiffKind, f64, f64)>,
}

pub(super) fn close(p: P3, q: P3, tol: f64) -> bool {
    (0..3).all(|k| (p[k] - q[k]).abs() <= tol)
}

/// Do two operations cut the same (geometry only)?
pub fn same_cut(x: &Op, y: &Op, tol: f64) -> bool {
    match (&x.kind, &y.kind) {
        (OpKind::Line { to: p, .. }, OpKind::Line { to: q, .. })
        | (OpKind::Probe { to: p }, OpKind::Probe { to: q }) => close(*p, *q, tol),
        (OpKind::Plunge { at: p, .. }, OpKind::Plunge { at: q, .. }) => close(*p, *q, tol),
        (
            OpKind::Arc {
                to: p,
                centre: c,
                axes: a,
                rotation: r,
            },
            OpKind::Arc {
                to: q,
                centre: d,
                axes: b,
                rotation: t,
            },
        ) => {
            a == b
                && r == t
                && close(*p, *q, tol)
                && (c[0] - d[0]).abs() <= tol
                && (c[1] - d[1]).abs() <= tol
        }
        (OpKind::Tool(s), OpKind::Tool(t)) => s == t,
        _ => false,
    }
}

pub(super) fn differ(x: f64, y: f64) -> bool {
    (x - y).abs() > 1e-6 * x.abs().max(y.abs()).max(1.0)
}

/// Feeds and speeds: equal within [`super::RATE_TOLERANCE`] of the larger.
pub(super) fn rates_differ(x: f64, y: f64) -> bool {
    (x - y).abs() > super::RATE_TOLERANCE * x.abs().max(y.abs()).max(1.0)
}

impl<'a> Aligner<'a> {
    pub fn new(a: OpWindow<'a>, b: OpWindow<'a>, opts: &'a CompareOptions) -> Self {
        let out = Comparison {
            same: true,
            differences: Vec::new(),
            rapid_differences: Vec::new(),
            truncated: false,
            ops_a: 0,
            ops_b: 0,
        };
        Aligner {
            a,
            b,
            opts,
            out,
            open_tech: None,
        }
    }

    fn same(&self, i: usize, j: usize) -> bool {
        match (self.a.get(i), self.b.get(j)) {
            (Some(x), Some(y)) => same_cut(x, y, self.opts.tolerance_mm),
            _ => false,
        }
    }

    /// Holds what the walk at `i`, `j` may read, and lets go of what lies
    /// behind it (one operation is kept: an empty range names its
    /// neighbour).
    fn window_at(&mut self, i: usize, j: usize) {
        self.a.fill_to(i + AHEAD);
        self.b.fill_to(j + AHEAD);
        self.a.forget_before(i.saturating_sub(1));
        self.b.forget_before(j.saturating_sub(1));
    }

    pub fn run(mut self) -> Comparison {
        let (mut i, mut j) = (0, 0);
        loop {
            self.window_at(i, j);
            let (na, nb) = (self.a.len(), self.b.len());
            if i >= na && j >= nb {
                break;
            }
            if self.out.differences.len() >= MAX_DIFFERENCES {
                self.out.truncated = true;
                break;
            }
            if i < na && j < nb && self.same(i, j) {
                self.matched(i, j);
                i += 1;
                j += 1;
                continue;
            }
            self.open_tech = None;
            match self.resync(i, j) {
                Some((di, dj)) => {
                    self.region(i..i + di, j..j + dj);
                    i += di;
                    j += dj;
                }
                None => {
                    self.region_to_end(i, j);
                    break;
                }
            }
        }
        // Both runs to their end: the counts, and no producer left waiting.
        self.a.drain_from(usize::MAX, |_| {});
        self.b.drain_from(usize::MAX, |_| {});
        self.out.ops_a = self.a.len();
        self.out.ops_b = self.b.len();
        self.out.same = self.out.differences.is_empty();
        self.out
    }

    /// Are `a[p..]` and `b[q..]` in step: [`RUN`] matches in a row, or
    /// both ending together?
    fn in_step(&self, p: usize, q: usize) -> bool {
        let (na, nb) = (self.a.len(), self.b.len());
        for k in 0..RUN {
            if p + k == na || q + k == nb {
                return p + k == na && q + k == nb;
            }
            if !self.same(p + k, q + k) {
                return false;
            }
        }
        true
    }

    /// The fewest operations to skip on each side (fewest in all first)
    /// before the two are in step again; `None` when never within the
    /// window. Only a run that has ended has a known rest, so a skip past
    /// its end is never tried.
    fn resync(&self, i: usize, j: usize) -> Option<(usize, usize)> {
        let (ra, rb) = (
            self.a.len() - i.min(self.a.len()),
            self.b.len() - j.min(self.b.len()),
        );
        for total in 1..=2 * WINDOW {
            // Prefer a replacement (equal skips) over an insertion.
            let mut order: Vec<usize> = (0..=total).collect();
            order.sort_by_key(|&di| (di as isize - (total - di) as isize).unsigned_abs());
            for di in order {
                let dj = total - di;
                if di > WINDOW || dj > WINDOW || di > ra || dj > rb {
                    continue;
                }
                if self.in_step(i + di, j + dj) {
                    return Some((di, dj));
                }
            }
        }
        None
    }

    /// The rest of both runs as one difference (they never came back in
    /// step), read to their ends.
    fn region_to_end(&mut self, i: usize, j: usize) {
        let first_a = self.a.get(i).cloned();
        let first_b = self.b.get(j).cloned();
        let (ga, gb) = (self.group_at(true, i), self.group_at(false, j));
        let mut pts = Vec::new();
        let mut tools = [true, true];
        let mut count = [0usize, 0usize];
        let mut note = |side: usize, o: &Op, pts: &mut Vec<P3>| {
            count[side] += 1;
            tools[side] &= matches!(o.kind, OpKind::Tool(_));
            if let Some(p) = describe::end_of(o) {
                // Only the box is kept: its corners stand for the points.
                pts.push(p);
                if pts.len() > 2 {
                    let b = bbox(pts).expect("points");
                    *pts = b.to_vec();
                }
            }
        };
        self.a.drain_from(i, |o| note(0, o, &mut pts));
        self.b.drain_from(j, |o| note(1, o, &mut pts));
        let summary = Summary {
            a: first_a.as_ref(),
            b: first_b.as_ref(),
            na: count[0],
            nb: count[1],
            tools: tools[0] && tools[1],
        };
        let Some((kind, what)) = summary.text() else {
            return;
        };
        let d = Difference {
            kind,
            what,
            a: first_a.as_ref().map(|o| o.span),
            b: first_b.as_ref().map(|o| o.span),
            a_ops: i..i + count[0],
            b_ops: j..j + count[1],
            group_a: ga.0,
            group_b: gb.0,
            tool_a: ga.1,
            tool_b: gb.1,
            region: bbox(&pts),
        };
        self.out.differences.push(d);
    }

    /// The operation group and tool at index `k` of one side (its
    /// neighbour's where `k` is past the end).
    fn group_at(&self, side_a: bool, k: usize) -> (usize, i64) {
        let w = if side_a { &self.a } else { &self.b };
        let k = k.min(w.len().saturating_sub(1));
        w.get(k)
            .map(|o| (o.group as usize, o.tool))
            .unwrap_or((0, 0))
    }

    /// Reports the operations between two in-step places as one difference.
    fn region(&mut self, ra: Range<usize>, rb: Range<usize>) {
        let (a, b) = (self.a.slice(ra.clone()), self.b.slice(rb.clone()));
        let tools = |s: &[Op]| s.iter().all(|o| matches!(o.kind, OpKind::Tool(_)));
        let summary = Summary {
            a: a.first(),
            b: b.first(),
            na: a.len(),
            nb: b.len(),
            tools: tools(a) && tools(b),
        };
        let Some((kind, what)) = summary.text() else {
            return;
        };
        let pts: Vec<P3> = a.iter().chain(b).filter_map(describe::end_of).collect();
        let d = self.difference(kind, what, ra, rb, pts);
        self.out.differences.push(d);
    }

    pub(super) fn difference(
        &self,
        kind: DiffKind,
        what: String,
        ra: Range<usize>,
        rb: Range<usize>,
        pts: Vec<P3>,
    ) -> Difference {
        let span = |w: &OpWindow<'_>, r: &Range<usize>| {
            w.get(r.start).filter(|_| !r.is_empty()).map(|o| o.span)
        };
        let (group_a, tool_a) = self.group_at(true, ra.start);
        let (group_b, tool_b) = self.group_at(false, rb.start);
        Difference {
            kind,
            what,
            a: span(&self.a, &ra),
            b: span(&self.b, &rb),
            a_ops: ra,
            b_ops: rb,
            group_a,
            group_b,
            tool_a,
            tool_b,
            region: bbox(&pts),
        }
    }
}

/// What two differing stretches hold: their first operations and sizes.
struct Summary<'o> {
    a: Option<&'o Op>,
    b: Option<&'o Op>,
    na: usize,
    nb: usize,
    /// Both are tool changes only.
    tools: bool,
}

impl Summary<'_> {
    /// The difference's kind and text (none when both are empty).
    fn text(&self) -> Option<(DiffKind, String)> {
        let kind = if self.tools {
            DiffKind::Tool
        } else {
            DiffKind::Cuts
        };
        let (na, nb) = (self.na, self.nb);
        let what = match (self.a, self.b) {
            (None, Some(y)) => {
                format!("only in B: {} ({} operation{})", describe::op(y), nb, s(nb))
            }
            (Some(x), None) => {
                format!("only in A: {} ({} operation{})", describe::op(x), na, s(na))
            }
            (Some(x), Some(y)) if na == 1 && nb == 1 => {
                format!("A: {}; B: {}", describe::op(x), describe::op(y))
            }
            (Some(x), Some(y)) => format!(
                "A: {} operations from {}; B: {} operations from {}",
                na,
                describe::op(x),
                nb,
                describe::op(y)
            ),
            (None, None) => return None,
        };
        Some((kind, what))
    }
}

fn s(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

/// The box around points (none when there are none).
pub fn bbox(pts: &[P3]) -> Option<[P3; 2]> {
    let first = *pts.first()?;
    let mut b = [first, first];
    for p in pts {
        for k in 0..3 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
    Some(b)
}
