//! Runs every oracle probe (`../shared/reference/oracle-probe/p*.ngc`,
//! `e*.ngc`) through the library and compares the calls with the stored
//! output of LinuxCNC's `rs274`, normalised as `canon-diff` normalises:
//! `COMMENT("interpreter: ...")` lines are dropped and numbers compared
//! within 1e-4 (plus the `%.4f` rounding). An e-probe must also end with
//! an error, or be rejected when it is read (the reader's checks catch
//! some mistakes before the program runs; rs274 finds them at run time).
//! Skips with a note when the probes are absent.

use cncc::canon::{format_call, Canon};
use cncc::dialect::builtin::builtin;
use cncc::driver::{read_program, FsLoader};
use cncc::interp::{self, tooltable::ToolTable, Options};
use cncc::source::SourceMap;
use std::path::{Path, PathBuf};

/// Probes known not to match yet, with the reason.
const KNOWN: &[(&str, &str)] = &[];

fn probe_dir() -> Option<PathBuf> {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/oracle-probe");
    d.is_dir().then_some(d)
}

/// The numbers in a call and the text between them.
fn split(line: &str) -> (String, Vec<f64>) {
    let mut text = String::new();
    let mut nums = Vec::new();
    let mut cur = String::new();
    let flush = |cur: &mut String, text: &mut String, nums: &mut Vec<f64>| {
        if let Ok(v) = cur.parse::<f64>() {
            nums.push(v);
            text.push('#');
        } else {
            text.push_str(cur);
        }
        cur.clear();
    };
    for ch in line.chars() {
        let numeric = ch.is_ascii_digit() || ch == '.' || (ch == '-' && cur.is_empty());
        if numeric
            && !(text.ends_with(|c: char| c.is_ascii_alphabetic() || c == '_')
                && cur.is_empty()
                && ch != '-')
        {
            cur.push(ch);
        } else {
            flush(&mut cur, &mut text, &mut nums);
            text.push(ch);
        }
    }
    flush(&mut cur, &mut text, &mut nums);
    (text, nums)
}

fn same(a: &str, b: &str) -> bool {
    if a == b {
        return true;
    }
    let ((ta, na), (tb, nb)) = (split(a), split(b));
    ta == tb && na.len() == nb.len() && na.iter().zip(&nb).all(|(x, y)| (x - y).abs() <= 1.5e-4)
}

fn normalise(lines: impl Iterator<Item = String>) -> Vec<String> {
    lines
        .map(|l| l.trim().to_string())
        .filter(|l| !l.is_empty() && !l.starts_with("COMMENT(\"interpreter:"))
        .collect()
}

/// Runs one probe: Ok(()) when it matches, Err(why) otherwise.
fn run_probe(ngc: &Path, table: &ToolTable) -> Result<(), String> {
    let spec = builtin("linuxcnc").expect("linuxcnc dialect");
    let text = cncc::driver::decode(&std::fs::read(ngc).map_err(|e| e.to_string())?);
    let mut files = SourceMap::new();
    let id = files.add(ngc.display().to_string(), text.clone());
    let (program, diags) = read_program(&text, id, &spec);
    let error_probe = ngc
        .file_name()
        .is_some_and(|n| n.to_string_lossy().starts_with('e'));
    if diags.iter().any(|d| d.is_error()) {
        return if error_probe {
            Ok(())
        } else {
            Err("rejected when read".into())
        };
    }
    let options = Options {
        tool_table: table.clone(),
        ..Options::default()
    };
    let mut calls: Vec<Canon> = Vec::new();
    let mut sink = |c: Canon, _| calls.push(c);
    let dir = ngc.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut loader = FsLoader::new(dir, spec.clone(), &mut files);
    let run_diags = interp::run(
        std::rc::Rc::new(program),
        &spec,
        &options,
        &mut loader,
        &mut sink,
    );
    let failed = run_diags.iter().any(|d| d.is_error());
    if error_probe && !failed {
        return Err("no error reported".into());
    }
    if !error_probe && failed {
        let msgs: Vec<_> = run_diags
            .iter()
            .filter(|d| d.is_error())
            .map(|d| d.message.clone())
            .collect();
        return Err(format!("error: {}", msgs.join("; ")));
    }
    let expected =
        std::fs::read_to_string(ngc.with_extension("canon")).map_err(|e| e.to_string())?;
    let expected = normalise(expected.lines().map(str::to_string));
    let actual = normalise(calls.iter().map(format_call));
    for (i, (e, a)) in expected.iter().zip(&actual).enumerate() {
        if !same(e, a) {
            return Err(format!("call {}: expected {e}, got {a}", i + 1));
        }
    }
    if expected.len() != actual.len() {
        return Err(format!(
            "{} calls expected, {} made",
            expected.len(),
            actual.len()
        ));
    }
    Ok(())
}

#[test]
fn oracle_probes_match_rs274() {
    let Some(dir) = probe_dir() else {
        eprintln!("note: ../shared/reference/oracle-probe not found; oracle probe test skipped");
        return;
    };
    let tbl = dir.join("../../tools/default.tbl");
    let table = match std::fs::read_to_string(&tbl) {
        Ok(t) => ToolTable::parse(&t, cncc::span::FileId(0)).0,
        Err(_) => ToolTable::builtin(),
    };
    let mut probes: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ngc"))
        .collect();
    probes.sort();
    let (mut passed, mut unexpected) = (0, Vec::new());
    for p in &probes {
        let name = p.file_stem().unwrap().to_string_lossy().to_string();
        let known = KNOWN.iter().find(|(k, _)| *k == name);
        match (run_probe(p, &table), known) {
            (Ok(()), None) => passed += 1,
            (Ok(()), Some(_)) => {
                passed += 1;
                eprintln!("note: {name} now matches; remove it from KNOWN");
            }
            (Err(why), Some((_, reason))) => eprintln!("known: {name}: {why} ({reason})"),
            (Err(why), None) => unexpected.push(format!("{name}: {why}")),
        }
    }
    eprintln!("oracle probes: {passed} of {} match", probes.len());
    assert!(
        unexpected.is_empty(),
        "probes that do not match:\n{}",
        unexpected.join("\n")
    );
}
