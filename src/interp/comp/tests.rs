//! Tests: a tiny G-code driver (enough of LinuxCNC's interpreter for the
//! test programs in `testdata/`) feeds the engine; its calls are compared
//! with snapshots checked against rs274, and with rs274 itself when it is
//! installed.

mod driver;

use crate::canon::format_call;
use std::path::{Path, PathBuf};
use std::process::Command;

fn testdata() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src/interp/comp/testdata")
}

fn programs() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(testdata())
        .expect("testdata")
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ngc"))
        .collect();
    v.sort();
    v
}

fn run_engine(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    driver::run(&text)
        .iter()
        .map(|l| format!("{l}\n"))
        .collect()
}

/// The calls the driver models, from rs274's output: everything between the
/// start-up calls and the program end's resets, minus plane and units.
fn filter_oracle(stdout: &str, stderr: &str, ok: bool) -> String {
    let lines: Vec<&str> = stdout.lines().collect();
    let start = lines
        .iter()
        .position(|l| l.starts_with("ON_RESET"))
        .map_or(0, |i| i + 1);
    let end = if ok {
        lines
            .iter()
            .rposition(|l| l.starts_with("SET_G5X_OFFSET"))
            .unwrap_or(lines.len())
    } else {
        lines.len()
    };
    let mut s = String::new();
    for l in &lines[start..end.max(start)] {
        if driver::MODELLED.iter().any(|p| l.starts_with(p)) {
            s.push_str(l);
            s.push('\n');
        }
    }
    if !ok {
        s.push_str(&format!("ERROR: {}\n", stderr.lines().next().unwrap_or("")));
    }
    s
}

#[test]
fn snapshots() {
    for p in programs() {
        let name = p.file_stem().unwrap().to_string_lossy().to_string();
        let src = std::fs::read_to_string(&p).unwrap();
        insta::assert_snapshot!(name.clone(), run_engine(&p), &src);
    }
}

#[test]
fn matches_rs274_live() {
    let tool = Path::new("/work/shared/tools/rs274-canon");
    let tool = if tool.exists() {
        tool.to_path_buf()
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/tools/rs274-canon")
    };
    let mut checked = 0;
    for p in programs() {
        let out = match Command::new(&tool).arg(&p).output() {
            Ok(o) => o,
            Err(_) => {
                println!("skipped: rs274-canon not found");
                return;
            }
        };
        let code = out.status.code().unwrap_or(3);
        if code == 2 || code == 3 {
            println!(
                "skipped: rs274 not installed or failed ({})",
                String::from_utf8_lossy(&out.stderr)
            );
            return;
        }
        let expected = filter_oracle(
            &String::from_utf8_lossy(&out.stdout),
            &String::from_utf8_lossy(&out.stderr),
            code == 0,
        );
        assert_eq!(run_engine(&p), expected, "{}", p.display());
        checked += 1;
    }
    println!("checked {checked} programs against rs274");
}

#[test]
fn matches_probe_p10() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/reference/oracle-probe");
    let (ngc, canon) = (
        dir.join("p10-cutter-comp.ngc"),
        dir.join("p10-cutter-comp.canon"),
    );
    if !ngc.exists() || !canon.exists() {
        println!("skipped: {} absent", dir.display());
        return;
    }
    let expected = filter_oracle(&std::fs::read_to_string(canon).unwrap(), "", true);
    assert_eq!(run_engine(&ngc), expected);
}

#[test]
fn formats_through_canon_printer() {
    // The driver prints through the shared printer: a sanity check that a
    // held-back move comes out after the entry comment.
    let out = driver::run("G21 F100\nG0 X0 Y0\nG41.1 D2 G1 X10\nG1 X20\nM2\n");
    assert_eq!(
        out,
        vec![
            "SET_FEED_RATE(100.0000)".to_string(),
            "STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)".into(),
            "COMMENT(\"interpreter: cutter radius compensation on left\")".into(),
            "STRAIGHT_FEED(10.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)".into(),
            "STRAIGHT_FEED(20.0000, 1.0000, 0.0000, 0.0000, 0.0000, 0.0000)".into(),
        ]
    );
    let _ = format_call;
}
