//! Generic Part 21 graph → typed [`crate::stepnc::model`]: follows the
//! references from the PROJECT, accepts the spelling variants real files
//! use (through [`crate::stepnc::schema::canonical`]) and converts units at
//! the boundary (feed m/s → mm/min, cut speed m/s → m/min, spindle rev/s
//! with ISO's sign → rpm positive clockwise).
//!
//! What does not fit the typed model (an unexpected entity, a mandatory
//! attribute left `$`) is kept as a [`Raw`] subtree with a `kept-raw`
//! warning, so nothing the file says is dropped.

mod feature;
mod geom;
mod operation;
mod structure;
mod tool;

use super::model::*;
use super::part21::{Instance, P21File, Param, Value};
use super::schema;
use crate::diag::{Code, Diagnostic};
use crate::span::Span;
use std::collections::{HashMap, HashSet};

/// Deepest nesting of references followed.
const MAX_DEPTH: usize = 200;
/// Most values a file may expand to when kept as raw subtrees.
const MAX_RAW_NODES: usize = 2_000_000;

/// Why a value could not be read as the typed model expects.
#[derive(Debug)]
pub(crate) struct Fail {
    pub msg: String,
    pub span: Span,
}

pub(crate) type R<T> = Result<T, Fail>;

/// Reads the project of a validated file. `None` (with errors) when there
/// is no usable PROJECT.
pub fn read_project(file: &P21File) -> (Option<Project>, Vec<Diagnostic>) {
    let mut rd = Rd::new(file);
    let roots: Vec<&Instance> = file
        .instances
        .iter()
        .filter(|i| schema::canonical(&i.entity) == "PROJECT")
        .collect();
    let Some(root) = roots.first() else {
        let d = Diagnostic::new(Code::StepncModel, "the file has no PROJECT instance")
            .help("an ISO 14649 programme starts at a PROJECT(its_id, main_workplan, its_workpieces, ...) instance");
        return (None, vec![d]);
    };
    for extra in &roots[1..] {
        rd.diags.push(
            Diagnostic::new(Code::StepncModel, "a second PROJECT instance")
                .primary(extra.span, "second project")
                .secondary(root.span, "the project read")
                .help("a file holds one ISO 14649 project"),
        );
    }
    let project = match rd.project(root) {
        Ok(p) => Some(p),
        Err(f) => {
            rd.hard(f);
            None
        }
    };
    rd.report_unused();
    rd.report_duplicate_ids();
    let ok = !rd.diags.iter().any(Diagnostic::is_error);
    (if ok { project } else { None }, rd.diags)
}

/// The reading context: the file, arenas being filled, memo tables.
pub(crate) struct Rd<'f> {
    pub file: &'f P21File,
    pub diags: Vec<Diagnostic>,
    pub p: Project,
    pub workpieces: HashMap<u64, WorkpieceId>,
    pub features: HashMap<u64, FeatureId>,
    pub operations: HashMap<u64, OperationId>,
    pub tools: HashMap<u64, ToolId>,
    /// Shared objects being read (a cycle guard).
    pub open: HashSet<u64>,
    pub used: HashSet<u64>,
    pub depth: usize,
    pub raw_nodes: usize,
    /// its_id → (what, span) of features, operations, executables.
    pub ids: Vec<(String, &'static str, Span)>,
}

impl<'f> Rd<'f> {
    fn new(file: &'f P21File) -> Self {
        Rd {
            file,
            diags: Vec::new(),
            p: Project::default(),
            workpieces: HashMap::new(),
            features: HashMap::new(),
            operations: HashMap::new(),
            tools: HashMap::new(),
            open: HashSet::new(),
            used: HashSet::new(),
            depth: 0,
            raw_nodes: 0,
            ids: Vec::new(),
        }
    }

    /// A failure that stops a part of the model being read.
    pub fn hard(&mut self, f: Fail) {
        self.diags.push(
            Diagnostic::new(Code::StepncModel, f.msg)
                .primary(f.span, "here")
                .help("ISO 14649-10/11 give each attribute the entity kinds it may refer to"),
        );
    }

    /// Reads with `typed`; when that fails, keeps the instance as written
    /// (`other`) with a `kept-raw` warning.
    pub fn or_raw<T>(
        &mut self,
        i: &'f Instance,
        typed: impl FnOnce(&mut Self, &'f Instance) -> R<T>,
        other: impl FnOnce(Raw) -> T,
    ) -> R<T> {
        let kept = self.diags.len();
        match typed(self, i) {
            Ok(v) => Ok(v),
            Err(f) => {
                self.diags.truncate(kept);
                let raw = self.raw(i)?;
                self.diags.push(
                    Diagnostic::new(
                        Code::KeptRaw,
                        format!("#{} {} kept as written: {}", i.id, i.entity, f.msg),
                    )
                    .primary(f.span, "not as ISO 14649 gives it")
                    .secondary(i.span, "this instance")
                    .help("it is carried to the output unchanged but takes no part in checks, differences or posting"),
                );
                Ok(other(raw))
            }
        }
    }

    // ------------------------------------------------------------ access

    /// The instance a parameter refers to.
    pub fn inst(&mut self, p: &'f Param) -> R<&'f Instance> {
        match &p.value {
            Value::Ref(n) => match self.file.get(*n) {
                Some(i) => {
                    self.used.insert(*n);
                    Ok(i)
                }
                None => Err(fail(p.span, format!("#{n} is not defined"))),
            },
            Value::Null => Err(fail(p.span, "a mandatory reference is `$`")),
            _ => Err(fail(p.span, "expected an instance reference")),
        }
    }

    pub fn opt_inst(&mut self, p: &'f Param) -> R<Option<&'f Instance>> {
        match p.value {
            Value::Null => Ok(None),
            _ => self.inst(p).map(Some),
        }
    }

    /// The instances of a list parameter.
    pub fn insts(&mut self, p: &'f Param) -> R<Vec<&'f Instance>> {
        list(p)?.iter().map(|q| self.inst(q)).collect()
    }

    pub fn enter(&mut self, span: Span) -> R<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(fail(span, "references nest too deeply (a cycle?)"));
        }
        Ok(())
    }

    pub fn leave(&mut self) {
        self.depth -= 1;
    }

    // ------------------------------------------------------------ raw

    /// An instance as written, references followed and held inline.
    pub fn raw(&mut self, i: &'f Instance) -> R<Raw> {
        self.enter(i.span)?;
        let params = i
            .params
            .iter()
            .map(|p| self.raw_value(p))
            .collect::<R<Vec<_>>>();
        self.leave();
        Ok(Raw {
            entity: i.entity.clone(),
            params: params?,
        })
    }

    pub fn opt_raw(&mut self, p: &'f Param) -> R<Option<Raw>> {
        match self.opt_inst(p)? {
            Some(i) => self.raw(i).map(Some),
            None => Ok(None),
        }
    }

    pub fn raw_list(&mut self, p: &'f Param) -> R<Vec<Raw>> {
        let items = self.insts(p)?;
        items.into_iter().map(|i| self.raw(i)).collect()
    }

    pub fn raw_value(&mut self, p: &'f Param) -> R<RawValue> {
        self.raw_nodes += 1;
        if self.raw_nodes > MAX_RAW_NODES {
            return Err(fail(p.span, "the file expands to too many values"));
        }
        Ok(match &p.value {
            Value::Null => RawValue::Null,
            Value::Derived => RawValue::Derived,
            Value::Int(v) => RawValue::Integer(*v),
            Value::Real(v) => RawValue::Real(*v),
            Value::Str(s) => RawValue::String(s.clone()),
            Value::Enum(e) if e == "T" => RawValue::Bool(true),
            Value::Enum(e) if e == "F" => RawValue::Bool(false),
            Value::Enum(e) => RawValue::Enum(e.clone()),
            Value::Binary(b) => {
                RawValue::Typed("BINARY".into(), Box::new(RawValue::String(b.clone())))
            }
            Value::Ref(_) => {
                let i = self.inst(p)?;
                RawValue::Instance(Box::new(self.raw(i)?))
            }
            Value::List(l) => {
                RawValue::List(l.iter().map(|q| self.raw_value(q)).collect::<R<Vec<_>>>()?)
            }
            Value::Typed(t, inner) => RawValue::Typed(t.clone(), Box::new(self.raw_value(inner)?)),
        })
    }

    // ------------------------------------------------------------ reports

    fn report_unused(&mut self) {
        for i in &self.file.instances {
            if !self.used.contains(&i.id) && schema::canonical(&i.entity) != "PROJECT" {
                self.diags.push(
                    Diagnostic::new(
                        Code::UnusedInstance,
                        format!("#{} {} is not part of the project", i.id, i.entity),
                    )
                    .primary(i.span, "never referred to")
                    .help("a normalised file leaves it out; remove it or refer to it"),
                );
            }
        }
    }

    fn report_duplicate_ids(&mut self) {
        let mut seen: HashMap<(&str, &str), Span> = HashMap::new();
        let mut out = Vec::new();
        for (id, what, span) in &self.ids {
            match seen.get(&(id.as_str(), *what)) {
                Some(first) => out.push(
                    Diagnostic::new(
                        Code::DuplicateItsId,
                        format!("two {what}s have the its_id '{id}'"),
                    )
                    .primary(*span, "second")
                    .secondary(*first, "first")
                    .help("ISO 14649 asks for unique its_id values; rename one"),
                ),
                None => {
                    seen.insert((id.as_str(), what), *span);
                }
            }
        }
        self.diags.extend(out);
    }
}

// ---------------------------------------------------------------- values

pub(crate) fn fail(span: Span, msg: impl Into<String>) -> Fail {
    Fail {
        msg: msg.into(),
        span,
    }
}

/// The canonical entity name of an instance.
pub(crate) fn ent(i: &Instance) -> &str {
    schema::canonical(&i.entity)
}

/// Parameter `k` of an instance (validation has checked the count, but a
/// shorter instance still fails cleanly).
pub(crate) fn arg(i: &Instance, k: usize) -> R<&Param> {
    i.params
        .get(k)
        .ok_or_else(|| fail(i.span, format!("{} has no parameter {}", i.entity, k + 1)))
}

pub(crate) fn real(p: &Param) -> R<f64> {
    match p.value {
        Value::Real(v) => Ok(v),
        Value::Int(v) => Ok(v as f64),
        Value::Null => Err(fail(p.span, "a mandatory number is `$`")),
        _ => Err(fail(p.span, "expected a number")),
    }
}

pub(crate) fn opt_real(p: &Param) -> R<Option<f64>> {
    match p.value {
        Value::Null => Ok(None),
        _ => real(p).map(Some),
    }
}

pub(crate) fn int(p: &Param) -> R<i64> {
    match p.value {
        Value::Int(v) => Ok(v),
        _ => Err(fail(p.span, "expected an integer")),
    }
}

pub(crate) fn opt_int(p: &Param) -> R<Option<i64>> {
    match p.value {
        Value::Null => Ok(None),
        _ => int(p).map(Some),
    }
}

pub(crate) fn string(p: &Param) -> R<String> {
    match &p.value {
        Value::Str(s) => Ok(s.clone()),
        Value::Null => Err(fail(p.span, "a mandatory string is `$`")),
        _ => Err(fail(p.span, "expected a string")),
    }
}

pub(crate) fn boolean(p: &Param) -> R<bool> {
    match &p.value {
        Value::Enum(e) if e == "T" => Ok(true),
        Value::Enum(e) if e == "F" => Ok(false),
        Value::Null => Err(fail(p.span, "a mandatory boolean is `$`")),
        _ => Err(fail(p.span, "expected .T. or .F.")),
    }
}

pub(crate) fn opt_bool(p: &Param) -> R<Option<bool>> {
    match p.value {
        Value::Null => Ok(None),
        _ => boolean(p).map(Some),
    }
}

pub(crate) fn enumeration(p: &Param) -> R<&str> {
    match &p.value {
        Value::Enum(e) => Ok(e),
        Value::Null => Err(fail(p.span, "a mandatory enumeration is `$`")),
        _ => Err(fail(p.span, "expected an enumeration")),
    }
}

pub(crate) fn opt_enum(p: &Param) -> R<Option<&str>> {
    match p.value {
        Value::Null => Ok(None),
        _ => enumeration(p).map(Some),
    }
}

pub(crate) fn list(p: &Param) -> R<&[Param]> {
    match &p.value {
        Value::List(l) => Ok(l),
        _ => Err(fail(p.span, "expected a list")),
    }
}

/// Checks an instance's entity against the accepted names.
pub(crate) fn expect<'i>(i: &'i Instance, names: &[&str], what: &str) -> R<&'i str> {
    let e = ent(i);
    if names.contains(&e) {
        Ok(e)
    } else {
        Err(fail(
            i.entity_span,
            format!("expected {what}, found {} (#{})", i.entity, i.id),
        ))
    }
}
