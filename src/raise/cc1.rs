//! CC1: a run's events raised to explicit toolpaths (Xu, Anwer, Lavernhe
//! 2014: G-code → canonical calls → Part 21 explicit toolpaths).
//!
//! Events are taken one at a time (a large program is never held whole):
//! - rapids gather into one RAPID_MOVEMENT whose toolpath is the polyline
//!   through them (the first rapid of a run starts at an unknown position:
//!   it gets no toolpath, which ISO 14649 reads as "via the security
//!   plane");
//! - a run of cutting moves between rapids with one tool, spindle speed
//!   and coolant is one MACHINING_WORKINGSTEP of a FREEFORM_OPERATION whose
//!   TOOLPATH_LIST holds one CUTTER_LOCATION_TRAJECTORY per feed rate
//!   (the first inherits the operation's technology, later ones carry
//!   their own); a change of tool, spindle or coolant starts a new
//!   workingstep; these workingsteps are tied to one TOOLPATH_FEATURE per
//!   tool, placed at the workpiece origin;
//! - a drilling cycle (see [`super::holes`]) becomes a ROUND_HOLE with its
//!   drilling operation, whose toolpath is the cycle's moves; a tapping
//!   cycle a TAPPING operation (spindle synchronised with the feed: the
//!   pitch is feed / speed) whose tool becomes a TAP of the spindle's hand;
//! - a dwell inside a run is a FEEDSTOP; a program stop a PROGRAM_STOP;
//! - a comment names the workingstep that follows it.

use super::curves::CurveBuilder;
use super::holes::{classify, HoleCycle, HoleKind, Item, Pattern};
use super::ops;
use super::project::{placement, plane_at, ToolRegistry};
use super::report::Losses;
use super::stock::Stock;
use crate::span::Span;
use crate::stepnc::model::*;
use crate::toolpath::{CoolantState, Event, Move, MoveKind, P3};
use std::collections::HashMap;

/// What starts a new workingstep when it changes.
#[derive(Clone, Copy, PartialEq)]
struct CutKey {
    tool: i64,
    spindle: f64,
    coolant: CoolantState,
}

/// The cutting run being built.
struct Cut {
    key: CutKey,
    first: Move,
    feed: f64,
    curve: CurveBuilder,
    /// The technology the current curve carries (None: the operation's).
    curve_tech: Option<Technology>,
    toolpaths: Vec<Toolpath>,
    min_z: f64,
    /// The workingstep's name, given when the run starts.
    name: String,
}

pub struct Cc1Builder {
    pub project: Project,
    pub tools: ToolRegistry,
    pub losses: Losses,
    stock: Option<Stock>,
    group: Vec<Item>,
    group_span: Option<Span>,
    rapids: Vec<P3>,
    cut: Option<Cut>,
    /// Where the tool is, once a move has said.
    known: bool,
    /// The last comment, with where it is: the next workingstep's name.
    name: Option<(String, Span)>,
    steps: usize,
    holes: usize,
    pub max_rapid_z: Option<f64>,
    pub max_z: Option<f64>,
    /// The toolpath feature of each tool, with the lowest Z it reached.
    toolpath_features: HashMap<ToolId, (FeatureId, f64)>,
}

impl Cc1Builder {
    pub fn new(project: Project, tools: ToolRegistry, stock: Option<Stock>) -> Self {
        Cc1Builder {
            project,
            tools,
            losses: Losses::default(),
            stock,
            group: Vec::new(),
            group_span: None,
            rapids: Vec::new(),
            cut: None,
            known: false,
            name: None,
            steps: 0,
            holes: 0,
            max_rapid_z: None,
            max_z: None,
            toolpath_features: HashMap::new(),
        }
    }

    pub fn push(&mut self, e: Event) {
        match e {
            Event::Move(m) => {
                if self.group_span != Some(m.span) {
                    self.flush_group();
                    self.group_span = Some(m.span);
                }
                self.group.push(Item::Move(m));
            }
            Event::Dwell { seconds, span } => {
                if self.group_span != Some(span) {
                    self.flush_group();
                    self.dwell(seconds);
                } else {
                    self.group.push(Item::Dwell(seconds));
                }
            }
            Event::ToolChange { .. } => {
                self.flush_group();
                self.close_cut();
            }
            Event::Stop { end, span } => {
                self.flush_group();
                self.close_cut();
                self.flush_rapids();
                if !end {
                    let id = format!("STOP {}", span.start);
                    self.project
                        .main_workplan
                        .elements
                        .push(Executable::ProgramStop { id });
                }
            }
            Event::Comment { text, span } => self.comment(text, span),
        }
    }

    /// Ends the run: everything pending goes into the project.
    pub fn finish(mut self) -> (Project, ToolRegistry, Losses, Option<f64>, Option<f64>) {
        self.flush_group();
        self.close_cut();
        self.flush_rapids();
        if let Some((n, span)) = self.name.take() {
            self.losses.comment(n, span);
        }
        for (fid, min_z) in self.toolpath_features.values() {
            let f = &mut self.project.features[fid.index()];
            f.depth = Some(plane_at(&format!("{} DEPTH", f.id), *min_z));
        }
        self.tools.settle_kinds(&mut self.project);
        (
            self.project,
            self.tools,
            self.losses,
            self.max_rapid_z,
            self.max_z,
        )
    }

    fn comment(&mut self, text: String, span: Span) {
        // LinuxCNC's own notes (`interpreter: ...`) are not the program's.
        if text.starts_with("interpreter:") {
            return;
        }
        self.flush_group();
        if let Some((old, at)) = self.name.replace((text, span)) {
            self.losses.comment(old, at);
        }
    }

    fn flush_group(&mut self) {
        self.group_span = None;
        let items = std::mem::take(&mut self.group);
        match classify(&items) {
            Pattern::Hole(h) => self.hole(h, items),
            pattern => {
                if pattern == Pattern::Other {
                    if let Some(Item::Move(m)) = items.first() {
                        self.losses.cycle(m.span);
                    }
                }
                for it in items {
                    match it {
                        Item::Move(m) => self.motion(m),
                        Item::Dwell(s) => self.dwell(s),
                    }
                }
            }
        }
    }

    fn track_z(&mut self, m: &Move) {
        let top = m.to[2].max(if self.known { m.from[2] } else { m.to[2] });
        self.max_z = Some(self.max_z.map_or(top, |z| z.max(top)));
        if m.kind == MoveKind::Rapid {
            self.max_rapid_z = Some(self.max_rapid_z.map_or(top, |z| z.max(top)));
        }
    }

    fn motion(&mut self, m: Move) {
        let tool = self.tools.id(&mut self.project, m.tool, m.span);
        self.track_z(&m);
        if m.kind == MoveKind::Rapid {
            self.close_cut();
            if self.rapids.is_empty() && self.known {
                self.rapids.push(m.from);
            }
            if self.rapids.last() != Some(&m.to) {
                self.rapids.push(m.to);
            }
            self.known = true;
            return;
        }
        self.tools.used(tool, false);
        let key = CutKey {
            tool: m.tool,
            spindle: m.spindle,
            coolant: m.coolant,
        };
        if self.cut.as_ref().is_some_and(|c| c.key != key) {
            self.close_cut();
        }
        if self.cut.is_none() {
            self.flush_rapids();
            let name = self.step_name("FREEFORM");
            self.cut = Some(Cut {
                name,
                key,
                first: m.clone(),
                feed: m.feed,
                curve: CurveBuilder::default(),
                curve_tech: None,
                toolpaths: Vec::new(),
                min_z: f64::INFINITY,
            });
        }
        let cut = self.cut.as_mut().expect("a cut is open");
        if m.feed != cut.feed {
            let curve = std::mem::take(&mut cut.curve);
            close_curve(cut, curve);
            cut.feed = m.feed;
            cut.curve_tech = Some(ops::technology(&m));
        }
        cut.min_z = cut.min_z.min(m.to[2]).min(m.from[2]);
        match &m.kind {
            MoveKind::Arc(g) => cut.curve.arc(m.from, m.to, g),
            MoveKind::Line | MoveKind::Probe | MoveKind::Rapid => cut.curve.line(m.from, m.to),
        }
        if cut.curve.helices > 0 {
            self.losses.helix(m.span, cut.curve.helices);
            cut.curve.helices = 0;
        }
        self.known = true;
    }

    fn dwell(&mut self, seconds: f64) {
        match self.cut.as_mut() {
            Some(cut) => {
                let curve = std::mem::take(&mut cut.curve);
                close_curve(cut, curve);
                cut.toolpaths.push(ops::feedstop(seconds));
            }
            None => {
                self.flush_rapids();
                self.push_rapid(Some(vec![ops::feedstop(seconds)]));
            }
        }
    }

    fn push_rapid(&mut self, toolpath: Option<Vec<Toolpath>>) {
        let n = self.project.main_workplan.elements.len() + 1;
        self.project
            .main_workplan
            .elements
            .push(Executable::Rapid(RapidMovement {
                id: format!("RAPID {n}"),
                secplane: plane_at("SECURITY PLANE", 0.0),
                toolpath,
                tool_direction: None,
            }));
    }

    fn flush_rapids(&mut self) {
        if self.rapids.is_empty() {
            return;
        }
        let pts = std::mem::take(&mut self.rapids);
        let toolpath = (pts.len() >= 2).then(|| {
            let curve = Curve::Polyline {
                name: String::new(),
                points: pts.into_iter().map(super::curves::point).collect(),
            };
            vec![ops::trajectory(curve, None, ToolpathType::TrajectoryPath)]
        });
        self.push_rapid(toolpath);
    }

    fn step_name(&mut self, what: &str) -> String {
        self.steps += 1;
        match self.name.take() {
            Some((n, _)) => format!("WS {} {}", self.steps, n),
            None => format!("WS {} {what}", self.steps),
        }
    }

    fn toolpath_feature(&mut self, tool: ToolId, min_z: f64) -> FeatureId {
        if let Some((fid, z)) = self.toolpath_features.get_mut(&tool) {
            *z = z.min(min_z);
            return *fid;
        }
        let fid = FeatureId(self.project.features.len() as u32);
        let name = format!("TOOLPATHS {}", self.project.tool(tool).id);
        self.project.features.push(Feature {
            id: name.clone(),
            workpiece: WorkpieceId(0),
            operations: Vec::new(),
            placement: placement(&name, [0.0; 3]),
            depth: Some(plane_at(&format!("{name} DEPTH"), min_z)),
            kind: FeatureKind::ToolpathFeature,
        });
        self.toolpath_features.insert(tool, (fid, min_z));
        fid
    }

    fn close_cut(&mut self) {
        let Some(mut cut) = self.cut.take() else {
            return;
        };
        let curve = std::mem::take(&mut cut.curve);
        close_curve(&mut cut, curve);
        let tool = self
            .tools
            .id(&mut self.project, cut.key.tool, cut.first.span);
        let feature = self.toolpath_feature(tool, cut.min_z);
        let kind = OperationKind::Freeform {
            approach: None,
            retract: None,
            strategy: None,
        };
        self.add_step(cut.name, feature, &cut.first, tool, cut.toolpaths, kind);
    }

    fn add_step(
        &mut self,
        name: String,
        feature: FeatureId,
        first: &Move,
        tool: ToolId,
        toolpaths: Vec<Toolpath>,
        kind: OperationKind,
    ) {
        let op = OperationId(self.project.operations.len() as u32);
        self.project.operations.push(Operation {
            id: name.replacen("WS", "OP", 1),
            toolpath: Some(toolpaths),
            tool_direction: None,
            retract_plane: None,
            start_point: None,
            tool,
            technology: ops::technology(first),
            machine_functions: ops::machine_functions(first),
            overcut_length: None,
            kind,
        });
        self.project.features[feature.index()].operations.push(op);
        self.project
            .main_workplan
            .elements
            .push(Executable::Workingstep(MachiningWorkingstep {
                id: name,
                secplane: plane_at("SECURITY PLANE", 0.0),
                feature,
                operation: op,
                effect: None,
            }));
    }

    fn hole(&mut self, h: HoleCycle, items: Vec<Item>) {
        self.close_cut();
        let mut items = items.into_iter();
        for it in items.by_ref().take(h.lead) {
            if let Item::Move(m) = it {
                self.motion(m);
            }
        }
        self.flush_rapids();
        let body: Vec<Item> = items.collect();
        let Some(Item::Move(first)) = body.first().cloned() else {
            return;
        };
        let tool = self.tools.id(&mut self.project, first.tool, first.span);
        self.tools.used(tool, true);
        let diameter = self.tools.diameter(first.tool).unwrap_or(0.0);
        self.holes += 1;
        let fname = format!(
            "HOLE {} D{} X{} Y{}",
            self.holes,
            fmt(diameter),
            fmt(h.x),
            fmt(h.y)
        );
        let stock = self.stock.map(|s| (s.corner[2], s.top()));
        let feature = ops::hole_feature(fname, &h, diameter, stock);
        let top = feature.placement.location.xyz[2];
        let origin = [h.x, h.y, top];
        let fid = FeatureId(self.project.features.len() as u32);
        self.project.features.push(feature);
        let kind = ops::hole_operation_kind(&h, top);
        let toolpaths = hole_toolpaths(&body, &first, origin);
        for it in &body {
            if let Item::Move(m) = it {
                self.track_z(m);
            }
        }
        let name = self.step_name(ops::operation_name(&kind));
        self.add_step(name, fid, &first, tool, toolpaths, kind);
        let op = self.project.operations.last_mut().expect("just added");
        op.retract_plane = Some(h.r_z - top);
        if let HoleKind::Tapping { left_hand, .. } = h.kind {
            // The pitch is the feed over the speed (ISO 14649: the spindle
            // synchronised with the feed); the tool is a tap of that hand.
            op.technology.synchronize_spindle_with_feed = true;
            let body = &mut self.project.tools[tool.index()].body;
            body.kind = ToolBodyKind::Tap;
            body.hand_of_cut = Some(if left_hand { Hand::Left } else { Hand::Right });
        }
        self.known = true;
    }
}

/// Closes a curve into a toolpath of the cut.
fn close_curve(cut: &mut Cut, curve: CurveBuilder) {
    if let Some(c) = curve.finish() {
        cut.toolpaths.push(ops::trajectory(
            c,
            cut.curve_tech.clone(),
            ToolpathType::TrajectoryPath,
        ));
    }
}

/// The toolpaths of a hole cycle in the hole's frame: runs of feeds as
/// trajectory paths (with their own technology when the feed differs from
/// the first), runs of rapids as connecting moves at rapid speed, dwells
/// as feedstops.
fn hole_toolpaths(body: &[Item], first: &Move, origin: P3) -> Vec<Toolpath> {
    let shift = |p: P3| [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
    let mut out = Vec::new();
    let mut run: Option<(ToolpathType, Option<Technology>, CurveBuilder)> = None;
    let close = |run: &mut Option<(ToolpathType, Option<Technology>, CurveBuilder)>,
                 out: &mut Vec<Toolpath>| {
        if let Some((kind, tech, b)) = run.take() {
            if let Some(curve) = b.finish() {
                out.push(ops::trajectory(curve, tech, kind));
            }
        }
    };
    for it in body {
        let Item::Move(m) = it else {
            close(&mut run, &mut out);
            if let Item::Dwell(s) = it {
                out.push(ops::feedstop(*s));
            }
            continue;
        };
        let (kind, tech) = match m.kind {
            MoveKind::Rapid => (ToolpathType::Connect, None),
            _ if m.feed != first.feed || m.spindle != first.spindle => {
                (ToolpathType::TrajectoryPath, Some(ops::technology(m)))
            }
            _ => (ToolpathType::TrajectoryPath, None),
        };
        if run
            .as_ref()
            .is_some_and(|(k, t, _)| *k != kind || *t != tech)
        {
            close(&mut run, &mut out);
        }
        let (_, _, b) = run.get_or_insert_with(|| (kind, tech, CurveBuilder::default()));
        b.line(shift(m.from), shift(m.to));
    }
    close(&mut run, &mut out);
    out
}

/// A number for a name: no trailing zeros.
fn fmt(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}
