//! What a plot draws, built in one pass while the events stream in: for
//! each view, file, tool and kind of move (feed or rapid) one layer of
//! paths, in view-plane millimetres (u right, v up).
//!
//! Detail below the pixel is dropped as it comes ([`super::layer`]). The
//! scale of the final picture is not known until the end, but it can only
//! fall as the box around the moves grows, so the scale of the box seen so
//! far ([`Layout::scale`]) gives a tolerance that is fine enough. A
//! program of millions of moves keeps its shape in a few thousand
//! segments per view.

use super::layer::Layer;
pub use super::layer::{Pt, Seg};
use super::layout::Layout;
use super::view::View;
use crate::stats::Bounds;
use crate::toolpath::{Event, Move, MoveKind, P3};
use std::collections::BTreeMap;

/// Points closer than this (pixels) are one.
const MERGE_PX: f64 = 0.5;
/// Points left out stay this close (pixels) to the line drawn.
const CHORD_PX: f64 = 0.25;
/// Moves between re-estimates of the scale.
const RESCALE_EVERY: u64 = 1024;

/// Which layer a move goes to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct LayerKey {
    pub panel: usize,
    pub file: usize,
    pub rapid: bool,
    pub tool: i64,
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
    pub views: Vec<View>,
    pub width: f64,
    /// The box around every move (and the stock).
    pub bounds: Bounds,
    pub layers: BTreeMap<LayerKey, Layer>,
    /// Tools in order of first use (per file).
    pub tools: Vec<ToolUse>,
    /// Boxes around differences (overlays), mm.
    pub marks: Vec<[P3; 2]>,
    /// Tool diameters (mm), for drawing holes.
    pub diameters: std::collections::HashMap<i64, f64>,
    /// Half a pixel at the scale of the box seen so far, mm.
    half_px: f64,
    moves: u64,
    rescaled_at: Bounds,
    /// The bottom of the last plunge (file, point) while the tool stays
    /// over it.
    plunged: Option<(usize, P3)>,
}

impl Scene {
    /// An empty scene of `views`, `width` pixels wide, around `bounds`
    /// (the stock, or nothing).
    pub fn new(views: Vec<View>, width: f64, bounds: Bounds) -> Scene {
        let mut s = Scene {
            views,
            width,
            bounds,
            layers: BTreeMap::new(),
            tools: Vec::new(),
            marks: Vec::new(),
            diameters: Default::default(),
            half_px: 0.0,
            moves: 0,
            rescaled_at: bounds,
            plunged: None,
        };
        s.rescale();
        s
    }

    fn rescale(&mut self) {
        let scale = Layout::scale(&self.views, &self.bounds, self.width);
        self.half_px = MERGE_PX / scale.max(1e-12);
        self.rescaled_at = self.bounds;
    }

    /// The picture's layout, from everything seen.
    pub fn layout(&self) -> Layout {
        Layout::new(&self.views, &self.bounds, self.width)
    }

    /// Adds one event of file `file` (0 or 1).
    pub fn push(&mut self, file: usize, e: &Event) {
        let Event::Move(m) = e else { return };
        self.bounds.add_move(m);
        self.moves += 1;
        if self.moves.is_multiple_of(RESCALE_EVERY) && self.bounds != self.rescaled_at {
            self.rescale();
        }
        let rapid = matches!(m.kind, MoveKind::Rapid);
        if !rapid {
            self.note_feed(file, m);
        }
        // A drilled hole: a vertical feed down, then straight back up (a
        // plunge followed by a move sideways is an entry, not a hole).
        let vertical = (m.from[0] - m.to[0]).abs() < 1e-6 && (m.from[1] - m.to[1]).abs() < 1e-6;
        let hole = vertical && m.to[2] > m.from[2] && self.plunged.is_some_and(|(f, _)| f == file);
        let (merge, chord) = (self.half_px, self.half_px * CHORD_PX / MERGE_PX);
        for (i, view) in self.views.iter().enumerate() {
            let key = LayerKey {
                panel: i,
                file,
                rapid,
                tool: if rapid { 0 } else { m.tool },
            };
            let layer = self.layers.entry(key).or_default();
            draw_move(layer, *view, m, merge, chord);
            if hole && *view == View::Top {
                let r = self.diameters.get(&m.tool).copied().unwrap_or(0.0) / 2.0;
                let at = self.plunged.map(|(_, p)| p).unwrap_or(m.from);
                let key = LayerKey {
                    rapid: false,
                    tool: m.tool,
                    ..key
                };
                self.layers
                    .entry(key)
                    .or_default()
                    .hole(view.project(at), r, merge);
            }
        }
        self.note_plunge(file, m, vertical);
    }

    fn note_plunge(&mut self, file: usize, m: &Move, vertical: bool) {
        let down = vertical && matches!(m.kind, MoveKind::Line) && m.to[2] < m.from[2];
        self.plunged = match self.plunged {
            _ if down => Some((file, m.to)),
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

fn draw_move(layer: &mut Layer, view: View, m: &Move, merge: f64, chord: f64) {
    layer.begin(view.project(m.from), merge);
    match &m.kind {
        MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => {
            layer.line_to(view.project(m.to), merge, chord)
        }
        MoveKind::Arc(g) => match view.arc_sign(g) {
            Some(sign) if g.radius(m.from) >= merge => {
                let centre = view.project(g.centre);
                let (from, to) = (view.project(m.from), view.project(m.to));
                let seg = Seg::Arc {
                    to,
                    centre,
                    r: g.radius(m.from),
                    start: (from.1 - centre.1).atan2(from.0 - centre.0),
                    sweep: bounded_sweep(sign * g.sweep(m.from, m.to)),
                };
                layer.arc_to(seg, to);
            }
            _ => {
                for p in g.points(m.from, m.to, chord) {
                    layer.line_to(view.project(p), merge, chord);
                }
            }
        },
    }
}

/// A circle seen whole draws the same pixels however many turns it
/// makes: more than one turn is drawn as one to two turns ending at the
/// same angle, so a helix of a million turns is a bounded picture.
fn bounded_sweep(sweep: f64) -> f64 {
    use std::f64::consts::TAU;
    if sweep.abs() <= 2.0 * TAU {
        return sweep;
    }
    sweep % TAU + TAU * sweep.signum()
}

#[cfg(test)]
#[path = "scene_tests.rs"]
mod tests;
