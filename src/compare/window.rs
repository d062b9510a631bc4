//! The operations the aligner ([`super::align`]) reads: a whole list
//! held by the caller, or a window over a run that is still going on,
//! filled batch by batch ([`super::OpBuilder::take_ready`]) as the walk
//! needs operations further ahead and emptied behind it. The aligner
//! never looks more than its resynchronisation window ahead, so two runs
//! compared side by side hold a few hundred operations each, not their
//! programs.

use super::ops::{Op, Ops};
use crate::span::Span;
use crate::toolpath::P3;
use std::ops::Range;

/// Operations a run hands over at a time ([`hand_over`]), and the
/// batches it may have waiting before it waits for the comparison.
pub const BATCH: usize = 1024;
pub const QUEUED: usize = 4;

/// Sends `ops`' finished operations once a batch is ready; whether the
/// comparison still listens (it stops only when it has all it needs).
pub fn hand_over(
    ops: &mut super::OpBuilder,
    to: &std::sync::mpsc::SyncSender<Ops>,
    listening: bool,
) -> bool {
    if ops.ready() < BATCH {
        return listening;
    }
    let batch = ops.take_ready();
    listening && to.send(batch).is_ok()
}

/// Gives the next batch of a run's operations; `None` once it has ended.
pub type Pull<'a> = Box<dyn FnMut() -> Option<Ops> + 'a>;

/// One side's operations, by their index in the whole run.
pub struct OpWindow<'a> {
    store: Store<'a>,
}

enum Store<'a> {
    Whole(&'a Ops),
    Pulled(Pulled<'a>),
}

struct Pulled<'a> {
    ops: Vec<Op>,
    /// The index of `ops[0]` in the run.
    base: usize,
    rapids: Vec<(P3, Span)>,
    rapid_base: usize,
    /// `None` once the run has ended.
    more: Option<Pull<'a>>,
}

impl<'a> OpWindow<'a> {
    /// A list held whole.
    pub fn whole(ops: &'a Ops) -> Self {
        OpWindow {
            store: Store::Whole(ops),
        }
    }

    /// A run read batch by batch from `more`.
    pub fn pulled(more: Pull<'a>) -> Self {
        OpWindow {
            store: Store::Pulled(Pulled {
                ops: Vec::new(),
                base: 0,
                rapids: Vec::new(),
                rapid_base: 0,
                more: Some(more),
            }),
        }
    }

    /// Makes operations up to index `n` (excluded) available, where the
    /// run has them.
    pub fn fill_to(&mut self, n: usize) {
        let Store::Pulled(p) = &mut self.store else {
            return;
        };
        while p.base + p.ops.len() < n {
            let Some(more) = p.more.as_mut() else {
                return;
            };
            match more() {
                Some(batch) => {
                    p.ops.extend(batch.ops);
                    p.rapids.extend(batch.rapids);
                }
                None => p.more = None,
            }
        }
    }

    /// Fills to the end of the run, calling `seen` on each operation
    /// from index `from`, and forgets them as it goes.
    pub fn drain_from(&mut self, from: usize, mut seen: impl FnMut(&Op)) {
        let mut next = from.max(self.first());
        loop {
            let end = self.len();
            for i in next..end {
                if let Some(op) = self.get(i) {
                    seen(op);
                }
            }
            next = next.max(end);
            if self.ended() {
                return;
            }
            self.forget_before(end);
            self.fill_to(end + 1);
        }
    }

    /// Has the run ended (is [`OpWindow::len`] its number of operations)?
    pub fn ended(&self) -> bool {
        match &self.store {
            Store::Whole(_) => true,
            Store::Pulled(p) => p.more.is_none(),
        }
    }

    /// The operations known so far (all of them once [`OpWindow::ended`]).
    pub fn len(&self) -> usize {
        match &self.store {
            Store::Whole(o) => o.ops.len(),
            Store::Pulled(p) => p.base + p.ops.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The first index still held.
    fn first(&self) -> usize {
        match &self.store {
            Store::Whole(_) => 0,
            Store::Pulled(p) => p.base,
        }
    }

    /// The operation at index `i`, if it is held.
    pub fn get(&self, i: usize) -> Option<&Op> {
        match &self.store {
            Store::Whole(o) => o.ops.get(i),
            Store::Pulled(p) => i.checked_sub(p.base).and_then(|k| p.ops.get(k)),
        }
    }

    /// The operations of `r` (which must be held).
    pub fn slice(&self, r: Range<usize>) -> &[Op] {
        match &self.store {
            Store::Whole(o) => &o.ops[r],
            Store::Pulled(p) => &p.ops[r.start - p.base..r.end - p.base],
        }
    }

    /// The rapids of an operation's range (held with it).
    pub fn rapids(&self, r: &Range<u32>) -> &[(P3, Span)] {
        let (s, e) = (r.start as usize, r.end as usize);
        match &self.store {
            Store::Whole(o) => &o.rapids[s..e],
            Store::Pulled(p) => &p.rapids[s - p.rapid_base..e - p.rapid_base],
        }
    }

    /// Lets go of the operations before index `i` (and their rapids);
    /// the memory is given back once they are half the window.
    pub fn forget_before(&mut self, i: usize) {
        let Store::Pulled(p) = &mut self.store else {
            return;
        };
        let n = i.saturating_sub(p.base).min(p.ops.len());
        if n == 0 || n < p.ops.len() / 2 {
            return;
        }
        let rapid_end = p
            .ops
            .get(n)
            .map(|o| o.rapids.start as usize)
            .unwrap_or(p.rapid_base + p.rapids.len());
        p.ops.drain(..n);
        p.base += n;
        let nr = rapid_end.saturating_sub(p.rapid_base).min(p.rapids.len());
        p.rapids.drain(..nr);
        p.rapid_base += nr;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::{OpBuilder, OpKind};
    use crate::toolpath::{Event, FeedMode, Move, MoveKind};

    fn mv(kind: MoveKind, from: P3, to: P3) -> Event {
        Event::Move(Move {
            kind,
            from,
            to,
            feed: 100.0,
            feed_mode: FeedMode::PerMinute,
            tool: 1,
            spindle: 1000.0,
            coolant: Default::default(),
            span: Span::default(),
        })
    }

    /// A run taken in batches gives the same operations, at the same
    /// indices, with the same rapids, as the run built whole.
    #[test]
    fn batches_give_the_whole_runs_operations() {
        let mut events = Vec::new();
        let mut at = [0.0, 0.0, 5.0];
        for k in 0..50 {
            let x = k as f64;
            events.push(mv(MoveKind::Rapid, at, [x, 0.0, 5.0]));
            events.push(mv(MoveKind::Rapid, [x, 0.0, 5.0], [x, 1.0, 5.0]));
            events.push(mv(MoveKind::Line, [x, 1.0, 5.0], [x, 1.0, -1.0]));
            events.push(mv(MoveKind::Line, [x, 1.0, -1.0], [x, 3.0, -1.0]));
            at = [x, 3.0, -1.0];
        }
        let whole = Ops::from_events(&events, 0.001);
        let mut b = OpBuilder::new(0.001);
        let mut batches = Vec::new();
        for (k, e) in events.iter().enumerate() {
            b.push(e);
            if k % 7 == 0 {
                batches.push(b.take_ready());
            }
        }
        batches.push(b.finish());
        let mut it = batches.into_iter();
        let mut w = OpWindow::pulled(Box::new(move || it.next()));
        w.fill_to(usize::MAX);
        assert!(w.ended());
        assert_eq!(w.len(), whole.ops.len());
        for (i, op) in whole.ops.iter().enumerate() {
            let got = w.get(i).unwrap();
            assert_eq!(got, op);
            assert_eq!(
                w.rapids(&got.rapids),
                &whole.rapids[op.rapids.start as usize..op.rapids.end as usize]
            );
            assert!(matches!(
                got.kind,
                OpKind::Plunge { .. } | OpKind::Line { .. }
            ));
        }
        w.forget_before(60);
        assert!(w.get(59).is_none() && w.get(60).is_some());
        let op = w.get(60).unwrap().clone();
        assert_eq!(w.rapids(&op.rapids).len(), op.rapids.len());
    }
}
