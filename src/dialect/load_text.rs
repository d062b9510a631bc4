//! Reads `<text>`: what comments and messages may hold on the target
//! (see [`super::text`]). A `<text>` in an extending spec replaces the
//! inherited one whole.

use super::load_items::Ctx;
use super::text::{ActiveWord, Replace, TextForm, TextRules};
use super::xml::Node;

pub fn read_text(cx: &mut Ctx, n: &Node) -> TextRules {
    cx.check_attrs(
        n,
        &["charset", "comma-with", "prefix-with", "doc", "confidence"],
    );
    let mut r = TextRules {
        comma_with: ":".into(),
        prefix_with: "_".into(),
        ..TextRules::default()
    };
    if let Some(a) = n.attr("charset") {
        let parse = |s: &str| match s {
            "ascii" => Some(true),
            "utf-8" => Some(false),
            _ => None,
        };
        if let Some(v) = cx.parse(
            a,
            "`ascii` or `utf-8`",
            "the characters the target reads",
            parse,
        ) {
            r.ascii = v;
        }
    }
    for (name, slot) in [
        ("comma-with", &mut r.comma_with),
        ("prefix-with", &mut r.prefix_with),
    ] {
        if let Some(a) = n.attr(name) {
            *slot = a.value.clone();
        }
    }
    for c in &n.children {
        match c.name.as_str() {
            "replace" => {
                if let Some(x) = read_replace(cx, c) {
                    r.replace.push(x);
                }
            }
            "active" => {
                cx.check_attrs(c, &["word", "comma", "doc", "confidence"]);
                if let Some(w) = cx.req(c, "word") {
                    let word = w.value.trim().to_string();
                    let comma = cx.bool_attr(c, "comma", true);
                    r.active.push(ActiveWord { word, comma });
                }
            }
            _ => super::load_items::unknown_element(cx, c, "`<text>`", &["replace", "active"]),
        }
    }
    r
}

fn read_replace(cx: &mut Ctx, c: &Node) -> Option<Replace> {
    cx.check_attrs(c, &["char", "with", "in", "doc", "confidence"]);
    let ch = cx.req(c, "char")?;
    let ch = cx.parse(ch, "one character", "as in `%`", |s| {
        let mut it = s.chars();
        match (it.next(), it.next()) {
            (Some(ch), None) => Some(ch),
            _ => None,
        }
    })?;
    let with = c
        .attr("with")
        .map(|a| a.value.clone())
        .unwrap_or_else(|| " ".into());
    let form = match c.attr("in") {
        Some(a) => Some(cx.parse(
            a,
            "a text form",
            "paren, semicolon, quoted or plain",
            TextForm::parse,
        )?),
        None => None,
    };
    Some(Replace { ch, with, form })
}
