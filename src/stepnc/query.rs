//! `cncc query FILE.stp PATH`: attribute paths over a Part 21 file's
//! instance graph, by the attribute names of the schema table.
//!
//! A path starts at every instance of an entity (`/project`, case does not
//! matter, spelling variants accepted) or at one instance (`/#18`), then
//! goes through attribute names (`/its_id`), list indexes (`[0]`) and
//! `[*]` (every element). Results print one a line: strings as their
//! text, numbers and enumerations as Part 21 writes them, lists in Part 21
//! form, and an instance as its whole line `#18=CLOSED_POCKET('POCKET1',...)`.

use super::part21::text::write_value;
use super::part21::{Instance, P21File, Value};
use super::schema;

/// A node of a query result.
#[derive(Clone, Debug)]
enum Node<'f> {
    Inst(&'f Instance),
    Val(&'f Value),
}

/// Runs a query; the lines to print, or a message saying which step of
/// the path failed.
pub fn query(file: &P21File, path: &str) -> Result<Vec<String>, String> {
    let steps = parse_path(path)?;
    let Some((first, rest)) = steps.split_first() else {
        return Err("an empty path; start with /ENTITY or /#n".into());
    };
    let mut nodes = start(file, first)?;
    for step in rest {
        nodes = apply(file, &nodes, step)?;
    }
    Ok(nodes
        .iter()
        .map(|n| match deref(file, n) {
            Some(i) => instance_line(i),
            None => show(n),
        })
        .collect())
}

#[derive(Debug)]
struct Step {
    name: String,
    indexes: Vec<Index>,
}

#[derive(Debug, Clone, Copy)]
enum Index {
    At(usize),
    All,
}

fn parse_path(path: &str) -> Result<Vec<Step>, String> {
    let body = path
        .strip_prefix('/')
        .ok_or_else(|| format!("`{path}`: a path starts with `/`"))?;
    body.split('/')
        .filter(|s| !s.is_empty())
        .map(|part| {
            let (name, mut rest) = match part.find('[') {
                Some(k) => (&part[..k], &part[k..]),
                None => (part, ""),
            };
            let mut indexes = Vec::new();
            while let Some(r) = rest.strip_prefix('[') {
                let end = r
                    .find(']')
                    .ok_or_else(|| format!("`{part}`: `[` without `]`"))?;
                let inner = r[..end].trim();
                indexes.push(if inner == "*" {
                    Index::All
                } else {
                    Index::At(
                        inner
                            .parse()
                            .map_err(|_| format!("`{part}`: `[{inner}]` is not an index"))?,
                    )
                });
                rest = &r[end + 1..];
            }
            if !rest.is_empty() {
                return Err(format!("`{part}`: unexpected `{rest}`"));
            }
            Ok(Step {
                name: name.to_string(),
                indexes,
            })
        })
        .collect()
}

fn start<'f>(file: &'f P21File, step: &Step) -> Result<Vec<Node<'f>>, String> {
    let nodes: Vec<Node> = if let Some(n) = step.name.strip_prefix('#') {
        let id: u64 = n
            .parse()
            .map_err(|_| format!("`{}` is not an instance", step.name))?;
        let i = file
            .get(id)
            .ok_or_else(|| format!("#{id} is not in the file"))?;
        vec![Node::Inst(i)]
    } else {
        let want = step.name.to_ascii_uppercase();
        let want = schema::canonical(&want).to_string();
        if schema::entity(&want).is_none() {
            return Err(format!("`{}` is not an entity cncc knows", step.name));
        }
        file.instances
            .iter()
            .filter(|i| schema::canonical(&i.entity) == want)
            .map(Node::Inst)
            .collect()
    };
    index_all(file, nodes, &step.indexes)
}

fn apply<'f>(file: &'f P21File, nodes: &[Node<'f>], step: &Step) -> Result<Vec<Node<'f>>, String> {
    let mut out = Vec::new();
    let mut first_error = None;
    for n in nodes {
        match attribute(file, n, &step.name) {
            Ok(v) => out.push(v),
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    if out.is_empty() {
        if let Some(e) = first_error {
            return Err(e);
        }
    }
    index_all(file, out, &step.indexes)
}

/// The attribute `name` of a node (an instance, or a reference to one).
fn attribute<'f>(file: &'f P21File, n: &Node<'f>, name: &str) -> Result<Node<'f>, String> {
    let inst = match deref(file, n) {
        Some(i) => i,
        None => {
            return Err(match n {
                Node::Val(Value::List(_)) => {
                    format!("`{name}` applied to a list: add [*] or an index before it")
                }
                Node::Val(Value::Null) => format!("`{name}` applied to an unset value (`$`)"),
                _ => format!("`{name}` applied to a value that is not an instance"),
            })
        }
    };
    let def = schema::entity(&inst.entity)
        .ok_or_else(|| format!("#{} {} is not an entity cncc knows", inst.id, inst.entity))?;
    let k = def.attr_index(name).ok_or_else(|| {
        let names: Vec<&str> = def.attrs.iter().map(|a| a.name.as_str()).collect();
        format!(
            "{} has no attribute `{name}`; it has: {}",
            def.name,
            names.join(", ")
        )
    })?;
    let p = inst
        .params
        .get(k)
        .ok_or_else(|| format!("#{} has no parameter for `{name}`", inst.id))?;
    Ok(Node::Val(&p.value))
}

fn deref<'f>(file: &'f P21File, n: &Node<'f>) -> Option<&'f Instance> {
    match n {
        Node::Inst(i) => Some(i),
        Node::Val(Value::Ref(id)) => file.get(*id),
        _ => None,
    }
}

fn index_all<'f>(
    file: &'f P21File,
    mut nodes: Vec<Node<'f>>,
    idx: &[Index],
) -> Result<Vec<Node<'f>>, String> {
    for ix in idx {
        let mut out = Vec::new();
        for n in &nodes {
            let Node::Val(Value::List(items)) = n else {
                let what = match deref(file, n) {
                    Some(i) => format!("#{} {}", i.id, i.entity),
                    None => "a value".to_string(),
                };
                return Err(format!("an index applied to {what}, which is not a list"));
            };
            match ix {
                Index::All => out.extend(items.iter().map(|p| Node::Val(&p.value))),
                Index::At(k) => match items.get(*k) {
                    Some(p) => out.push(Node::Val(&p.value)),
                    None => {
                        return Err(format!(
                            "index [{k}] past the end of a list of {}",
                            items.len()
                        ))
                    }
                },
            }
        }
        nodes = out;
    }
    Ok(nodes)
}

fn show(n: &Node) -> String {
    match n {
        Node::Inst(i) => instance_line(i),
        Node::Val(Value::Str(s)) => s.clone(),
        Node::Val(v) => {
            let mut s = String::new();
            write_value(&mut s, v);
            s
        }
    }
}

/// `#18=CLOSED_POCKET('POCKET1',#4,...)` without the newline.
fn instance_line(i: &Instance) -> String {
    let mut s = String::new();
    super::part21::text::write_instance(&mut s, i);
    s.trim_end().trim_end_matches(';').to_string()
}

/// The `#id` line of the instance a post or check message names by its
/// `its_id` (a feature first, then an operation, then a workingstep), so
/// that every diagnostic about a project points into its Part 21 file.
pub fn locate_its_id(file: &P21File, its_id: &str) -> Option<crate::span::Span> {
    if its_id.is_empty() {
        return None;
    }
    let rank = |i: &Instance| -> Option<u8> {
        let def = super::schema::entity(&i.entity)?;
        let k = def.attr_index("its_id")?;
        match &i.params.get(k)?.value {
            Value::Str(s) if s == its_id => {}
            _ => return None,
        }
        Some(if def.attr_index("its_workpiece").is_some() {
            0
        } else if def.attr_index("its_tool").is_some() {
            1
        } else {
            2
        })
    };
    file.instances
        .iter()
        .filter_map(|i| rank(i).map(|r| (r, i.span)))
        .min_by_key(|(r, _)| *r)
        .map(|(_, s)| s)
}

/// The place a query path (`/project/main_workplan/its_elements[1]/
/// its_operation/its_technology`) leads to: the last parameter's (a `$`
/// too), or the instance's `#id` for a path of one step. The first
/// element where a step matches several.
pub fn locate_path(file: &P21File, path: &str) -> Option<crate::span::Span> {
    let steps = parse_path(path).ok()?;
    let (first, rest) = steps.split_first()?;
    let mut inst: &Instance = match start(file, first).ok()?.first()? {
        Node::Inst(i) => i,
        n => deref(file, n)?,
    };
    let mut span = inst.span;
    for (k, step) in rest.iter().enumerate() {
        let def = schema::entity(&inst.entity)?;
        let mut p: &super::part21::Param = inst.params.get(def.attr_index(&step.name)?)?;
        for ix in &step.indexes {
            let Value::List(items) = &p.value else {
                return None;
            };
            p = match ix {
                Index::At(i) => items.get(*i)?,
                Index::All => items.first()?,
            };
        }
        span = p.span;
        if k + 1 < rest.len() {
            let Value::Ref(id) = p.value else { return None };
            inst = file.get(id)?;
        }
    }
    Some(span)
}

/// Gives each diagnostic without a place the place of the query path
/// its message names between backquotes (`/project/...`), else the
/// `#id` line of the entity its message names first (by its_id).
pub fn locate_diagnostics(file: &P21File, diags: &mut [crate::diag::Diagnostic]) {
    for d in diags.iter_mut().filter(|d| d.labels.is_empty()) {
        let quoted: Vec<&str> = d.message.split('`').skip(1).step_by(2).collect();
        if let Some(span) = quoted
            .iter()
            .filter(|q| q.starts_with('/'))
            .find_map(|q| locate_path(file, q))
        {
            *d = d.clone().primary(span, "here");
            continue;
        }
        let Some(name) = quoted.first() else {
            continue;
        };
        if let Some(span) = locate_its_id(file, name) {
            *d = d.clone().primary(span, "this entity");
        }
    }
}
