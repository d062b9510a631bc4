//! The shapes [`super::owords`] recognises in Klartext jumps: positions
//! of the structures they become, loop exits, if/else pairs, and whether
//! the structures nest.

use crate::ir::ExprId;
use crate::span::Span;

/// One jump and the structure it becomes; positions count gaps before
/// block k as 2k and the jump in block j as 2j + 1.
pub(super) struct Jump {
    pub block: usize,
    pub stmt: usize,
    pub target: usize,
    pub cond: Option<ExprId>,
    pub span: Span,
    /// An if with an else: the block its unconditional jump over the
    /// else branch goes to (where the structure ends).
    pub join: Option<usize>,
}

impl Jump {
    pub fn back(&self) -> bool {
        self.target <= self.block
    }
    pub fn open(&self) -> usize {
        if self.back() {
            2 * self.target
        } else {
            2 * self.block + 1
        }
    }
    pub fn close(&self) -> usize {
        if let Some(u) = self.join {
            return 2 * u;
        }
        if self.back() {
            2 * self.block + 1
        } else {
            2 * self.target
        }
    }
}

/// For each jump, the loop (its index among `jumps`) it leaves
/// (`false`: break) or starts again (`true`: continue), from inside it and
/// no inner loop:
///
/// * break: a jump to the block after the loop;
/// * continue: a jump back to the loop's top when the loop's own jump back
///   is unconditional (the outermost one to that top), so that `continue`
///   (which tests the loop's condition) starts it again as the jump did.
pub(super) fn loop_exits(jumps: &[Jump]) -> Vec<Option<(usize, bool)>> {
    let inside = |l: &Jump, at: usize| l.back() && l.open() < at && at < l.close();
    let at = |j: &Jump| 2 * j.block + 1;
    // The loop each jump would leave or start again.
    let candidate = |j: &Jump| -> Option<(usize, bool)> {
        if j.back() {
            let (l, _) = jumps
                .iter()
                .enumerate()
                .filter(|(_, l)| l.cond.is_none() && l.target == j.target && l.block > j.block)
                .max_by_key(|(_, l)| l.block)?;
            Some((l, true))
        } else {
            let l = jumps
                .iter()
                .position(|l| l.back() && l.block + 1 == j.target && inside(l, at(j)))?;
            Some((l, false))
        }
    };
    let mut exits: Vec<_> = jumps.iter().map(candidate).collect();
    // rs274 runs `oN continue` as the next `oN` line after it: a later
    // `oN break` would then leave the loop (probed with the oracle). Such
    // a jump stays a loop of its own.
    let leaves: Vec<(usize, usize)> = exits
        .iter()
        .zip(jumps)
        .filter_map(|(e, j)| match e {
            Some((l, false)) => Some((*l, j.block)),
            _ => None,
        })
        .collect();
    for (e, j) in exits.iter_mut().zip(jumps) {
        if let Some((l, true)) = *e {
            if leaves.iter().any(|&(bl, b)| bl == l && b > j.block) {
                *e = None;
            }
        }
    }
    // Only from the loop itself, not from a loop inside it.
    let is_continue: Vec<bool> = exits.iter().map(|e| matches!(e, Some((_, true)))).collect();
    for (i, j) in jumps.iter().enumerate() {
        let Some((l, _)) = exits[i] else { continue };
        let outer = &jumps[l];
        let inner = jumps.iter().enumerate().any(|(k, m)| {
            k != i
                && k != l
                && !is_continue[k]
                && inside(m, at(j))
                && m.close() <= outer.close()
                && m.open() >= outer.open()
        });
        if inner {
            exits[i] = None;
        }
    }
    exits
}

/// The first structure that overlaps another without nesting in it.
pub(super) fn crossing(intervals: &[(usize, usize, Span)]) -> Option<Span> {
    let mut open: Vec<usize> = Vec::new();
    for &(o, c, span) in intervals {
        while open.last().is_some_and(|&top| top <= o) {
            open.pop();
        }
        if open.last().is_some_and(|&top| c > top) {
            return Some(span);
        }
        open.push(c);
    }
    None
}

/// `FN ..: IF c GOTO LBL a` ... `FN 9: IF +0 EQU +0 GOTO LBL b` `LBL a`
/// ... `LBL b`: an if with an else, when the first jump is the only one to
/// `a`. Returns the jumps left (the if now ends at `b`) and, for each
/// else, its jump's block and statement and the index of its if.
pub(super) fn pair_else(jumps: Vec<Jump>) -> (Vec<Jump>, Vec<(usize, usize, usize)>) {
    let n = jumps.len();
    let mut over = vec![None; n];
    for (i, a) in jumps.iter().enumerate() {
        if a.back() || jumps.iter().filter(|x| x.target == a.target).count() != 1 {
            continue;
        }
        over[i] = jumps.iter().position(|b| {
            b.cond.is_none()
                && !b.back()
                && b.block + 1 == a.target
                && b.block > a.block
                && b.target > a.target
        });
    }
    let taken: Vec<usize> = over.iter().flatten().copied().collect();
    for &t in &taken {
        over[t] = None; // a jump over an else is not an if of its own
    }
    let mut kept = Vec::new();
    let mut index = vec![0; n];
    let mut joins = Vec::new();
    for (i, j) in jumps.into_iter().enumerate() {
        if taken.contains(&i) {
            joins.push((i, j.block, j.stmt, j.target));
        } else {
            index[i] = kept.len();
            kept.push(j);
        }
    }
    let mut elses = Vec::new();
    for (i, b) in over.iter().enumerate() {
        let Some(b) = b else { continue };
        let Some(&(_, block, stmt, target)) = joins.iter().find(|x| x.0 == *b) else {
            continue;
        };
        kept[index[i]].join = Some(target);
        elses.push((block, stmt, index[i]));
    }
    (kept, elses)
}

/// The intervals to check: each structure, and the then-part of an if
/// with an else (nothing may cross the else).
pub(super) fn intervals(
    jumps: &[Jump],
    elses: &[(usize, usize, usize)],
) -> Vec<(usize, usize, Span)> {
    let mut out: Vec<_> = jumps
        .iter()
        .map(|j| (j.open(), j.close(), j.span))
        .collect();
    for &(block, _, of) in elses {
        out.push((jumps[of].open(), 2 * block + 1, jumps[of].span));
    }
    out.sort_by_key(|&(o, c, _)| (o, std::cmp::Reverse(c)));
    out
}
