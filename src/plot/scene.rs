//! What a plot draws, in picture pixels: for each view, file, tool and
//! kind of move (feed or rapid) one layer of paths, built while the events
//! stream in. Detail below the pixel is dropped as it comes: points closer
//! than half a pixel to the last one kept are merged, and a point that
//! lies within a quarter pixel of the straight line past it is left out,
//! so a program of millions of moves keeps its shape in a few thousand
//! segments per view.

use super::layout::{Layout, Panel};
use crate::toolpath::{Event, Move, MoveKind, P3};
use std::collections::BTreeMap;

/// Points closer than this (pixels) are one.
const MERGE_PX: f64 = 0.5;
/// A point this close (pixels) to the chord past it is left out.
const CHORD_PX: f64 = 0.25;
/// Most points left out of one straight run before one is kept anyway.
const MAX_SKIPPED: usize = 32;

type Pt = (f64, f64);

/// One piece of a path, pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Start a new subpath here.
    Move(Pt),
    Line(Pt),
    /// A circular arc to `to` around `centre`: `start` angle and signed
    /// `sweep` in screen radians (y down, positive turning clockwise as
    /// seen).
    Arc {
        to: Pt,
        centre: Pt,
        r: f64,
        start: f64,
        sweep: f64,
    },
}

/// Which layer a move goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct LayerKey {
    pub panel: usize,
    pub file: usize,
    pub rapid: bool,
    pub tool: i64,
}

/// One layer's paths, with the state of the simplifier.
#[derive(Clone, Debug, Default)]
pub struct Layer {
    pub segs: Vec<Seg>,
    last: Option<Pt>,
    /// The start of the straight run that ends at `last`, and the points
    /// left out of it.
    anchor: Option<Pt>,
    skipped: Vec<Pt>,
    pending: Option<Pt>,
    /// Where the last hole circle was drawn (pecks draw it once).
    last_hole: Option<Pt>,
}

fn d2(a: Pt, b: Pt) -> f64 {
    (a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)
}

/// Distance from `p` to the segment a-b.
fn to_segment(p: Pt, a: Pt, b: Pt) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    };
    d2(p, (a.0 + t * dx, a.1 + t * dy)).sqrt()
}

impl Layer {
    fn pen(&self) -> Option<Pt> {
        self.pending.or(self.last)
    }

    fn begin(&mut self, p: Pt) {
        if let Some(q) = self.pen() {
            if d2(p, q) < MERGE_PX * MERGE_PX {
                return;
            }
        }
        self.flush();
        self.segs.push(Seg::Move(p));
        self.last = Some(p);
        self.anchor = None;
        self.skipped.clear();
    }

    fn line_to(&mut self, p: Pt) {
        let Some(last) = self.last else {
            self.begin(p);
            return;
        };
        if d2(p, last) < MERGE_PX * MERGE_PX {
            self.pending = Some(p);
            return;
        }
        self.pending = None;
        if let (Some(a), Some(Seg::Line(_))) = (self.anchor, self.segs.last()) {
            let straight = self.skipped.len() < MAX_SKIPPED
                && to_segment(last, a, p) <= CHORD_PX
                && self
                    .skipped
                    .iter()
                    .all(|&s| to_segment(s, a, p) <= CHORD_PX);
            if straight {
                self.skipped.push(last);
                if let Some(Seg::Line(end)) = self.segs.last_mut() {
                    *end = p;
                }
                self.last = Some(p);
                return;
            }
        }
        self.segs.push(Seg::Line(p));
        self.anchor = Some(last);
        self.skipped.clear();
        self.last = Some(p);
    }

    fn arc_to(&mut self, seg: Seg, to: Pt) {
        self.flush();
        self.segs.push(seg);
        self.last = Some(to);
        self.anchor = None;
        self.skipped.clear();
    }

    /// A circle of radius `r` around `c` (a hole seen from above).
    fn hole(&mut self, c: Pt, r: f64) {
        if self
            .last_hole
            .is_some_and(|h| d2(h, c) < MERGE_PX * MERGE_PX)
        {
            return;
        }
        self.last_hole = Some(c);
        let start = (c.0 + r, c.1);
        self.begin(start);
        let seg = Seg::Arc {
            to: start,
            centre: c,
            r,
            start: 0.0,
            sweep: std::f64::consts::TAU,
        };
        self.arc_to(seg, start);
    }

    /// Draws a merged last point, if any.
    fn flush(&mut self) {
        if let Some(p) = self.pending.take() {
            self.segs.push(Seg::Line(p));
            self.anchor = self.last;
            self.skipped.clear();
            self.last = Some(p);
        }
    }
}

/// A tool's use in one file, for the legend.
#[derive(Clone, Debug, PartialEq)]
pub struct ToolUse {
    pub file: usize,
    pub tool: i64,
    /// Lowest and highest feed, mm/min (per-revolution feeds times rpm).
    pub feeds: Option<[f64; 2]>,
}

/// Everything to draw.
#[derive(Clone, Debug)]
pub struct Scene {
    pub layout: Layout,
    pub layers: BTreeMap<LayerKey, Layer>,
    /// Tools in order of first use (per file).
    pub tools: Vec<ToolUse>,
    /// Boxes around differences (overlays), mm.
    pub marks: Vec<[P3; 2]>,
    /// Tool diameters (mm), for drawing holes.
    pub diameters: std::collections::HashMap<i64, f64>,
    /// The bottom of the last plunge (file, point) while its tool stays
    /// over it.
    plunged: Option<(usize, P3)>,
}

impl Scene {
    pub fn new(layout: Layout) -> Scene {
        Scene {
            layout,
            layers: BTreeMap::new(),
            tools: Vec::new(),
            marks: Vec::new(),
            diameters: Default::default(),
            plunged: None,
        }
    }

    /// Adds one event of file `file` (0 or 1).
    pub fn push(&mut self, file: usize, e: &Event) {
        let Event::Move(m) = e else { return };
        let rapid = matches!(m.kind, MoveKind::Rapid);
        if !rapid {
            self.note_feed(file, m);
        }
        // A drilled hole: a vertical feed down, then straight back up
        // (a plunge followed by a move sideways is an entry, not a hole).
        let vertical = (m.from[0] - m.to[0]).abs() < 1e-6 && (m.from[1] - m.to[1]).abs() < 1e-6;
        let hole = vertical && m.to[2] > m.from[2] && self.plunged.is_some_and(|(f, _)| f == file);
        for (i, panel) in self.layout.panels.iter().enumerate() {
            let key = LayerKey {
                panel: i,
                file,
                rapid,
                tool: if rapid { 0 } else { m.tool },
            };
            let layer = self.layers.entry(key).or_default();
            draw_move(layer, panel, m);
            if hole && panel.view == super::View::Top {
                let dia = self.diameters.get(&m.tool).copied().unwrap_or(0.0);
                let r = (dia / 2.0 * panel.scale).max(3.0);
                let at = self.plunged.map(|(_, p)| p).unwrap_or(m.from);
                let key = LayerKey {
                    rapid: false,
                    tool: m.tool,
                    ..key
                };
                self.layers.entry(key).or_default().hole(panel.px(at), r);
            }
        }
        self.note_plunge(file, m);
    }

    fn note_plunge(&mut self, file: usize, m: &Move) {
        let vertical = (m.from[0] - m.to[0]).abs() < 1e-6 && (m.from[1] - m.to[1]).abs() < 1e-6;
        self.plunged = match self.plunged {
            _ if vertical && matches!(m.kind, MoveKind::Line) && m.to[2] < m.from[2] => {
                Some((file, m.to))
            }
            // Peck retracts and re-entries keep the hole open.
            Some((f, p)) if vertical && f == file => {
                Some((f, if m.to[2] < p[2] { m.to } else { p }))
            }
            _ => None,
        };
    }

    fn note_feed(&mut self, file: usize, m: &Move) {
        let rate = match m.feed_mode {
            crate::toolpath::FeedMode::PerMinute => m.feed,
            crate::toolpath::FeedMode::PerRev => m.feed * m.spindle.abs(),
        };
        let i = match self
            .tools
            .iter()
            .rposition(|t| t.file == file && t.tool == m.tool)
        {
            Some(i) => i,
            None => {
                self.tools.push(ToolUse {
                    file,
                    tool: m.tool,
                    feeds: None,
                });
                self.tools.len() - 1
            }
        };
        if rate > 0.0 && rate.is_finite() {
            let t = &mut self.tools[i];
            t.feeds = Some(match t.feeds {
                None => [rate, rate],
                Some([a, b]) => [a.min(rate), b.max(rate)],
            });
        }
    }

    /// Draws what is still merged into the last points.
    pub fn finish(&mut self) {
        for l in self.layers.values_mut() {
            l.flush();
        }
    }
}

fn draw_move(layer: &mut Layer, panel: &Panel, m: &Move) {
    layer.begin(panel.px(m.from));
    match &m.kind {
        MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => layer.line_to(panel.px(m.to)),
        MoveKind::Arc(g) => {
            let r = g.radius(m.from) * panel.scale;
            match panel.view.arc_sign(g) {
                Some(sign) if r >= 1.0 => {
                    let centre = panel.px(g.centre);
                    let (from, to) = (panel.px(m.from), panel.px(m.to));
                    let start = (from.1 - centre.1).atan2(from.0 - centre.0);
                    let sweep = sign * g.sweep(m.from, m.to);
                    let seg = Seg::Arc {
                        to,
                        centre,
                        r,
                        start,
                        sweep,
                    };
                    layer.arc_to(seg, to);
                }
                _ => {
                    let tol = 0.5 / panel.scale.max(1e-9);
                    for p in g.points(m.from, m.to, tol) {
                        layer.line_to(panel.px(p));
                    }
                }
            }
        }
    }
}
