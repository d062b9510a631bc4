//! One run's events reduced, one at a time, to what `port --verify`
//! compares ([`super::verify`]): the operations ([`OpBuilder`]), and a
//! [`Tally`] of the rest (the highest cutting height, the rapids that may
//! lie below it, the tool length each tool cuts with). Nothing here looks
//! back at an earlier event, so a run can be reduced while it goes on and
//! two runs compared side by side ([`super::verify_lockstep`]).

use super::verify::{Difference, LENGTH_MARK, MACHINE_MARK, TOLERANCE_MM};
use crate::compare::OpBuilder;
use crate::span::Span;
use crate::toolpath::{dist, Event, Move, P3};
use std::collections::{BTreeMap, HashMap};

/// A run being reduced.
pub(crate) struct Digest {
    pub ops: OpBuilder,
    pub tally: Tally,
}

impl Digest {
    pub fn new(tolerance_mm: f64) -> Self {
        Digest {
            ops: OpBuilder::new(tolerance_mm),
            tally: Tally::default(),
        }
    }

    /// Takes one event, its tools renumbered by `tools` where given.
    pub fn push(&mut self, e: &Event, tools: Option<&super::ToolMap>) {
        match tools.filter(|t| !t.is_empty()) {
            Some(t) => {
                let e = super::verify::renumber(e.clone(), t);
                self.ops.push(&e);
                self.tally.push(&e);
            }
            None => {
                self.ops.push(e);
                self.tally.push(e);
            }
        }
    }
}

/// What a run tells the proof besides its operations.
#[derive(Default)]
pub(crate) struct Tally {
    /// The highest Z of any feed move (None: nothing is cut).
    pub top: Option<f64>,
    rapids: LowRapids,
    lengths: CutLengths,
}

impl Tally {
    pub fn push(&mut self, e: &Event) {
        if let Event::Move(m) = e {
            if m.is_feed() {
                let z = m.from[2].max(m.to[2]);
                self.top = Some(self.top.map_or(z, |t| t.max(z)));
            }
        }
        self.rapids.push(e);
        self.lengths.push(e);
    }

    /// The first rapid below the source's (`self`) highest cutting height
    /// that the two runs do not share: its ends must be as close as the
    /// cutting moves' points (`tolerance_mm`, half the target's smallest
    /// increment where it writes coarser than 1 µm: a rapid the port
    /// rounded to a Fanuc inch program's 0.0001 in is the same rapid on
    /// that machine).
    pub fn low_rapid(&self, b: &Tally, tolerance_mm: f64) -> Option<Difference> {
        let top = self.top?;
        let below = |t: &'_ Tally| -> Vec<LowRapid> {
            t.rapids
                .out
                .iter()
                .filter(|r| r.from[2].min(r.to[2]) < top - TOLERANCE_MM)
                .copied()
                .collect()
        };
        let (ra, rb) = (below(self), below(b));
        let near = |p: &P3, q: &P3| dist(*p, *q) <= tolerance_mm;
        let show = |m: Option<&LowRapid>| match m {
            Some(r) => format!("rapid from {} to {}", point(&r.from), point(&r.to)),
            None => "no such rapid".to_string(),
        };
        for i in 0..ra.len().max(rb.len()) {
            let (x, y) = (ra.get(i), rb.get(i));
            if let (Some(x), Some(y)) = (x, y) {
                if near(&x.from, &y.from) && near(&x.to, &y.to) {
                    continue;
                }
            }
            return Some(Difference {
                what: format!(
                    "a rapid below the highest cutting height Z{}: A: {}; B: {}",
                    num(top),
                    show(x),
                    show(y)
                ),
                a: x.map(|r| r.span),
                b: y.map(|r| r.span),
            });
        }
        None
    }

    /// A tool cut with another length offset on each side (`G43 H2`
    /// while T1 is in the spindle cuts at another depth). A side that
    /// cuts with no offset at all (LinuxCNC without `G43`, the control's
    /// convention) is not compared.
    pub fn length_offset(&self, b: &Tally) -> Option<Difference> {
        for (tool, (len_a, span_a)) in &self.lengths.first {
            let Some((len_b, span_b)) = b.lengths.first.get(tool) else {
                continue;
            };
            if (len_a - len_b).abs() > TOLERANCE_MM {
                return Some(Difference {
                    what: format!(
                        "tool length offset: T{tool} cuts with A {}; B {} mm",
                        num(*len_a),
                        num(*len_b)
                    ),
                    a: Some(*span_a),
                    b: Some(*span_b),
                });
            }
        }
        None
    }
}

/// A rapid that may be compared: it does not move in a place already cut
/// deeper (whether it is below the cutting height is known at the end).
#[derive(Clone, Copy, Debug)]
struct LowRapid {
    from: P3,
    to: P3,
    span: Span,
}

/// The rapids of a run that do not move in a place already cut deeper
/// (see [`super::verify`]'s module doc), in order.
struct LowRapids {
    cut: CutPlaces,
    /// The first move starts where the machine happens to be (the run
    /// assumes zero): only where it goes counts.
    first: bool,
    /// Between a tool change (or the start) and the first feed move:
    /// the approach, where positions rest on what the run cannot know.
    approach: bool,
    /// The last move counted was a rapid (or none was): a feed now enters.
    after_rapid: bool,
    /// Where the last feed move ended, while no rapid has followed it.
    feed_end: Option<P3>,
    out: Vec<LowRapid>,
}

/// The deepest Z cut so far at the X Y where feed moves started or
/// ended, which a vertical rapid may later leave or enter.
///
/// The places a rapid comes back to are kept for the whole run: the ends
/// of vertical feeds (a hole, a peck), where cutting starts after a rapid
/// (an entry) and where it stops before one (an exit). The other ends of
/// feed moves are kept for the last [`RECENT`] to [`RECENT`] x 2 of them
/// (a retract where a rapid across the cut floor has gone, say), so the
/// map grows with the rapids, not with the cuts. [?] A vertical rapid
/// onto a point in the middle of a contour cut longer ago than that is
/// compared as if nothing had been cut there: the proof can only be
/// stricter for it.
#[derive(Default)]
struct CutPlaces {
    kept: Places,
    recent: Places,
    older: Places,
}

/// The deepest Z at each X Y on the tolerance grid, hashed with foldhash
/// (several times faster than SipHash on two integers; seeded per run, so
/// a program cannot be written to collide; the maps are only looked up,
/// never listed, so the seed changes no output).
type Places = HashMap<(i64, i64), f64, foldhash::fast::RandomState>;

/// How many ends of feed moves inside a contour [`CutPlaces`] holds.
const RECENT: usize = 1 << 16;

impl CutPlaces {
    fn lower(map: &mut Places, p: &P3) {
        let d = map.entry(key(p)).or_insert(f64::INFINITY);
        *d = d.min(p[2]);
    }

    /// A place a rapid may come back to.
    fn keep(&mut self, p: &P3) {
        Self::lower(&mut self.kept, p);
    }

    /// Any other end of a feed move.
    fn pass(&mut self, p: &P3) {
        if self.recent.len() >= RECENT {
            // The full map becomes the older one and the older one's
            // table is emptied and reused: no table grows again from
            // nothing, no memory is given back and faulted in again.
            std::mem::swap(&mut self.older, &mut self.recent);
            self.recent.clear();
        }
        Self::lower(&mut self.recent, p);
    }

    /// The deepest Z cut at the X Y of `p`, where known.
    fn depth(&self, p: &P3) -> Option<f64> {
        let k = key(p);
        [&self.kept, &self.recent, &self.older]
            .iter()
            .filter_map(|m| m.get(&k).copied())
            .reduce(f64::min)
    }
}

impl Default for LowRapids {
    fn default() -> Self {
        LowRapids {
            cut: CutPlaces::default(),
            first: true,
            approach: true,
            after_rapid: true,
            feed_end: None,
            out: Vec::new(),
        }
    }
}

fn key(p: &P3) -> (i64, i64) {
    let q = |v: f64| (v / TOLERANCE_MM).round() as i64;
    (q(p[0]), q(p[1]))
}

impl LowRapids {
    fn push(&mut self, e: &Event) {
        let m = match e {
            Event::Move(m) => m,
            Event::ToolChange { .. } => return self.approach(),
            Event::Comment { text, .. } if text == MACHINE_MARK => return self.approach(),
            Event::Dwell { .. } | Event::Stop { .. } | Event::Comment { .. } => return,
        };
        // A move to where the tool already is (`G1` alone after `G43`)
        // goes nowhere: it neither starts the run nor ends an approach.
        if dist(m.from, m.to) <= TOLERANCE_MM {
            return;
        }
        let from = if std::mem::take(&mut self.first) {
            m.to
        } else {
            m.from
        };
        self.approach &= !m.is_feed();
        if self.approach || dist(from, m.to) <= TOLERANCE_MM {
            return;
        }
        if m.is_feed() {
            self.feed(m);
        } else {
            self.rapid(from, m);
        }
    }

    fn approach(&mut self) {
        self.approach = true;
        self.after_rapid = true;
        self.feed_end = None;
    }

    fn feed(&mut self, m: &Move) {
        let vertical = key(&m.from) == key(&m.to);
        // A contour's moves start where the one before ended, which is
        // recorded already (kept, or passed as now).
        let recorded = self.feed_end == Some(m.from);
        match vertical || std::mem::take(&mut self.after_rapid) {
            true => self.cut.keep(&m.from),
            false if recorded => {}
            false => self.cut.pass(&m.from),
        }
        match vertical {
            true => self.cut.keep(&m.to),
            false => self.cut.pass(&m.to),
        }
        self.after_rapid = false;
        self.feed_end = Some(m.to);
    }

    fn rapid(&mut self, from: P3, m: &Move) {
        if let Some(p) = self.feed_end.take() {
            self.cut.keep(&p);
        }
        self.after_rapid = true;
        let low = from[2].min(m.to[2]);
        let in_air = key(&from) == key(&m.to)
            && self
                .cut
                .depth(&from)
                .is_some_and(|d| d <= low + TOLERANCE_MM);
        if !in_air {
            self.out.push(LowRapid {
                from,
                to: m.to,
                span: m.span,
            });
        }
    }
}

/// The first non-zero length offset each tool makes a feed move with,
/// and that move's statement.
#[derive(Default)]
struct CutLengths {
    now: f64,
    first: BTreeMap<i64, (f64, Span)>,
}

impl CutLengths {
    fn push(&mut self, e: &Event) {
        match e {
            Event::Comment { text, .. } => {
                if let Some(v) = text.strip_prefix(LENGTH_MARK) {
                    self.now = v.parse().unwrap_or(0.0);
                }
            }
            Event::Move(m) if m.is_feed() && self.now != 0.0 => {
                self.first.entry(m.tool).or_insert((self.now, m.span));
            }
            _ => {}
        }
    }
}

fn num(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}

fn point(p: &P3) -> String {
    format!("X{} Y{} Z{}", num(p[0]), num(p[1]), num(p[2]))
}
