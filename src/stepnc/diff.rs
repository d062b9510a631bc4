//! The semantic difference of two STEP-NC files: features, operations,
//! tools, technology, placements, compared by what they say, not by
//! instance numbers or the order of unrelated instances.
//!
//! Both files are read into the model and written normalised (spelling
//! variants, sharing and numbers made uniform); each normalised graph is
//! then flattened into `section / attribute path = value` facts, where a
//! section is one identified object (`feature 'POCKET1'`, `operation
//! 'DRILL HOLE1'`, `tool 'MILL 18MM'`, `workingstep '...'`, ...) and a
//! reference to another identified object is written as its name. The
//! differences are the facts present on one side only or with another
//! value. Technology shows the model units next to the file's.

use super::part21::text::write_value;
use super::part21::{Instance, P21File, Value};
use super::{read_file, schema, units};
use crate::diag::Diagnostic;
use crate::source::SourceMap;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// The outcome of comparing two files.
#[derive(Debug)]
pub struct DiffReport {
    pub same: bool,
    /// Readable lines: `- fact` only in A, `+ fact` only in B,
    /// `~ path: a → b` changed.
    pub lines: Vec<String>,
}

/// Why two files could not be compared: the diagnostics of a file that
/// does not read (render them with `files`).
pub struct DiffError {
    pub files: SourceMap,
    pub diagnostics: Vec<Diagnostic>,
    pub io: Option<String>,
}

/// Compares two STEP-NC files.
pub fn diff_files(a: &Path, b: &Path) -> Result<DiffReport, DiffError> {
    let mut files = SourceMap::new();
    let mut projects = Vec::new();
    let mut diags = Vec::new();
    for path in [a, b] {
        match read_file(path, &mut files) {
            Ok(r) => {
                diags.extend(r.diagnostics.into_iter().filter(Diagnostic::is_error));
                projects.push(r.project);
            }
            Err(e) => {
                return Err(DiffError {
                    files,
                    diagnostics: Vec::new(),
                    io: Some(format!("{}: {e}", path.display())),
                })
            }
        }
    }
    match (&projects[0], &projects[1]) {
        (Some(pa), Some(pb)) if diags.is_empty() => Ok(diff_projects(pa, pb)),
        _ => Err(DiffError {
            files,
            diagnostics: diags,
            io: None,
        }),
    }
}

/// Compares two models.
pub fn diff_projects(a: &super::model::Project, b: &super::model::Project) -> DiffReport {
    let fa = facts(a);
    let fb = facts(b);
    let mut lines = Vec::new();
    for (k, va) in &fa {
        match fb.get(k) {
            None => lines.push(format!("- {k} = {va}")),
            Some(vb) if vb != va => lines.push(format!("~ {k}: {va} → {vb}")),
            Some(_) => {}
        }
    }
    for (k, vb) in &fb {
        if !fa.contains_key(k) {
            lines.push(format!("+ {k} = {vb}"));
        }
    }
    DiffReport {
        same: lines.is_empty(),
        lines,
    }
}

/// The facts of a model: its normalised graph flattened.
fn facts(p: &super::model::Project) -> BTreeMap<String, String> {
    let text = super::write_project(p);
    let (graph, _) = super::part21::parse::parse(&text, crate::span::FileId(0));
    let names = section_names(&graph);
    let mut out = BTreeMap::new();
    for inst in &graph.instances {
        if let Some(section) = names.get(&inst.id) {
            let mut f = Flat {
                graph: &graph,
                names: &names,
                out: &mut out,
                depth: 0,
            };
            f.instance(section, inst);
        }
    }
    out
}

/// Which kind of identified object an entity is, if any.
fn section_kind(entity: &str) -> Option<&'static str> {
    let def = schema::entity(entity)?;
    Some(match entity {
        "PROJECT" => "project",
        "WORKPLAN" => "workplan",
        "WORKPIECE" => "workpiece",
        "MILLING_CUTTING_TOOL" => "tool",
        "MACHINING_WORKINGSTEP" | "RAPID_MOVEMENT" => "workingstep",
        "PROGRAM_STOP" | "OPTIONAL_STOP" | "DISPLAY_MESSAGE" => "nc function",
        _ if def.attr_index("its_operations") == Some(2) => "feature",
        _ if def.attr_index("its_tool") == Some(5) => "operation",
        _ => return None,
    })
}

/// `feature 'POCKET1'` for every identified instance (a number added
/// when an id repeats).
fn section_names(g: &P21File) -> HashMap<u64, String> {
    let mut names = HashMap::new();
    let mut seen: HashMap<String, usize> = HashMap::new();
    for i in &g.instances {
        let Some(kind) = section_kind(&i.entity) else {
            continue;
        };
        let k = schema::entity(&i.entity).and_then(|d| d.attr_index("its_id"));
        let id = match k.and_then(|k| i.params.get(k)).map(|p| &p.value) {
            Some(Value::Str(s)) => s.clone(),
            _ => String::new(),
        };
        let base = format!("{kind} '{id}'");
        let n = seen.entry(base.clone()).or_insert(0);
        *n += 1;
        names.insert(
            i.id,
            if *n == 1 {
                base
            } else {
                format!("{base} ({n})")
            },
        );
    }
    names
}

struct Flat<'a> {
    graph: &'a P21File,
    names: &'a HashMap<u64, String>,
    out: &'a mut BTreeMap<String, String>,
    depth: usize,
}

impl Flat<'_> {
    fn instance(&mut self, path: &str, i: &Instance) {
        self.out
            .insert(format!("{path} / entity"), i.entity.clone());
        let def = schema::entity(&i.entity);
        for (k, p) in i.params.iter().enumerate() {
            let name = def
                .and_then(|d| d.attrs.get(k))
                .map_or_else(|| format!("#{}", k + 1), |a| a.name.clone());
            let sub = format!("{path} / {name}");
            let v = self.value(&sub, &name, &p.value);
            if let Some(v) = v {
                let v = annotate(&i.entity, &name, &p.value, v);
                self.out.insert(sub, v);
            }
        }
    }

    /// The value's text, or None when it was flattened into sub-facts.
    fn value(&mut self, path: &str, name: &str, v: &Value) -> Option<String> {
        match v {
            Value::Ref(n) => {
                if let Some(s) = self.names.get(n) {
                    return Some(s.clone());
                }
                let inst = self.graph.get(*n)?;
                if self.depth > 64 {
                    return Some(format!("{}(...)", inst.entity));
                }
                self.depth += 1;
                self.instance(path, inst);
                self.depth -= 1;
                None
            }
            Value::List(items) => {
                let named: Option<Vec<String>> = items
                    .iter()
                    .map(|p| match &p.value {
                        Value::Ref(n) => self.names.get(n).cloned(),
                        _ => None,
                    })
                    .collect();
                if let (Some(mut named), false) = (named, items.is_empty()) {
                    // SETs of identified objects compare without order;
                    // the workplan's elements keep theirs.
                    if name != "its_elements" {
                        named.sort();
                    }
                    return Some(format!("[{}]", named.join(", ")));
                }
                if items.iter().all(|p| !matches!(p.value, Value::Ref(_))) {
                    let mut s = String::new();
                    write_value(&mut s, v);
                    return Some(s);
                }
                self.out
                    .insert(format!("{path} / count"), items.len().to_string());
                for (k, p) in items.iter().enumerate() {
                    let sub = format!("{path}[{k}]");
                    if let Some(t) = self.value(&sub, name, &p.value) {
                        self.out.insert(sub, t);
                    }
                }
                None
            }
            other => {
                let mut s = String::new();
                write_value(&mut s, other);
                Some(s)
            }
        }
    }
}

/// Technology values with the model's units beside the file's.
fn annotate(entity: &str, attr: &str, v: &Value, text: String) -> String {
    let Value::Real(x) = v else { return text };
    if entity != "MILLING_TECHNOLOGY" {
        return text;
    }
    match attr {
        "feedrate" => format!("{text} m/s ({} mm/min)", units::feed_from_file(*x)),
        "cutspeed" => format!("{text} m/s ({} m/min)", units::cut_speed_from_file(*x)),
        "spindle" => format!(
            "{text} rev/s ({} rpm, + = clockwise)",
            units::spindle_from_file(*x)
        ),
        _ => text,
    }
}
