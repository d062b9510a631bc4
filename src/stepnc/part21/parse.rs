//! Reading a Part 21 text into the generic [`P21File`]: the token stream is
//! cut at `;`, the section structure (ISO-10303-21, HEADER, DATA, ENDSEC)
//! is followed here and every statement goes to the LALRPOP grammar on its
//! own, so one bad instance costs only itself.

use super::lexer::{tokens, Tok};
use super::{Instance, P21File, Stmt, Value};
use crate::diag::{Code, Diagnostic};
use crate::span::{FileId, Span};

lalrpop_util::lalrpop_mod!(
    #[allow(clippy::all, unused_parens, dead_code, unused_imports)]
    grammar,
    "/part21.rs"
);

type Spanned = (usize, Tok, usize);

/// Deepest parenthesis nesting read (values are freed and written
/// recursively).
const MAX_NESTING: usize = 64;

/// The `(` that nests too deep, if any.
fn too_deep(toks: &[Spanned]) -> Option<&Spanned> {
    let mut depth = 0usize;
    for t in toks {
        match t.1 {
            Tok::LParen => {
                depth += 1;
                if depth > MAX_NESTING {
                    return Some(t);
                }
            }
            Tok::RParen => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Section {
    Before,
    Header,
    Between,
    Data,
    After,
}

impl Section {
    fn place(self) -> &'static str {
        match self {
            Section::Before => "before its HEADER section",
            Section::Header => "inside its HEADER section",
            Section::Between => "after a section's ENDSEC",
            Section::Data => "inside its DATA section",
            Section::After => "after END-ISO-10303-21",
        }
    }
}

/// Reads a Part 21 text; diagnostics for every statement that cannot be
/// read (it is skipped) and for a broken file structure.
pub fn parse(src: &str, file: FileId) -> (P21File, Vec<Diagnostic>) {
    parse_with(src, file, true)
}

/// [`parse`], with or without the fast path for well-formed statements
/// (off only in the test comparing the two).
pub fn parse_with(src: &str, file: FileId, fast_path: bool) -> (P21File, Vec<Diagnostic>) {
    parse_within(src, file, fast_path, MAX_GRAPH_BYTES)
}

/// [`parse_with`], reading instances up to `budget` bytes of memory (E0813).
fn parse_within(
    src: &str,
    file: FileId,
    fast_path: bool,
    budget: usize,
) -> (P21File, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    let mut out = P21File::default();
    let mut stmt: Vec<Spanned> = Vec::new();
    let mut section = Section::Before;
    let parser = grammar::StatementParser::new();
    let mut open_string = false;
    let mut cap = crate::diag::PerCode::default();
    let mut graph_bytes = 0usize;
    for t in tokens(src) {
        let from = diags.len();
        match t {
            Err((a, b)) => diags.push(unreadable(file, a, b, "a character that starts no token")),
            Ok((a, Tok::OpenComment, _)) => {
                diags.push(unreadable(file, a, a + 2, "this comment is never closed"))
            }
            Ok((a, Tok::OpenString, _)) => {
                // It runs to the end of the file.
                diags.push(unreadable(file, a, a + 1, "this string is never closed"));
                stmt.clear();
                open_string = true;
            }
            Ok((_, Tok::Semi, b)) => {
                let s = std::mem::take(&mut stmt);
                let cx = Cx {
                    src,
                    file,
                    parser: &parser,
                    fast_path,
                };
                let n = out.instances.len();
                section = statement(&cx, &s, b, section, &mut out, &mut diags);
                if let Some(i) = out.instances.get(n) {
                    graph_bytes += instance_bytes(i);
                    if graph_bytes > budget {
                        cap.finish(&mut diags);
                        diags.push(too_large(i, budget));
                        return (out, diags);
                    }
                }
            }
            Ok(t) => stmt.push(t),
        }
        if diags.len() > from {
            cap.admit(&mut diags, from);
        }
    }
    cap.finish(&mut diags);
    if let Some(&(a, _, b)) = stmt.first() {
        diags.push(syntax(
            file,
            a,
            b,
            "the file ends inside a statement (a `;` is missing)",
        ));
    }
    if section != Section::After && !open_string {
        let at = src.len();
        diags.push(
            Diagnostic::new(
                Code::P21Structure,
                "the file does not end with `END-ISO-10303-21;`",
            )
            .primary(Span::new(file, at, at), "file ends here")
            .help(format!(
                "the file stops {}; a truncated file?",
                section.place()
            )),
        );
    }
    (out, diags)
}

/// The most memory the instances read may take (estimated by
/// [`instance_bytes`]): with the text, a file stays under 2 GB.
pub const MAX_GRAPH_BYTES: usize = 1536 << 20;

/// About what an instance takes in memory: the record, its name and its
/// parameters (48 bytes each for two bytes of `$,`).
fn instance_bytes(i: &Instance) -> usize {
    fn params(ps: &[super::Param]) -> usize {
        ps.iter()
            .map(|p| {
                std::mem::size_of::<super::Param>()
                    + match &p.value {
                        Value::Str(s) | Value::Enum(s) | Value::Binary(s) => s.len(),
                        Value::List(l) => params(l),
                        Value::Typed(t, inner) => t.len() + params(std::slice::from_ref(inner)),
                        _ => 0,
                    }
            })
            .sum()
    }
    let parts: usize = i
        .more_parts
        .iter()
        .map(|r| std::mem::size_of::<super::Record>() + r.entity.len() + params(&r.params))
        .sum();
    std::mem::size_of::<Instance>() + 32 + params(&i.params) + parts
}

/// E0813 at the instance that passed the budget.
fn too_large(i: &Instance, budget: usize) -> Diagnostic {
    Diagnostic::new(
        Code::P21TooLarge,
        format!(
            "the file holds more instance data than cncc reads ({} MB in memory)",
            budget >> 20
        ),
    )
    .primary(i.span, "reading stops here")
    .help("ISO 14649 programs are far smaller; check the generator, or split the file")
}

/// What every statement is read with.
struct Cx<'a> {
    src: &'a str,
    file: FileId,
    parser: &'a grammar::StatementParser,
    fast_path: bool,
}

fn statement(
    cx: &Cx<'_>,
    toks: &[Spanned],
    end: usize,
    section: Section,
    out: &mut P21File,
    diags: &mut Vec<Diagnostic>,
) -> Section {
    let (src, file) = (cx.src, cx.file);
    if let Some(&(a, _, b)) = too_deep(toks) {
        diags.push(
            Diagnostic::new(
                Code::P21TooDeep,
                format!("parentheses nest more than {MAX_NESTING} deep"),
            )
            .primary(Span::new(file, a, b), "too deep")
            .help("ISO 14649 data nests lists a few levels at most; this statement is skipped"),
        );
        return section;
    }
    let Some(&(a, first, b)) = toks.first() else {
        diags.push(syntax(file, end - 1, end, "an empty statement"));
        return section;
    };
    let word = &src[a..b];
    let lone = toks.len() == 1;
    let next = match (section, first, word) {
        (Section::Before, Tok::Begin, _) if lone => Some(Section::Before),
        (Section::Before, Tok::Keyword, "HEADER") if lone => Some(Section::Header),
        (Section::Header | Section::Data, Tok::Keyword, "ENDSEC") if lone => Some(Section::Between),
        // DATA; or, from edition 3 on, DATA('name',('schema'));
        (Section::Between, Tok::Keyword, "DATA") => Some(Section::Data),
        (Section::Between, Tok::End, _) if lone => Some(Section::After),
        _ => None,
    };
    if let Some(n) = next {
        return n;
    }
    match section {
        Section::Header | Section::Data => {}
        _ => {
            diags.push(
                Diagnostic::new(
                    Code::P21Structure,
                    format!("`{word}` outside the HEADER and DATA sections"),
                )
                .primary(Span::new(file, a, b), "not expected here")
                .help("a Part 21 file is `ISO-10303-21; HEADER; ... ENDSEC; DATA; ... ENDSEC; END-ISO-10303-21;`"),
            );
            return section;
        }
    }
    let fast = if cx.fast_path {
        super::fast::statement(src, file, toks)
    } else {
        None
    };
    let parsed = match fast {
        Some(stmt) => Ok(stmt),
        None => {
            let feed = toks.iter().map(|&t| Ok::<_, (usize, usize, String)>(t));
            cx.parser.parse(src, file, feed)
        }
    };
    match parsed {
        Ok(Stmt::Header(r)) if section == Section::Header => out.header.push(r),
        Ok(Stmt::Instance { id, id_span, parts }) if section == Section::Data => {
            add_instance(out, id, id_span, parts, diags)
        }
        Ok(_) => diags.push(syntax(
            file,
            a,
            b,
            if section == Section::Header {
                "an instance in the HEADER section"
            } else {
                "a header entity in the DATA section (`#n=` is missing)"
            },
        )),
        Err(e) => diags.push(parse_error(file, e, end)),
    }
    section
}

fn add_instance(
    out: &mut P21File,
    id: u64,
    span: Span,
    mut parts: Vec<crate::stepnc::part21::Record>,
    diags: &mut Vec<Diagnostic>,
) {
    if let Some(first) = out.get(id) {
        diags.push(
            Diagnostic::new(Code::DuplicateInstance, format!("#{id} is defined twice"))
                .primary(span, "second definition")
                .secondary(first.span, "first definition, the one kept")
                .help("give the second instance a number of its own"),
        );
        return;
    }
    let first = parts.remove(0);
    // A simple instance keeps no allocation for the parts it does not have
    // (80 bytes each, 800 MB in a file of ten million instances).
    let more_parts = if parts.is_empty() { Vec::new() } else { parts };
    out.push(Instance {
        id,
        entity: first.entity,
        params: first.params,
        span,
        entity_span: first.span,
        more_parts,
    });
}

fn unreadable(file: FileId, a: usize, b: usize, what: &str) -> Diagnostic {
    Diagnostic::new(Code::P21UnreadableText, what.to_string())
        .primary(Span::new(file, a, b.max(a + 1)), "here")
        .help(
            "close strings with `'` and comments with `*/`; write a quote inside a string as `''`",
        )
}

fn syntax(file: FileId, a: usize, b: usize, msg: &str) -> Diagnostic {
    Diagnostic::new(Code::P21Syntax, msg.to_string())
        .primary(Span::new(file, a, b), "here")
        .help("an instance is `#n=ENTITY(p1,p2,...);`")
}

fn parse_error(
    file: FileId,
    e: lalrpop_util::ParseError<usize, Tok, (usize, usize, String)>,
    end: usize,
) -> Diagnostic {
    use lalrpop_util::ParseError as P;
    let (a, b, msg) = match e {
        P::InvalidToken { location } => (location, location + 1, "invalid token".to_string()),
        P::UnrecognizedEof { location, expected } => (
            location,
            end,
            format!(
                "the statement ends too early; expected {}",
                expected_list(&expected)
            ),
        ),
        P::UnrecognizedToken {
            token: (a, t, b),
            expected,
        } => (
            a,
            b,
            format!(
                "unexpected {}; expected {}",
                describe(t),
                expected_list(&expected)
            ),
        ),
        P::ExtraToken { token: (a, t, b) } => (a, b, format!("unexpected {}", describe(t))),
        P::User { error: (a, b, m) } => (a, b, m),
    };
    Diagnostic::new(Code::P21Syntax, msg)
        .primary(Span::new(file, a, b.max(a)), "here")
        .help("an instance is `#n=ENTITY(p1,p2,...);`; this one is skipped")
}

fn describe(t: Tok) -> &'static str {
    match t {
        Tok::Begin => "`ISO-10303-21`",
        Tok::End => "`END-ISO-10303-21`",
        Tok::Keyword => "a name",
        Tok::InstanceName => "an instance reference",
        Tok::Integer => "an integer",
        Tok::Real => "a real",
        Tok::Str => "a string",
        Tok::Enumeration => "an enumeration",
        Tok::Binary => "a binary",
        Tok::Dollar => "`$`",
        Tok::Star => "`*`",
        Tok::LParen => "`(`",
        Tok::RParen => "`)`",
        Tok::Comma => "`,`",
        Tok::Eq => "`=`",
        Tok::Semi => "`;`",
        Tok::OpenComment => "an unclosed comment",
        Tok::OpenString => "an unclosed string",
    }
}

fn expected_list(expected: &[String]) -> String {
    let names: Vec<String> = expected
        .iter()
        .map(|e| match e.trim_matches('"') {
            "keyword" => "a name".to_string(),
            "#n" => "`#n`".to_string(),
            other if other.len() == 1 => format!("`{other}`"),
            other => format!("a {other}"),
        })
        .collect();
    match names.len() {
        0 => "nothing more".to_string(),
        1 => names[0].clone(),
        _ => format!("one of {}", names.join(", ")),
    }
}

#[cfg(test)]
mod budget_tests {
    use super::*;

    /// `#1=A($,$,...)`: 48 bytes of memory for two of text; a file of
    /// them stops at the budget (1.5 GB; 100 MB of them took 2.5 GB).
    #[test]
    fn instance_data_over_the_budget_is_e0813_not_gigabytes() {
        let mut src = String::from("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n");
        for n in 1..=1000 {
            src.push_str(&format!("#{n}=A({}$);\n", "$,".repeat(99)));
        }
        src.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
        let (whole, d) = parse_within(&src, FileId(0), true, usize::MAX);
        assert_eq!(whole.instances.len(), 1000);
        assert!(d.is_empty(), "{d:?}");
        let one = instance_bytes(&whole.instances[0]);
        assert!(
            one > 100 * std::mem::size_of::<super::super::Param>(),
            "{one}"
        );
        let (part, d) = parse_within(&src, FileId(0), true, 10 * one);
        assert_eq!(part.instances.len(), 11, "stops at the one that passes");
        assert_eq!(d.len(), 1, "{d:?}");
        assert_eq!(d[0].code, Code::P21TooLarge);
        assert_eq!(d[0].span(), Some(part.instances[10].span));
    }
}
