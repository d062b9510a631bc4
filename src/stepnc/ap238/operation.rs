//! AP238 operations, tools, technology, machine functions, toolpaths and
//! their curves.

use super::super::graph::{number, reference, reference_of, refs, string};
use super::Reader;
use crate::stepnc::model::*;
use crate::stepnc::part21::{Instance, Value};

impl<'f> Reader<'f> {
    pub(super) fn operation(&mut self, op: &'f Instance) -> Option<OperationId> {
        let id = string(op, 0);
        let tool = self.tool_of(op)?;
        let (technology, feed_unit) = self
            .related(op, "MACHINING_TECHNOLOGY_RELATIONSHIP")
            .map(|t| self.technology(t))
            .unwrap_or_default();
        if let Some((unit_mm, span)) = feed_unit {
            let tool = &self.p.tools[tool.0 as usize];
            let (d, name) = (tool.body.dimension.diameter, tool.id.clone());
            let doubt = super::plausible::doubt(&technology, d, unit_mm);
            if let Some(d) = doubt {
                self.diags.push(d.diagnostic(&name, span));
            }
        }
        let machine_functions = self
            .related(op, "MACHINING_FUNCTIONS_RELATIONSHIP")
            .map(|m| self.functions(m))
            .unwrap_or_default();
        let mut rels = self
            .g
            .referring(op.id, "MACHINING_TOOLPATH_SEQUENCE_RELATIONSHIP", 2);
        rels.sort_by(|a, b| {
            let key = |i: &Instance| i.params.get(4).and_then(number).unwrap_or(0.0);
            key(a).total_cmp(&key(b))
        });
        let mut toolpaths = Vec::new();
        for rel in rels {
            self.g.touch(rel);
            if let Some(tp) = reference(rel, 3).and_then(|t| self.g.get(t)) {
                if let Some(t) = self.toolpath(tp) {
                    toolpaths.push(t);
                }
            }
        }
        if toolpaths.is_empty() {
            self.skip(
                format!("{} `{id}` has no cutter-location toolpath cncc reads: feature-level operations are not run", op.entity),
                op.span,
            );
            return None;
        }
        if op.entity != "FREEFORM_MILLING_OPERATION" {
            self.skip(
                format!("{} `{id}`: only its toolpaths are read", op.entity),
                op.span,
            );
        }
        for (name, prop, _) in self.properties(op.id) {
            self.skip(format!("operation property `{name}`"), prop.span);
        }
        let oid = OperationId(self.p.operations.len() as u32);
        self.p.operations.push(Operation {
            id,
            toolpath: Some(toolpaths),
            tool_direction: None,
            retract_plane: None,
            start_point: None,
            tool,
            technology,
            machine_functions,
            overcut_length: None,
            kind: OperationKind::Freeform {
                approach: None,
                retract: None,
                strategy: None,
            },
        });
        Some(oid)
    }

    /// The instance a relationship of `entity` relates `of` to.
    fn related(&self, of: &Instance, entity: &str) -> Option<&'f Instance> {
        let rel = self.g.referring(of.id, entity, 2);
        let rel = rel.first()?;
        self.g.touch(rel);
        self.g.get(reference(rel, 3)?)
    }

    /// The MACHINING_TOOL whose usage lists the operation.
    fn tool_of(&mut self, op: &'f Instance) -> Option<ToolId> {
        let tool = self
            .g
            .referring(op.id, "MACHINING_TOOL", 2)
            .into_iter()
            .next();
        let Some(tool) = tool else {
            self.skip(
                format!(
                    "{} `{}` names no MACHINING_TOOL: not run",
                    op.entity,
                    string(op, 0)
                ),
                op.span,
            );
            return None;
        };
        if let Some(&t) = self.tools.get(&tool.id) {
            return Some(t);
        }
        self.g.touch(tool);
        if let Some(k) = reference(tool, 3) {
            self.g.get(k);
        }
        let desc = string(tool, 1);
        if !known_body(&desc) {
            self.skip(
                format!(
                    "tool `{}` described `{desc}`: read as an end mill",
                    string(tool, 0)
                ),
                tool.span,
            );
        }
        let mut dim = ToolDimension::default();
        let mut length = None;
        for prop in self.g.referring(tool.id, "RESOURCE_PROPERTY", 2) {
            self.g.touch(prop);
            for rpr in self
                .g
                .referring(prop.id, "RESOURCE_PROPERTY_REPRESENTATION", 2)
            {
                self.g.touch(rpr);
                let name = string(rpr, 0).to_ascii_lowercase();
                let Some(value) = reference(rpr, 3)
                    .and_then(|r| self.g.get(r))
                    .and_then(|rep| self.measure_of(rep))
                else {
                    self.skip(
                        format!("tool property `{name}` with no measure in a unit cncc reads"),
                        rpr.span,
                    );
                    continue;
                };
                match name.as_str() {
                    "effective cutting diameter" => dim.diameter = value,
                    "corner radius" => dim.edge_radius = Some(value),
                    "corner radius center vertical" => dim.edge_center_vertical = Some(value),
                    "corner radius center horizontal" => dim.edge_center_horizontal = Some(value),
                    "overall assembly length" => length = Some(value),
                    "flute length" | "cutting edge length" => dim.cutting_edge_length = Some(value),
                    "point angle" | "tip angle" => dim.tip_half_angle = Some(value / 2.0),
                    _ => self.skip(format!("tool property `{name}`"), rpr.span),
                }
            }
        }
        let t = ToolId(self.p.tools.len() as u32);
        self.p.tools.push(Tool {
            id: string(tool, 0),
            body: ToolBody {
                kind: body_kind(&desc),
                dimension: dim,
                number_of_teeth: None,
                hand_of_cut: None,
                coolant_through_tool: None,
                pilot_length: None,
                extra: Vec::new(),
            },
            cutting_edges: Vec::new(),
            overall_assembly_length: length,
            direction_for_spindle_orientation: None,
            holder_diameter_for_spindle_orientation: None,
        });
        self.tools.insert(tool.id, t);
        Some(t)
    }

    /// The first measure item of a representation, as mm (lengths, each
    /// by its own declared unit) or degrees (angles: the file's unit is
    /// taken as degrees [?]); None for a length in a unit cncc cannot
    /// resolve (never taken as mm unsaid).
    fn measure_of(&self, rep: &Instance) -> Option<f64> {
        for item in refs(rep, 1).into_iter().filter_map(|r| self.g.get(r)) {
            let Some((v, unit)) = self.g.measure(item) else {
                continue;
            };
            let is_length = self
                .g
                .get(unit)
                .is_some_and(|u| self.g.part(u, "LENGTH_UNIT").is_some());
            return match self.g.length_mm(unit, 0) {
                Some(mm) => Some(v * mm),
                None if is_length => None,
                None => Some(v),
            };
        }
        None
    }

    /// A rate measure of a representation, per minute (mm or rev), with
    /// its length unit (mm per unit) and where the item is.
    fn rate_of(&self, rep: &Instance) -> Option<(f64, f64, crate::span::Span)> {
        for item in refs(rep, 1).into_iter().filter_map(|r| self.g.get(r)) {
            let Some((v, unit)) = self.g.measure(item) else {
                continue;
            };
            self.g.get(unit);
            let (factor, length) = self.g.per_minute(unit)?;
            return Some((v * factor, length, item.span));
        }
        None
    }

    /// The technology, and the feed's length unit (mm per unit) with the
    /// feed item's place.
    fn technology(&mut self, t: &'f Instance) -> (Technology, Option<(f64, crate::span::Span)>) {
        let mut tech = Technology {
            feed_at_tcp: true,
            ..Technology::default()
        };
        let mut feed_unit = None;
        for (name, prop, rep) in self.properties(t.id) {
            self.use_property(prop, rep);
            let value = rep.and_then(|r| self.rate_of(r));
            match (name.as_str(), value) {
                ("feedrate", Some((v, unit, span))) => {
                    tech.feed = Some(v);
                    feed_unit = Some((unit, span));
                }
                // ISO 14649's sign: positive = counter-clockwise (M4).
                ("spindle", Some((v, _, _))) => tech.spindle = Some(-v),
                _ => self.skip(format!("technology property `{name}`"), prop.span),
            }
        }
        (tech, feed_unit)
    }

    fn functions(&mut self, m: &'f Instance) -> MachineFunctions {
        let mut f = MachineFunctions::default();
        for (name, prop, rep) in self.properties(m.id) {
            self.use_property(prop, rep);
            let text = rep
                .map(|r| self.items(r).0)
                .unwrap_or_default()
                .iter()
                .find(|i| i.entity == "DESCRIPTIVE_REPRESENTATION_ITEM")
                .map(|i| string(i, 1).to_ascii_lowercase())
                .unwrap_or_default();
            let on = text.ends_with(" on") || text == "on";
            match name.as_str() {
                "coolant" => f.coolant = on,
                "chip removal" => f.chip_removal = on,
                "through spindle coolant" => f.through_spindle_coolant = on,
                "mist" => f.mist = Some(on),
                _ => self.skip(format!("machine function `{name}`"), prop.span),
            }
        }
        f
    }

    fn toolpath(&mut self, tp: &'f Instance) -> Option<Toolpath> {
        let desc = string(tp, 1);
        if !desc.eq_ignore_ascii_case("cutter location trajectory") {
            self.skip(format!("toolpath `{}` ({desc})", string(tp, 0)), tp.span);
            return None;
        }
        let technology = self
            .related(tp, "MACHINING_TECHNOLOGY_RELATIONSHIP")
            .map(|t| self.technology(t).0);
        let mut curve = None;
        for (name, prop, rep) in self.properties(tp.id) {
            if name != "basic curve" {
                self.skip(format!("toolpath property `{name}`"), prop.span);
                continue;
            }
            self.use_property(prop, rep);
            if let Some(rep) = rep {
                let (items, mm) = self.items(rep);
                curve = items.first().and_then(|c| self.curve(c, mm, 0));
            }
        }
        let Some(curve) = curve else {
            self.skip(
                format!("toolpath `{}` has no basic curve cncc reads", string(tp, 0)),
                tp.span,
            );
            return None;
        };
        Some(crate::raise::ops::trajectory(
            curve,
            technology,
            ToolpathType::TrajectoryPath,
        ))
    }

    fn pt(&self, r: Option<u64>, mm: f64) -> Option<Point> {
        let i = self.g.get(r?)?;
        Some(Point {
            name: string(i, 0),
            xyz: self.point(i, mm)?,
        })
    }

    /// A curve in the representation's unit (`mm` per unit).
    fn curve(&mut self, c: &'f Instance, mm: f64, depth: u32) -> Option<Curve> {
        match c.entity.as_str() {
            "POLYLINE" => {
                let points: Option<Vec<Point>> = refs(c, 1)
                    .into_iter()
                    .map(|r| self.pt(Some(r), mm))
                    .collect();
                Some(Curve::Polyline {
                    name: string(c, 0),
                    points: points?,
                })
            }
            "COMPOSITE_CURVE" if depth < 8 => {
                let mut segments = Vec::new();
                let segs: Vec<&'f Instance> = refs(c, 1)
                    .into_iter()
                    .filter_map(|r| self.g.get(r))
                    .collect();
                for s in segs {
                    let parent = reference(s, 2).and_then(|p| self.g.get(p))?;
                    segments.push(CompositeSegment {
                        transition: match s.params.first().map(|p| &p.value) {
                            Some(Value::Enum(e)) => e.clone(),
                            _ => "CONTINUOUS".into(),
                        },
                        same_sense: !matches!(
                            s.params.get(1).map(|p| &p.value),
                            Some(Value::Enum(e)) if e == "F"
                        ),
                        curve: self.curve(parent, mm, depth + 1)?,
                    });
                }
                Some(Curve::Composite {
                    name: string(c, 0),
                    segments,
                    self_intersect: None,
                })
            }
            "TRIMMED_CURVE" => self.trimmed(c, mm),
            other => {
                self.skip(
                    format!("curve {other} (not read: its toolpath is left out)"),
                    c.span,
                );
                None
            }
        }
    }

    /// A TRIMMED_CURVE of a LINE or CIRCLE, trimmed by cartesian points.
    fn trimmed(&mut self, c: &'f Instance, mm: f64) -> Option<Curve> {
        let basis = self.g.get(reference(c, 1)?)?;
        let trim = |k: usize| -> Option<u64> {
            match &c.params.get(k)?.value {
                Value::List(l) => l.iter().find_map(reference_of),
                _ => None,
            }
        };
        let (start, end) = (self.pt(trim(2), mm)?, self.pt(trim(3), mm)?);
        let sense = !matches!(c.params.get(4).map(|p| &p.value), Some(Value::Enum(e)) if e == "F");
        match basis.entity.as_str() {
            "LINE" => {
                for k in [1, 2] {
                    if let Some(r) = reference(basis, k) {
                        self.g.get(r);
                    }
                }
                if let Some(d) = reference(basis, 2)
                    .and_then(|v| self.g.f.get(v))
                    .and_then(|v| reference(v, 1))
                {
                    self.g.get(d);
                }
                let basis = line_basis(&start, &end);
                Some(Curve::Line {
                    name: string(c, 0),
                    start,
                    end,
                    basis,
                })
            }
            "CIRCLE" => {
                let place = self.g.get(reference(basis, 1)?)?;
                let centre = self.pt(reference(place, 1), mm)?;
                let dir = |k: usize| -> Option<Direction> {
                    let d = self.g.get(reference(place, k)?)?;
                    let Value::List(r) = &d.params.get(1)?.value else {
                        return None;
                    };
                    let v: Vec<f64> = r.iter().filter_map(number).collect();
                    Some(Direction {
                        name: string(d, 0),
                        ratios: [*v.first()?, *v.get(1)?, *v.get(2)?],
                    })
                };
                Some(Curve::Arc {
                    name: string(c, 0),
                    circle: Axis2Placement {
                        name: string(place, 0),
                        location: centre,
                        axis: dir(2),
                        ref_direction: dir(3),
                    },
                    circle_name: string(basis, 0),
                    radius: basis.params.get(2).and_then(number)? * mm,
                    start,
                    end,
                    sense,
                })
            }
            other => {
                self.skip(
                    format!("trimmed {other} (not read: its toolpath is left out)"),
                    c.span,
                );
                None
            }
        }
    }
}

/// The LINE a trimmed line lies on, in mm, pointing from `start` to
/// `end` (the file's own LINE may be in another unit).
fn line_basis(start: &Point, end: &Point) -> Raw {
    let d: Vec<f64> = (0..3).map(|k| end.xyz[k] - start.xyz[k]).collect();
    let len = d.iter().map(|v| v * v).sum::<f64>().sqrt();
    let ratios = d
        .iter()
        .map(|v| RawValue::Real(if len > 0.0 { v / len } else { 0.0 }))
        .collect();
    let inst = |entity: &str, params: Vec<RawValue>| {
        RawValue::Instance(Box::new(Raw {
            entity: entity.into(),
            params,
        }))
    };
    let point = inst(
        "CARTESIAN_POINT",
        vec![
            RawValue::String(String::new()),
            RawValue::List(start.xyz.iter().map(|v| RawValue::Real(*v)).collect()),
        ],
    );
    let direction = inst(
        "DIRECTION",
        vec![RawValue::String(String::new()), RawValue::List(ratios)],
    );
    let vector = inst(
        "VECTOR",
        vec![
            RawValue::String(String::new()),
            direction,
            RawValue::Real(len),
        ],
    );
    Raw {
        entity: "LINE".into(),
        params: vec![RawValue::String(String::new()), point, vector],
    }
}

/// The tool body a MACHINING_TOOL's description names [?: AP238 gives
/// the kind as text; these are STEP-NC Maker's words]; an end mill when
/// it names none cncc knows.
fn body_kind(desc: &str) -> ToolBodyKind {
    let d = desc.to_ascii_lowercase();
    if d.contains("ball") {
        ToolBodyKind::BallEndmill
    } else if d.contains("bullnose") {
        ToolBodyKind::BullnoseEndmill
    } else if d.contains("face") {
        ToolBodyKind::Facemill
    } else if d.contains("center drill") || d.contains("centre drill") {
        ToolBodyKind::CenterDrill
    } else if d.contains("drill") {
        ToolBodyKind::TwistDrill
    } else if d.contains("end mill") || d.contains("endmill") || d.contains("milling tool") {
        ToolBodyKind::Endmill
    } else {
        ToolBodyKind::Endmill
    }
}

/// Whether [`body_kind`] recognised the description.
fn known_body(desc: &str) -> bool {
    let d = desc.to_ascii_lowercase();
    [
        "ball",
        "bullnose",
        "face",
        "drill",
        "end mill",
        "endmill",
        "milling tool",
    ]
    .iter()
    .any(|w| d.contains(w))
}
