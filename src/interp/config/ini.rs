//! A LinuxCNC INI file, read as LinuxCNC's `IniFile` reads it (checked
//! against rs274 2.9 with `-i`): `[SECTION]` lines open a section (the name
//! is the text between the brackets, spaces included; anything after `]`
//! is ignored), `NAME = VALUE` lines give a value (name and value trimmed;
//! an inline `#` or `;` is part of the value), lines whose first non-blank
//! character is `#` or `;` are comments, and a line ending in `\` goes on
//! in the next one. Names are case-sensitive and the first of two equal
//! names in a section wins. A line that is none of these is skipped with a
//! warning (W0594).

use crate::diag::{Code, Diagnostic};
use crate::span::{FileId, Span};

/// One `NAME = VALUE` line.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    pub section: String,
    pub name: String,
    pub value: String,
    /// The value's place in the file (the whole line for an empty value).
    pub span: Span,
}

/// The entries of an INI file, in file order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ini {
    pub entries: Vec<Entry>,
}

impl Ini {
    /// Reads `text` (file `id`); lines that are neither sections, values
    /// nor comments are reported and skipped.
    pub fn parse(text: &str, id: FileId) -> (Ini, Vec<Diagnostic>) {
        let mut ini = Ini::default();
        let mut diags = Vec::new();
        let mut section = String::new();
        for (line, start, end) in logical_lines(text) {
            let body = line.trim();
            if body.is_empty() || body.starts_with('#') || body.starts_with(';') {
                continue;
            }
            let lead = line.len() - line.trim_start().len();
            let joined = end - start != line.len();
            if joined {
                // A line continued with `\`: offsets inside it do not map
                // back to the file, so its diagnostics point at all of it.
                let span = Span::new(id, start, end);
                if let Some(e) = entry(body, &section, span) {
                    ini.entries.push(e);
                } else if let Some(rest) = body.strip_prefix('[') {
                    if let Some(end) = rest.find(']') {
                        section = rest[..end].to_string();
                    }
                } else {
                    diags.push(bad_line(
                        span,
                        "a line that is not `[SECTION]` or `NAME = VALUE`",
                    ));
                }
                continue;
            }
            let span = Span::new(id, start + lead, start + lead + body.len());
            if let Some(rest) = body.strip_prefix('[') {
                match rest.find(']') {
                    Some(end) => section = rest[..end].to_string(),
                    None => diags.push(bad_line(span, "a section line without its `]`")),
                }
                continue;
            }
            let Some(eq) = body.find('=') else {
                diags.push(bad_line(
                    span,
                    "a line that is not `[SECTION]` or `NAME = VALUE`",
                ));
                continue;
            };
            let name = body[..eq].trim();
            if name.is_empty() {
                diags.push(bad_line(span, "a value without a name"));
                continue;
            }
            let raw = &body[eq + 1..];
            let value = raw.trim();
            let vstart = span.start as usize + eq + 1 + (raw.len() - raw.trim_start().len());
            let vspan = if value.is_empty() {
                span
            } else {
                Span::new(id, vstart, vstart + value.len())
            };
            ini.entries.push(Entry {
                section: section.clone(),
                name: name.to_string(),
                value: value.to_string(),
                span: vspan,
            });
        }
        (ini, diags)
    }

    /// The first value of `name` in `[section]` (case-sensitive).
    pub fn get(&self, section: &str, name: &str) -> Option<&Entry> {
        self.entries
            .iter()
            .find(|e| e.section == section && e.name == name)
    }

    /// `#<_ini[section]name>`: the value as a number, when it is one (the
    /// program's names are looked up in capitals, as rs274 does).
    pub fn number(&self, section: &str, name: &str) -> Option<f64> {
        let e = self.get(&section.to_ascii_uppercase(), &name.to_ascii_uppercase())?;
        parse_number(&e.value)
    }
}

/// A whole value read as a finite number (`3`, `-3.`, `+1.5e1`); anything
/// else (`3 # comment`, `0x10`, `1e999`) is not one, as for rs274 [?] (it
/// reads `inf`; cncc does not).
pub fn parse_number(value: &str) -> Option<f64> {
    let v: f64 = value.trim().parse().ok()?;
    v.is_finite().then_some(v)
}

/// A whole value read as an integer, as rs274 reads its integer settings
/// (`DISABLE_G92_PERSISTENCE = yes` is not one and leaves the default).
pub fn parse_integer(value: &str) -> Option<i64> {
    value.trim().parse().ok()
}

fn bad_line(span: Span, what: &str) -> Diagnostic {
    Diagnostic::new(Code::BadIniLine, format!("{what}: LinuxCNC skips it"))
        .primary(span, "skipped")
        .help("an INI file holds `[SECTION]` lines, `NAME = VALUE` lines and `#` or `;` comment lines")
}

/// A `NAME = VALUE` line (not a section line) as an entry spanning `span`.
fn entry(body: &str, section: &str, span: Span) -> Option<Entry> {
    if body.starts_with('[') {
        return None;
    }
    let (name, value) = body.split_once('=')?;
    let name = name.trim();
    (!name.is_empty()).then(|| Entry {
        section: section.to_string(),
        name: name.to_string(),
        value: value.trim().to_string(),
        span,
    })
}

/// The file's lines with `\` continuations joined, each with the byte
/// range of its physical lines (line ends left out).
fn logical_lines(text: &str) -> Vec<(String, usize, usize)> {
    let mut out = Vec::new();
    let mut cur: Option<(String, usize)> = None;
    let mut at = 0;
    for raw in text.split_inclusive('\n') {
        let line = raw.trim_end_matches(['\n', '\r']);
        let (piece, more) = match line.strip_suffix('\\') {
            Some(p) => (p, true),
            None => (line, false),
        };
        match &mut cur {
            Some((s, _)) => s.push_str(piece),
            None => cur = Some((piece.to_string(), at)),
        }
        if !more {
            if let Some((s, start)) = cur.take() {
                out.push((s, start, at + line.len()));
            }
        }
        at += raw.len();
    }
    if let Some((s, start)) = cur {
        out.push((s, start, at));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(t: &str) -> Ini {
        let (ini, d) = Ini::parse(t, FileId(0));
        assert!(d.is_empty(), "{d:?}");
        ini
    }

    #[test]
    fn reads_sections_values_and_comments_as_linuxcnc() {
        let ini = parse("# c\n[RS274NGC] # x\n  ORIENT_OFFSET  =  42.0\n; c\n[A]\nVALUE=3 # c\nVALUE=4\nCONT=3\\\n4\n");
        assert_eq!(ini.get("RS274NGC", "ORIENT_OFFSET").unwrap().value, "42.0");
        assert_eq!(ini.get("A", "VALUE").unwrap().value, "3 # c");
        assert_eq!(ini.number("a", "value"), None);
        assert_eq!(ini.number("a", "cont"), Some(34.0));
        assert_eq!(ini.get("a", "VALUE"), None, "sections are case-sensitive");
    }

    #[test]
    fn a_bad_line_is_located() {
        let (ini, d) = Ini::parse("[A]\nVALUE=1\nnonsense\n", FileId(0));
        assert_eq!(ini.entries.len(), 1);
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].code, Code::BadIniLine);
    }

    #[test]
    fn numbers_are_whole_values() {
        assert_eq!(parse_number(" -3. "), Some(-3.0));
        assert_eq!(parse_number("+1.5e1"), Some(15.0));
        assert_eq!(parse_number("0x10"), None);
        assert_eq!(parse_integer("yes"), None);
        assert_eq!(parse_integer(" 2"), Some(2));
    }
}
