//! Meanings live only in the dialect specs: shared code (everything in
//! `src/` but the spec loader `src/dialect/`) never matches a G or M code
//! number nor a dialect id. It asks the spec (a meaning, a capability, a
//! table column) instead.
//!
//! The scan reads the Rust source with comments and test code
//! (`#[cfg(test)]` items, `tests/` folders, `*tests.rs`, `test_support.rs`,
//! `testhost.rs`) left out, and reports:
//! * a string literal that is a dialect id or alias (`"fanuc"`, `"tnc"`)
//!   in a comparison, a match pattern, or alone as an argument
//!   (`builtin("fanuc")`);
//! * a string literal that is a code (`"G70"`, `"M6"`) in a comparison or
//!   a match pattern (next to `==`, `!=`, `=>` or `|`);
//! * a `'G'`/`'M'` letter paired with a number: in a tuple (`('M', 480`)
//!   or compared in the same expression (`'G') && (code - 76.0`);
//! * a code value compared with a number (`code.to_f64() < 12.5`,
//!   `code == 33.0`) or scaled to tenths to be matched (`code * 10.0`).
//!
//! Writing a code is not matching one: messages (`"G84 needs M3"`) and a
//! writer's spelling are not reported. What remains is in [`ALLOWED`], each
//! with its reason; keep that list short.

use std::path::{Path, PathBuf};

/// (file, the text of the reported token, why it stays).
const ALLOWED: &[(&str, &str, &str)] = &[(
    "src/plot/view.rs",
    "\"iso\"",
    "the isometric view of `plot --views`, not the dialect alias `iso`",
)];

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Str(String),
    Char(String),
    Num(String),
    Ident(String),
    Punct(String),
}

/// Rust source as tokens with their line numbers; comments dropped.
fn tokens(src: &str) -> Vec<(usize, Tok)> {
    let b: Vec<char> = src.chars().collect();
    let mut out = Vec::new();
    let (mut i, mut line) = (0, 1);
    while i < b.len() {
        let c = b[i];
        let next = b.get(i + 1).copied().unwrap_or(' ');
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if c == '/' && next == '/' {
            while i < b.len() && b[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && next == '*' {
            i += 2;
            while i + 1 < b.len() && !(b[i] == '*' && b[i + 1] == '/') {
                line += usize::from(b[i] == '\n');
                i += 1;
            }
            i += 2;
        } else if c == 'r' && (next == '#' || next == '"') && raw_string(&b, i).is_some() {
            let (end, text) = raw_string(&b, i).unwrap();
            out.push((line, Tok::Str(text.clone())));
            line += text.matches('\n').count();
            i = end;
        } else if c == '"' || (c == 'b' && next == '"') {
            let start = line;
            i += if c == 'b' { 2 } else { 1 };
            let mut s = String::new();
            while i < b.len() && b[i] != '"' {
                if b[i] == '\\' {
                    i += 1;
                }
                if i < b.len() {
                    line += usize::from(b[i] == '\n');
                    s.push(b[i]);
                }
                i += 1;
            }
            i += 1;
            out.push((start, Tok::Str(s)));
        } else if c == '\'' || (c == 'b' && next == '\'') {
            // A char literal, or a lifetime.
            let j = i + if c == 'b' { 1 } else { 0 };
            let close = if b.get(j + 1) == Some(&'\\') {
                (j + 2..b.len().min(j + 12)).find(|&k| b[k] == '\'')
            } else {
                (b.get(j + 2) == Some(&'\'')).then_some(j + 2)
            };
            match close {
                Some(k) => {
                    out.push((line, Tok::Char(b[j + 1..k].iter().collect())));
                    i = k + 1;
                }
                None => {
                    i = j + 1;
                    while i < b.len() && (b[i].is_alphanumeric() || b[i] == '_') {
                        i += 1;
                    }
                }
            }
        } else if c.is_ascii_digit() {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == '_' || b[i] == '.') {
                if b[i] == '.' && !b.get(i + 1).is_some_and(|d| d.is_ascii_digit()) {
                    break;
                }
                i += 1;
            }
            out.push((line, Tok::Num(b[s..i].iter().collect())));
        } else if c.is_alphabetic() || c == '_' {
            let s = i;
            while i < b.len() && (b[i].is_alphanumeric() || b[i] == '_') {
                i += 1;
            }
            out.push((line, Tok::Ident(b[s..i].iter().collect())));
        } else {
            let two: String = [c, next].iter().collect();
            let p =
                if ["==", "!=", "=>", "<=", ">=", "&&", "||", "::", "->"].contains(&two.as_str()) {
                    two
                } else {
                    c.to_string()
                };
            i += p.chars().count();
            out.push((line, Tok::Punct(p)));
        }
    }
    out
}

/// `r"..."` / `r#"..."#` at `i`: the end and the text.
fn raw_string(b: &[char], i: usize) -> Option<(usize, String)> {
    let mut j = i + 1;
    let mut hashes = 0;
    while b.get(j) == Some(&'#') {
        hashes += 1;
        j += 1;
    }
    if b.get(j) != Some(&'"') {
        return None;
    }
    let start = j + 1;
    let mut k = start;
    while k < b.len() {
        if b[k] == '"' && (0..hashes).all(|h| b.get(k + 1 + h) == Some(&'#')) {
            return Some((k + 1 + hashes, b[start..k].iter().collect()));
        }
        k += 1;
    }
    None
}

/// The tokens without `#[cfg(test)]` items.
fn without_tests(toks: Vec<(usize, Tok)>) -> Vec<(usize, Tok)> {
    let p = |s: &str| Tok::Punct(s.into());
    let id = |s: &str| Tok::Ident(s.into());
    let attr = [
        p("#"),
        p("["),
        id("cfg"),
        p("("),
        id("test"),
        p(")"),
        p("]"),
    ];
    let mut out = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let is_attr = toks.len() >= i + attr.len()
            && toks[i..i + attr.len()]
                .iter()
                .zip(&attr)
                .all(|((_, t), a)| t == a);
        if !is_attr {
            out.push(toks[i].clone());
            i += 1;
            continue;
        }
        // Skip the item: to its `;` or through its braces.
        i += attr.len();
        let mut depth = 0;
        while i < toks.len() {
            match &toks[i].1 {
                Tok::Punct(s) if s == "{" => depth += 1,
                Tok::Punct(s) if s == "}" => {
                    depth -= 1;
                    if depth == 0 {
                        i += 1;
                        break;
                    }
                }
                Tok::Punct(s) if s == ";" && depth == 0 => {
                    i += 1;
                    break;
                }
                _ => {}
            }
            i += 1;
        }
    }
    out
}

fn is_code_text(s: &str) -> bool {
    let mut c = s.chars();
    matches!(c.next(), Some('G' | 'M' | 'g' | 'm'))
        && !s[1..].is_empty()
        && s[1..].chars().all(|c| c.is_ascii_digit() || c == '.')
        && s[1..].starts_with(|c: char| c.is_ascii_digit())
}

fn is_letter(t: &Tok) -> bool {
    matches!(t, Tok::Char(c) if c == "G" || c == "M")
}

fn is_cmp(t: &Tok) -> bool {
    matches!(t, Tok::Punct(p) if ["==", "!=", "<", ">", "<=", ">=", "-"].contains(&p.as_str()))
}

fn is_float_or_code_num(t: &Tok) -> bool {
    matches!(t, Tok::Num(n) if n.contains('.') || n.parse::<u32>().is_ok_and(|v| v >= 2))
}

/// Every finding of one file: (line, token text, rule).
fn scan(src: &str, ids: &[String]) -> Vec<(usize, String, &'static str)> {
    let toks = without_tests(tokens(src));
    let mut found = Vec::new();
    let punct = |k: usize| match toks.get(k) {
        Some((_, Tok::Punct(p))) => p.as_str(),
        _ => "",
    };
    for (k, (line, t)) in toks.iter().enumerate() {
        let prev = if k > 0 { punct(k - 1) } else { "" };
        let next = punct(k + 1);
        match t {
            Tok::Str(s)
                if ids.contains(&s.to_ascii_lowercase())
                    && (["==", "!=", "|", "=>"].contains(&next)
                        || ["==", "!=", "|"].contains(&prev)
                        || (prev == "(" && next == ")")) =>
            {
                found.push((
                    *line,
                    format!("\"{s}\""),
                    "dialect id compared, matched or asked for",
                ))
            }
            Tok::Str(s)
                if is_code_text(s)
                    && (["==", "!=", "|", "=>"].contains(&next)
                        || ["==", "!=", "|", "("].contains(&prev) && next != ".") =>
            {
                if prev == "(" && !matches!(next, "|" | "=>" | "==" | "!=") {
                    continue;
                }
                found.push((*line, format!("\"{s}\""), "code compared or matched"))
            }
            Tok::Char(_) if is_letter(t) => {
                // ('M', 480 ...): a letter and a number in a tuple.
                if next == ","
                    && toks
                        .get(k + 2)
                        .is_some_and(|(_, n)| is_float_or_code_num(n))
                {
                    found.push((
                        *line,
                        format!("'{}'", t_text(t)),
                        "letter and number paired",
                    ));
                    continue;
                }
                // 'G') && (code.to_f64() - 76.0): compared in the same expression.
                let rest = toks[k + 1..].iter().take_while(|(l, x)| {
                    *l == *line && *x != Tok::Punct(";".into()) && *x != Tok::Punct("{".into())
                });
                let w: Vec<&Tok> = rest.map(|(_, x)| x).collect();
                if w.windows(2)
                    .any(|p| is_cmp(p[0]) && is_float_or_code_num(p[1]))
                    && w.iter().any(|x| matches!(x, Tok::Ident(i) if i == "code"))
                {
                    found.push((
                        *line,
                        format!("'{}'", t_text(t)),
                        "letter and number compared",
                    ));
                }
            }
            Tok::Ident(i) if i == "code" => {
                // code.to_f64() < 12.5, code == 33.0, code * 10.0
                let mut j = k + 1;
                while let Some((_, x)) = toks.get(j) {
                    match x {
                        Tok::Punct(p) if p == "." || p == "(" || p == ")" => j += 1,
                        Tok::Ident(m) if m == "to_f64" => j += 1,
                        _ => break,
                    }
                }
                let op = toks.get(j).map(|(_, x)| x);
                let num = toks.get(j + 1).map(|(_, x)| x);
                let scaled = matches!(op, Some(Tok::Punct(p)) if p == "*")
                    && matches!(num, Some(Tok::Num(n)) if n.starts_with("10"));
                if (op.is_some_and(is_cmp) && num.is_some_and(is_float_or_code_num)) || scaled {
                    found.push((*line, "code".into(), "code value compared with a number"));
                }
            }
            _ => {}
        }
    }
    found
}

fn t_text(t: &Tok) -> &str {
    match t {
        Tok::Str(s) | Tok::Char(s) | Tok::Num(s) | Tok::Ident(s) | Tok::Punct(s) => s,
    }
}

/// The built-in dialect ids and aliases, from the specs.
fn dialect_names(root: &Path) -> Vec<String> {
    let mut names = Vec::new();
    for e in std::fs::read_dir(root.join("dialects")).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "xml") {
            let text = std::fs::read_to_string(&p).unwrap();
            for key in ["<dialect id=\"", "<alias name=\""] {
                for part in text.split(key).skip(1) {
                    names.push(part.split('"').next().unwrap().to_ascii_lowercase());
                }
            }
        }
    }
    names
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if p.is_dir() {
            if name != "tests" && name != "dialect" {
                rust_files(&p, out);
            }
        } else if name.ends_with(".rs")
            && !name.ends_with("tests.rs")
            && name != "test_support.rs"
            && name != "testhost.rs"
        {
            out.push(p);
        }
    }
}

#[test]
fn shared_code_matches_no_code_number_nor_dialect_id() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let ids = dialect_names(&root);
    assert!(ids.contains(&"fanuc".to_string()) && ids.contains(&"tnc".to_string()));
    let mut files = Vec::new();
    rust_files(&root.join("src"), &mut files);
    files.sort();
    let mut bad = Vec::new();
    let mut used = vec![false; ALLOWED.len()];
    for f in &files {
        let rel = f
            .strip_prefix(&root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        let src = std::fs::read_to_string(f).unwrap();
        for (line, text, rule) in scan(&src, &ids) {
            match ALLOWED.iter().position(|(p, t, _)| *p == rel && *t == text) {
                Some(i) => used[i] = true,
                None => bad.push(format!("{rel}:{line}: {text} ({rule})")),
            }
        }
    }
    assert!(
        bad.is_empty(),
        "shared code matches code numbers or dialect ids; ask the spec instead (a meaning, a capability):\n{}",
        bad.join("\n")
    );
    let stale: Vec<_> = ALLOWED
        .iter()
        .zip(&used)
        .filter(|(_, u)| !**u)
        .map(|((p, t, _), _)| format!("{p}: {t}"))
        .collect();
    assert!(
        stale.is_empty(),
        "allow-list entries no longer needed:\n{}",
        stale.join("\n")
    );
}

/// The scan finds the forms it is meant to find (each was in the code once).
#[test]
fn the_scan_finds_each_form() {
    let ids = vec!["fanuc".to_string(), "haas".to_string()];
    let src = r#"
        const AUX: &[(char, i64, F)] = &[('M', 480, F::On)];
        fn a(letter: char, code: Decimal) -> bool {
            letter.eq_ignore_ascii_case(&'G') && (code.to_f64() - 76.0).abs() < 1e-9
        }
        fn b(code: Decimal) -> &'static str { if code.to_f64() < 12.5 { "G12" } else { "G13" } }
        fn c(w: &str) -> bool { matches!(w, "G70" | "G71") }
        fn d(id: &str) -> u8 { match id { "fanuc" => 1, _ => 0 } }
        fn e(code: Decimal) -> i64 { (code.to_f64() * 10.0).round() as i64 }
        fn fine(code: Decimal) -> String { format!("G84 needs M3 at {code}") }
        #[cfg(test)]
        mod tests { const X: &str = "haas"; }
    "#;
    let found = scan(src, &ids);
    let rules: Vec<_> = found.iter().map(|(_, t, r)| format!("{t} {r}")).collect();
    assert_eq!(
        rules,
        [
            "'M' letter and number paired",
            "'G' letter and number compared",
            "code code value compared with a number",
            "code code value compared with a number",
            "\"G70\" code compared or matched",
            "\"G71\" code compared or matched",
            "\"fanuc\" dialect id compared, matched or asked for",
            "code code value compared with a number",
        ],
        "{found:?}"
    );
}

fn canon(args: &[&str]) -> (Option<i32>, String, String) {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_cncc"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(args)
        .output()
        .unwrap();
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into(),
        String::from_utf8_lossy(&o.stderr).into(),
    )
}

const M50: &str = "tests/programs/linuxcnc/m50-feed-override.ngc";

/// M50 is LinuxCNC's feed override because linuxcnc.xml says so; on Haas
/// the number is another function [?: pallet change] and runs as nothing.
#[test]
fn m50_is_the_feed_override_only_where_the_spec_says() {
    let (code, out, err) = canon(&["canon", "--dialect", "linuxcnc", M50]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("DISABLE_FEED_OVERRIDE()") && out.contains("ENABLE_FEED_OVERRIDE()"));
    let (code, out, err) = canon(&["canon", "--dialect", "haas", M50]);
    assert_eq!(code, Some(0), "{err}");
    assert!(!out.contains("FEED_OVERRIDE"), "{out}");
    let (_, out, _) = canon(&["canon", "--dialect", "fanuc", M50]);
    assert!(!out.contains("FEED_OVERRIDE"), "{out}");
}

/// A user's spec gives the same meanings to codes of its own choosing,
/// with no Rust: M50 as the feed override, G12 as a circular pocket.
#[test]
fn a_user_spec_declares_machine_functions_by_meaning() {
    let spec = "tests/dialects/override-fanuc.xml";
    let (code, out, err) = canon(&[
        "--dialect-file",
        spec,
        "canon",
        "--dialect",
        "override-fanuc",
        M50,
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("DISABLE_FEED_OVERRIDE()"), "{out}");
    let dir = tempfile::tempdir().unwrap();
    let prog = dir.path().join("pocket.nc");
    std::fs::write(
        &prog,
        "G21 G90 G17 G54\nG0 X0. Y0. Z1.\nG1 Z0. F100.\nG12 I5. Z-1. F200.\nG0 Z5.\nM30\n",
    )
    .unwrap();
    let prog = prog.to_str().unwrap();
    let (code, out, err) = canon(&[
        "--dialect-file",
        spec,
        "canon",
        "--dialect",
        "override-fanuc",
        prog,
    ]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("ARC_FEED"), "the pocket's circles: {out}");
    // The built-in Fanuc has no G12: an unknown code, not Haas's pocket.
    let (code, _, err) = canon(&["check", "--dialect", "fanuc", prog]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("E0203"), "{err}");
}
