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
mod strategy;
mod structure;
mod tool;
mod toolpath;
mod values;

pub(crate) use values::*;

use super::model::*;
use super::part21::{Instance, P21File, Param, Value};
use super::schema;
use crate::diag::{Code, Diagnostic};
use crate::span::Span;
use std::collections::{HashMap, HashSet};

/// Deepest nesting of references followed.
const MAX_DEPTH: usize = 200;
/// Most values a file may expand to (following shared references over
/// and over), beyond a multiple of what it holds.
const MAX_EXPANSION: usize = 1_000_000;
/// How many times over a file's values may be visited.
const EXPANSION_FACTOR: usize = 8;
/// Most values expanded whatever the file's size (about 230 bytes each:
/// a 4.7 KB bomb took 226 MB at a million; without this bound, 100 MB of
/// filler parameters beside it would allow hundreds of millions).
const MAX_NODES: usize = 4_000_000;

/// Why a value could not be read as the typed model expects.
#[derive(Debug)]
pub(crate) struct Fail {
    pub msg: String,
    pub span: Span,
    /// The file breaks the schema (an attribute refers to an entity of a
    /// kind its type does not allow), or nests too deep: an error, never
    /// kept as raw.
    pub invalid: bool,
    pub too_deep: bool,
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
    // Unused instances and repeated ids mean something only in a project
    // that was read through.
    if !rd.diags.iter().any(Diagnostic::is_error) {
        rd.report_unused();
        rd.report_duplicate_ids();
    }
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
    /// By position in the file's instances.
    pub used: Vec<bool>,
    pub depth: usize,
    pub raw_nodes: usize,
    /// The budget for `raw_nodes` (bounds work on files whose shared
    /// instances expand exponentially).
    pub max_nodes: usize,
    /// its_id → (what, span) of features, operations, executables.
    pub ids: Vec<(String, &'static str, Span)>,
    /// The span of the reference followed last (for errors about the
    /// instance it leads to).
    pub last_ref: Option<Span>,
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
            used: vec![false; file.instances.len()],
            depth: 0,
            raw_nodes: 0,
            max_nodes: (MAX_EXPANSION
                + EXPANSION_FACTOR
                    * file
                        .instances
                        .iter()
                        .map(|i| i.params.len() + 1)
                        .sum::<usize>())
            .min(MAX_NODES),
            ids: Vec::new(),
            last_ref: None,
        }
    }

    /// A failure that stops a part of the model being read.
    pub fn hard(&mut self, f: Fail) {
        let code = if f.too_deep {
            Code::P21TooDeep
        } else {
            Code::StepncModel
        };
        let mut d = Diagnostic::new(code, f.msg)
            .primary(f.span, "here")
            .help(if f.too_deep {
                "ISO 14649 data is a shallow tree; check the references for a cycle"
            } else {
                "ISO 14649-10/11 give each attribute the entity kinds it may refer to"
            });
        if f.too_deep && self.diags.iter().any(|d| d.code == Code::P21TooDeep) {
            return;
        }
        if let Some(r) = self
            .last_ref
            .filter(|r| *r != f.span && f.invalid && !f.too_deep)
        {
            d = d.secondary(r, "referred to here");
        }
        self.diags.push(d);
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
        let mark = self.mark();
        match typed(self, i) {
            Ok(v) => Ok(v),
            Err(f) if f.invalid => Err(f),
            Err(f) => {
                self.diags.truncate(kept);
                self.roll_back(mark);
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

    /// The arena sizes, to undo a typed attempt that failed part way.
    fn mark(&self) -> [usize; 5] {
        [
            self.p.workpieces.len(),
            self.p.features.len(),
            self.p.operations.len(),
            self.p.tools.len(),
            self.ids.len(),
        ]
    }

    /// Forgets the shared objects read since `mark` (they belong to the
    /// instance now kept as written).
    fn roll_back(&mut self, m: [usize; 5]) {
        self.p.workpieces.truncate(m[0]);
        self.p.features.truncate(m[1]);
        self.p.operations.truncate(m[2]);
        self.p.tools.truncate(m[3]);
        self.ids.truncate(m[4]);
        self.workpieces.retain(|_, v| v.index() < m[0]);
        self.features.retain(|_, v| v.index() < m[1]);
        self.operations.retain(|_, v| v.index() < m[2]);
        self.tools.retain(|_, v| v.index() < m[3]);
    }

    // ------------------------------------------------------------ access

    /// The instance a parameter refers to.
    pub fn inst(&mut self, p: &'f Param) -> R<&'f Instance> {
        match &p.value {
            Value::Ref(n) => match self.file.position(*n) {
                Some(_) if self.raw_nodes >= self.max_nodes => Err(too_deep(
                    p.span,
                    "the file expands to too many values (shared instances referred to over and over?)",
                )),
                Some(k) => {
                    self.raw_nodes += 1;
                    let i = &self.file.instances[k];
                    self.used[k] = true;
                    self.last_ref = Some(p.span);
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
        self.raw_nodes += 1;
        if self.depth > MAX_DEPTH {
            return Err(too_deep(span, "references nest too deeply (a cycle?)"));
        }
        if self.raw_nodes > self.max_nodes {
            return Err(too_deep(
                span,
                "the file expands to too many values (shared instances referred to over and over?)",
            ));
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
        if self.raw_nodes > self.max_nodes {
            return Err(too_deep(p.span, "the file expands to too many values"));
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

    /// W0801 for each instance the project does not reach (at most
    /// [`MAX_KEPT_PER_CODE`](crate::diag::MAX_KEPT_PER_CODE) kept).
    fn report_unused(&mut self) {
        let mut cap = crate::diag::PerCode::default();
        let from = self.diags.len();
        for (k, i) in self.file.instances.iter().enumerate() {
            if !self.used[k] && schema::canonical(&i.entity) != "PROJECT" {
                let at = self.diags.len();
                self.diags.push(
                    Diagnostic::new(
                        Code::UnusedInstance,
                        format!("#{} {} is not part of the project", i.id, i.entity),
                    )
                    .primary(i.span, "never referred to")
                    .help("a normalised file leaves it out; remove it or refer to it"),
                );
                cap.admit(&mut self.diags, at);
            }
        }
        cap.finish(&mut self.diags[from..]);
    }

    fn report_duplicate_ids(&mut self) {
        let mut seen: HashMap<(&str, &str), Span> = HashMap::new();
        let mut out = Vec::new();
        for (id, what, span) in &self.ids {
            match seen.get(&(id.as_str(), *what)) {
                // The same instance met twice (a workingstep listed twice).
                Some(first) if first == span => {}
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
