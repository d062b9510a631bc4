//! Reads a dialect spec (`dialects/*.xml`, schema `dialects/dialect.xsd`)
//! into a [`DialectSpec`]: resolves `extends` (a child overrides inherited
//! entries with the same key, `<remove>` drops one) and reports every
//! mistake as a diagnostic pointing into the XML file.

use super::load_items::*;
use super::load_seen::{code_key, Codes, Seen};
use super::spec::*;
use super::xml::{self, Node};
use crate::diag::{Code, Diagnostic};
use crate::ir::Decimal;
use crate::span::FileId;
use std::sync::Arc;

const ROOT_ATTRS: &[&str] = &["id", "name", "family", "extends", "repeat-letter"];
const ELEMENTS: &[&str] = &[
    "doc",
    "alias",
    "extension",
    "capability",
    "numbers",
    "group",
    "address",
    "code",
    "code-range",
    "cycle",
    "function",
    "command",
    "variables",
    "remove",
    "text",
    "post-template",
    "constant",
];

/// Reads one spec. `resolve_base` finds the (already loaded) spec that
/// `extends` names, by id or alias.
pub fn load_spec(
    text: &str,
    file: FileId,
    resolve_base: &dyn Fn(&str) -> Option<Arc<DialectSpec>>,
) -> Result<DialectSpec, Vec<Diagnostic>> {
    let root = xml::parse(text, file).map_err(|d| vec![d])?;
    let mut cx = Ctx::default();
    let spec = read_root(&mut cx, &root, resolve_base);
    match spec {
        Some(mut s) if cx.diags.is_empty() => {
            s.reindex();
            Ok(s)
        }
        _ => Err(cx.diags),
    }
}

fn read_root(
    cx: &mut Ctx,
    root: &Node,
    resolve_base: &dyn Fn(&str) -> Option<Arc<DialectSpec>>,
) -> Option<DialectSpec> {
    if root.name != "dialect" {
        cx.diags.push(
            Diagnostic::new(
                Code::SpecUnknownItem,
                format!("the root element is `<{}>`", root.name),
            )
            .primary(root.span, "expected `<dialect>`")
            .help("a dialect spec is one `<dialect id=\"...\" ...>` element"),
        );
        return None;
    }
    cx.check_attrs(root, ROOT_ATTRS);
    let id = cx
        .req(root, "id")
        .map(|a| a.value.trim().to_ascii_lowercase());
    let base = match root.attr("extends") {
        Some(a) => match resolve_base(a.value.trim()) {
            Some(b) => Some(b),
            None => {
                cx.diags.push(
                    Diagnostic::new(Code::SpecUnknownBase, format!("no dialect `{}` to extend", a.value))
                        .primary(a.value_span, "unknown dialect")
                        .help("extend a built-in dialect (fanuc, haas, linuxcnc, siemens840d, iso6983) or one loaded before"),
                );
                return None;
            }
        },
        None => None,
    };
    let mut spec = start_spec(cx, root, id?, base.as_deref())?;
    read_children(cx, root, &mut spec);
    Some(spec)
}

/// The spec before the children are read: a copy of the base or empty.
fn start_spec(
    cx: &mut Ctx,
    root: &Node,
    id: String,
    base: Option<&DialectSpec>,
) -> Option<DialectSpec> {
    let family_attr = if base.is_some() {
        root.attr("family")
    } else {
        cx.req(root, "family")
    };
    let family = match family_attr {
        Some(a) => Some(cx.parse(
            a,
            "a syntax family",
            "families: word-address, sinumerik, klartext",
            Family::parse,
        )?),
        None => None,
    };
    let mut spec = match base {
        Some(b) => {
            if let (Some(f), Some(a)) = (family, family_attr) {
                if f != b.family {
                    cx.bad(
                        a,
                        &format!("the family of `{}` ({})", b.id, b.family.name()),
                        "a spec extends a dialect of its own syntax family",
                    );
                }
            }
            let mut s = b.clone();
            s.extends = Some(b.id.clone());
            s.ancestors.insert(0, b.id.clone());
            s.aliases.clear();
            s.extensions.clear();
            s.doc.clear();
            s.id = id.clone();
            s
        }
        None => DialectSpec::new(id.clone(), String::new(), family?, default_numbers()),
    };
    spec.name = root
        .attr("name")
        .map(|a| a.value.trim().to_string())
        .unwrap_or(id);
    if let Some(a) = root.attr("repeat-letter") {
        if let Some(c) = cx.letter_attr(a) {
            spec.repeat_letter = c;
        }
    }
    Some(spec)
}

/// The number rules used for attributes a spec without a base leaves out.
pub fn default_numbers() -> NumberRules {
    NumberRules {
        integer_lengths: IntegerLengths::Units,
        increment_mm: Decimal::parse("0.001").unwrap_or(Decimal::from_int(0)),
        increment_inch: Decimal::parse("0.0001").unwrap_or(Decimal::from_int(0)),
        length_places_mm: 3,
        length_places_inch: 4,
        point_on_lengths: false,
        feed_places: 3,
        angle_places: 3,
        integer_digits: 8,
    }
}

fn read_children(cx: &mut Ctx, root: &Node, spec: &mut DialectSpec) {
    let mut seen = Seen::default();
    let mut codes = Codes::new(std::mem::take(&mut spec.codes));
    // Groups first: codes refer to them wherever they are declared.
    for n in root.children.iter().filter(|n| n.name == "group") {
        if let Some(g) = read_group(cx, n) {
            seen.check(
                cx,
                format!("group {}", g.name),
                &format!("group `{}`", g.name),
                n.span,
            );
            upsert(&mut spec.groups, g, |a, b| a.name == b.name);
        }
    }
    let mut numbers_seen = false;
    for n in &root.children {
        match n.name.as_str() {
            "group" => {}
            "doc" => {
                cx.check_attrs(n, &[]);
                spec.doc = n.text.split_whitespace().collect::<Vec<_>>().join(" ");
            }
            "numbers" => {
                if numbers_seen {
                    seen.check(cx, "numbers".into(), "`<numbers>`", n.span);
                }
                numbers_seen = true;
                read_numbers(cx, n, &mut spec.numbers);
            }
            "remove" => read_remove(cx, n, spec, &mut codes),
            "text" => {
                seen.check(cx, "text".into(), "`<text>`", n.span);
                spec.text = super::load_text::read_text(cx, n);
            }
            _ => read_entry(cx, n, spec, &mut seen, &mut codes),
        }
    }
    spec.codes = codes.finish();
}

/// Every element that adds or overrides one entry.
fn read_entry(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, seen: &mut Seen, codes: &mut Codes) {
    match n.name.as_str() {
        "alias" | "extension" | "capability" | "command" => read_name_entry(cx, n, spec, seen),
        "post-template" => read_post_template(cx, n, spec, seen),
        "constant" => read_constant(cx, n, spec, seen),
        "address" => {
            if let Some(a) = read_address(cx, n) {
                seen.check(
                    cx,
                    format!("address {}", a.letter),
                    &format!("address `{}`", a.letter),
                    n.span,
                );
                upsert(&mut spec.addresses, a, |x, y| x.letter == y.letter);
            }
        }
        "code" => {
            if let Some(c) = read_code(cx, n, &spec.groups) {
                add_code(cx, codes, seen, c);
            }
        }
        "code-range" => {
            for c in read_code_range(cx, n, &spec.groups) {
                add_code(cx, codes, seen, c);
            }
        }
        "cycle" => {
            if let Some(c) = read_cycle(cx, n) {
                seen.check(
                    cx,
                    format!("cycle {}", c.name),
                    &format!("cycle `{}`", c.name),
                    n.span,
                );
                upsert(&mut spec.cycles, c, |x, y| x.name == y.name);
            }
        }
        "function" => {
            if let Some(f) = read_function(cx, n) {
                seen.check(
                    cx,
                    format!("function {}", f.name),
                    &format!("function `{}`", f.name),
                    n.span,
                );
                upsert(&mut spec.functions, f, |x, y| x.name == y.name);
            }
        }
        "variables" => {
            if let Some(v) = read_variables(cx, n) {
                seen.check(
                    cx,
                    format!("vars {}{}", v.prefix, v.first),
                    &format!("variables from {}{}", v.prefix, v.first),
                    n.span,
                );
                add_variables(spec, v, seen);
            }
        }
        _ => unknown_element(cx, n, "<dialect>", ELEMENTS),
    }
}

fn add_code(cx: &mut Ctx, codes: &mut Codes, seen: &mut Seen, c: CodeDef) {
    let key = code_key(c.letter, c.code);
    seen.check(cx, format!("code {key}"), &format!("code `{key}`"), c.span);
    codes.upsert(c);
}

/// The first `<variables>` of a spec replaces the inherited list.
fn add_variables(spec: &mut DialectSpec, v: VarRange, seen: &Seen) {
    let first_here = seen.vars == 1;
    if first_here {
        spec.variables.clear();
    }
    spec.variables.push(v);
}

/// `<alias name=/>`, `<extension name=/>`, `<capability name=/>`, `<command name=/>`.
fn read_name_entry(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, seen: &mut Seen) {
    if n.name == "command" {
        cx.check_attrs(n, &["name", "doc", "confidence", "meaning", "run"]);
    } else {
        cx.check_attrs(n, &["name", "doc", "confidence"]);
    }
    let Some(a) = cx.req(n, "name") else { return };
    let v = a.value.trim().to_string();
    seen.check(
        cx,
        format!("{} {}", n.name, v.to_ascii_lowercase()),
        &format!("{} `{v}`", n.name),
        n.span,
    );
    match n.name.as_str() {
        "alias" => spec.aliases.push(v.to_ascii_lowercase()),
        "extension" => spec
            .extensions
            .push(v.trim_start_matches('.').to_ascii_lowercase()),
        "capability" => {
            let help = format!(
                "capabilities: {}",
                CAPABILITIES
                    .iter()
                    .map(|(n, _)| *n)
                    .collect::<Vec<_>>()
                    .join(", ")
            );
            if let Some(c) = cx.parse(a, "a capability", &help, Capability::parse) {
                spec.capabilities.insert(c);
            }
        }
        _ => {
            if !spec.is_command(&v) {
                spec.commands.push(v.to_ascii_uppercase());
            }
            read_command_attrs(cx, n, spec, &v);
        }
    }
}

/// `<constant name= value=/>`: a name the control defines for every
/// program (Siemens `_ROUGH` for CYCLE832's machining type), read as its
/// number.
fn read_constant(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, seen: &mut Seen) {
    cx.check_attrs(n, &["name", "value", "doc", "confidence"]);
    let (Some(name), Some(value)) = (cx.req(n, "name"), cx.req(n, "value")) else {
        return;
    };
    let name = name.value.trim().to_ascii_uppercase();
    let help = "a decimal number, such as `3` or `0.5`";
    let Some(v) = cx.parse(value, "a number", help, |s| Decimal::parse(s).ok()) else {
        return;
    };
    seen.check(
        cx,
        format!("constant {name}"),
        &format!("constant `{name}`"),
        n.span,
    );
    spec.constants.retain(|(k, _)| *k != name);
    spec.constants.push((name, v));
}

/// A command's `meaning="machine-coords"` and `run="pass"`.
fn read_command_attrs(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, v: &str) {
    let name = v.to_ascii_uppercase();
    if let Some(a) = n.attr("meaning") {
        let help = "a meaning of the code tables, such as `machine-coords`";
        if let Some(m) = cx.parse(a, "a meaning", help, crate::dialect::Meaning::parse) {
            spec.command_meanings.retain(|(c, _)| *c != name);
            spec.command_meanings.push((name.clone(), m));
        }
    }
    if let Some(a) = n.attr("run") {
        if cx
            .parse(a, "`pass`", "the only run a command takes is `pass`", |s| {
                (s == "pass").then_some(())
            })
            .is_some()
            && !spec.command_passes(&name)
        {
            spec.passing_commands.push(name);
        }
    }
}

/// `<post-template name="drill"/>`: a template the target's post has.
fn read_post_template(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, seen: &mut Seen) {
    use super::post_templates::{is_post_template, PostTemplateDecl, POST_TEMPLATES};
    cx.check_attrs(n, &["name", "doc", "confidence"]);
    let Some(a) = cx.req(n, "name") else { return };
    let help = format!(
        "post templates: {}",
        POST_TEMPLATES
            .iter()
            .map(|(n, _)| *n)
            .collect::<Vec<_>>()
            .join(", ")
    );
    let Some(name) = cx.parse(a, "a post template", &help, |v| {
        let v = v.trim_end_matches(".j2");
        is_post_template(v).then(|| v.to_string())
    }) else {
        return;
    };
    seen.check(
        cx,
        format!("post-template {name}"),
        &format!("post template `{name}`"),
        n.span,
    );
    let decl = PostTemplateDecl { name, span: n.span };
    upsert(&mut spec.post_templates, decl, |x, y| x.name == y.name);
}

fn read_numbers(cx: &mut Ctx, n: &Node, r: &mut NumberRules) {
    const ATTRS: &[&str] = &[
        "integer-lengths",
        "increment-mm",
        "increment-inch",
        "length-places-mm",
        "length-places-inch",
        "point-on-lengths",
        "feed-places",
        "angle-places",
        "integer-digits",
        "doc",
        "confidence",
    ];
    cx.check_attrs(n, ATTRS);
    if let Some(a) = n.attr("integer-lengths") {
        let parse = |s: &str| match s {
            "units" => Some(IntegerLengths::Units),
            "increments" => Some(IntegerLengths::Increments),
            _ => None,
        };
        if let Some(v) = cx.parse(
            a,
            "`units` or `increments`",
            "`units`: X10 is 10 mm; `increments`: X10 is 10 least increments",
            parse,
        ) {
            r.integer_lengths = v;
        }
    }
    for (name, slot) in [
        ("increment-mm", &mut r.increment_mm),
        ("increment-inch", &mut r.increment_inch),
    ] {
        if let Some(a) = n.attr(name) {
            let parse = |s: &str| Decimal::parse(s).ok().filter(|d| !d.is_negative());
            if let Some(v) = cx.parse(a, "a positive decimal", "as in `0.001`", parse) {
                *slot = v;
            }
        }
    }
    let places = [
        ("length-places-mm", &mut r.length_places_mm),
        ("length-places-inch", &mut r.length_places_inch),
        ("feed-places", &mut r.feed_places),
        ("angle-places", &mut r.angle_places),
    ];
    if let Some(a) = n.attr("integer-digits") {
        if let Some(v) = cx.parse(a, "a count of digits from 1 to 12", "as in `5`", |s| {
            s.parse::<u8>().ok().filter(|p| (1..=12).contains(p))
        }) {
            r.integer_digits = v;
        }
    }
    for (name, slot) in places {
        if let Some(a) = n.attr(name) {
            if let Some(v) = cx.parse(a, "a count of places from 0 to 9", "as in `3`", |s| {
                s.parse::<u8>().ok().filter(|p| *p < 10)
            }) {
                *slot = v;
            }
        }
    }
    r.point_on_lengths = cx.bool_attr(n, "point-on-lengths", r.point_on_lengths);
}

/// Replaces the entry `same` as `item`, or appends it.
fn upsert<T>(list: &mut Vec<T>, item: T, same: impl Fn(&T, &T) -> bool) {
    match list.iter().position(|x| same(x, &item)) {
        Some(i) => list[i] = item,
        None => list.push(item),
    }
}

/// `<remove letter= number=/>` or `<remove cycle|function|capability|command|address|group=/>`.
fn read_remove(cx: &mut Ctx, n: &Node, spec: &mut DialectSpec, codes: &mut Codes) {
    const KINDS: &[&str] = &[
        "cycle",
        "function",
        "capability",
        "command",
        "address",
        "group",
        "post-template",
    ];
    let mut allowed = vec!["letter", "number", "doc"];
    allowed.extend(KINDS);
    cx.check_attrs(n, &allowed);
    let found = if n.attr("number").is_some() || n.attr("letter").is_some() {
        remove_code(cx, n, codes)
    } else if let Some(kind) = KINDS.iter().find(|k| n.attr(k).is_some()) {
        remove_named(n, kind, spec)
    } else {
        cx.diags.push(
            Diagnostic::new(Code::SpecMissing, "`<remove>` does not say what to remove")
                .primary(n.span, "nothing named")
                .help("write `letter=\"M\" number=\"97\"`, or one of cycle=, function=, capability=, command=, address=, group=, post-template="),
        );
        return;
    };
    if let Some((false, a)) = found {
        cx.bad(
            a,
            "an inherited entry",
            "`<remove>` drops an entry inherited from the base; check the name",
        );
    }
}

fn remove_code<'n>(cx: &mut Ctx, n: &'n Node, codes: &mut Codes) -> Option<(bool, &'n xml::Attr)> {
    let letter = code_letter(cx, n);
    let num_attr = cx.req(n, "number")?;
    let code = code_number(cx, num_attr)?;
    let letter = letter?;
    Some((codes.remove(letter, code), num_attr))
}

fn remove_named<'n>(
    n: &'n Node,
    kind: &str,
    spec: &mut DialectSpec,
) -> Option<(bool, &'n xml::Attr)> {
    let a = n.attr(kind)?;
    let v = a.value.trim();
    let before = count(spec);
    match kind {
        "cycle" => spec.cycles.retain(|c| !c.name.eq_ignore_ascii_case(v)),
        "function" => spec.functions.retain(|f| !f.name.eq_ignore_ascii_case(v)),
        "capability" => spec.capabilities.retain(|c| c.name() != v),
        "command" => {
            spec.commands.retain(|c| !c.eq_ignore_ascii_case(v));
            spec.command_meanings
                .retain(|(c, _)| !c.eq_ignore_ascii_case(v));
            spec.passing_commands.retain(|c| !c.eq_ignore_ascii_case(v));
        }
        "address" => spec
            .addresses
            .retain(|x| !x.letter.to_string().eq_ignore_ascii_case(v)),
        "post-template" => spec
            .post_templates
            .retain(|t| t.name != v.trim_end_matches(".j2")),
        _ => spec.groups.retain(|g| g.name != v),
    }
    Some((count(spec) < before, a))
}

fn count(s: &DialectSpec) -> usize {
    s.cycles.len()
        + s.functions.len()
        + s.capabilities.len()
        + s.commands.len()
        + s.addresses.len()
        + s.groups.len()
        + s.post_templates.len()
}
