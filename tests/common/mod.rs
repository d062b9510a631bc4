//! Helpers shared by the integration tests.
#![allow(dead_code)]

pub mod field;

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

/// Skips a test that needs LinuxCNC's rs274 or `../shared` with a note,
/// unless `CNCC_REQUIRE_ORACLE=1` (CI) asks for it to run.
pub fn skip_oracle(what: &str, why: &str) {
    let required = std::env::var("CNCC_REQUIRE_ORACLE").is_ok_and(|v| v == "1");
    assert!(
        !required,
        "CNCC_REQUIRE_ORACLE=1 but {what} was skipped: {why}"
    );
    eprintln!("note: {what} skipped: {why}");
}

/// Whether LinuxCNC's `rs274` is on the PATH.
pub fn rs274_present() -> bool {
    Command::new("sh")
        .args(["-c", "command -v rs274"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
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

/// `cncc port SRC [--from FROM] --to TO --verify -o OUT`: the written
/// text when the port is verified (exit 0 and `verify: OK`), else the
/// stderr of the refusal.
pub fn port_verified(
    src: &Path,
    from: Option<&str>,
    to: &str,
    out: &Path,
) -> Result<String, String> {
    let mut args = vec!["port", src.to_str().unwrap()];
    if let Some(f) = from {
        args.extend(["--from", f]);
    }
    args.extend(["--to", to, "--verify", "-o", out.to_str().unwrap()]);
    let o = cncc(&args);
    let err = stderr(&o);
    match o.status.code() {
        Some(0) => {
            assert!(err.contains("verify: OK"), "{err}");
            Ok(std::fs::read_to_string(out).unwrap())
        }
        _ => Err(err),
    }
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
        .map(|rd| {
            rd.filter_map(|e| e.ok())
                .map(|e| e.path())
                .filter(|p| p.is_file())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// The meta-model of a program as text without spans, numbers by value
/// (`10` and `10.` are the same number): what "the meta-model does not
/// change" compares.
pub fn model_fingerprint(p: &cncc::ir::Program) -> String {
    let opts = cncc::ir::print::PrintOptions {
        spans: false,
        by_value: true,
    };
    cncc::ir::print::print_program_with(p, opts)
}

/// The first line where two fingerprints differ.
pub fn first_difference(a: &str, b: &str) -> Option<String> {
    let (la, lb): (Vec<_>, Vec<_>) = (a.lines().collect(), b.lines().collect());
    for (i, (x, y)) in la.iter().zip(&lb).enumerate() {
        if x != y {
            return Some(format!("block {}: {x:?} became {y:?}", i + 1));
        }
    }
    (la.len() != lb.len()).then(|| format!("{} blocks became {}", la.len(), lb.len()))
}

/// Runs a LinuxCNC program (a post's output) through rs274 and requires
/// it to run to its end; a note when `rs274` or `../shared` is absent.
pub fn runs_in_rs274(path: &Path) {
    let oracle = root().join("../shared/tools/rs274-canon");
    if !oracle.exists() || !rs274_present() {
        eprintln!("note: rs274 or ../shared/tools/rs274-canon is absent; not running LinuxCNC");
        return;
    }
    let ngc = path.with_extension("ngc");
    std::fs::copy(path, &ngc).unwrap();
    let o = Command::new(&oracle).arg(&ngc).output().unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "rs274: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}
