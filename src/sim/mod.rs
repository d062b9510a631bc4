//! Material removal for 3-axis milling (`cncc simulate`, the rapid check
//! of `cncc check`, `cncc diff --material`): the stock as a height field
//! ([`grid::HeightField`]) cut by each tool's shape ([`cutter::Cutter`])
//! swept along every move of the run ([`sweep`]).
//!
//! A [`Simulation`] takes the resolved events of a run
//! ([`crate::toolpath::Event`], the level `plot` and `stats` read) as
//! they stream in, so memory is the grid's whatever the program's length.
//! Lines are swept exactly at each cell centre; arcs and helices as
//! chords no further than [`Simulation::chord`] from the true path.
//! Rapids cut too (a crash removes material as well), and when asked
//! each rapid is first probed: material above the tool's surface deeper
//! than [`RAPID_DEPTH`] is a [`RapidHit`].

pub mod compare;
pub mod cutter;
pub mod grid;
pub mod image;
pub mod material;
pub mod report;
pub mod stl;
pub mod sweep;
pub mod tool_defs;

use crate::interp::tool_header::HeaderTool;
use crate::interp::tooltable::ToolTable;
use crate::span::Span;
use crate::toolpath::{Event, FeedMode, Move, MoveKind, P3};
pub use cutter::{Cutter, Shape};
pub use grid::HeightField;
use nalgebra::Vector3;
use std::collections::HashMap;
use sweep::Sweep;

/// Material standing this far (mm) above a rapid's tool surface is a hit.
pub const RAPID_DEPTH: f64 = 0.01;
/// The side play a rapid is given (mm, and at least half a cell): a rapid
/// along a wall the tool has just cut does not touch it.
pub const RAPID_PLAY: f64 = 0.02;

/// A rapid that went through material.
#[derive(Clone, Debug, PartialEq)]
pub struct RapidHit {
    pub span: Span,
    pub tool: i64,
    /// The deepest point: cell centre and the material's height there.
    pub at: P3,
    /// How deep the tool went into the material there, mm.
    pub depth: f64,
}

/// A flat tool fed straight down (pure -Z feed) into material standing
/// under its centre: a flat end mill without centre cutting cannot cut
/// there. The first plunge of each tool, with how many it made.
#[derive(Clone, Debug, PartialEq)]
pub struct Plunge {
    pub span: Span,
    pub tool: i64,
    /// The tool's axis and the material's height there.
    pub at: P3,
    /// How deep the centre went into the material, mm.
    pub depth: f64,
    /// Plunges of this tool in all.
    pub count: usize,
}

/// What one tool did.
#[derive(Clone, Debug, PartialEq)]
pub struct ToolReport {
    pub tool: i64,
    pub cutter: Cutter,
    /// Volume removed, mm³.
    pub volume: f64,
    /// Feed path length, mm, and the part of it with a known feed rate.
    pub feed_length: f64,
    /// Minutes at the programmed feed (moves with no usable rate left out).
    pub feed_minutes: f64,
    pub rapid_length: f64,
}

/// The cutters of a run's tools, by tool number.
#[derive(Clone, Debug, Default)]
pub struct Cutters {
    pub by_tool: HashMap<i64, Cutter>,
    /// Flat tools whose name says they are made to feed along their axis
    /// (see [`cutter::axial_name`]), and tools whose shape nothing
    /// states: no plunge warning for them.
    pub axial: std::collections::HashSet<i64>,
}

impl Cutters {
    /// Every tool of `table` (sizes times `mm`) with the shapes its
    /// comment and the program's CAM tool list (`head`) give. With
    /// `known_only`, a tool whose size cncc invented (the built-in table)
    /// is a point: only its axis is simulated.
    pub fn from_table(table: &ToolTable, head: &str, mm: f64, known_only: bool) -> Cutters {
        let header: Vec<HeaderTool> = crate::interp::tool_header::header_tools(head);
        // A tool whose shape nothing states (a `TOOL DEF` or a table row
        // with sizes only) is not judged: it may be a drill.
        let axial = table
            .tools
            .iter()
            .filter(|t| {
                let h = header.iter().find(|h| h.number == t.number);
                cutter::axial_name(&t.comment)
                    || h.is_some_and(|h| cutter::axial_name(&h.name))
                    || !cutter::shape_stated(t, h)
            })
            .map(|t| t.number)
            .collect();
        let by_tool = table
            .tools
            .iter()
            .map(|t| {
                let invented = table.invented && !table.from_program.contains(&t.number);
                let h = header.iter().find(|h| h.number == t.number);
                let c = if known_only && invented {
                    Cutter::flat(0.0)
                } else {
                    Cutter::from_tool(Some(t), h, mm)
                };
                (t.number, c)
            })
            .collect();
        Cutters { by_tool, axial }
    }

    /// Can tool `tool` feed straight down into solid material? Any shape
    /// but a flat one can (a drill's point, a ball), and a flat tool
    /// whose name says it is made to (a tap, a reamer); a tool of unknown
    /// size is not judged.
    pub fn may_plunge(&self, tool: i64) -> bool {
        let c = self.get(tool);
        !c.is_flat() || self.axial.contains(&tool)
    }

    pub fn get(&self, tool: i64) -> Cutter {
        self.by_tool
            .get(&tool)
            .copied()
            .unwrap_or(Cutter::flat(0.0))
    }
}

/// A run's material removal, fed event by event.
pub struct Simulation {
    pub field: HeightField,
    pub cutters: Cutters,
    /// Per tool, in order of first use.
    pub tools: Vec<ToolReport>,
    /// Probe rapids before cutting with them.
    pub check_rapids: bool,
    pub rapid_hits: Vec<RapidHit>,
    /// Largest chord error of arcs, mm.
    pub chord: f64,
    /// A cell whose last cut is wanted (see [`Watch`]).
    pub watch: Option<Watch>,
    /// The tool stands at a height not known at check time: it moved in
    /// machine coordinates (see [`Simulation::push_in_frame`]).
    unknown_height: bool,
    /// Where the rapid probe stopped: the first cut of a tool of unknown
    /// size (a point here, narrower than the real tool), after which the
    /// material left is more than the real run leaves and a hit is no
    /// longer certain.
    pub probe_stopped: Option<(Span, i64)>,
    /// Plunges of flat tools into material (checked with the rapids).
    pub plunges: Vec<Plunge>,
}

/// The move that last lowered one cell of the field: where a difference
/// between two parts was made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Watch {
    /// The cell (`j * nx + i`).
    pub cell: usize,
    /// The last move that cut it and the height it left.
    pub last: Option<(Span, f64)>,
}

impl Simulation {
    pub fn new(field: HeightField, cutters: Cutters) -> Simulation {
        let chord = (field.dx.min(field.dy) / 4.0).min(0.005);
        Simulation {
            field,
            cutters,
            tools: Vec::new(),
            check_rapids: false,
            rapid_hits: Vec::new(),
            chord,
            watch: None,
            // Where the tool starts is not known either (the run starts
            // it at the work zero): taken as above the work, as after a
            // move in machine coordinates.
            unknown_height: true,
            probe_stopped: None,
            plunges: Vec::new(),
        }
    }

    /// Takes one event of the run.
    pub fn push(&mut self, e: &Event) {
        self.push_in_frame(e, false)
    }

    /// Takes one event; `machine`: it comes from a block that moves in
    /// machine coordinates (Heidenhain `M91`/`M92`, `G53`), whose place
    /// relative to the work is not known at check time (the run takes
    /// the machine datum at the work zero). Such a move neither cuts nor
    /// is probed, and the tool is then at an unknown height, taken to be
    /// above the work [?: the datums machine builders set are]: rapids
    /// that keep that height are passed by too, the first rapid that
    /// changes Z comes straight down onto its end point from above the
    /// stock, and a feed is cut as it is (the program cuts from there).
    pub fn push_in_frame(&mut self, e: &Event, machine: bool) {
        let Event::Move(m) = e else { return };
        if machine {
            self.unknown_height = true;
            return;
        }
        if self.unknown_height {
            let rapid = matches!(m.kind, MoveKind::Rapid);
            if rapid && m.from[2] == m.to[2] {
                return;
            }
            self.unknown_height = false;
            if rapid {
                let mut m = m.clone();
                m.from = [m.to[0], m.to[1], m.to[2].max(self.field.top)];
                return self.push_move(&m);
            }
        }
        self.push_move(m)
    }

    fn push_move(&mut self, m: &Move) {
        let cutter = self.cutters.get(m.tool);
        let i = self.report_for(m.tool, cutter);
        let rapid = matches!(m.kind, MoveKind::Rapid);
        let len = m.length();
        if rapid {
            self.tools[i].rapid_length += len;
            if self.check_rapids && self.probe_stopped.is_none() {
                self.probe_rapid(m, &cutter);
            }
        } else {
            if self.check_rapids && self.probe_stopped.is_none() {
                self.probe_plunge(m, &cutter);
            }
            self.tools[i].feed_length += len;
            if let Some(rate) = rate(m).filter(|r| *r > 0.0 && r.is_finite()) {
                self.tools[i].feed_minutes += len / rate;
            }
        }
        let reach = cutter.radius.max(self.half_cell());
        let before = self.watch.and_then(|w| self.field.z.get(w.cell).copied());
        let mut removed = 0.0;
        for (a, b) in self.chords(m) {
            removed += Sweep {
                cutter: &cutter,
                a,
                b,
                reach,
            }
            .cut(&mut self.field);
        }
        self.tools[i].volume += removed;
        if self.check_rapids && cutter.radius == 0.0 && removed > 0.0 && !rapid {
            self.probe_stopped.get_or_insert((m.span, m.tool));
        }
        if let (Some(w), Some(h)) = (self.watch.as_mut(), before) {
            let after = self.field.z.get(w.cell).copied().unwrap_or(h);
            if after < h {
                w.last = Some((m.span, after as f64));
            }
        }
    }

    fn report_for(&mut self, tool: i64, cutter: Cutter) -> usize {
        if let Some(i) = self.tools.iter().position(|t| t.tool == tool) {
            return i;
        }
        self.tools.push(ToolReport {
            tool,
            cutter,
            volume: 0.0,
            feed_length: 0.0,
            feed_minutes: 0.0,
            rapid_length: 0.0,
        });
        self.tools.len() - 1
    }

    /// The straight pieces of a move (chords of an arc).
    fn chords(&self, m: &Move) -> Vec<(Vector3<f64>, Vector3<f64>)> {
        let v = |p: P3| Vector3::new(p[0], p[1], p[2]);
        match &m.kind {
            MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => vec![(v(m.from), v(m.to))],
            MoveKind::Arc(g) => {
                let mut prev = m.from;
                g.points(m.from, m.to, self.chord)
                    .into_iter()
                    .map(|p| {
                        let c = (v(prev), v(p));
                        prev = p;
                        c
                    })
                    .collect()
            }
        }
    }

    fn probe_rapid(&mut self, m: &Move, cutter: &Cutter) {
        let play = RAPID_PLAY.max(self.field.dx.max(self.field.dy) / 2.0);
        let reach = (cutter.radius - play).max(self.half_cell());
        let hit = Sweep {
            cutter,
            a: Vector3::from(m.from),
            b: Vector3::from(m.to),
            reach,
        }
        .probe(&mut self.field);
        if let Some(h) = hit.filter(|h| h.depth > RAPID_DEPTH) {
            self.rapid_hits.push(RapidHit {
                span: m.span,
                tool: m.tool,
                at: h.at,
                depth: h.depth,
            });
        }
    }

    /// A pure -Z feed of a flat tool that cannot plunge (see
    /// [`Cutters::may_plunge`]) whose axis goes into material.
    fn probe_plunge(&mut self, m: &Move, cutter: &Cutter) {
        let straight_down = matches!(m.kind, MoveKind::Line)
            && (m.from[0] - m.to[0]).abs() < 1e-6
            && (m.from[1] - m.to[1]).abs() < 1e-6
            && m.to[2] < m.from[2];
        if !straight_down || cutter.radius <= 0.0 || self.cutters.may_plunge(m.tool) {
            return;
        }
        let Some(k) = self.field.cell_at(m.to[0], m.to[1]) else {
            return;
        };
        let h = self.field.z[k] as f64;
        let depth = h.min(m.from[2]) - m.to[2].max(self.field.bottom);
        if depth <= RAPID_DEPTH {
            return;
        }
        if let Some(p) = self.plunges.iter_mut().find(|p| p.tool == m.tool) {
            p.count += 1;
            return;
        }
        self.plunges.push(Plunge {
            span: m.span,
            tool: m.tool,
            at: [m.to[0], m.to[1], h],
            depth,
            count: 1,
        });
    }

    /// Half a cell's diagonal: a tool of no size still reaches the
    /// nearest cell centre, wherever its axis stands.
    fn half_cell(&self) -> f64 {
        self.field.dx.hypot(self.field.dy) / 2.0
    }

    /// The volume removed in all, mm³.
    pub fn removed(&self) -> f64 {
        self.tools.iter().map(|t| t.volume).sum()
    }
}

/// A move's feed in mm/min, when it has one.
fn rate(m: &Move) -> Option<f64> {
    match m.feed_mode {
        FeedMode::PerMinute => Some(m.feed),
        FeedMode::PerRev => Some(m.feed * m.spindle.abs()),
    }
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;
