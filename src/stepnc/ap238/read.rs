//! The descent from `MACHINING_PROJECT` to cutter-location points (see
//! the module note of [`super`]).

use super::graph::{number, reference, refs, string, Graph};
use crate::diag::{Code, Diagnostic};
use crate::span::Span;
use crate::stepnc::model::*;
use crate::stepnc::part21::{Instance, P21File, Value};
use std::collections::HashMap;

pub struct Reader<'f> {
    g: Graph<'f>,
    p: Project,
    diags: Vec<Diagnostic>,
    /// What was not read, by description, with the first place.
    skipped: Vec<(String, Span)>,
    tools: HashMap<u64, ToolId>,
    /// Workplans being read (a workplan listing itself is not followed).
    open_plans: Vec<u64>,
    /// Workplans read so far (each read once; a file listing many
    /// elements many times cannot blow up).
    plans_read: usize,
}

fn plane_at(name: &str, z: f64) -> Plane {
    Plane {
        name: name.into(),
        position: crate::raise::project::placement(name, [0.0, 0.0, z]),
    }
}

impl<'f> Reader<'f> {
    pub fn new(f: &'f P21File) -> Self {
        Reader {
            g: Graph::new(f),
            p: Project::default(),
            diags: Vec::new(),
            skipped: Vec::new(),
            tools: HashMap::new(),
            open_plans: Vec::new(),
            plans_read: 0,
        }
    }

    fn skip(&mut self, what: String, span: Span) {
        if !self.skipped.iter().any(|(w, _)| *w == what) {
            self.skipped.push((what, span));
        }
    }

    pub fn project(mut self) -> (Option<Project>, Vec<Diagnostic>) {
        let projects = self.g.all("MACHINING_PROJECT");
        let Some(root) = projects.first() else {
            let d = Diagnostic::new(
                Code::StepncModel,
                "the AP238 file has no MACHINING_PROJECT instance",
            )
            .help("an AP238 programme starts at a MACHINING_PROJECT");
            return (None, vec![d]);
        };
        self.g.touch(root);
        self.p.id = string(root, 0);
        self.workpieces();
        let plans: Vec<&Instance> = self
            .g
            .all("MACHINING_WORKPLAN")
            .into_iter()
            .filter(|w| {
                self.g
                    .referring(w.id, "MACHINING_PROCESS_SEQUENCE_RELATIONSHIP", 3)
                    .is_empty()
            })
            .collect();
        let Some(main) = plans.first() else {
            let d = Diagnostic::new(Code::StepncModel, "the AP238 file has no main MACHINING_WORKPLAN")
                .primary(root.span, "this project")
                .help("the main workplan is the MACHINING_WORKPLAN no process sequence relationship lists");
            return (None, vec![d]);
        };
        self.p.main_workplan = self.workplan(main, 0);
        self.report_unused();
        let Reader {
            p,
            mut diags,
            skipped,
            ..
        } = self;
        for (what, span) in skipped {
            diags.push(
                Diagnostic::new(Code::Ap238NotRead, format!("AP238: {what}"))
                    .primary(span, "here")
                    .help("see `cncc explain W0807` for what cncc reads of AP238"),
            );
        }
        let ok = !diags.iter().any(Diagnostic::is_error);
        (ok.then_some(p), diags)
    }

    fn report_unused(&mut self) {
        let mut names: Vec<(String, usize, Span)> = Vec::new();
        for i in self.g.unused() {
            if BOOKKEEPING.contains(&i.entity.as_str()) || i.entity.ends_with("_CONTEXT") {
                continue;
            }
            match names.iter_mut().find(|(n, _, _)| *n == i.entity) {
                Some(e) => e.1 += 1,
                None => names.push((i.entity.clone(), 1, i.span)),
            }
        }
        if let Some((_, _, span)) = names.first() {
            let list: Vec<String> = names.iter().map(|(n, k, _)| format!("{n} ×{k}")).collect();
            let span = *span;
            self.skip(
                format!(
                    "instances not read (left out of the plan): {}",
                    list.join(", ")
                ),
                span,
            );
        }
    }

    fn workpieces(&mut self) {
        for rel in self.g.all("MACHINING_PROJECT_WORKPIECE_RELATIONSHIP") {
            self.g.touch(rel);
            let name = reference(rel, 4)
                .and_then(|pd| self.g.get(pd))
                .and_then(|pd| self.g.get(reference(pd, 2)?))
                .and_then(|pdf| self.g.get(reference(pdf, 2)?))
                .map(|prod| string(prod, 0));
            if let Some(id) = name {
                let wid = WorkpieceId(self.p.workpieces.len() as u32);
                self.p.workpieces.push(workpiece(id));
                self.p.its_workpieces.push(wid);
            }
        }
        if self.p.workpieces.is_empty() {
            self.p.workpieces.push(workpiece("workpiece".into()));
            self.p.its_workpieces.push(WorkpieceId(0));
        }
    }

    fn workplan(&mut self, wp: &'f Instance, depth: u32) -> Workplan {
        self.g.touch(wp);
        self.open_plans.push(wp.id);
        self.plans_read += 1;
        let mut rels = self
            .g
            .referring(wp.id, "MACHINING_PROCESS_SEQUENCE_RELATIONSHIP", 2);
        rels.sort_by(|a, b| {
            let key = |i: &Instance| i.params.get(4).and_then(number).unwrap_or(0.0);
            key(a).total_cmp(&key(b))
        });
        let mut elements = Vec::new();
        for rel in rels {
            self.g.touch(rel);
            let Some(e) = reference(rel, 3).and_then(|e| self.g.get(e)) else {
                continue;
            };
            match e.entity.as_str() {
                "MACHINING_WORKINGSTEP" => {
                    if let Some(ws) = self.workingstep(e) {
                        elements.push(Executable::Workingstep(ws));
                    }
                }
                "MACHINING_WORKPLAN"
                    if depth < 32
                        && !self.open_plans.contains(&e.id)
                        && self.plans_read < 10_000 =>
                {
                    elements.push(Executable::Workplan(self.workplan(e, depth + 1)))
                }
                other => {
                    self.skip(format!("executable {other} `{}`", string(e, 0)), e.span);
                    elements.push(Executable::Other(Raw {
                        entity: other.to_string(),
                        params: vec![RawValue::String(string(e, 0))],
                    }));
                }
            }
        }
        self.open_plans.pop();
        Workplan {
            id: string(wp, 0),
            elements,
            ..Workplan::default()
        }
    }

    /// The ACTION_PROPERTY instances on `id`, with their representation
    /// (through ACTION_PROPERTY_REPRESENTATION), by property name.
    fn properties(&self, id: u64) -> Vec<(String, &'f Instance, Option<&'f Instance>)> {
        self.g
            .referring(id, "ACTION_PROPERTY", 2)
            .into_iter()
            .map(|prop| {
                let rep = self
                    .g
                    .referring(prop.id, "ACTION_PROPERTY_REPRESENTATION", 2)
                    .first()
                    .and_then(|apr| reference(apr, 3));
                (
                    string(prop, 0).to_ascii_lowercase(),
                    prop,
                    rep.and_then(|r| self.g.f.get(r)),
                )
            })
            .collect()
    }

    /// Marks a property, its representation link and representation used.
    fn use_property(&self, prop: &Instance, rep: Option<&Instance>) {
        self.g.touch(prop);
        for apr in self
            .g
            .referring(prop.id, "ACTION_PROPERTY_REPRESENTATION", 2)
        {
            self.g.touch(apr);
        }
        if let Some(r) = rep {
            self.g.touch(r);
        }
    }

    /// The representation's items (used) and its length unit, mm.
    fn items(&self, rep: &Instance) -> (Vec<&'f Instance>, f64) {
        let items = refs(rep, 1)
            .into_iter()
            .filter_map(|r| self.g.get(r))
            .collect();
        (items, self.g.context_mm(reference(rep, 2)))
    }

    fn workingstep(&mut self, ws: &'f Instance) -> Option<MachiningWorkingstep> {
        let id = string(ws, 0);
        let op_inst = self
            .g
            .referring(ws.id, "MACHINING_OPERATION_RELATIONSHIP", 2)
            .into_iter()
            .next();
        let Some(op_inst) = op_inst.and_then(|r| {
            self.g.touch(r);
            self.g.get(reference(r, 3)?)
        }) else {
            self.skip(format!("workingstep `{id}` with no operation"), ws.span);
            return None;
        };
        let operation = self.operation(op_inst)?;
        let feature = self.feature(ws, operation);
        // AP238 gives the plane in workpiece coordinates; the ARM model
        // holds it in the feature's frame (ISO 14649-10), which the
        // feature's placement (a translation) shifts.
        let mut secplane = self.secplane(ws, operation);
        let origin = self.p.features[feature.index()].placement.location.xyz;
        secplane.position.location.xyz[2] -= origin[2];
        Some(MachiningWorkingstep {
            id,
            secplane,
            feature,
            operation,
            effect: None,
        })
    }

    /// The workingstep's security plane, or (none given) the highest
    /// point of its toolpaths, said in a warning.
    fn secplane(&mut self, ws: &'f Instance, op: OperationId) -> Plane {
        for (name, prop, rep) in self.properties(ws.id) {
            if !name.contains("security plane") {
                continue;
            }
            self.use_property(prop, rep);
            if let Some(rep) = rep {
                let (items, mm) = self.items(rep);
                for it in items {
                    if let Some(z) = self.placement_z(it) {
                        return plane_at("SECURITY PLANE", z * mm);
                    }
                }
            }
        }
        let clear = crate::post::plan::DEFAULT_SDIS;
        let top = toolpath_top(self.p.operation(op)).unwrap_or(0.0) + clear;
        self.skip(
            format!(
                "workingstep `{}` gives no security plane: taken {clear} mm above the highest point of its toolpaths (Z{top}), the post's clearance for a missing retract plane",
                string(ws, 0)
            ),
            ws.span,
        );
        plane_at("SECURITY PLANE", top)
    }

    /// The z of a PLANE's or AXIS2_PLACEMENT_3D's location.
    fn placement_z(&self, it: &Instance) -> Option<f64> {
        let place = match it.entity.as_str() {
            "PLANE" => self.g.get(reference(it, 1)?)?,
            "AXIS2_PLACEMENT_3D" => it,
            _ => return None,
        };
        let pt = self.g.get(reference(place, 1)?)?;
        self.point(pt, 1.0).map(|p| p[2])
    }

    fn point(&self, pt: &Instance, mm: f64) -> Option<P3> {
        self.g.touch(pt);
        let Value::List(c) = &pt.params.get(1)?.value else {
            return None;
        };
        let v: Vec<f64> = c.iter().filter_map(number).collect();
        Some([
            v.first().copied()? * mm,
            v.get(1).copied().unwrap_or(0.0) * mm,
            v.get(2).copied().unwrap_or(0.0) * mm,
        ])
    }

    /// The workingstep's feature, as a toolpath feature (its geometry is
    /// not read) placed where its shape representation says.
    fn feature(&mut self, ws: &'f Instance, op: OperationId) -> FeatureId {
        let inst = self
            .g
            .referring(ws.id, "MACHINING_FEATURE_RELATIONSHIP", 2)
            .first()
            .and_then(|r| {
                self.g.touch(r);
                self.g.get(reference(r, 3)?)
            })
            .and_then(|mfp| {
                let pp = self.g.referring(mfp.id, "PROPERTY_PROCESS", 2);
                let pp = pp.first()?;
                self.g.touch(pp);
                let ppa = self.g.referring(pp.id, "PROCESS_PROPERTY_ASSOCIATION", 2);
                let ppa = ppa.first()?;
                self.g.touch(ppa);
                self.g.get(reference(ppa, 3)?)
            });
        let mut origin = [0.0; 3];
        let mut name = format!("{} FEATURE", string(ws, 0));
        if let Some(f) = inst {
            if !string(f, 0).is_empty() {
                name = string(f, 0);
            }
            if let Some(z) = self.feature_origin(f) {
                origin = z;
            }
            let kind = string(f, 1);
            if !kind.eq_ignore_ascii_case("toolpath") {
                self.skip(
                    format!(
                        "{} `{}` ({kind}): its feature geometry is not read, only its toolpaths",
                        f.entity, name
                    ),
                    f.span,
                );
            }
        }
        let fid = FeatureId(self.p.features.len() as u32);
        let bottom = toolpath_bottom(self.p.operation(op)).unwrap_or(0.0);
        self.p.features.push(Feature {
            id: name.clone(),
            workpiece: WorkpieceId(0),
            operations: vec![op],
            placement: crate::raise::project::placement(&name, origin),
            depth: Some(plane_at(&format!("{name} DEPTH"), bottom - origin[2])),
            kind: FeatureKind::ToolpathFeature,
        });
        fid
    }

    /// A feature's placement origin, through PRODUCT_DEFINITION_SHAPE →
    /// SHAPE_DEFINITION_REPRESENTATION → its representation.
    fn feature_origin(&self, f: &Instance) -> Option<P3> {
        let pds = self.g.referring(f.id, "PRODUCT_DEFINITION_SHAPE", 2);
        let pds = pds.first()?;
        self.g.touch(pds);
        let sdr = self
            .g
            .referring(pds.id, "SHAPE_DEFINITION_REPRESENTATION", 0);
        let sdr = sdr.first()?;
        self.g.touch(sdr);
        let rep = self.g.get(reference(sdr, 1)?)?;
        let (items, mm) = self.items(rep);
        let place = items
            .into_iter()
            .find(|i| i.entity == "AXIS2_PLACEMENT_3D")?;
        for k in [2, 3] {
            if let Some(d) = reference(place, k) {
                self.g.get(d);
            }
        }
        let pt = self.g.get(reference(place, 1)?)?;
        self.point(pt, mm)
    }
}

/// AIM instances that only tie products, contexts and unit dimensions
/// together: not reported as unread.
const BOOKKEEPING: &[&str] = &[
    "PRODUCT_DEFINITION",
    "PRODUCT_DEFINITION_FORMATION",
    "PRODUCT",
    "PROCESS_PRODUCT_ASSOCIATION",
    "PRODUCT_DEFINITION_PROCESS",
    "DIMENSIONAL_EXPONENTS",
    "NAME_ATTRIBUTE",
    "ACTION_RESOURCE_TYPE",
];

fn workpiece(id: String) -> Workpiece {
    Workpiece {
        id,
        material: None,
        global_tolerance: None,
        rawpiece: None,
        geometry: None,
        bounding: None,
        clamping_positions: Vec::new(),
    }
}

/// Every point of an operation's toolpaths.
fn toolpath_points(op: &Operation) -> Vec<P3> {
    let mut out = Vec::new();
    for tp in op.toolpath.iter().flatten() {
        if let Toolpath::CutterLocation { basic_curve, .. } = tp {
            curve_points(basic_curve, &mut out);
        }
    }
    out
}

fn curve_points(c: &Curve, out: &mut Vec<P3>) {
    match c {
        Curve::Polyline { points, .. } => out.extend(points.iter().map(|p| p.xyz)),
        Curve::Arc { start, end, .. } | Curve::Line { start, end, .. } => {
            out.push(start.xyz);
            out.push(end.xyz);
        }
        Curve::Composite { segments, .. } => {
            for s in segments {
                curve_points(&s.curve, out);
            }
        }
        Curve::Other(_) => {}
    }
}

fn toolpath_top(op: &Operation) -> Option<f64> {
    toolpath_points(op).iter().map(|p| p[2]).reduce(f64::max)
}

fn toolpath_bottom(op: &Operation) -> Option<f64> {
    toolpath_points(op).iter().map(|p| p[2]).reduce(f64::min)
}

#[path = "operation.rs"]
mod operation;
#[path = "plausible.rs"]
mod plausible;
