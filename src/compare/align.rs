//! Walks two operation lists side by side. Where they part, it looks
//! ahead for the nearest place both go on the same way (a few operations
//! matching in a row) and reports what lies between as one difference, so
//! one changed block gives one difference, not a cascade. On operations
//! that match it compares the technology (feeds, speeds, dwells) and the
//! rapids that led to them ([`super::technology`]).

use super::describe;
use super::ops::{Op, OpKind, Ops};
use super::{CompareOptions, Comparison, DiffKind, Difference};
use crate::toolpath::P3;
use std::ops::Range;

/// How far ahead (operations, on each side) a resynchronisation looks.
const WINDOW: usize = 256;
/// How many operations must match in a row to count as back in step.
const RUN: usize = 3;
/// Differences reported before the comparison stops.
pub const MAX_DIFFERENCES: usize = 1000;

pub(super) struct Aligner<'a> {
    pub(super) a: &'a Ops,
    pub(super) b: &'a Ops,
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
    pub fn new(a: &'a Ops, b: &'a Ops, opts: &'a CompareOptions) -> Self {
        let out = Comparison {
            same: true,
            differences: Vec::new(),
            rapid_differences: Vec::new(),
            truncated: false,
            ops_a: a.ops.len(),
            ops_b: b.ops.len(),
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
        same_cut(&self.a.ops[i], &self.b.ops[j], self.opts.tolerance_mm)
    }

    pub fn run(mut self) -> Comparison {
        let (na, nb) = (self.a.ops.len(), self.b.ops.len());
        let (mut i, mut j) = (0, 0);
        while i < na || j < nb {
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
            let (di, dj) = self.resync(i, j);
            self.region(i..i + di, j..j + dj);
            i += di;
            j += dj;
        }
        self.out.same = self.out.differences.is_empty();
        self.out
    }

    /// Are `a[p..]` and `b[q..]` in step: [`RUN`] matches in a row, or
    /// both ending together?
    fn in_step(&self, p: usize, q: usize) -> bool {
        let (na, nb) = (self.a.ops.len(), self.b.ops.len());
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
    /// before the two are in step again; the rest of both when never.
    fn resync(&self, i: usize, j: usize) -> (usize, usize) {
        let (ra, rb) = (self.a.ops.len() - i, self.b.ops.len() - j);
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
                    return (di, dj);
                }
            }
        }
        (ra, rb)
    }

    /// The operation group and tool at the start of a range (the
    /// neighbouring operation's when the range is empty).
    fn group_of(ops: &Ops, r: &Range<usize>) -> (usize, i64) {
        let k = r.start.min(ops.ops.len().saturating_sub(1));
        ops.ops
            .get(k)
            .map(|o| (o.group as usize, o.tool))
            .unwrap_or((0, 0))
    }

    /// Reports the operations between two in-step places as one difference.
    fn region(&mut self, ra: Range<usize>, rb: Range<usize>) {
        let (a, b) = (&self.a.ops[ra.clone()], &self.b.ops[rb.clone()]);
        let tools = |s: &[Op]| s.iter().all(|o| matches!(o.kind, OpKind::Tool(_)));
        let kind = if tools(a) && tools(b) {
            DiffKind::Tool
        } else {
            DiffKind::Cuts
        };
        let what = match (a, b) {
            ([], [x, ..]) => format!(
                "only in B: {} ({} operation{})",
                describe::op(x),
                b.len(),
                s(b.len())
            ),
            ([x, ..], []) => format!(
                "only in A: {} ({} operation{})",
                describe::op(x),
                a.len(),
                s(a.len())
            ),
            ([x], [y]) => format!("A: {}; B: {}", describe::op(x), describe::op(y)),
            ([x, ..], [y, ..]) => format!(
                "A: {} operations from {}; B: {} operations from {}",
                a.len(),
                describe::op(x),
                b.len(),
                describe::op(y)
            ),
            ([], []) => return,
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
        let span = |ops: &Ops, r: &Range<usize>| {
            ops.ops
                .get(r.start)
                .filter(|_| !r.is_empty())
                .map(|o| o.span)
        };
        let (group_a, tool_a) = Self::group_of(self.a, &ra);
        let (group_b, tool_b) = Self::group_of(self.b, &rb);
        Difference {
            kind,
            what,
            a: span(self.a, &ra),
            b: span(self.b, &rb),
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
