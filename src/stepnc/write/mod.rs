//! Typed model → Part 21 text. Equal value objects (points, directions,
//! placements, technology...) are written once and shared; the project's
//! arenas (workpieces, features, operations, tools) are written once each.
//! Numbering is stable: depth-first from the PROJECT (#1), following
//! parameters in order. Each instance is held as its text in a compact
//! graph ([`graph`]) and streamed out once numbered.

mod feature;
mod geom;
mod graph;
mod operation;
mod structure;
mod tool;
mod toolpath;

use super::model::*;
use super::part21::text::{push_real, push_string, write_record, write_value};
use super::part21::{Param, Record, Value};
use crate::span::Span;
use std::collections::HashMap;

/// The Part 21 text of a project.
pub fn write_project(p: &Project) -> String {
    write_project_with_header(p, &[])
}

/// The Part 21 text of a project, keeping the FILE_DESCRIPTION and
/// FILE_NAME of the file it was read from (FILE_SCHEMA is always cncc's).
pub fn write_project_with_header(p: &Project, original: &[Record]) -> String {
    let mut out = Vec::new();
    // Writing into memory cannot fail.
    let _ = write_project_to(p, original, &mut out);
    // Every piece written is a `&str`, so the bytes are UTF-8.
    String::from_utf8(out).unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned())
}

/// Writes the Part 21 text of a project to `out` (see
/// [`write_project_with_header`]) without holding the text in memory.
pub fn write_project_to<O: std::io::Write + ?Sized>(
    p: &Project,
    original: &[Record],
    out: &mut O,
) -> std::io::Result<()> {
    let timer = graph::PhaseTimer::new();
    let (graph, root) = W::new(p, Vec::new()).build();
    timer.phase("build graph");
    write_graph(graph, root, &p.id, original, out)?;
    timer.phase("number and write");
    Ok(())
}

/// [`write_project_to`] for a project that is not needed afterwards:
/// each operation's toolpath is dropped as soon as it is written and the
/// rest of the project before the numbering, so the model and its text
/// are never both held whole. The text is the same.
pub fn write_owned_project_to<O: std::io::Write + ?Sized>(
    mut p: Project,
    original: &[Record],
    out: &mut O,
) -> std::io::Result<()> {
    let timer = graph::PhaseTimer::new();
    let toolpaths = p.operations.iter_mut().map(|o| o.toolpath.take());
    let toolpaths = toolpaths.collect();
    let (graph, root) = W::new(&p, toolpaths).build();
    timer.phase("build graph");
    let name = std::mem::take(&mut p.id);
    drop(p);
    write_graph(graph, root, &name, original, out)?;
    timer.phase("number and write");
    Ok(())
}

/// The header (the project's `name`, with the FILE_DESCRIPTION and
/// FILE_NAME of `original` when given) and the instances, numbered.
fn write_graph<O: std::io::Write + ?Sized>(
    graph: graph::Graph,
    root: Option<u64>,
    name: &str,
    original: &[Record],
    out: &mut O,
) -> std::io::Result<()> {
    let Some(root) = root else {
        return Ok(());
    };
    let mut head = header(name);
    for r in head.iter_mut() {
        if r.entity == "FILE_SCHEMA" {
            continue;
        }
        if let Some(o) = original.iter().find(|o| o.entity == r.entity) {
            r.params = o.params.clone();
        }
    }
    let mut text = String::from("ISO-10303-21;\nHEADER;\n");
    for r in &head {
        write_record(&mut text, r);
        text.push_str(";\n");
    }
    text.push_str("ENDSEC;\nDATA;\n");
    out.write_all(text.as_bytes())?;
    graph.write_numbered(root, out)?;
    out.write_all(b"ENDSEC;\nEND-ISO-10303-21;\n")
}

fn header(name: &str) -> Vec<Record> {
    let rec = |entity: &str, params: Vec<Value>| Record {
        entity: entity.to_string(),
        params: params.into_iter().map(Param::new).collect(),
        span: Span::default(),
    };
    vec![
        rec(
            "FILE_DESCRIPTION",
            vec![
                list(vec![s("ISO 14649 programme written by cncc")]),
                s("2;1"),
            ],
        ),
        rec(
            "FILE_NAME",
            vec![
                s(name),
                s(""),
                list(vec![s("")]),
                list(vec![s("")]),
                s("cncc"),
                s(""),
                s(""),
            ],
        ),
        rec(
            "FILE_SCHEMA",
            vec![list(vec![s("MACHINING_SCHEMA"), s("MILLING_SCHEMA")])],
        ),
    ]
}

/// The writer: the project being written and the instance graph so far.
pub(crate) struct W<'p> {
    pub p: &'p Project,
    graph: graph::Graph,
    pub workpieces: HashMap<WorkpieceId, u64>,
    pub features: HashMap<FeatureId, u64>,
    pub operations: HashMap<OperationId, u64>,
    pub tools: HashMap<ToolId, u64>,
    /// Operations' toolpaths taken out of the project, by operation
    /// index: each is dropped once written (empty: they are in the
    /// project).
    toolpaths: Vec<Option<Vec<Toolpath>>>,
}

impl<'p> W<'p> {
    fn new(p: &'p Project, toolpaths: Vec<Option<Vec<Toolpath>>>) -> Self {
        W {
            p,
            graph: graph::Graph::default(),
            workpieces: HashMap::new(),
            features: HashMap::new(),
            operations: HashMap::new(),
            tools: HashMap::new(),
            toolpaths,
        }
    }

    /// The instance graph from the PROJECT, and the PROJECT's number.
    fn build(mut self) -> (graph::Graph, Option<u64>) {
        let root = match self.project() {
            Value::Ref(n) => Some(n),
            _ => None,
        };
        (self.graph, root)
    }

    /// An operation's toolpath taken out of the project, if it was.
    pub fn take_toolpath(&mut self, id: OperationId) -> Option<Vec<Toolpath>> {
        self.toolpaths.get_mut(id.index()).and_then(Option::take)
    }

    /// A value instance, shared with an equal one already written.
    pub fn add(&mut self, entity: &str, params: Vec<Value>) -> Value {
        let text = self.graph.scratch();
        write_values(text, entity, &params);
        Value::Ref(self.graph.add_scratch_shared())
    }

    /// `ENTITY('name',(r1,r2,...))` (points, directions), shared like
    /// [`W::add`] but written without building values.
    pub fn add_reals(&mut self, entity: &str, name: &str, reals: &[f64]) -> Value {
        let text = self.graph.scratch();
        text.push_str(entity);
        text.push('(');
        push_string(text, name);
        text.push_str(",(");
        for (k, &v) in reals.iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            push_real(text, v);
        }
        text.push_str("))");
        Value::Ref(self.graph.add_scratch_shared())
    }

    /// Reserves a number for an instance whose parameters come later.
    pub fn reserve(&mut self) -> u64 {
        self.graph.reserve()
    }

    pub fn fill(&mut self, id: u64, entity: &str, params: Vec<Value>) {
        let text = self.graph.scratch();
        write_values(text, entity, &params);
        self.graph.fill_from_scratch(id);
    }

    /// A raw subtree written back as instances.
    pub fn raw(&mut self, r: &Raw) -> Value {
        let params = r.params.iter().map(|v| self.raw_value(v)).collect();
        self.add(&r.entity, params)
    }

    pub fn opt_raw(&mut self, r: &Option<Raw>) -> Value {
        match r {
            Some(r) => self.raw(r),
            None => Value::Null,
        }
    }

    pub fn raw_list(&mut self, rs: &[Raw]) -> Value {
        list(rs.iter().map(|r| self.raw(r)).collect())
    }

    pub fn raw_value(&mut self, v: &RawValue) -> Value {
        match v {
            RawValue::Integer(i) => Value::Int(*i),
            RawValue::Real(r) => Value::Real(*r),
            RawValue::String(s) => Value::Str(s.clone()),
            RawValue::Enum(e) => Value::Enum(e.clone()),
            RawValue::Bool(b) => bool_value(*b),
            RawValue::Null => Value::Null,
            RawValue::Derived => Value::Derived,
            RawValue::List(l) => list(l.iter().map(|v| self.raw_value(v)).collect()),
            RawValue::Typed(t, inner) => match (t.as_str(), inner.as_ref()) {
                ("BINARY", RawValue::String(b)) => Value::Binary(b.clone()),
                _ => Value::Typed(t.clone(), Box::new(Param::new(self.raw_value(inner)))),
            },
            RawValue::Instance(r) => self.raw(r),
        }
    }
}

/// `NAME(p1,p2,...)`.
fn write_values(out: &mut String, entity: &str, params: &[Value]) {
    out.push_str(entity);
    out.push('(');
    for (k, v) in params.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        write_value(out, v);
    }
    out.push(')');
}

// ---------------------------------------------------------------- values

pub(crate) fn s(v: &str) -> Value {
    Value::Str(v.to_string())
}

pub(crate) fn r(v: f64) -> Value {
    Value::Real(v)
}

pub(crate) fn or(v: Option<f64>) -> Value {
    v.map_or(Value::Null, Value::Real)
}

pub(crate) fn bool_value(b: bool) -> Value {
    Value::Enum(if b { "T" } else { "F" }.to_string())
}

pub(crate) fn ob(v: Option<bool>) -> Value {
    v.map_or(Value::Null, bool_value)
}

pub(crate) fn e(v: &str) -> Value {
    Value::Enum(v.to_string())
}

pub(crate) fn oe(v: Option<&str>) -> Value {
    v.map_or(Value::Null, e)
}

pub(crate) fn list(v: Vec<Value>) -> Value {
    Value::List(v.into_iter().map(Param::new).collect())
}

pub(crate) fn opt(v: Option<Value>) -> Value {
    v.unwrap_or(Value::Null)
}
