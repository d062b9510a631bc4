//! The state of one recognition run: the project being filled, the
//! features found so far (what later operations are matched against),
//! the top surface, the cuts' envelopes, names, diagnostics.

use super::{level, radius, shape, slot, Cc2Context};
use crate::diag::Diagnostic;
use crate::stepnc::model::{
    Executable, Feature, FeatureId, MachiningWorkingstep, Operation, OperationId, Project, ToolId,
};

/// A feature found so far, with what later operations are matched by.
#[derive(Clone, Debug)]
pub(crate) enum Known {
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
    /// Holes by position (µm grid): the feature and whether a tool that
    /// sizes holes has cut it.
    pub holes: std::collections::HashMap<(i64, i64), (FeatureId, bool)>,
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
    /// `envelopes` and `tops`: every cut's, by index (`cuts::Stored`).
    pub fn new(
        project: &'a mut Project,
        tool: &'a dyn Fn(i64) -> ToolId,
        ctx: &'a Cc2Context,
        envelopes: Vec<level::Box2>,
        tops: Vec<f64>,
    ) -> Self {
        Raiser {
            tops,
            top: ctx.stock.map_or(0.0, |s| s.1[2]),
            project,
            tool,
            ctx,
            known: Vec::new(),
            holes: Default::default(),
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
                secplane: super::build::plane("SECURITY PLANE", [0.0, 0.0, z]),
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
