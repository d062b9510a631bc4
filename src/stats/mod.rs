//! Machining statistics of a run: per tool and in total, the cutting and
//! rapid lengths, an estimated time, the box around the cutting moves and
//! the Z range. Accumulated event by event ([`StatsBuilder::push`]) so a
//! program of any length is summed in constant memory.
//!
//! The time estimate: each feed move takes its length over its feed rate
//! (mm/min; per-revolution feeds times the spindle speed in force), each
//! rapid its length over the rapid rate ([`StatsOptions::rapid_rate`],
//! 10000 mm/min unless told, one rate for all axes: real machines move
//! axes at their own rates and accelerate, so this is a lower bound),
//! plus dwells and a fixed time per tool change. A feed move with no feed
//! rate has no time; its length is counted in `no_feed_mm`.

pub mod bounds;
pub mod report;

pub use bounds::Bounds;

use crate::toolpath::{Event, FeedMode, Move, MoveKind};
use serde::Serialize;

/// How time is estimated.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StatsOptions {
    /// Rapid traverse rate, mm/min.
    pub rapid_rate: f64,
    /// Seconds per tool change.
    pub tool_change_s: f64,
}

impl Default for StatsOptions {
    fn default() -> Self {
        StatsOptions {
            rapid_rate: 10_000.0,
            tool_change_s: 5.0,
        }
    }
}

/// The figures for one tool (or the whole program).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct ToolStats {
    /// The tool number (0: no tool; the total's is 0 too).
    pub tool: i64,
    /// Diameter from the tool table, mm.
    pub diameter_mm: Option<f64>,
    pub feed_moves: u64,
    pub rapid_moves: u64,
    pub cutting_mm: f64,
    pub rapid_mm: f64,
    pub cutting_s: f64,
    pub rapid_s: f64,
    pub dwell_s: f64,
    pub tool_changes: u64,
    pub tool_change_s: f64,
    /// Length of feed moves made without a feed rate (not timed).
    pub no_feed_mm: f64,
    /// Lowest and highest feed rate of its feed moves, mm/min.
    pub feed_range: Option<[f64; 2]>,
    /// The box around its cutting moves.
    pub cutting_box: Bounds,
    /// Lowest and highest Z of all its moves.
    pub z_range: Option<[f64; 2]>,
}

impl ToolStats {
    /// The estimated time, seconds.
    pub fn total_s(&self) -> f64 {
        self.cutting_s + self.rapid_s + self.dwell_s + self.tool_change_s
    }

    fn add_move(&mut self, m: &Move, rate: f64, opts: &StatsOptions) {
        let len = m.length();
        let (zlo, zhi) = (m.from[2].min(m.to[2]), m.from[2].max(m.to[2]));
        self.z_range = Some(match self.z_range {
            None => [zlo, zhi],
            Some([a, b]) => [a.min(zlo), b.max(zhi)],
        });
        if let MoveKind::Rapid = m.kind {
            self.rapid_moves += 1;
            self.rapid_mm += len;
            if opts.rapid_rate > 0.0 {
                self.rapid_s += len / opts.rapid_rate * 60.0;
            }
            return;
        }
        self.feed_moves += 1;
        self.cutting_mm += len;
        self.cutting_box.add_move(m);
        if rate > 0.0 && rate.is_finite() {
            self.cutting_s += len / rate * 60.0;
            self.feed_range = Some(match self.feed_range {
                None => [rate, rate],
                Some([a, b]) => [a.min(rate), b.max(rate)],
            });
        } else {
            self.no_feed_mm += len;
        }
    }

    fn merge(&mut self, o: &ToolStats) {
        self.feed_moves += o.feed_moves;
        self.rapid_moves += o.rapid_moves;
        self.cutting_mm += o.cutting_mm;
        self.rapid_mm += o.rapid_mm;
        self.cutting_s += o.cutting_s;
        self.rapid_s += o.rapid_s;
        self.dwell_s += o.dwell_s;
        self.tool_changes += o.tool_changes;
        self.tool_change_s += o.tool_change_s;
        self.no_feed_mm += o.no_feed_mm;
        self.cutting_box.merge(&o.cutting_box);
        for (mine, theirs) in [
            (&mut self.feed_range, o.feed_range),
            (&mut self.z_range, o.z_range),
        ] {
            if let Some([a, b]) = theirs {
                *mine = Some(match *mine {
                    None => [a, b],
                    Some([c, d]) => [a.min(c), b.max(d)],
                });
            }
        }
    }
}

/// The figures of a run: per tool in order of first use, and the total.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Stats {
    pub tools: Vec<ToolStats>,
    pub total: ToolStats,
    /// The options the time was estimated with.
    pub rapid_rate: f64,
    pub tool_change_time_s: f64,
}

/// Sums events into [`Stats`].
#[derive(Clone, Debug)]
pub struct StatsBuilder {
    opts: StatsOptions,
    tools: Vec<ToolStats>,
    /// The tool in the spindle (its index in `tools`).
    current: Option<usize>,
}

impl StatsBuilder {
    pub fn new(opts: StatsOptions) -> StatsBuilder {
        StatsBuilder {
            opts,
            tools: Vec::new(),
            current: None,
        }
    }

    fn slot(&mut self, tool: i64) -> usize {
        match self.tools.iter().position(|t| t.tool == tool) {
            Some(i) => i,
            None => {
                self.tools.push(ToolStats {
                    tool,
                    ..ToolStats::default()
                });
                self.tools.len() - 1
            }
        }
    }

    pub fn push(&mut self, e: &Event) {
        match e {
            Event::Move(m) => {
                let i = match self.current {
                    Some(i) if self.tools[i].tool == m.tool => i,
                    _ => self.slot(m.tool),
                };
                self.current = Some(i);
                let rate = match m.feed_mode {
                    FeedMode::PerMinute => m.feed,
                    FeedMode::PerRev => m.feed * m.spindle.abs(),
                };
                let opts = self.opts;
                self.tools[i].add_move(m, rate, &opts);
            }
            Event::ToolChange { tool, .. } => {
                let i = self.slot(*tool);
                self.current = Some(i);
                self.tools[i].tool_changes += 1;
                self.tools[i].tool_change_s += self.opts.tool_change_s;
            }
            Event::Dwell { seconds, .. } => {
                let i = match self.current {
                    Some(i) => i,
                    None => self.slot(0),
                };
                self.tools[i].dwell_s += seconds.max(0.0);
            }
            Event::Stop { .. } | Event::Comment { .. } => {}
        }
    }

    /// The figures, with diameters from the tool table (converted from
    /// `units_mm` millimetres per table unit).
    pub fn finish(self, table: &crate::interp::tooltable::ToolTable, units_mm: f64) -> Stats {
        let mut total = ToolStats::default();
        let mut tools = self.tools;
        for t in tools.iter_mut() {
            t.diameter_mm = table.get(t.tool).map(|d| d.diameter * units_mm);
            total.merge(t);
        }
        Stats {
            tools,
            total,
            rapid_rate: self.opts.rapid_rate,
            tool_change_time_s: self.opts.tool_change_s,
        }
    }
}
