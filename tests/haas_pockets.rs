//! Haas G12/G13 circular pocket milling: read and written back by the
//! Haas spec, run (expanded into feeds and arcs about the centre), its
//! errors, and `cncc post --to haas` writing circular pockets as G12/G13
//! (explicit moves elsewhere).

mod common;

use cncc::dialect::builtin::builtin;
use cncc::post::{fixture, post};
use cncc::stepnc::model::*;
use std::path::PathBuf;

fn save(name: &str, text: &str) -> PathBuf {
    let dir = common::root().join("target/tmp/haas-pocket-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn canon(name: &str, text: &str) -> (Option<i32>, String, String) {
    let p = save(name, text);
    let o = common::cncc(&["canon", "--dialect", "haas", p.to_str().unwrap()]);
    (o.status.code(), common::stdout(&o), common::stderr(&o))
}

/// The motion calls only.
fn moves(out: &str) -> Vec<&str> {
    out.lines()
        .filter(|l| l.starts_with("STRAIGHT_") || l.starts_with("ARC_FEED"))
        .collect()
}

const PROGRAM: &str = "%
O01000 (G12 G13)
G17 G21 G40 G49 G80 G90 G94
T1 M6
G0 G54 X50. Y40.
G43 H1 Z5.
S2000 M3
G12 I5. K15. Q5. Z-3. F300. D0
G0 Z10.
G91 G13 X-30. I4. Z-2. L2 F200.
G90 G0 Z10.
M30
%
";

#[test]
fn g12_cuts_circles_from_i_to_k_and_g13_repeats_incremental_depths() {
    let (code, out, err) = canon("g12.nc", PROGRAM);
    assert_eq!(code, Some(0), "{err}");
    let m = moves(&out);
    let at = m
        .iter()
        .position(|l| l.starts_with("STRAIGHT_FEED(50.0000, 40.0000, -3.0000"))
        .expect("plunge at the centre");
    let g12 = [
        "STRAIGHT_FEED(50.0000, 40.0000, -3.0000, 0.0000, 0.0000, 0.0000)",
        "STRAIGHT_FEED(55.0000, 40.0000, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(45.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(55.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "STRAIGHT_FEED(60.0000, 40.0000, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(40.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(60.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "STRAIGHT_FEED(65.0000, 40.0000, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(35.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "ARC_FEED(65.0000, 40.0000, 50.0000, 40.0000, -1, -3.0000, 0.0000, 0.0000, 0.0000)",
        "STRAIGHT_FEED(50.0000, 40.0000, -3.0000, 0.0000, 0.0000, 0.0000)",
    ];
    assert_eq!(&m[at..at + g12.len()], &g12[..], "{out}");
    // G91 G13 X-30 Z-2 L2 from Z10: a rapid to the centre (20, 40), two
    // passes at Z8 and Z6, counter-clockwise, radius 4.
    let rest = &m[at + g12.len()..];
    assert_eq!(
        rest[0],
        "STRAIGHT_TRAVERSE(50.0000, 40.0000, 10.0000, 0.0000, 0.0000, 0.0000)"
    );
    assert_eq!(
        rest[1],
        "STRAIGHT_TRAVERSE(20.0000, 40.0000, 10.0000, 0.0000, 0.0000, 0.0000)"
    );
    assert_eq!(
        rest[2],
        "STRAIGHT_FEED(20.0000, 40.0000, 8.0000, 0.0000, 0.0000, 0.0000)"
    );
    assert_eq!(
        rest[4],
        "ARC_FEED(16.0000, 40.0000, 20.0000, 40.0000, 1, 8.0000, 0.0000, 0.0000, 0.0000)"
    );
    assert!(rest.contains(&"STRAIGHT_FEED(20.0000, 40.0000, 6.0000, 0.0000, 0.0000, 0.0000)"));
    assert_eq!(
        rest.last().unwrap(),
        &"STRAIGHT_TRAVERSE(20.0000, 40.0000, 10.0000, 0.0000, 0.0000, 0.0000)"
    );
}

#[test]
fn d_compensates_the_radii_by_the_tools_radius() {
    let table = save("t.tbl", "T1 P1 D4 Z50\n");
    let p = save(
        "d.nc",
        "G17 G21 G90\nT1 M6\nG0 X0. Y0. Z1.\nG13 I5. D1 Z-1. F100.\nM30\n",
    );
    let o = common::cncc(&[
        "canon",
        "--dialect",
        "haas",
        "--machine-units",
        "mm",
        "--tool-table",
        table.to_str().unwrap(),
        p.to_str().unwrap(),
    ]);
    let out = common::stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    // Circle radius 5, tool radius 2: the tool centre runs on radius 3.
    assert!(
        out.contains("ARC_FEED(-3.0000, 0.0000, 0.0000, 0.0000, 1, -1.0000"),
        "{out}"
    );
}

#[test]
fn the_haas_spec_reads_and_writes_g12_back() {
    let p = save("rt.nc", PROGRAM);
    let o = common::cncc(&[
        "port",
        "--from",
        "haas",
        "--to",
        "haas",
        p.to_str().unwrap(),
    ]);
    let out = common::stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    assert!(out.contains("G12 I5. K15. Q5. D0 Z-3."), "{out}");
    assert!(out.contains("G91 G13 I4. L2 Z-2. X-30."), "{out}");
    let (_, again, _) = canon("rt2.nc", &out);
    let (_, first, _) = canon("rt1.nc", PROGRAM);
    assert_eq!(moves(&again), moves(&first));
}

#[test]
fn impossible_words_are_errors_with_their_codes() {
    for (block, code) in [
        ("G12 I5. K15. F300.", "E0517"),
        ("G12 I5. K3. Q1. F300.", "E0516"),
        ("G12 I5. K15. Q2. L0 F300.", "E0543"),
        ("G12 K5. F300.", "E0206"),
        ("G41 D1 G1 X10. Y0. F100.\nG12 I5. F300.", "E0515"),
        ("G18 G12 I5. F300.", "E0510"),
    ] {
        let text = format!("G17 G21 G90\nT1 M6\n{block}\nM30\n");
        let (status, _, err) = canon("bad.nc", &text);
        assert_eq!(status, Some(1), "{block}: {err}");
        assert!(err.contains(code), "{block}: {err}");
    }
}

/// Example 1 with its pocket made circular (diameter 60).
fn round_pocket() -> Project {
    let mut p = fixture::ex1();
    if let FeatureKind::ClosedPocket { boundary, .. } = &mut p.features[2].kind {
        *boundary = ClosedProfile::Circular {
            placement: None,
            diameter: Toleranced {
                nominal: 60.0,
                tolerance: Tolerance::PlusMinus {
                    upper: 0.05,
                    lower: 0.05,
                    significant_digits: 3,
                },
            },
        };
    }
    p
}

#[test]
fn post_writes_a_circular_pocket_as_g12_on_haas_only() {
    let p = round_pocket();
    let text = post(&p, &builtin("haas").unwrap()).unwrap().text;
    let calls: Vec<&str> = text.lines().filter(|l| l.starts_with("G12 ")).collect();
    // Roughing: 18 mm tool, side allowance 1: last circle 30 - 9 - 1 = 20,
    // first and stepover 5 (the operation's radial depth), five levels
    // down to the floor allowance (-29.5).
    assert!(calls.contains(&"G12 I5. K20. Q5. Z-5.9 D0 F2400"), "{text}");
    assert!(
        calls.contains(&"G12 I5. K20. Q5. Z-29.5 D0 F2400"),
        "{text}"
    );
    // Finishing: the wall circle (30 - 9) on the upper levels, the floor
    // cleared at the bottom (first circle the tool radius, stepover 10).
    assert!(calls.contains(&"G12 I21. Z-2. D0 F2400"), "{text}");
    assert!(
        calls.contains(&"G12 I9. K21. Q10. Z-30. D0 F2400"),
        "{text}"
    );
    assert_eq!(calls.len(), 20, "{text}");
    let path = save("round.nc", &text);
    let o = common::cncc(&["check", "--dialect", "haas", path.to_str().unwrap()]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("warning["), "{err}");
    // A face mill does not plunge: explicit moves, as on the others.
    let mut face = p.clone();
    face.tools[0].body.kind = ToolBodyKind::Facemill;
    let text = post(&face, &builtin("haas").unwrap()).unwrap().text;
    assert!(!text.lines().any(|l| l.starts_with("G12 ")), "{text}");
    for id in ["fanuc", "linuxcnc"] {
        let text = post(&p, &builtin(id).unwrap()).unwrap().text;
        assert!(!text.lines().any(|l| l.starts_with("G12 ")), "{id}");
        assert!(text.lines().any(|l| l.starts_with("G2 X")), "{id}");
    }
}

#[test]
fn g150_is_kept_and_reported_as_not_expanded() {
    let text = "G17 G21 G90\nT1 M6\nG0 X0. Y0. Z1.\nG150 P2000 Q0.5 R0.1 Z-1. F100. D1\nG1 X5. F100.\nM30\n";
    let (code, out, err) = canon("g150.nc", text);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("W0510"), "{err}");
    // The run goes on: the next block's move is there.
    assert!(
        out.contains("STRAIGHT_FEED(5.0000, 0.0000, 1.0000"),
        "{out}"
    );
    let p = save("g150rt.nc", text);
    let o = common::cncc(&[
        "port",
        "--from",
        "haas",
        "--to",
        "haas",
        p.to_str().unwrap(),
    ]);
    assert!(
        common::stdout(&o).contains("G150 P2000 Q0.5 R0.1"),
        "{}",
        common::stderr(&o)
    );
}

#[test]
fn port_refuses_g12_where_the_target_has_none_and_expands_it_on_request() {
    let p = save("port.nc", PROGRAM);
    let p = p.to_str().unwrap();
    for to in ["fanuc", "linuxcnc", "siemens840d", "heidenhain"] {
        let o = common::cncc(&["port", "--strict", "--from", "haas", "--to", to, p]);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{to}: {err}");
        assert!(
            err.contains("E0610") && err.contains("G12 cannot be ported"),
            "{to}: {err}"
        );
    }
    // --expand-cycles: the G90 G12 becomes its moves; the G91 G13 stays
    // refused (with --strict: without it the port writes it as its moves).
    let o = common::cncc(&[
        "port",
        "--strict",
        "--from",
        "haas",
        "--to",
        "linuxcnc",
        "--expand-cycles",
        p,
    ]);
    let err = common::stderr(&o);
    assert!(
        err.contains("G13 cannot be ported to linuxcnc: in G91"),
        "{err}"
    );
    assert!(!err.contains("G12 cannot"), "{err}");
    let absolute = PROGRAM.replace("G91 G13 X-30. I4. Z-2. L2 F200.\n", "");
    let p = save("port-abs.nc", &absolute);
    let o = common::cncc(&[
        "port",
        "--from",
        "haas",
        "--to",
        "linuxcnc",
        "--expand-cycles",
        "--verify",
        p.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let out = common::stdout(&o);
    assert!(out.contains("G2 X35 Y40 Z-3 I-15 J0"), "{out}");
    assert!(!out.lines().any(|l| l.starts_with("G12")), "{out}");
    // G150 is never expanded.
    let p = save(
        "port150.nc",
        "G17 G21 G90\nT1 M6\nG150 P2000 Q0.5 R0.1 Z-1. F100. D1\nM30\n",
    );
    let o = common::cncc(&[
        "port",
        "--from",
        "haas",
        "--to",
        "fanuc",
        "--expand-cycles",
        p.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        common::stderr(&o).contains("G150 cannot be ported"),
        "{}",
        common::stderr(&o)
    );
}
