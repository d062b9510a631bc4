//! A small element tree read from a dialect spec with quick-xml, keeping the
//! byte span of every tag, attribute name and attribute value so the spec
//! loader can point its diagnostics into the XML file.

use crate::diag::{Code, Diagnostic};
use crate::span::{FileId, Span};
use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

/// Deepest nesting accepted; specs are three levels deep.
const MAX_DEPTH: usize = 32;

/// One attribute with where its name and its value are.
#[derive(Clone, Debug)]
pub struct Attr {
    pub name: String,
    pub value: String,
    pub name_span: Span,
    pub value_span: Span,
}

/// One element: its start tag, attributes, children and text.
#[derive(Clone, Debug)]
pub struct Node {
    pub name: String,
    /// The start tag (or the whole empty-element tag).
    pub span: Span,
    pub attrs: Vec<Attr>,
    pub children: Vec<Node>,
    pub text: String,
}

impl Node {
    pub fn attr(&self, name: &str) -> Option<&Attr> {
        self.attrs.iter().find(|a| a.name == name)
    }
}

/// Reads the whole document; the root element is returned.
pub fn parse(text: &str, file: FileId) -> Result<Node, Diagnostic> {
    let mut reader = Reader::from_str(text);
    reader.config_mut().check_end_names = true;
    let mut stack: Vec<Node> = Vec::new();
    let mut root: Option<Node> = None;
    loop {
        let before = reader.buffer_position() as usize;
        let event = reader.read_event().map_err(|e| {
            let at = reader.error_position() as usize;
            malformed(file, at, (at + 1).min(text.len()), &e.to_string())
        })?;
        let after = reader.buffer_position() as usize;
        let tag = Span::new(file, before, after);
        match event {
            Event::Start(e) => {
                if stack.len() >= MAX_DEPTH {
                    return Err(malformed(file, before, after, "elements nested too deeply"));
                }
                stack.push(node(&e, text, tag)?);
            }
            Event::Empty(e) => {
                let n = node(&e, text, tag)?;
                attach(&mut stack, &mut root, n, tag)?;
            }
            Event::End(_) => {
                let n = stack.pop().ok_or_else(|| {
                    malformed(file, before, after, "closing tag without opening tag")
                })?;
                attach(&mut stack, &mut root, n, tag)?;
            }
            Event::Text(t) => push_text(&mut stack, &t.xml10_content()),
            Event::CData(t) => push_text(&mut stack, &t),
            Event::GeneralRef(r) => {
                let s = resolve_ref(&r)
                    .ok_or_else(|| malformed(file, before, after, "unknown entity reference"))?;
                push_text(&mut stack, &s);
            }
            Event::Comment(_) | Event::Decl(_) | Event::PI(_) | Event::DocType(_) => {}
            Event::Eof => break,
        }
    }
    if let Some(open) = stack.last() {
        return Err(malformed(
            file,
            open.span.start as usize,
            open.span.end as usize,
            &format!("element `{}` is not closed", open.name),
        ));
    }
    root.ok_or_else(|| malformed(file, 0, 0, "the file has no root element"))
}

fn push_text(stack: &mut [Node], s: &str) {
    if let Some(top) = stack.last_mut() {
        top.text.push_str(s);
    }
}

fn resolve_ref(r: &quick_xml::events::BytesRef) -> Option<String> {
    if r.is_char_ref() {
        return r.resolve_char_ref().ok().flatten().map(String::from);
    }
    let name: &str = r;
    let s = match name {
        "amp" => "&",
        "lt" => "<",
        "gt" => ">",
        "quot" => "\"",
        "apos" => "'",
        _ => return None,
    };
    Some(s.to_string())
}

fn attach(
    stack: &mut [Node],
    root: &mut Option<Node>,
    n: Node,
    at: Span,
) -> Result<(), Diagnostic> {
    match stack.last_mut() {
        Some(parent) => parent.children.push(n),
        None if root.is_none() => *root = Some(n),
        None => {
            return Err(malformed(
                at.file,
                at.start as usize,
                at.end as usize,
                "a second root element",
            ));
        }
    }
    Ok(())
}

fn malformed(file: FileId, start: usize, end: usize, msg: &str) -> Diagnostic {
    Diagnostic::new(
        Code::SpecMalformed,
        format!("the dialect spec is not well-formed XML: {msg}"),
    )
    .primary(
        Span::new(file, start, end.max(start)),
        "the XML reader stopped here",
    )
    .help("check that every tag is closed, attribute values are quoted, and `&` is written `&amp;`")
}

fn node(e: &BytesStart, text: &str, tag: Span) -> Result<Node, Diagnostic> {
    let raw = text.get(tag.range()).unwrap_or("");
    let spans = attr_spans(raw, tag.start as usize);
    let mut attrs = Vec::new();
    for (i, a) in e.attributes().enumerate() {
        let a = a.map_err(|err| {
            // Attribute errors count from the byte after `<`.
            let at = (tag.start as usize + 1 + attr_error_offset(&err)).min(tag.end as usize);
            let start = Span::new(tag.file, tag.start as usize, tag.start as usize + 1);
            malformed(
                tag.file,
                at,
                (at + 1).min(tag.end as usize),
                &err.to_string(),
            )
            .secondary(start, "in the tag that starts here")
        })?;
        let value = a
            .normalized_value(quick_xml::XmlVersion::Implicit1_0)
            .map_err(|err| {
                malformed(
                    tag.file,
                    tag.start as usize,
                    tag.end as usize,
                    &err.to_string(),
                )
            })?;
        let key: &str = a.key.as_ref();
        let (ns, vs) = spans.get(i).copied().unwrap_or((
            (tag.start as usize, tag.end as usize),
            (tag.start as usize, tag.end as usize),
        ));
        attrs.push(Attr {
            name: key.to_string(),
            value: value.into_owned(),
            name_span: Span::new(tag.file, ns.0, ns.1),
            value_span: Span::new(tag.file, vs.0, vs.1),
        });
    }
    let qname = e.name();
    let name: &str = qname.as_ref();
    Ok(Node {
        name: name.to_string(),
        span: tag,
        attrs,
        children: Vec::new(),
        text: String::new(),
    })
}

fn attr_error_offset(e: &quick_xml::events::attributes::AttrError) -> usize {
    use quick_xml::events::attributes::AttrError as E;
    match *e {
        E::ExpectedEq(p)
        | E::ExpectedValue(p)
        | E::UnquotedValue(p)
        | E::ExpectedQuote(p, _)
        | E::Duplicated(p, _) => p,
    }
}

type Range2 = ((usize, usize), (usize, usize));

/// Finds each `name="value"` in a raw start tag: spans of names and values
/// (values without their quotes), in order.
fn attr_spans(raw: &str, base: usize) -> Vec<Range2> {
    let b = raw.as_bytes();
    let mut out = Vec::new();
    let mut i = 1;
    while i < b.len() && !is_space(b[i]) && b[i] != b'>' && b[i] != b'/' {
        i += 1;
    }
    loop {
        while i < b.len() && is_space(b[i]) {
            i += 1;
        }
        if i >= b.len() || b[i] == b'>' || b[i] == b'/' {
            return out;
        }
        let ns = i;
        while i < b.len() && b[i] != b'=' && !is_space(b[i]) {
            i += 1;
        }
        let ne = i;
        while i < b.len() && (is_space(b[i]) || b[i] == b'=') {
            i += 1;
        }
        let Some(&q) = b.get(i) else { return out };
        if q != b'"' && q != b'\'' {
            return out;
        }
        let vs = i + 1;
        let Some(len) = b[vs..].iter().position(|&c| c == q) else {
            return out;
        };
        let ve = vs + len;
        out.push(((base + ns, base + ne), (base + vs, base + ve)));
        i = ve + 1;
    }
}

fn is_space(c: u8) -> bool {
    matches!(c, b' ' | b'\t' | b'\r' | b'\n')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_tree_with_spans() {
        let t = "<a x=\"1\">\n  <b y='two &amp; three'/>text</a>";
        let n = parse(t, FileId(0)).unwrap();
        assert_eq!(n.name, "a");
        assert_eq!(n.text.trim(), "text");
        let b = &n.children[0];
        let y = b.attr("y").unwrap();
        assert_eq!(y.value, "two & three");
        assert_eq!(&t[y.value_span.range()], "two &amp; three");
        assert_eq!(&t[y.name_span.range()], "y");
        assert_eq!(&t[b.span.range()], "<b y='two &amp; three'/>");
    }

    #[test]
    fn mismatched_end_is_malformed() {
        let e = parse("<a><b></a>", FileId(0)).unwrap_err();
        assert_eq!(e.code, Code::SpecMalformed);
    }

    #[test]
    fn unclosed_is_malformed() {
        let e = parse("<a><b/>", FileId(0)).unwrap_err();
        assert_eq!(e.code, Code::SpecMalformed);
    }
}
