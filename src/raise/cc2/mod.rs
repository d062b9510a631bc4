//! CC2 feature recognition: a program's resolved moves raised into ISO
//! 14649 machining features (2.5D milling) with their operations, after
//! the method of Xu, Anwer and Lavernhe (2014): the moves are cut into
//! chunks (one tool at one place, [`segment`]), chunks are recognised as
//! drilling ([`hole`], [`drill`]) or milling cuts made of layers and
//! loops ([`level`], [`shape`]); milling cuts become planar faces
//! ([`face`]), closed pockets ([`pocket`]), open pockets and steps
//! ([`open`]), slots ([`slot`]), outside profiles ([`profile`]); an
//! operation over a feature already found is a further (finishing)
//! operation of it, and the allowances of the earlier ones are read from
//! the offset between them. Whatever is
//! not recognised stays a TOOLPATH_FEATURE with its explicit toolpath
//! ([`freeform`]), reported with W0870: nothing is dropped.
//!
//! Frames: feature placements and toolpaths are in workpiece
//! coordinates (the setup and workpiece placements are identity); a
//! feature's geometry (depth plane, profiles) is in its local frame. The
//! workingsteps' security plane is at `secplane_z` in workpiece
//! coordinates (as NIST's Example 1 shares one plane).

mod build;
mod cuts;
mod drill;
mod face;
mod freeform;
mod hole;
mod level;
pub mod listing;
mod open;
mod pocket;
mod profile;
mod segment;
mod shape;
mod slot;
mod strategy;
#[cfg(test)]
mod tests;

use crate::diag::Diagnostic;
use crate::stepnc::model::{
    Executable, Feature, FeatureId, MachiningWorkingstep, Operation, OperationId, Project, ToolId,
    P3,
};
use crate::toolpath::Event;

/// What recognition needs beyond the moves.
pub struct Cc2Context {
    /// The diameter (mm) of a tool by its number.
    pub tool_diameter: Box<dyn Fn(i64) -> Option<f64>>,
    /// The stock's box (min, max, mm, work coordinates), when known:
    /// through holes, open slot ends, steps and faces are told by it.
    pub stock: Option<(P3, P3)>,
    /// The security plane's Z, work coordinates.
    pub secplane_z: f64,
}

impl Default for Cc2Context {
    fn default() -> Self {
        Cc2Context {
            tool_diameter: Box::new(|_| None),
            stock: None,
            secplane_z: 50.0,
        }
    }
}

/// Appends the features, operations and workingsteps the moves make to
/// the project, in program order. See [`recognise_report`] for the
/// diagnostics (moves left as toolpath features).
pub fn recognise(
    events: &[Event],
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) {
    // The moves are all carried into the project; the notes saying which
    // were not recognised are available from `recognise_report`.
    let _notes = recognise_report(events, project, tool, ctx);
}

/// [`recognise`], returning a W0870 note for each run of moves kept as a
/// TOOLPATH_FEATURE.
pub fn recognise_report(
    events: &[Event],
    project: &mut Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
) -> Vec<Diagnostic> {
    let cuts = cuts::cuts(events, &|t| radius(project, tool, ctx, t));
    let mut r = Raiser::new(project, tool, ctx, &cuts);
    for (i, cut) in cuts.iter().enumerate() {
        r.current = i;
        match cut {
            cuts::Cut::Hole { hole, tool, moves } => drill::raise(&mut r, hole, *tool, moves),
            cuts::Cut::Mill(m) => raise_mill(&mut r, m),
            cuts::Cut::Other(c) => freeform::raise(&mut r, c.tool, &c.moves, "moves"),
        }
    }
    r.diags
}

fn raise_mill(r: &mut Raiser, m: &level::MillCut) {
    let Some(rad) = r.radius(m.tool) else {
        return freeform::raise(r, m.tool, &m.moves, "the tool's diameter is unknown; moves");
    };
    let done = face::raise(r, m, rad)
        || slot::raise(r, m, rad)
        || profile::raise(r, m, rad)
        || pocket::raise(r, m, rad);
    if !done {
        freeform::raise(r, m.tool, &m.moves, "milling moves");
    }
}

fn radius(
    project: &Project,
    tool: &dyn Fn(i64) -> ToolId,
    ctx: &Cc2Context,
    t: i64,
) -> Option<f64> {
    let d = (ctx.tool_diameter)(t).or_else(|| {
        let id = tool(t);
        project
            .tools
            .get(id.index())
            .map(|tl| tl.body.dimension.diameter)
    });
    d.filter(|d| *d > 0.0 && d.is_finite()).map(|d| d / 2.0)
}

/// A feature found so far, with what later operations are matched by.
#[derive(Clone, Debug)]
pub(crate) enum Known {
    Hole {
        feature: FeatureId,
        xy: [f64; 2],
        /// Has a tool that sizes holes (not a spot drill) cut it?
        sized: bool,
    },
    Face {
        feature: FeatureId,
        /// Each operation with the Z it cut to.
        ops: Vec<(OperationId, f64)>,
    },
    Pocket {
        feature: FeatureId,
        /// Each operation with the wall it left and the bottom it cut to.
        ops: Vec<(OperationId, shape::Shape, f64)>,
    },
    Profile {
        feature: FeatureId,
        /// Each operation with the outline it left and its bottom.
        ops: Vec<(OperationId, shape::Shape, f64)>,
    },
    Slot {
        feature: FeatureId,
        /// Each operation with the slot it left.
        ops: Vec<(OperationId, slot::SlotGeom)>,
    },
}

/// The state of one recognition run.
pub(crate) struct Raiser<'a> {
    pub project: &'a mut Project,
    pub tool: &'a dyn Fn(i64) -> ToolId,
    pub ctx: &'a Cc2Context,
    pub known: Vec<Known>,
    /// The top surface features are measured from: the stock top, or the
    /// level a face was cut to, or 0 when neither is known.
    pub top: f64,
    /// The XY envelopes of all cuts, by index, and the cut being raised.
    pub envelopes: Vec<level::Box2>,
    /// The highest cutting level of each milling cut (-∞ for others).
    pub tops: Vec<f64>,
    pub current: usize,
    counters: std::collections::HashMap<&'static str, usize>,
    pub diags: Vec<Diagnostic>,
}

impl<'a> Raiser<'a> {
    fn new(
        project: &'a mut Project,
        tool: &'a dyn Fn(i64) -> ToolId,
        ctx: &'a Cc2Context,
        cuts: &[cuts::Cut],
    ) -> Self {
        let envelopes = cuts
            .iter()
            .map(|c| c.envelope(&|t| radius(project, tool, ctx, t)))
            .collect();
        let tops = cuts
            .iter()
            .map(|c| match c {
                cuts::Cut::Mill(m) => m
                    .levels
                    .iter()
                    .map(|l| l.z)
                    .fold(f64::NEG_INFINITY, f64::max),
                cuts::Cut::Hole { .. } | cuts::Cut::Other(_) => f64::NEG_INFINITY,
            })
            .collect();
        Raiser {
            tops,
            top: ctx.stock.map_or(0.0, |s| s.1[2]),
            project,
            tool,
            ctx,
            known: Vec::new(),
            envelopes,
            current: 0,
            counters: Default::default(),
            diags: Vec::new(),
        }
    }

    pub fn radius(&self, t: i64) -> Option<f64> {
        radius(self.project, self.tool, self.ctx, t)
    }

    /// `POCKET3`: the next name of a kind.
    pub fn name(&mut self, kind: &'static str) -> String {
        let n = self.counters.entry(kind).or_insert(0);
        *n += 1;
        format!("{kind}{n}")
    }

    /// The stock's XY box and its Z range.
    pub fn stock_box(&self) -> Option<(level::Box2, f64, f64)> {
        self.ctx
            .stock
            .map(|(lo, hi)| ([lo[0], lo[1], hi[0], hi[1]], lo[2], hi[2]))
    }

    /// The envelopes of the other cuts.
    pub fn other_envelopes(&self) -> Vec<level::Box2> {
        let i = self.current;
        self.envelopes
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != i)
            .map(|(_, b)| *b)
            .collect()
    }

    pub fn add_feature(&mut self, f: Feature) -> FeatureId {
        self.project.features.push(f);
        FeatureId(self.project.features.len() as u32 - 1)
    }

    /// Adds an operation of a feature and its workingstep, in order.
    pub fn add_operation(&mut self, feature: FeatureId, op: Operation) -> OperationId {
        let ws_id = format!("WS {}", op.id);
        self.project.operations.push(op);
        let id = OperationId(self.project.operations.len() as u32 - 1);
        self.project.features[feature.index()].operations.push(id);
        let z = self.ctx.secplane_z;
        self.project
            .main_workplan
            .elements
            .push(Executable::Workingstep(MachiningWorkingstep {
                id: ws_id,
                secplane: build::plane("SECURITY PLANE", [0.0, 0.0, z]),
                feature,
                operation: id,
                effect: None,
            }));
        id
    }
}

impl Raiser<'_> {
    /// The tool's corner (edge) radius when the project knows it, else 0.
    pub fn tool_edge_radius(&self, t: i64) -> f64 {
        self.project
            .tools
            .get((self.tool)(t).index())
            .and_then(|tl| tl.body.dimension.edge_radius)
            .unwrap_or(0.0)
    }
}

impl Raiser<'_> {
    /// Names a milling feature's operations once it has more than one:
    /// `ROUGH POCKET1` (`ROUGH1 ..`, `ROUGH2 ..` when several) and
    /// `FINISH POCKET1`, with their workingsteps.
    pub fn name_passes(&mut self, feature: FeatureId, verb: &str) {
        let f = &self.project.features[feature.index()];
        let (name, ops) = (f.id.clone(), f.operations.clone());
        let n = ops.len();
        for (i, op) in ops.iter().enumerate() {
            let id = match (n, i + 1 == n) {
                (1, _) => format!("{verb} {name}"),
                (_, true) => format!("FINISH {name}"),
                (2, false) => format!("ROUGH {name}"),
                _ => format!("ROUGH{} {name}", i + 1),
            };
            self.project.operations[op.index()].id = id.clone();
            for e in self.project.main_workplan.elements.iter_mut() {
                if let Executable::Workingstep(ws) = e {
                    if ws.operation == *op {
                        ws.id = format!("WS {id}");
                    }
                }
            }
        }
    }
}
