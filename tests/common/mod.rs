//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The crate root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `../shared` beside the checkout, if it is there.
pub fn shared() -> Option<PathBuf> {
    let p = root().join("../shared");
    if p.is_dir() {
        Some(p)
    } else {
        eprintln!("note: ../shared is absent; skipping the tests that read it");
        None
    }
}

/// Runs the `cncc` binary from the crate root.
pub fn cncc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .current_dir(root())
        .env("NO_COLOR", "1")
        .output()
        .expect("run cncc")
}

pub fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// The files of a folder with one of the extensions, sorted.
pub fn files_in(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| rd.filter_map(|e| e.ok()).map(|e| e.path()).filter(|p| p.is_file()).collect())
        .unwrap_or_default();
    v.sort();
    v
}

/// The meta-model of a program as a JSON value without spans, numbers by
/// value (`10` and `10.` are the same number): what "the meta-model does
/// not change" compares.
pub fn model_fingerprint(p: &cncc::ir::Program) -> serde_json::Value {
    let mut v = serde_json::to_value(&p.blocks).expect("serialize");
    let exprs = serde_json::to_value(&p.exprs).expect("serialize");
    let mut all = serde_json::json!({ "blocks": v.take(), "exprs": exprs });
    normalize(&mut all);
    all
}

fn normalize(v: &mut serde_json::Value) {
    use serde_json::Value;
    match v {
        Value::Object(map) => {
            map.remove("span");
            map.remove("address_span");
            if map.len() == 3 && map.contains_key("mantissa") && map.contains_key("scale") && map.contains_key("point") {
                let m = map["mantissa"].as_i64().unwrap_or(0);
                let s = map["scale"].as_u64().unwrap_or(0) as u8;
                let d = cncc::ir::Decimal { mantissa: m, scale: s, point: false }.normalized();
                *v = Value::String(d.to_string());
                return;
            }
            for (_, x) in map.iter_mut() {
                normalize(x);
            }
        }
        Value::Array(items) => items.iter_mut().for_each(normalize),
        _ => {}
    }
}

/// The first difference between two JSON values, as a path.
pub fn first_difference(a: &serde_json::Value, b: &serde_json::Value, path: &str) -> Option<String> {
    use serde_json::Value;
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for (k, va) in x {
                match y.get(k) {
                    Some(vb) => {
                        if let Some(d) = first_difference(va, vb, &format!("{path}.{k}")) {
                            return Some(d);
                        }
                    }
                    None => return Some(format!("{path}.{k} missing on the right")),
                }
            }
            y.keys().find(|k| !x.contains_key(*k)).map(|k| format!("{path}.{k} missing on the left"))
        }
        (Value::Array(x), Value::Array(y)) => {
            for (i, (va, vb)) in x.iter().zip(y).enumerate() {
                if let Some(d) = first_difference(va, vb, &format!("{path}[{i}]")) {
                    return Some(d);
                }
            }
            (x.len() != y.len()).then(|| format!("{path}: {} vs {} items", x.len(), y.len()))
        }
        _ => (a != b).then(|| format!("{path}: {a} vs {b}")),
    }
}
