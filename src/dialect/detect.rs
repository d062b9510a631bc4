//! Choosing a dialect for a file given without `--dialect`: first from the
//! file extension (the extensions come from the specs), then from hints in
//! the text, else Fanuc. The reason is reported by the CLI on stderr.

use super::builtin::Registry;
use std::path::Path;

/// The dialect chosen and why, e.g. `siemens840d`, `"extension .mpf"`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Detection {
    pub id: String,
    pub reason: String,
}

/// The dialect used when nothing points elsewhere.
pub const DEFAULT_DIALECT: &str = "fanuc";

/// Most bytes of a file looked at for content hints.
const SCAN_LIMIT: usize = 256 * 1024;

/// Chooses a dialect for `path` with contents `text`.
pub fn detect(reg: &Registry, path: Option<&Path>, text: &str) -> Detection {
    let ext = path
        .and_then(|p| p.extension())
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase())
        .unwrap_or_default();
    let head = prefix(text, SCAN_LIMIT);
    if ext == "h" || ext == "i" {
        return found("heidenhain", format!("extension .{ext}"));
    }
    let by_ext: Vec<&str> = reg
        .specs()
        .iter()
        .filter(|s| !ext.is_empty() && s.extensions.contains(&ext))
        .map(|s| s.id.as_str())
        .collect();
    // An extension only one dialect claims decides, unless it is one the
    // default dialect claims (.nc, .txt): those files are often others'.
    if let [only] = by_ext.as_slice() {
        if *only != DEFAULT_DIALECT {
            return found(only, format!("extension .{ext}"));
        }
    }
    if let Some(d) = content_hint(head) {
        return d;
    }
    match by_ext.first() {
        Some(id) => found(id, format!("extension .{ext}")),
        None => found(
            DEFAULT_DIALECT,
            "no dialect-specific extension or content; the default".to_string(),
        ),
    }
}

fn found(id: &str, reason: String) -> Detection {
    Detection {
        id: id.to_string(),
        reason,
    }
}

/// At most `n` bytes of `text`, cut at a character boundary.
fn prefix(text: &str, n: usize) -> &str {
    if text.len() <= n {
        return text;
    }
    let mut end = n;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

/// A dialect named by what the text contains, with the line that says so.
fn content_hint(text: &str) -> Option<Detection> {
    for (i, line) in text.lines().enumerate() {
        let upper = line.trim().to_ascii_uppercase();
        let at = |what: &str| format!("{what} on line {}", i + 1);
        if upper.contains("BEGIN PGM") {
            return Some(found("heidenhain", at("`BEGIN PGM`")));
        }
        if is_o_word(&upper) {
            return Some(found("linuxcnc", at("O-word syntax")));
        }
        if upper.contains("#<") {
            return Some(found("linuxcnc", at("a named parameter `#<...>`")));
        }
        if let Some(what) = siemens_hint(&upper) {
            return Some(found("siemens840d", at(what)));
        }
        if let Some(what) = haas_hint(&upper) {
            return Some(found("haas", at(what)));
        }
    }
    None
}

/// `o100 sub`, `O<name> call`, `o101 if [...]` (not a Fanuc `O1234` program number).
fn is_o_word(line: &str) -> bool {
    let line = strip_block_number(line);
    let Some(rest) = line.strip_prefix('O') else {
        return false;
    };
    let rest = if let Some(r) = rest.strip_prefix('<') {
        match r.find('>') {
            Some(end) => &r[end + 1..],
            None => return false,
        }
    } else {
        let digits = rest.bytes().take_while(|b| b.is_ascii_digit()).count();
        if digits == 0 {
            return false;
        }
        &rest[digits..]
    };
    const WORDS: &[&str] = &[
        "SUB",
        "ENDSUB",
        "CALL",
        "RETURN",
        "IF",
        "ELSEIF",
        "ELSE",
        "ENDIF",
        "WHILE",
        "ENDWHILE",
        "DO",
        "REPEAT",
        "ENDREPEAT",
        "BREAK",
        "CONTINUE",
    ];
    let kw: String = rest
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_alphabetic())
        .collect();
    rest.starts_with(char::is_whitespace) && WORDS.contains(&kw.as_str())
}

fn strip_block_number(line: &str) -> &str {
    match line.strip_prefix('N') {
        Some(r) if r.starts_with(|c: char| c.is_ascii_digit()) => r
            .trim_start_matches(|c: char| c.is_ascii_digit())
            .trim_start(),
        _ => line,
    }
}

fn siemens_hint(line: &str) -> Option<&'static str> {
    let line = strip_block_number(line);
    const STARTS: &[(&str, &str)] = &[
        ("%_N_", "a Sinumerik `%_N_` header"),
        (";$PATH=", "a Sinumerik `;$PATH=` header"),
        ("DEF ", "a `DEF` declaration"),
        ("PROC ", "a `PROC` definition"),
        ("MCALL", "an `MCALL`"),
    ];
    if let Some((_, what)) = STARTS.iter().find(|(s, _)| line.starts_with(s)) {
        return Some(what);
    }
    let code = line.split(';').next().unwrap_or("");
    let calls = ["CYCLE", "POCKET", "HOLES", "SLOT", "LONGHOLE"]
        .iter()
        .any(|c| has_call(code, c));
    let jumps = ["GOTOF ", "GOTOB "]
        .iter()
        .any(|j| code.contains(j) && !in_paren_comment(code, j));
    (calls || jumps).then_some("a Sinumerik cycle or jump")
}

/// `NAME<digits>(` outside a parenthesised comment: a Sinumerik cycle call.
fn has_call(line: &str, name: &str) -> bool {
    line.match_indices(name).any(|(i, _)| {
        let rest = &line[i + name.len()..];
        let digits = rest.bytes().take_while(|b| b.is_ascii_digit()).count();
        digits > 0 && rest[digits..].starts_with('(') && !in_paren_comment(line, &line[i..])
    })
}

/// Is the first occurrence of `what` inside a `( ... )` comment?
fn in_paren_comment(line: &str, what: &str) -> bool {
    let Some(at) = line.find(what) else {
        return false;
    };
    let before = &line[..at];
    before.matches('(').count() > before.matches(')').count()
        && !before
            .trim_end()
            .ends_with(|c: char| c.is_ascii_alphanumeric())
}

fn haas_hint(line: &str) -> Option<&'static str> {
    if line.starts_with('(') && line.contains("HAAS") {
        return Some("a comment naming Haas");
    }
    for (word, what) in [
        ("G187", "Haas `G187`"),
        ("G154", "Haas `G154`"),
        ("G150", "Haas `G150`"),
        ("M97", "Haas `M97`"),
    ] {
        if has_word(line, word) {
            return Some(what);
        }
    }
    // Text engraving `G47 P0 (TEXT)`: Fanuc's G47 (an old tool position
    // offset) takes no P and no text.
    if has_word(line, "G47") && line.contains('(') && has_letter_word(line, 'P') {
        return Some("Haas engraving `G47 P.. (text)`");
    }
    None
}

/// A word with this letter and a number (`P0`) outside comments.
fn has_letter_word(line: &str, letter: char) -> bool {
    let code = line.split('(').next().unwrap_or("");
    let b = code.as_bytes();
    b.iter().enumerate().any(|(i, &c)| {
        c == letter as u8
            && (i == 0 || !b[i - 1].is_ascii_alphabetic())
            && b.get(i + 1)
                .is_some_and(|n| n.is_ascii_digit() || *n == b'-' || *n == b'.')
    })
}

/// `word` stands alone: not after a letter, not before a digit or point.
fn has_word(line: &str, word: &str) -> bool {
    let line = line.split('(').next().unwrap_or("");
    line.match_indices(word).any(|(i, _)| {
        let before = line[..i].chars().last();
        let after = line[i + word.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphabetic())
            && !after.is_some_and(|c| c.is_ascii_digit() || c == '.')
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn det(name: &str, text: &str) -> Detection {
        detect(&Registry::with_builtins(), Some(Path::new(name)), text)
    }

    #[test]
    fn by_extension() {
        assert_eq!(
            det("a.MPF", "G0 X1"),
            found("siemens840d", "extension .mpf".into())
        );
        assert_eq!(det("a.spf", "").id, "siemens840d");
        assert_eq!(det("a.ngc", "G0 X1").id, "linuxcnc");
        assert_eq!(det("a.h", "").id, "heidenhain");
    }

    #[test]
    fn by_content() {
        assert_eq!(
            det("a.nc", "G0\no100 sub\n").reason,
            "O-word syntax on line 2"
        );
        assert_eq!(det("a.nc", "o<drill> call [1]").id, "linuxcnc");
        assert_eq!(det("a.nc", "O1234\nG0 X1\nM30").id, "fanuc");
        assert_eq!(det("a.txt", "0 BEGIN PGM X MM").id, "heidenhain");
        assert_eq!(det("a.nc", "N10 G187 P1 E0.01").id, "haas");
        assert_eq!(
            det(
                "a.nc",
                "N535 G47 P0 (CADE) X.01 Y-2.95 I0. J0.1 R0.05 Z-0.005 F15. E10."
            )
            .id,
            "haas"
        );
        assert_eq!(det("a.nc", "G47 X1. (OFFSET)").id, "fanuc");
        assert_eq!(det("a.nc", "G1 X1 (G1870 is not G187)").id, "fanuc");
        assert_eq!(det("a.nc", "N5 MCALL CYCLE81(1,2,3)").id, "siemens840d");
        assert_eq!(
            det("prog", "G0 X1").reason,
            "no dialect-specific extension or content; the default"
        );
    }

    #[test]
    fn corpus_files() {
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
        if !root.exists() {
            println!(
                "note: {} absent, corpus detection test skipped",
                root.display()
            );
            return;
        }
        let reg = Registry::with_builtins();
        let mut wrong = Vec::new();
        for dir in ["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"] {
            let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
                continue;
            };
            for e in entries.flatten() {
                let bytes = std::fs::read(e.path()).unwrap_or_default();
                let text = String::from_utf8_lossy(&bytes);
                let d = detect(&reg, Some(&e.path()), &text);
                // Haas programs without Haas-only codes read as Fanuc.
                let ok = d.id == dir || (dir == "haas" && d.id == "fanuc");
                if !ok {
                    wrong.push(format!(
                        "{dir}/{}: {} ({})",
                        e.file_name().to_string_lossy(),
                        d.id,
                        d.reason
                    ));
                }
            }
        }
        assert!(wrong.is_empty(), "misdetected:\n{}", wrong.join("\n"));
    }
}
