//! SARIF 2.1.0 (OASIS Static Analysis Results Interchange Format): one
//! document per run, for CI systems that show annotations. Each
//! diagnostic is a result; each code that appears is a rule of the tool,
//! with its name, summary and `cncc explain` text.

use super::{Diagnostic, Severity};
use crate::source::SourceMap;
use serde_json::{json, Value};

const SCHEMA: &str = "https://json.schemastore.org/sarif-2.1.0.json";

/// The SARIF document for `diags`.
pub fn sarif(diags: &[Diagnostic], files: &SourceMap) -> String {
    let mut codes: Vec<_> = diags.iter().map(|d| d.code).collect();
    codes.sort();
    codes.dedup();
    let rules: Vec<Value> = codes
        .iter()
        .map(|c| {
            json!({
                "id": c.code(),
                "name": c.name(),
                "shortDescription": { "text": c.summary() },
                "fullDescription": { "text": c.explanation() },
                "help": { "text": format!("cncc explain {}", c.code()) },
                "defaultConfiguration": { "level": level(c.severity()) },
            })
        })
        .collect();
    let results: Vec<Value> = diags
        .iter()
        .map(|d| result(d, codes.binary_search(&d.code).unwrap_or(0), files))
        .collect();
    let doc = json!({
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": { "driver": {
                "name": "cncc",
                "version": env!("CARGO_PKG_VERSION"),
                "rules": rules,
            }},
            "columnKind": "unicodeCodePoints",
            "results": results,
        }]
    });
    let mut s = serde_json::to_string_pretty(&doc).unwrap_or_default();
    s.push('\n');
    s
}

fn level(s: Severity) -> &'static str {
    match s {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Note => "note",
    }
}

fn result(d: &Diagnostic, rule_index: usize, files: &SourceMap) -> Value {
    let mut text = d.message.clone();
    for n in &d.notes {
        text.push_str("\nnote: ");
        text.push_str(n);
    }
    if let Some(h) = &d.help {
        text.push_str("\nhelp: ");
        text.push_str(h);
    }
    let loc = |l: &super::Label| {
        let f = l.span.file;
        let (line, col) = files.line_col(f, l.span.start as usize);
        let (end_line, end_col) = files.line_col(f, l.span.end as usize);
        json!({
            "physicalLocation": {
                "artifactLocation": { "uri": uri(files.name(f)) },
                "region": {
                    "startLine": line.max(1), "startColumn": col.max(1),
                    "endLine": end_line.max(line.max(1)), "endColumn": end_col.max(1),
                },
            },
            "message": { "text": l.message },
        })
    };
    let primary: Vec<Value> = d
        .labels
        .iter()
        .filter(|l| l.primary)
        .take(1)
        .map(loc)
        .collect();
    let related: Vec<Value> = d
        .labels
        .iter()
        .filter(|l| !l.primary)
        .enumerate()
        .map(|(i, l)| {
            let mut v = loc(l);
            v["id"] = json!(i);
            v
        })
        .collect();
    let mut r = json!({
        "ruleId": d.code.code(),
        "ruleIndex": rule_index,
        "level": level(d.severity),
        "message": { "text": text },
        "locations": primary,
    });
    if !related.is_empty() {
        r["relatedLocations"] = json!(related);
    }
    r
}

/// A file name as a relative URI reference (forward slashes, spaces and
/// other unsafe characters percent-encoded).
fn uri(name: &str) -> String {
    let mut out = String::new();
    for b in name.replace('\\', "/").bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' | b':' => {
                out.push(b as char)
            }
            _ => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_are_escaped() {
        assert_eq!(uri("a b/c#.nc"), "a%20b/c%23.nc");
        assert_eq!(uri("dir\\x.nc"), "dir/x.nc");
    }
}
