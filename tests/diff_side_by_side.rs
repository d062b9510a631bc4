//! `cncc diff` runs the two programs side by side
//! (`src/cli/diff_side_by_side.rs`): each on a thread with a branch of the
//! source map, the comparison reading their operations in batches. These
//! tests check what a user sees: a difference in a subprogram loaded from
//! a file beside the program is named at that file's line (its span
//! renumbered from the branch), and a difference deep in a long program
//! (past the batches and the aligner's window) at its line on both sides.

mod common;

use std::fmt::Write as _;

fn write(dir: &std::path::Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn diff(a: &str, b: &str) -> (i32, String) {
    let o = common::cncc(&[
        "diff",
        "--dialect-a",
        "linuxcnc",
        "--dialect-b",
        "linuxcnc",
        a,
        b,
    ]);
    (o.status.code().unwrap_or(-1), common::stdout(&o))
}

#[test]
fn a_difference_in_a_called_file_is_named_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "sub.ngc",
        "o<sub> sub\nG1 X10 Y5\no<sub> endsub\nM2\n",
    );
    let a = write(
        dir.path(),
        "a.ngc",
        "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\no<sub> call\nG0 Z5\nM2\n",
    );
    let b = write(
        dir.path(),
        "b.ngc",
        "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y6\nG0 Z5\nM2\n",
    );
    let (code, out) = diff(&a, &b);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("A: line to X10 Y5 Z-1; B: line to X10 Y6 Z-1"),
        "{out}"
    );
    assert!(out.contains("sub.ngc:2: G1 X10 Y5"), "{out}");
    assert!(out.contains("b.ngc:4: G1 X10 Y6"), "{out}");
    let same = write(
        dir.path(),
        "c.ngc",
        "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y5\nG0 Z5\nM2\n",
    );
    assert_eq!(diff(&a, &same).0, 0);
}

#[test]
fn a_difference_deep_in_a_long_program_is_found_at_its_lines() {
    let dir = tempfile::tempdir().unwrap();
    let program = |odd: usize| {
        let mut t = String::from("G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F300\n");
        for i in 1..30_000 {
            let y = if i == odd { 0.5 } else { (i % 2) as f64 };
            writeln!(t, "X{i} Y{y}").unwrap();
        }
        t.push_str("G0 Z5\nM2\n");
        t
    };
    let a = write(dir.path(), "a.ngc", &program(0));
    let b = write(dir.path(), "b.ngc", &program(25_001));
    let (code, out) = diff(&a, &b);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("(30000 operations)"), "{out}");
    // Line 3 + 25001: the block that moves differently, on both sides.
    assert!(out.contains("a.ngc:25004: X25001 Y1"), "{out}");
    assert!(out.contains("b.ngc:25004: X25001 Y0.5"), "{out}");
    assert!(out.contains("different: 1 difference"), "{out}");
}
