//! `cncc canon` against LinuxCNC's standalone `rs274`.
//!
//! (a) Every probe in `../shared/reference/oracle-probe/`: the stored
//! `.canon` must equal cncc's output (interpreter notes skipped, numbers
//! within 1e-4, as `canon-diff` compares); an error probe (`eNN-*`) must be
//! an error in cncc too (exit 1), with the same calls before it (a block
//! rs274 cannot read prints nothing of its own).
//! (b) Every sample program listed `ok` in `samples-summary.tsv` that exists
//! on this machine: `rs274-canon` is run live, fresh each time, with the
//! default tool table, and cncc on the same file with the same table.
//!
//! Exceptions are listed below with their reasons: [`LINUXCNC_DIFFERENCES`]
//! are real differences (not bugs of ours); [`KNOWN_GAPS`] are OUR gaps,
//! recorded while the interpreter is incomplete. A listed gap that now
//! passes is printed so it can be removed. Set `CNCC_ORACLE_LIST=1` to print
//! the current failures as Rust lines; `CNCC_REQUIRE_ORACLE=1` (set by
//! `.ci/run`) turns a skip (no `rs274`, no `../shared`) into a failure.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

/// Programs whose difference from rs274 is a real LinuxCNC difference,
/// with the reason, or a program out of cncc's scope.
const LINUXCNC_DIFFERENCES: &[(&str, &str)] = &[
    // Free text after M2: rs274 stops reading at M2; cncc reads (checks) the
    // whole file and reports the text as a read error.
    (
        concat!(
            "sample/usr/share/doc/linuxcnc/examples/sample-configs/sim/",
            "qtdragon/qtdragon_multi_joint/on_abort.ngc"
        ),
        "prose after M2: rs274 stops reading at M2, cncc checks the whole file",
    ),
    (
        concat!(
            "sample/usr/share/doc/linuxcnc/examples/sample-configs/sim/",
            "qtdragon/qtdragon_xyz/on_abort.ngc"
        ),
        "prose after M2: rs274 stops reading at M2, cncc checks the whole file",
    ),
    (
        concat!(
            "sample/usr/share/doc/linuxcnc/examples/sample-configs/sim/",
            "qtdragon_hd/qtdragon_hd_xyz/on_abort.ngc"
        ),
        "prose after M2: rs274 stops reading at M2, cncc checks the whole file",
    ),
    (
        concat!(
            "sample/usr/share/doc/linuxcnc/examples/sample-configs/sim/",
            "qtvcp_screens/qtdragon/on_abort.ngc"
        ),
        "prose after M2: rs274 stops reading at M2, cncc checks the whole file",
    ),
    // User M codes defined by an INI [RS274NGC]REMAP (out of scope): rs274
    // never runs the sub that uses them; cncc checks every block.
    (
        "sample/usr/share/linuxcnc/ncfiles/g882.ngc",
        "M75 is a remapped user M code (INI REMAP); cncc rejects unknown M codes in every block",
    ),
    (
        "sample/usr/share/linuxcnc/ncfiles/m6remap.ngc",
        "M69 is a remapped user M code (INI REMAP); cncc rejects unknown M codes in every block",
    ),
    // rs274 2.9 moves its current point along a G7x contour as it reads it
    // (the tool stays): under cutter compensation the G70 passes then start,
    // for the compensation, from the contour's end, where the tool is not.
    (
        "sample/usr/share/linuxcnc/ncfiles/lathe_g70_71_demo.ngc",
        concat!(
            "G70 under G42.1: rs274's compensation takes the contour's end (15,-38.1) as the ",
            "start of the first pass move, though the tool is at the start point; it joins ",
            "the two with an extra traverse (14.85,-38.25) and its passes come out shifted ",
            "by -0.15 (the nose radius) in X and Z; cncc compensates from where the tool is",
        ),
    ),
];

/// OUR gaps: programs cncc does not yet run as rs274 does. Each entry is a
/// bug or a missing piece of cncc, not a LinuxCNC difference.
const KNOWN_GAPS: &[&str] = &include!("oracle_known_gaps.in");

/// Calls that are the interpreter's notes, not machining (as `canon-diff`).
const IGNORED: &[&str] = &[
    "SET_NAIVECAM_TOLERANCE",
    "SET_MOTION_CONTROL_MODE",
    "ON_RESET",
    "START_CHANGE",
];

const TOLERANCE: f64 = 1e-4 + 1e-9;

fn skip(why: &str) {
    common::skip_oracle("the oracle test", why);
}

fn probe_dir() -> Option<PathBuf> {
    let d = common::root().join("../shared/reference/oracle-probe");
    d.is_dir().then_some(d)
}

fn default_table() -> PathBuf {
    common::root().join("../shared/tools/default.tbl")
}

/// The calls that matter, one per line.
fn normalise(text: &str) -> Vec<String> {
    text.lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .filter(|l| !l.starts_with("COMMENT(\"interpreter:"))
        .filter(|l| !IGNORED.contains(&l.split('(').next().unwrap_or("").trim()))
        .map(str::to_string)
        .collect()
}

/// Splits a line into its text between numbers and its numbers.
fn split_numbers(line: &str) -> (String, Vec<f64>) {
    let (mut text, mut nums) = (String::new(), Vec::new());
    let b = line.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let starts = b[i].is_ascii_digit()
            || ((b[i] == b'-' || b[i] == b'+' || b[i] == b'.')
                && b.get(i + 1)
                    .is_some_and(|c| c.is_ascii_digit() || *c == b'.'));
        let in_word = i > 0 && (b[i - 1].is_ascii_alphabetic() || b[i - 1] == b'_');
        if starts && !in_word {
            let j = i
                + 1
                + b[i + 1..]
                    .iter()
                    .take_while(|c| c.is_ascii_digit() || **c == b'.')
                    .count();
            match line[i..j].parse::<f64>() {
                Ok(v) => {
                    nums.push(v);
                    text.push('#');
                }
                Err(_) => text.push_str(&line[i..j]),
            }
            i = j;
        } else {
            if b[i] != b' ' {
                text.push(b[i] as char);
            }
            i += 1;
        }
    }
    (text, nums)
}

fn same_line(a: &str, b: &str) -> bool {
    let (ta, na) = split_numbers(a);
    let (tb, nb) = split_numbers(b);
    ta == tb && na.len() == nb.len() && na.iter().zip(&nb).all(|(x, y)| (x - y).abs() <= TOLERANCE)
}

/// `None` when equal, else the first difference.
fn compare(expected: &str, actual: &str) -> Option<String> {
    let (e, a) = (normalise(expected), normalise(actual));
    for i in 0..e.len().max(a.len()) {
        let (x, y) = (e.get(i), a.get(i));
        let ok = matches!((x, y), (Some(x), Some(y)) if same_line(x, y));
        if !ok {
            return Some(format!(
                "call {}: expected {}, got {}",
                i + 1,
                x.map(String::as_str).unwrap_or("(end)"),
                y.map(String::as_str).unwrap_or("(end)")
            ));
        }
    }
    None
}

struct Run {
    code: i32,
    stdout: String,
    stderr: String,
}

fn run(cmd: &mut Command) -> Run {
    let o = cmd.env("NO_COLOR", "1").output().expect("run");
    Run {
        code: o.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
    }
}

fn cncc_canon(file: &Path, table: &Path) -> Run {
    run(Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["canon", "--dialect", "linuxcnc", "--tool-table"])
        .arg(table)
        .arg(file))
}

/// One program's verdict: `None` when it matches.
fn verdict(expected_code: i32, expected: &str, got: &Run) -> Option<String> {
    if expected_code == 0 {
        if got.code != 0 {
            let first = got
                .stderr
                .lines()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("");
            return Some(format!("cncc exit {} ({first})", got.code));
        }
        return compare(expected, &got.stdout);
    }
    if got.code != 1 {
        return Some(format!("rs274 reports an error; cncc exit {}", got.code));
    }
    // The calls made before the error must agree too.
    compare(expected, &got.stdout)
}

/// Splits failures into the unexpected ones and the gaps that now pass.
fn judge(name: &str, results: &[(String, Option<String>)]) {
    let excused =
        |p: &str| KNOWN_GAPS.contains(&p) || LINUXCNC_DIFFERENCES.iter().any(|(n, _)| *n == p);
    let failed: Vec<_> = results.iter().filter(|(_, v)| v.is_some()).collect();
    let unexpected: Vec<_> = failed.iter().filter(|(p, _)| !excused(p)).collect();
    let fixed: Vec<_> = results
        .iter()
        .filter(|(p, v)| v.is_none() && KNOWN_GAPS.contains(&p.as_str()))
        .collect();
    eprintln!(
        "{name}: {} programs, {} match, {} differ ({} listed gaps, {} unexpected); {} listed gaps now pass",
        results.len(),
        results.len() - failed.len(),
        failed.len(),
        failed.len() - unexpected.len(),
        unexpected.len(),
        fixed.len()
    );
    for (p, _) in &fixed {
        eprintln!("  now passes (remove from KNOWN_GAPS): {p}");
    }
    if std::env::var("CNCC_ORACLE_LIST").is_ok() {
        for (p, v) in &failed {
            println!(
                "    \"{p}\", // {}",
                v.as_deref().unwrap_or("").replace('\n', " ")
            );
        }
    }
    let report: Vec<String> = unexpected
        .iter()
        .map(|(p, v)| format!("{p}: {}", v.as_deref().unwrap_or("")))
        .collect();
    assert!(
        report.is_empty(),
        "{name}: {} unexpected differences:\n{}",
        report.len(),
        report.join("\n")
    );
}

#[test]
fn probes_match_stored_rs274_output() {
    let Some(dir) = probe_dir() else {
        return skip("../shared/reference/oracle-probe is absent");
    };
    let mut programs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("probe dir")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ngc"))
        .collect();
    programs.sort();
    assert!(
        programs.len() >= 50,
        "expected the ~51 probes, found {}",
        programs.len()
    );
    let mut results = Vec::new();
    for p in &programs {
        let expected = std::fs::read_to_string(p.with_extension("canon")).unwrap_or_default();
        let err = std::fs::read_to_string(p.with_extension("err")).unwrap_or_default();
        let code = err
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("exit "))
            .and_then(|n| n.trim().parse().ok())
            .unwrap_or(0);
        let got = cncc_canon(p, &default_table());
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        results.push((format!("probe/{name}"), verdict(code, &expected, &got)));
    }
    judge("probes", &results);
}

/// The `ok` samples of `samples-summary.tsv` present on this machine.
fn ok_samples(dir: &Path) -> Vec<PathBuf> {
    let tsv = std::fs::read_to_string(dir.join("samples-summary.tsv")).unwrap_or_default();
    tsv.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            (f.len() >= 4 && f[0] == "0" && f[2] == "ok").then(|| PathBuf::from(f[3]))
        })
        .filter(|p| p.is_file())
        .collect()
}

#[test]
fn samples_match_live_rs274() {
    let Some(dir) = probe_dir() else {
        return skip("../shared/reference/oracle-probe is absent");
    };
    if !common::rs274_present() {
        return skip("rs274 is not installed (apt-get install linuxcnc-uspace)");
    }
    let samples = ok_samples(&dir);
    if samples.is_empty() {
        return skip("no LinuxCNC sample programs on this machine");
    }
    let oracle = common::root().join("../shared/tools/rs274-canon");
    let table = default_table();
    let results = parallel(&samples, |p| {
        let want = run(Command::new(&oracle).arg(p).arg(&table));
        let got = cncc_canon(p, &table);
        let v = match want.code {
            0 | 1 => verdict(want.code, &want.stdout, &got),
            c => Some(format!(
                "rs274-canon failed (exit {c}): {}",
                want.stderr.trim()
            )),
        };
        (format!("sample{}", p.display()), v)
    });
    judge("samples", &results);
}

/// Our own LinuxCNC programs written to pin rs274's behaviour
/// (`tests/programs/linuxcnc/oracle/*.ngc`): run live through rs274 and
/// cncc with the default tool table. Both must agree on success or error,
/// and on every call, including the calls made before an error.
#[test]
fn own_programs_match_live_rs274() {
    if !common::root().join("../shared/tools").is_dir() {
        return skip("../shared/tools is absent");
    }
    if !common::rs274_present() {
        return skip("rs274 is not installed (apt-get install linuxcnc-uspace)");
    }
    let dir = common::root().join("tests/programs/linuxcnc/oracle");
    let mut programs: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("tests/programs/linuxcnc/oracle")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "ngc"))
        .collect();
    programs.sort();
    let oracle = common::root().join("../shared/tools/rs274-canon");
    let table = default_table();
    let results = parallel(&programs, |p| {
        let want = run(Command::new(&oracle).arg(p).arg(&table));
        let got = cncc_canon(p, &table);
        let v = match want.code {
            0 | 1 => verdict(want.code, &want.stdout, &got),
            c => Some(format!(
                "rs274-canon failed (exit {c}): {}",
                want.stderr.trim()
            )),
        };
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        (format!("own/{name}"), v)
    });
    assert!(!results.is_empty(), "no programs in {}", dir.display());
    judge("own programs", &results);
}

/// Runs `f` over `items` on two threads, keeping their order.
fn parallel<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    let half = items.len().div_ceil(2);
    std::thread::scope(|s| {
        let chunks: Vec<_> = items
            .chunks(half.max(1))
            .map(|c| s.spawn(|| c.iter().map(&f).collect::<Vec<R>>()))
            .collect();
        chunks
            .into_iter()
            .flat_map(|h| h.join().expect("worker"))
            .collect()
    })
}

#[test]
fn comparison_normalises_like_canon_diff() {
    let a = "SET_NAIVECAM_TOLERANCE(0.0010)\nSTRAIGHT_FEED(1.0000, 2.0000, -3.0000, 0.0000, 0.0000, 0.0000)\nON_RESET()\nCOMMENT(\"interpreter: x\")\n";
    let b = "STRAIGHT_FEED(1.0001, 2.0000, -2.9999, 0.0000, 0.0000, 0.0000)\n";
    assert_eq!(compare(a, b), None);
    let c = "STRAIGHT_FEED(1.0003, 2.0000, -3.0000, 0.0000, 0.0000, 0.0000)\n";
    assert!(compare(a, c).is_some());
    assert!(compare("CHANGE_TOOL(1)\n", "CHANGE_TOOL(2)\n").is_some());
    assert!(compare(
        "SELECT_PLANE(CANON_PLANE_XY)\n",
        "SELECT_PLANE(CANON_PLANE_XZ)\n"
    )
    .is_some());
    assert!(compare("A()\n", "A()\nB()\n").is_some());
}
