//! One part programmed in five dialects (`tests/programs/samepart/`) must
//! cut the same: `cncc check` accepts each silently, and `cncc canon` gives
//! the same cutting moves for each, in order, within 1e-4.
//!
//! What is compared (as `canon-diff --motion`, implemented here): the feed
//! moves, `STRAIGHT_FEED` end points and `ARC_FEED` end, centre, rotation
//! and axis end, in the XY plane (the part is cut in G17 only).
//!
//! Differences allowed, and why:
//! * Rapids (`STRAIGHT_TRAVERSE`) are not compared: tool-change retracts
//!   (Haas `G53 G0 Z0`), cycle clearance and retract levels (G98/G99 vs
//!   the Siemens RTP) differ between controllers without changing the part.
//! * Drilling: a run of vertical feeds at one X Y (only vertical rapids in
//!   between) is one plunge, compared by its position and deepest Z. Peck
//!   depths and chip-break moves differ between G83 (Q) and CYCLE83
//!   (FDEP/DAM/VARI); the hole's position and depth do not.
//! * Feed rates, spindle and tool calls are not compared (the tool numbers
//!   are the same in all four, but Siemens selects edges with D, not H).

use std::path::{Path, PathBuf};
use std::process::Command;

const TOL: f64 = 1e-4;

/// A cutting move, program units.
#[derive(Clone, Debug, PartialEq)]
enum Cut {
    Line([f64; 3]),
    Arc {
        end: [f64; 3],
        centre: [f64; 2],
        rotation: i64,
    },
    /// Vertical feeds at one X Y, by their deepest Z.
    Plunge([f64; 3]),
}

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/samepart")
}

fn cncc(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .output()
        .expect("cncc runs");
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (
        out.status.code().unwrap_or(-1),
        text(&out.stdout),
        text(&out.stderr),
    )
}

/// The numbers between the parentheses of a call.
fn args(line: &str) -> Vec<f64> {
    let inner = line
        .split_once('(')
        .map(|(_, r)| r.trim_end_matches(')'))
        .unwrap_or("");
    inner
        .split(',')
        .filter_map(|s| s.trim().parse::<f64>().ok())
        .collect()
}

fn same_xy(a: [f64; 3], b: [f64; 3]) -> bool {
    (a[0] - b[0]).abs() < TOL && (a[1] - b[1]).abs() < TOL
}

/// The cutting moves of a canon stream (see the module doc).
fn cuts(canon: &str) -> Vec<Cut> {
    let mut pos = [0.0f64; 3];
    let mut out: Vec<Cut> = Vec::new();
    // Is the last cut a plunge still open (no XY change since)?
    let mut open = false;
    for line in canon.lines() {
        let name = line.split('(').next().unwrap_or("").trim();
        let a = args(line);
        match name {
            "STRAIGHT_TRAVERSE" if a.len() >= 3 => {
                let to = [a[0], a[1], a[2]];
                open &= same_xy(pos, to);
                pos = to;
            }
            "STRAIGHT_FEED" if a.len() >= 3 => {
                let to = [a[0], a[1], a[2]];
                if same_xy(pos, to) {
                    match out.last_mut() {
                        Some(Cut::Plunge(p)) if open && same_xy(*p, to) => p[2] = p[2].min(to[2]),
                        _ => out.push(Cut::Plunge(to)),
                    }
                    open = true;
                } else {
                    out.push(Cut::Line(to));
                    open = false;
                }
                pos = to;
            }
            "ARC_FEED" if a.len() >= 6 => {
                let end = [a[0], a[1], a[5]];
                out.push(Cut::Arc {
                    end,
                    centre: [a[2], a[3]],
                    rotation: a[4] as i64,
                });
                open = false;
                pos = end;
            }
            _ => {}
        }
    }
    out
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() < TOL)
}

fn same_cut(a: &Cut, b: &Cut) -> bool {
    match (a, b) {
        (Cut::Line(p), Cut::Line(q)) | (Cut::Plunge(p), Cut::Plunge(q)) => close(p, q),
        (
            Cut::Arc {
                end: e1,
                centre: c1,
                rotation: r1,
            },
            Cut::Arc {
                end: e2,
                centre: c2,
                rotation: r2,
            },
        ) => r1 == r2 && close(e1, e2) && close(c1, c2),
        _ => false,
    }
}

const PROGRAMS: &[(&str, &str)] = &[
    ("part.nc", "fanuc"),
    ("part-haas.nc", "haas"),
    ("part.ngc", "linuxcnc"),
    ("part.mpf", "siemens840d"),
    ("part.h", "heidenhain"),
];

fn run(file: &str, dialect: &str) -> Vec<Cut> {
    let path = dir().join(file);
    let p = path.to_str().expect("utf-8 path");
    let (code, out, err) = cncc(&["canon", p, "--dialect", dialect]);
    assert_eq!(code, 0, "cncc canon {file}: {err}");
    cuts(&out)
}

#[test]
fn each_program_checks_clean() {
    for (file, dialect) in PROGRAMS {
        let path = dir().join(file);
        let (code, out, err) = cncc(&["check", path.to_str().unwrap(), "--dialect", dialect]);
        assert_eq!(code, 0, "cncc check {file}: {out}{err}");
        assert!(
            out.trim().is_empty() && err.trim().is_empty(),
            "cncc check {file} not silent: {out}{err}"
        );
    }
}

#[test]
fn four_dialects_cut_the_same() {
    let (ref_file, ref_dialect) = PROGRAMS[0];
    let reference = run(ref_file, ref_dialect);
    // The part: 6 facing cuts + 4 holes + 2 x 9 pocket moves with 2
    // plunges + a slot (plunge, line, arc, line).
    assert_eq!(reference.len(), 6 + 4 + 20 + 4, "{reference:#?}");
    for (file, dialect) in &PROGRAMS[1..] {
        let cuts = run(file, dialect);
        for (k, (a, b)) in reference.iter().zip(&cuts).enumerate() {
            assert!(
                same_cut(a, b),
                "{file}: cut {k} differs: {ref_file} {a:?}, {file} {b:?}"
            );
        }
        assert_eq!(cuts.len(), reference.len(), "{file}: number of cuts");
    }
}

#[test]
fn plunges_merge_pecks() {
    let canon = "STRAIGHT_TRAVERSE(5.0000, 5.0000, 2.0000, 0, 0, 0)\n\
                 STRAIGHT_FEED(5.0000, 5.0000, -3.0000, 0, 0, 0)\n\
                 STRAIGHT_TRAVERSE(5.0000, 5.0000, 2.0000, 0, 0, 0)\n\
                 STRAIGHT_FEED(5.0000, 5.0000, -8.0000, 0, 0, 0)\n\
                 STRAIGHT_TRAVERSE(9.0000, 5.0000, 2.0000, 0, 0, 0)\n\
                 STRAIGHT_FEED(9.0000, 5.0000, -1.0000, 0, 0, 0)\n\
                 STRAIGHT_FEED(19.0000, 5.0000, -1.0000, 0, 0, 0)\n";
    assert_eq!(
        cuts(canon),
        vec![
            Cut::Plunge([5.0, 5.0, -8.0]),
            Cut::Plunge([9.0, 5.0, -1.0]),
            Cut::Line([19.0, 5.0, -1.0])
        ]
    );
}

/// `cncc stepnc --cc2 PROGRAM -o OUT` (extra arguments after), OUT's text.
fn raise_cc2(file: &str, dialect: &str, extra: &[&str]) -> String {
    let path = dir().join(file);
    let out = std::env::temp_dir().join(format!("cncc-samepart-{}-{file}.stp", std::process::id()));
    let mut args = vec![
        "stepnc",
        "--cc2",
        path.to_str().unwrap(),
        "--dialect",
        dialect,
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    let (code, _, err) = cncc(&args);
    assert_eq!(code, 0, "cncc stepnc --cc2 {file}: {err}");
    assert!(err.trim().is_empty(), "{file}: {err}");
    let text = std::fs::read_to_string(&out).expect("the Part 21 file");
    let _ = std::fs::remove_file(&out);
    text
}

/// The TNC and the Fanuc program give the same CC2 features and
/// operations (`cncc diff` of the two Part 21 files). The Heidenhain stock
/// comes from its `BLK FORM`; the Fanuc one from `--stock`. Ignored, and
/// why: the peck depths of the pecked hole. Fanuc G83's Q counts the first
/// peck from the R plane (R2 Q5: to Z-3), TNC cycle 200's Q202 from the
/// surface (Q203=0 Q202=5: to Z-5), so MULTISTEP_DRILLING's `first_depth`
/// (from the hole's top: 3 and 5) and `retract_distance` (from the first
/// peck's bottom back up to the R plane: 5 and 7) legitimately differ;
/// the hole, its depth and everything else must not.
#[test]
fn fanuc_and_heidenhain_give_the_same_cc2_features() {
    let table = ["--tool-table", "tests/programs/builtin.tbl"];
    let fanuc = raise_cc2(
        "part.nc",
        "fanuc",
        &["--stock", "100x50x20", table[0], table[1]],
    );
    let tnc = raise_cc2("part.h", "heidenhain", &table);
    let tmp = std::env::temp_dir();
    let a = tmp.join(format!("cncc-samepart-{}-a.stp", std::process::id()));
    let b = tmp.join(format!("cncc-samepart-{}-b.stp", std::process::id()));
    std::fs::write(&a, &fanuc).unwrap();
    std::fs::write(&b, &tnc).unwrap();
    let (_, out, err) = cncc(&["diff", a.to_str().unwrap(), b.to_str().unwrap()]);
    let _ = (std::fs::remove_file(&a), std::fs::remove_file(&b));
    assert!(err.trim().is_empty(), "{err}");
    let differences: Vec<&str> = out
        .lines()
        .filter(|l| !l.ends_with("difference(s)"))
        .collect();
    assert_eq!(
        differences,
        [
            "~ operation 'PECK DRILL HOLE4' / first_depth: 3. → 5.",
            "~ operation 'PECK DRILL HOLE4' / retract_distance: 5. → 7."
        ],
        "{out}"
    );
    for entity in ["ROUND_HOLE(", "CLOSED_POCKET(", "MULTISTEP_DRILLING("] {
        assert!(tnc.contains(entity), "no {entity} in\n{tnc}");
    }
}

/// The workpiece's raw stock: from the program's `BLK FORM` when
/// `--stock` is absent, `--stock` when given; none for a Fanuc program
/// without `--stock`.
#[test]
fn blk_form_gives_the_stock() {
    let summary = |file: &str, dialect: &str, extra: &[&str]| {
        let path = dir().join(file);
        let mut args = vec![
            "stepnc",
            "--cc2",
            "--summary",
            path.to_str().unwrap(),
            "--dialect",
            dialect,
        ];
        args.extend_from_slice(extra);
        let (code, out, err) = cncc(&args);
        assert_eq!(code, 0, "{err}");
        out.lines()
            .find(|l| l.starts_with("workpiece"))
            .unwrap_or("")
            .to_string()
    };
    assert!(
        summary("part.h", "heidenhain", &[]).ends_with("block 100 x 50 x 20 from (0, 0, -20)"),
        "{}",
        summary("part.h", "heidenhain", &[])
    );
    let given = summary("part.h", "heidenhain", &["--stock", "110x60x25-5-5-25"]);
    assert!(
        given.ends_with("block 110 x 60 x 25 from (-5, -5, -25)"),
        "{given}"
    );
    let fanuc = summary("part.nc", "fanuc", &[]);
    assert!(!fanuc.contains("block"), "{fanuc}");
}
