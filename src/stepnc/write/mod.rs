//! Typed model → generic Part 21 graph → text. Equal value objects
//! (points, directions, placements, technology...) are written once and
//! shared; the project's arenas (workpieces, features, operations, tools)
//! are written once each. Numbering is stable: depth-first from the
//! PROJECT (#1), following parameters in order.

mod feature;
mod geom;
mod operation;
mod structure;

use super::model::*;
use super::part21::text::write_file;
use super::part21::{Instance, Param, Record, Value};
use crate::span::Span;
use std::collections::HashMap;

/// The Part 21 text of a project.
pub fn write_project(p: &Project) -> String {
    let mut w = W::new(p);
    let root = w.project();
    let instances = w.numbered(root);
    write_file(&header(&p.id), &instances)
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

/// The graph being built: instances by provisional number (index + 1).
pub(crate) struct W<'p> {
    pub p: &'p Project,
    nodes: Vec<(String, Vec<Value>)>,
    shared: HashMap<(String, String), u64>,
    pub workpieces: HashMap<WorkpieceId, u64>,
    pub features: HashMap<FeatureId, u64>,
    pub operations: HashMap<OperationId, u64>,
    pub tools: HashMap<ToolId, u64>,
}

impl<'p> W<'p> {
    fn new(p: &'p Project) -> Self {
        W {
            p,
            nodes: Vec::new(),
            shared: HashMap::new(),
            workpieces: HashMap::new(),
            features: HashMap::new(),
            operations: HashMap::new(),
            tools: HashMap::new(),
        }
    }

    /// A value instance, shared with an equal one already written.
    pub fn add(&mut self, entity: &str, params: Vec<Value>) -> Value {
        let mut key = String::new();
        for v in &params {
            crate::stepnc::part21::text::write_value(&mut key, v);
            key.push(',');
        }
        let k = (entity.to_string(), key);
        if let Some(&id) = self.shared.get(&k) {
            return Value::Ref(id);
        }
        let id = self.add_unique(entity, params);
        if let Value::Ref(n) = id {
            self.shared.insert(k, n);
        }
        id
    }

    /// An instance never shared (a project arena object).
    pub fn add_unique(&mut self, entity: &str, params: Vec<Value>) -> Value {
        self.nodes.push((entity.to_string(), params));
        Value::Ref(self.nodes.len() as u64)
    }

    /// Reserves a number for an instance whose parameters come later.
    pub fn reserve(&mut self) -> u64 {
        self.nodes.push((String::new(), Vec::new()));
        self.nodes.len() as u64
    }

    pub fn fill(&mut self, id: u64, entity: &str, params: Vec<Value>) {
        self.nodes[id as usize - 1] = (entity.to_string(), params);
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

    /// The instances renumbered depth-first from `root`, in number order.
    fn numbered(self, root: Value) -> Vec<Instance> {
        let Value::Ref(root) = root else {
            return Vec::new();
        };
        let mut new_id = vec![0u64; self.nodes.len() + 1];
        let mut order = Vec::new();
        let mut stack = vec![root];
        while let Some(n) = stack.pop() {
            if new_id[n as usize] != 0 {
                continue;
            }
            order.push(n);
            new_id[n as usize] = order.len() as u64;
            let mut refs = Vec::new();
            for v in &self.nodes[n as usize - 1].1 {
                collect_refs(v, &mut refs);
            }
            stack.extend(refs.into_iter().rev());
        }
        order
            .iter()
            .map(|&n| {
                let (entity, params) = &self.nodes[n as usize - 1];
                Instance {
                    id: new_id[n as usize],
                    entity: entity.clone(),
                    params: params
                        .iter()
                        .map(|v| Param::new(renumber(v, &new_id)))
                        .collect(),
                    span: Span::default(),
                    entity_span: Span::default(),
                    more_parts: Vec::new(),
                }
            })
            .collect()
    }
}

fn collect_refs(v: &Value, out: &mut Vec<u64>) {
    match v {
        Value::Ref(n) => out.push(*n),
        Value::List(l) => l.iter().for_each(|p| collect_refs(&p.value, out)),
        Value::Typed(_, p) => collect_refs(&p.value, out),
        _ => {}
    }
}

fn renumber(v: &Value, new_id: &[u64]) -> Value {
    match v {
        Value::Ref(n) => Value::Ref(new_id[*n as usize]),
        Value::List(l) => list(l.iter().map(|p| renumber(&p.value, new_id)).collect()),
        Value::Typed(t, p) => {
            Value::Typed(t.clone(), Box::new(Param::new(renumber(&p.value, new_id))))
        }
        other => other.clone(),
    }
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
