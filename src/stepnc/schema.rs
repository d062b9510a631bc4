//! The ISO 14649 schema cncc knows: entity → flattened attribute list
//! (name, kind, optional), spelling variants, and the validation of a
//! generic Part 21 graph against it (unknown entities, argument counts
//! and kinds, dangling references). The table itself is the checked-in
//! text `schema_table.txt`, written from reference/stepnc.md section 3.

use super::part21::{Instance, P21File, Param, Value};
use crate::diag::{Code, Diagnostic, PerCode};
use std::collections::HashMap;
use std::sync::OnceLock;

/// What kind of value an attribute holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Kind {
    Str,
    Real,
    Int,
    Bool,
    Logical,
    Enum,
    Instance,
    /// A SELECT: an instance, a typed value or a plain value.
    Select,
    List(Box<Kind>),
}

#[derive(Clone, Debug)]
pub struct Attr {
    pub name: String,
    pub kind: Kind,
    pub optional: bool,
}

#[derive(Clone, Debug)]
pub struct EntityDef {
    /// Canonical (upper case) name.
    pub name: String,
    pub attrs: Vec<Attr>,
    /// Fewest parameters accepted (older editions wrote fewer).
    pub min_args: usize,
}

impl EntityDef {
    /// The index of an attribute by (case-insensitive) name.
    pub fn attr_index(&self, name: &str) -> Option<usize> {
        self.attrs
            .iter()
            .position(|a| a.name.eq_ignore_ascii_case(name))
    }
}

struct Schema {
    entities: HashMap<String, EntityDef>,
    aliases: HashMap<String, String>,
}

fn schema() -> &'static Schema {
    static S: OnceLock<Schema> = OnceLock::new();
    S.get_or_init(|| load(include_str!("schema_table.txt")))
}

fn load(text: &str) -> Schema {
    let mut entities = HashMap::new();
    let mut aliases = HashMap::new();
    for line in text.lines().map(str::trim) {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let mut words = line.split_whitespace();
        let first = words.next().unwrap_or_default();
        if first == "=" {
            let alias = words.next().unwrap_or_default().to_string();
            let target = words.next().unwrap_or_default().to_string();
            aliases.insert(alias, target);
            continue;
        }
        let mut attrs = Vec::new();
        let mut min_args = None;
        for w in words {
            if w == "|" {
                min_args = Some(attrs.len());
                continue;
            }
            let (name, ty) = w.split_once(':').expect("schema table: attr:TYPE");
            let (optional, ty) = match ty.strip_prefix('?') {
                Some(t) => (true, t),
                None => (false, ty),
            };
            attrs.push(Attr {
                name: name.to_string(),
                kind: kind(ty),
                optional,
            });
        }
        let min_args = min_args.unwrap_or(attrs.len());
        entities.insert(
            first.to_string(),
            EntityDef {
                name: first.to_string(),
                attrs,
                min_args,
            },
        );
    }
    Schema { entities, aliases }
}

fn kind(code: &str) -> Kind {
    match code {
        "S" => Kind::Str,
        "R" => Kind::Real,
        "I" => Kind::Int,
        "B" => Kind::Bool,
        "L" => Kind::Logical,
        "E" => Kind::Enum,
        "#" => Kind::Instance,
        "*" => Kind::Select,
        l if l.starts_with('[') => Kind::List(Box::new(kind(&l[1..]))),
        other => panic!("schema table: unknown type code {other}"),
    }
}

/// The canonical spelling of an entity name (`BIDIRECTIONAL_MILLING` →
/// `BIDIRECTIONAL`); unknown names are returned unchanged.
pub fn canonical(name: &str) -> &str {
    match schema().aliases.get(name) {
        Some(t) => t,
        None => name,
    }
}

/// The definition of an entity (spelling variants resolved).
pub fn entity(name: &str) -> Option<&'static EntityDef> {
    let s = schema();
    s.entities.get(canonical(name))
}

/// Every entity name known (canonical spellings), sorted.
pub fn entity_names() -> Vec<&'static str> {
    let mut v: Vec<&str> = schema().entities.keys().map(String::as_str).collect();
    v.sort_unstable();
    v
}

/// Checks every instance of a file against the schema (at most
/// [`MAX_KEPT_PER_CODE`](crate::diag::MAX_KEPT_PER_CODE) diagnostics of
/// one code are kept, the rest counted).
pub fn validate(file: &P21File) -> Vec<Diagnostic> {
    let mut diags = Vec::new();
    let mut cap = PerCode::default();
    let mut suggestions = HashMap::new();
    for inst in &file.instances {
        let from = diags.len();
        validate_instance(file, inst, &mut diags, &mut suggestions);
        cap.admit(&mut diags, from);
    }
    cap.finish(&mut diags);
    diags
}

fn validate_instance(
    file: &P21File,
    inst: &Instance,
    diags: &mut Vec<Diagnostic>,
    suggestions: &mut HashMap<String, String>,
) {
    if inst.is_complex() {
        diags.push(
            Diagnostic::new(
                Code::ComplexInstance,
                format!("#{} is a complex instance", inst.id),
            )
            .primary(inst.span, "complex instance")
            .help("ISO 14649 ARM files use simple instances `#n=ENTITY(...)` only"),
        );
        return;
    }
    let Some(def) = entity(&inst.entity) else {
        diags.push(
            Diagnostic::new(
                Code::UnknownEntity,
                format!("unknown entity `{}`", inst.entity),
            )
            .primary(inst.entity_span, "not an ISO 14649 entity cncc knows")
            .help(
                suggestions
                    .entry(inst.entity.clone())
                    .or_insert_with(|| suggest(&inst.entity))
                    .clone(),
            ),
        );
        check_refs(file, &inst.params, diags);
        return;
    };
    let n = inst.params.len();
    if n < def.min_args || n > def.attrs.len() {
        let want = if def.min_args == def.attrs.len() {
            format!("{}", def.attrs.len())
        } else {
            format!("{} or {}", def.min_args, def.attrs.len())
        };
        let names: Vec<&str> = def.attrs.iter().map(|a| a.name.as_str()).collect();
        diags.push(
            Diagnostic::new(
                Code::WrongArgumentCount,
                format!("{} takes {want} parameters, #{} has {n}", def.name, inst.id),
            )
            .primary(inst.entity_span, format!("{n} parameters"))
            .help(format!("the attributes are: {}", names.join(", "))),
        );
        check_refs(file, &inst.params, diags);
        return;
    }
    for (p, a) in inst.params.iter().zip(&def.attrs) {
        check_param(file, def, a, p, diags);
    }
}

fn check_param(file: &P21File, def: &EntityDef, a: &Attr, p: &Param, diags: &mut Vec<Diagnostic>) {
    if let Value::Null = p.value {
        if !a.optional {
            // Real generators leave mandatory attributes unset (GRIMA's
            // SQUARE_U_PROFILE): read on, the model keeps such instances
            // as written.
            let help = match &a.kind {
                Kind::List(_) => {
                    "read as the empty list `()`, which is what ISO 10303-21 writes for it"
                }
                Kind::Str => "read as the empty string",
                Kind::Bool => "read as .F. (not asked for); give the attribute a value",
                Kind::Enum if a.name == "feedrate_reference" => "read as .TCP.",
                _ if a.name == "its_workpiece" => {
                    "read as the project's workpiece when the project has only one (otherwise the instance is kept as written)"
                }
                _ => "the instance is kept as written; give the attribute a value",
            };
            diags.push(
                Diagnostic::new(
                    Code::MandatoryUnset,
                    format!("{}.{} is mandatory but `$`", def.name, a.name),
                )
                .primary(p.span, format!("expected {}", expected(&a.kind)))
                .help(help),
            );
        }
        return;
    }
    if !fits(&a.kind, &p.value) {
        diags.push(type_error(def, a, p, &found(&p.value), &expected(&a.kind)));
    }
    check_refs(file, std::slice::from_ref(p), diags);
}

/// Whether a (non-`$`) value can be of that kind.
fn fits(kind: &Kind, v: &Value) -> bool {
    match (kind, v) {
        (_, Value::Derived) => true,
        (Kind::Select, _) => true,
        (Kind::Str, Value::Str(_)) => true,
        (Kind::Real, Value::Real(_) | Value::Int(_)) => true,
        (Kind::Int, Value::Int(_)) => true,
        (Kind::Bool, Value::Enum(e)) => e == "T" || e == "F",
        (Kind::Logical, Value::Enum(e)) => e == "T" || e == "F" || e == "U",
        (Kind::Enum, Value::Enum(_)) => true,
        (Kind::Instance, Value::Ref(_)) => true,
        (Kind::List(k), Value::List(items)) => items.iter().all(|i| fits(k, &i.value)),
        _ => false,
    }
}

fn check_refs(file: &P21File, params: &[Param], diags: &mut Vec<Diagnostic>) {
    for p in params {
        match &p.value {
            Value::Ref(n) if file.get(*n).is_none() => diags.push(
                Diagnostic::new(Code::DanglingReference, format!("#{n} is not defined"))
                    .primary(p.span, "refers to nothing")
                    .help("define the instance, or correct the number"),
            ),
            Value::List(l) => check_refs(file, l, diags),
            Value::Typed(_, inner) => check_refs(file, std::slice::from_ref(inner), diags),
            _ => {}
        }
    }
}

fn type_error(def: &EntityDef, a: &Attr, p: &Param, found: &str, want: &str) -> Diagnostic {
    Diagnostic::new(
        Code::WrongArgumentType,
        format!("{}.{} is {want}, not {found}", def.name, a.name),
    )
    .primary(p.span, format!("expected {want}"))
    .help(if a.optional {
        format!("write {want}, or `$` to leave it unset")
    } else {
        format!("write {want}; this attribute is mandatory")
    })
}

fn expected(k: &Kind) -> String {
    match k {
        Kind::Str => "a string".into(),
        Kind::Real => "a real".into(),
        Kind::Int => "an integer".into(),
        Kind::Bool => "a boolean (.T. or .F.)".into(),
        Kind::Logical => "a logical (.T., .F. or .U.)".into(),
        Kind::Enum => "an enumeration".into(),
        Kind::Instance => "an instance reference".into(),
        Kind::Select => "a value".into(),
        Kind::List(inner) => format!("a list of {}", plural(inner)),
    }
}

fn plural(k: &Kind) -> &'static str {
    match k {
        Kind::Str => "strings",
        Kind::Real => "reals",
        Kind::Int => "integers",
        Kind::Bool | Kind::Logical => "booleans",
        Kind::Enum => "enumerations",
        Kind::Instance => "instance references",
        Kind::Select | Kind::List(_) => "values",
    }
}

fn found(v: &Value) -> String {
    match v {
        Value::Null => "`$`".into(),
        Value::Derived => "`*`".into(),
        Value::Int(_) => "an integer".into(),
        Value::Real(_) => "a real".into(),
        Value::Str(_) => "a string".into(),
        Value::Enum(e) => format!("the enumeration .{e}."),
        Value::Binary(_) => "a binary".into(),
        Value::Ref(_) => "an instance reference".into(),
        Value::List(_) => "a list".into(),
        Value::Typed(t, _) => format!("a typed {t}(...)"),
    }
}

/// A help line for an unknown entity: the closest known name.
fn suggest(name: &str) -> String {
    let best = entity_names()
        .into_iter()
        .map(|n| (distance(n, name), n))
        .min();
    match best {
        Some((d, n)) if d <= 3 => format!("did you mean `{n}`?"),
        _ => "cncc reads the ISO 14649-10, -11 and -111 entities; check the spelling".into(),
    }
}

/// Levenshtein distance (names are short).
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_loads_with_aliases() {
        assert_eq!(entity("PROJECT").unwrap().attrs.len(), 6);
        assert_eq!(
            entity("BIDIRECTIONAL_MILLING").unwrap().name,
            "BIDIRECTIONAL"
        );
        assert_eq!(entity("CENTER_DRILL").unwrap().name, "CENTERDRILL");
        let cc = entity("CUTTING_COMPONENT").unwrap();
        assert_eq!((cc.min_args, cc.attrs.len()), (4, 5));
        assert_eq!(
            entity("BOTTOM_AND_SIDE_ROUGH_MILLING").unwrap().attrs.len(),
            16
        );
        assert_eq!(entity("MULTISTEP_DRILLING").unwrap().attrs.len(), 18);
    }
}
