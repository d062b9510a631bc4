//! Part 21 (ISO 10303-21) exchange structure: the generic instance graph
//! with spans, its reader ([`parse`], LALRPOP grammar `grammar/part21.lalrpop`
//! over the logos [`lexer`]) and its writer ([`text`]).

pub mod lexer;
pub mod parse;
pub mod text;

use crate::span::Span;
use std::collections::HashMap;

/// One parameter value as the file writes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `$`: an unset OPTIONAL attribute.
    Null,
    /// `*`: a value derived in a supertype.
    Derived,
    Int(i64),
    Real(f64),
    Str(String),
    /// `.NAME.` (booleans and logicals are `.T.`, `.F.`, `.U.`).
    Enum(String),
    /// `"0F3"`: hex digits as written.
    Binary(String),
    /// `#n`.
    Ref(u64),
    List(Vec<Param>),
    /// `TYPE_NAME(value)`: a value of a defined type in a SELECT.
    Typed(String, Box<Param>),
}

/// A parameter with the span it was read from.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    pub value: Value,
    pub span: Span,
}

impl Param {
    /// A parameter made by the writer (no place in a file).
    pub fn new(value: Value) -> Param {
        Param {
            value,
            span: Span::default(),
        }
    }
}

/// `NAME(params)`: a header entity, or one part of a data instance.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// Upper case.
    pub entity: String,
    pub params: Vec<Param>,
    /// The entity name's span.
    pub span: Span,
}

/// `#id=NAME(params);`. A complex instance `#id=(A(..)B(..));` keeps its
/// first part in `entity`/`params` and the others in `more_parts`.
#[derive(Clone, Debug, PartialEq)]
pub struct Instance {
    pub id: u64,
    pub entity: String,
    pub params: Vec<Param>,
    /// The `#id` span.
    pub span: Span,
    /// The entity name's span.
    pub entity_span: Span,
    pub more_parts: Vec<Record>,
}

impl Instance {
    pub fn is_complex(&self) -> bool {
        !self.more_parts.is_empty()
    }
}

/// A statement as the grammar reads it.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    Header(Record),
    Instance {
        id: u64,
        id_span: Span,
        parts: Vec<Record>,
    },
}

/// A whole Part 21 file: header entities and the data instances in file
/// order, with an index by instance number.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct P21File {
    pub header: Vec<Record>,
    pub instances: Vec<Instance>,
    index: HashMap<u64, usize>,
}

impl P21File {
    pub fn new(header: Vec<Record>, instances: Vec<Instance>) -> P21File {
        let mut f = P21File {
            header,
            instances: Vec::new(),
            index: HashMap::new(),
        };
        for i in instances {
            f.push(i);
        }
        f
    }

    /// Adds an instance; a second one with the same number is kept in the
    /// list but the index keeps the first (the reader reports it).
    pub fn push(&mut self, inst: Instance) {
        self.index.entry(inst.id).or_insert(self.instances.len());
        self.instances.push(inst);
    }

    pub fn get(&self, id: u64) -> Option<&Instance> {
        self.index.get(&id).map(|&i| &self.instances[i])
    }

    /// The FILE_SCHEMA names, upper case.
    pub fn schemas(&self) -> Vec<String> {
        let mut out = Vec::new();
        for r in self.header.iter().filter(|r| r.entity == "FILE_SCHEMA") {
            collect_strings(&r.params, &mut out);
        }
        out.iter().map(|s| s.to_ascii_uppercase()).collect()
    }

    /// The header record of that name.
    pub fn header_record(&self, name: &str) -> Option<&Record> {
        self.header.iter().find(|r| r.entity == name)
    }
}

fn collect_strings(params: &[Param], out: &mut Vec<String>) {
    for p in params {
        match &p.value {
            Value::Str(s) => out.push(s.clone()),
            Value::List(l) => collect_strings(l, out),
            _ => {}
        }
    }
}
