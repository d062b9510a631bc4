//! Tapping end to end: ISO 14649-11 TAPPING read and written; G84/G74,
//! CYCLE84 and CYCL DEF 207 raised to a ROUND_HOLE with a TAPPING
//! operation (CC1 and CC2); our hand-written `tapped_holes.stp` posted to
//! every dialect, each output checking clean and raising back to the same
//! holes and tapping operations; the LinuxCNC output run by rs274 as cncc
//! runs it; a tap's hand against its spindle and a missing pitch refused.

mod common;

use cncc::source::SourceMap;
use cncc::stepnc::{self, model::*};
use std::path::{Path, PathBuf};
use std::process::Command;

const DIALECTS: [(&str, &str); 5] = [
    ("fanuc", "nc"),
    ("haas", "nc"),
    ("linuxcnc", "ngc"),
    ("siemens840d", "mpf"),
    ("heidenhain", "h"),
];

fn sample() -> PathBuf {
    common::root().join("tests/programs/stepnc/tapped_holes.stp")
}

fn tmp(name: &str) -> PathBuf {
    let dir = common::root().join("target/tmp/tapping-tests");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Reads a file that must give no diagnostic at all.
fn read(path: &Path) -> Project {
    let mut files = SourceMap::new();
    let r = stepnc::read_file(path, &mut files).unwrap();
    assert!(
        r.diagnostics.is_empty(),
        "{}: {:?}",
        path.display(),
        r.diagnostics
    );
    r.project.expect("a project")
}

/// Each tapping operation as (hole X, hole Y, pitch, left hand), in
/// workplan order.
fn taps(p: &Project) -> Vec<(f64, f64, f64, bool)> {
    let mut out = Vec::new();
    for e in &p.main_workplan.elements {
        let Executable::Workingstep(ws) = e else {
            continue;
        };
        let op = p.operation(ws.operation);
        if !matches!(op.kind, OperationKind::Tapping { .. }) {
            continue;
        }
        let f = p.feature(ws.feature);
        assert!(matches!(f.kind, FeatureKind::RoundHole { .. }), "{f:?}");
        let xyz = f.placement.location.xyz;
        let pitch = op.thread_pitch().expect("a pitch");
        let left = op.technology.spindle.expect("a speed") < 0.0;
        assert!(op.technology.synchronize_spindle_with_feed, "{op:?}");
        assert_eq!(p.tool(op.tool).body.kind, ToolBodyKind::Tap);
        out.push((xyz[0], xyz[1], (pitch * 1e6).round() / 1e6, left));
    }
    out
}

const EXPECTED: [(f64, f64, f64, bool); 2] = [(15.0, 20.0, 1.25, false), (40.0, 20.0, 1.0, true)];

#[test]
fn the_sample_reads_writes_and_reads_back() {
    let p = read(&sample());
    assert_eq!(taps(&p), EXPECTED);
    let chucks: Vec<bool> = p
        .operations
        .iter()
        .filter_map(|o| match o.kind {
            OperationKind::Tapping {
                compensation_chuck, ..
            } => Some(compensation_chuck),
            _ => None,
        })
        .collect();
    assert_eq!(chucks, [false, false]);
    let hands: Vec<_> = p.tools.iter().map(|t| t.body.hand_of_cut).collect();
    assert!(hands.contains(&Some(Hand::Left)), "{hands:?}");
    let text = stepnc::write_project(&p);
    assert!(text.contains("TAPPING($,$,'TAP M8X1.25',"), "{text}");
    let mut files = SourceMap::new();
    let id = files.add("again.stp", text.clone());
    let r = stepnc::read_text(&text, id);
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.project.expect("reads back"), p);
}

#[test]
fn thread_drilling_writes_and_reads_back() {
    let mut p = read(&sample());
    let op = p
        .operations
        .iter_mut()
        .find(|o| matches!(o.kind, OperationKind::Tapping { .. }))
        .unwrap();
    let OperationKind::Tapping { drill, .. } = op.kind.clone() else {
        unreachable!()
    };
    op.kind = OperationKind::ThreadDrilling {
        drill,
        helical_movement_on_forward: true,
    };
    let text = stepnc::write_project(&p);
    assert!(text.contains("THREAD_DRILLING("), "{text}");
    let mut files = SourceMap::new();
    let id = files.add("td.stp", text.clone());
    let r = stepnc::read_text(&text, id);
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.project.expect("reads back"), p);
}

fn post(dialect: &str, ext: &str, input: &Path) -> (PathBuf, String) {
    let out = tmp(&format!("tapped_holes-{dialect}.{ext}"));
    let o = common::cncc(&[
        "post",
        input.to_str().unwrap(),
        "--to",
        dialect,
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{dialect}: {}",
        common::stderr(&o)
    );
    let text = std::fs::read_to_string(&out).unwrap();
    (out, text)
}

#[test]
fn posted_to_every_dialect_it_checks_clean_and_raises_back() {
    for (dialect, ext) in DIALECTS {
        let (path, text) = post(dialect, ext, &sample());
        let calls: &[&str] = match dialect {
            "siemens840d" => &[
                "MCALL CYCLE84(20,0,3,-14,,0,3,,1.25,0,600,600)",
                "MCALL CYCLE84(20,0,3,-12,,0,4,,-1,0,480,480)",
                "S480 M4",
            ],
            "heidenhain" => &[
                "CYCL DEF 207 RIGID TAPPING NEW Q200=3 Q201=-14 Q239=1.25 Q203=0 Q204=20",
                "Q239=-1 Q203=0",
                "M4",
            ],
            "linuxcnc" => &[
                "G98 G84 X15 Y20 Z-14 R3 F750",
                "G98 G74 X40 Y20 Z-12 R3 F480",
                "S480 M4",
            ],
            _ => &[
                "G98 G84 X15. Y20. Z-14. R3. F750",
                "G98 G74 X40. Y20. Z-12. R3. F480",
                "S480 M4",
            ],
        };
        for c in calls {
            assert!(text.contains(c), "{dialect}: no `{c}` in\n{text}");
        }
        assert!(!text.contains("NOT POSTED"), "{dialect}:\n{text}");
        let o = common::cncc(&["check", "--dialect", dialect, path.to_str().unwrap()]);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(0), "{dialect}: {err}");
        assert!(!err.contains("warning["), "{dialect}: {err}");
        let raised = tmp(&format!("raised-{dialect}.stp"));
        let o = common::cncc(&[
            "stepnc",
            "--cc2",
            "--dialect",
            dialect,
            path.to_str().unwrap(),
            "-o",
            raised.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{dialect}: {}",
            common::stderr(&o)
        );
        assert_eq!(taps(&read(&raised)), EXPECTED, "{dialect}");
    }
}

#[test]
fn linuxcnc_output_runs_in_rs274_as_cncc_runs_it() {
    let (path, _) = post("linuxcnc", "ngc", &sample());
    let oracle = common::root().join("../shared/tools/rs274-canon");
    let diff = common::root().join("../shared/tools/canon-diff");
    if !oracle.exists() || !diff.exists() {
        eprintln!("note: ../shared/tools/rs274-canon is absent; not running LinuxCNC");
        return;
    }
    let o = Command::new(&oracle).arg(&path).output().unwrap();
    if o.status.code() == Some(2) {
        eprintln!("note: rs274 is not installed; not running LinuxCNC");
        return;
    }
    assert_eq!(o.status.code(), Some(0), "rs274: {}", common::stderr(&o));
    let theirs = tmp("tapped_holes.rs274.canon");
    std::fs::write(&theirs, &o.stdout).unwrap();
    let ours = common::cncc(&["canon", "--dialect", "linuxcnc", path.to_str().unwrap()]);
    assert_eq!(ours.status.code(), Some(0), "{}", common::stderr(&ours));
    let mine = tmp("tapped_holes.cncc.canon");
    std::fs::write(&mine, &ours.stdout).unwrap();
    let d = Command::new(&diff)
        .arg(&theirs)
        .arg(&mine)
        .output()
        .unwrap();
    let report = common::stdout(&d);
    assert!(report.starts_with("same"), "{report}");
}

/// The sample with one text replaced, saved under `name`.
fn variant(name: &str, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(sample()).unwrap();
    assert!(text.contains(from), "{from}");
    let p = tmp(name);
    std::fs::write(&p, text.replace(from, to)).unwrap();
    p
}

#[test]
fn a_tap_against_its_spindle_or_without_a_pitch_is_refused() {
    let cases = [
        (
            "hand.stp",
            "#77=TAP(#95,$,.LEFT.",
            "#77=TAP(#95,$,.RIGHT.",
            ["W0805", "E0907"],
        ),
        (
            "nopitch.stp",
            "#83=MILLING_TECHNOLOGY(0.008,.TCP.,$,8.,",
            "#83=MILLING_TECHNOLOGY(0.008,.TCP.,$,0.,",
            ["W0804", "E0906"],
        ),
    ];
    for (name, from, to, codes) in cases {
        let p = variant(name, from, to);
        let o = common::cncc(&["post", p.to_str().unwrap(), "--to", "fanuc"]);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{name}: {err}");
        for code in codes {
            assert!(err.contains(code), "{name}: no {code} in {err}");
        }
    }
}

/// A compensating chuck: `CYCLE840` on the 840D, `CYCL DEF 206` on
/// Heidenhain, named as not posted on Fanuc; each raises back to tapping.
#[test]
fn a_compensation_chuck_posts_as_the_floating_tap_cycle() {
    let p = variant(
        "chuck.stp",
        "'TAP M8X1.25',3.,$,#72,#81,#85,$,14.,6.8,$,$,$,.F.)",
        "'TAP M8X1.25',3.,$,#72,#81,#85,$,14.,6.8,$,$,$,.T.)",
    );
    let cases = [
        (
            "siemens840d",
            "mpf",
            "MCALL CYCLE840(20,0,3,-14,,0,0,3,1,,1.25)",
        ),
        (
            "heidenhain",
            "h",
            "CYCL DEF 206 TAPPING NEW Q200=3 Q201=-14 Q206=750 Q211=0 Q203=0 Q204=20",
        ),
        ("fanuc", "nc", "(NOT POSTED: compensation chuck"),
    ];
    for (dialect, ext, want) in cases {
        let (path, text) = post(dialect, ext, &p);
        assert!(text.contains(want), "{dialect}: no `{want}` in\n{text}");
        let o = common::cncc(&["check", "--dialect", dialect, path.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{dialect}: {}",
            common::stderr(&o)
        );
        let raised = tmp(&format!("chuck-{dialect}.stp"));
        let o = common::cncc(&[
            "stepnc",
            "--cc2",
            "--dialect",
            dialect,
            path.to_str().unwrap(),
            "-o",
            raised.to_str().unwrap(),
        ]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{dialect}: {}",
            common::stderr(&o)
        );
        assert_eq!(taps(&read(&raised)), EXPECTED, "{dialect}");
    }
}

/// G84 and G74 (Fanuc), CYCLE84 and CYCLE840 (840D), CYCL DEF 207 and
/// 206 (Heidenhain) raise to tapping, in CC1 and CC2.
#[test]
fn tapping_cycles_raise_to_tapping_operations() {
    let m = common::root().join("tests/matrix/tapping");
    let left = tmp("g74.nc");
    std::fs::write(
        &left,
        "O1\nG21 G17 G90 G94\nT4 M6\nG0 G43 H4 Z20.\nS300 M4\nG0 X10. Y10.\n\
         G98 G74 X10. Y10. Z-8. R2. F300.\nG80\nM30\n",
    )
    .unwrap();
    let float = tmp("c840.mpf");
    std::fs::write(
        &float,
        "G71 G17 G90 G94\nT4 D1 M6\nG0 Z20\nS400 M4 F400\nG0 X15 Y15\n\
         MCALL CYCLE840(20,3,0,-12,,0.5,0,3,1,,-1)\nX15 Y15\nMCALL\nG0 Z20\nM30\n",
    )
    .unwrap();
    let cases = [
        (float, "siemens840d", 1.0, true),
        (m.join("from-heidenhain-float.h"), "heidenhain", 1.25, false),
        (m.join("from-fanuc.nc"), "fanuc", 1.25, false),
        (m.join("from-siemens840d.mpf"), "siemens840d", 1.25, false),
        (
            m.join("from-fanuc.to-heidenhain"),
            "heidenhain",
            1.25,
            false,
        ),
        (left, "fanuc", 1.0, true),
    ];
    for (file, dialect, pitch, lh) in cases {
        for cc in ["--cc1", "--cc2"] {
            let out = tmp(&format!("raised-{dialect}{cc}-{lh}.stp"));
            let o = common::cncc(&[
                "stepnc",
                cc,
                "--dialect",
                dialect,
                file.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ]);
            assert_eq!(
                o.status.code(),
                Some(0),
                "{}: {}",
                file.display(),
                common::stderr(&o)
            );
            let t = taps(&read(&out));
            assert!(!t.is_empty(), "{} {cc}: no tapping", file.display());
            for (_, _, p, l) in t {
                assert_eq!((p, l), (pitch, lh), "{} {cc}", file.display());
            }
        }
    }
}

/// CYCL DEF 207 ports to G84/G74 only when the spindle already turns the
/// way the tap's hand needs, and with a spindle speed known (F = Q239 x S).
#[test]
fn cycle_207_against_its_spindle_is_not_ported() {
    let src = common::root().join("tests/matrix/tapping/from-heidenhain.h");
    let text = std::fs::read_to_string(&src).unwrap();
    let cases = [
        (
            "wrong-hand.h",
            text.replace("3 M3\n", "3 M4\n"),
            "G84 needs M3",
        ),
        (
            "no-speed.h",
            text.replace("1 TOOL CALL 4 Z S400\n", "1 TOOL CALL 4 Z\n"),
            "without a spindle speed",
        ),
    ];
    for (name, program, why) in cases {
        let p = tmp(name);
        std::fs::write(&p, program).unwrap();
        let o = common::cncc(&[
            "port",
            "--from",
            "heidenhain",
            "--to",
            "fanuc",
            p.to_str().unwrap(),
        ]);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(1), "{name}: {err}");
        assert!(err.contains("E0610") && err.contains(why), "{name}: {err}");
    }
}

/// `port --features`: a Fanuc tapping program raised to CC2 and posted
/// with each target's tapping cycle, verified by raising it again.
#[test]
fn tapping_ports_by_features_to_every_dialect() {
    let src = common::root().join("tests/matrix/tapping/from-fanuc.nc");
    for (dialect, _) in DIALECTS {
        let o = common::cncc(&[
            "port",
            "--features",
            "--from",
            "fanuc",
            "--to",
            dialect,
            "--verify",
            src.to_str().unwrap(),
        ]);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(0), "{dialect}: {err}");
        assert!(err.contains("verify: OK"), "{dialect}: {err}");
        assert!(
            err.contains("verify: material: the same part"),
            "{dialect}: {err}"
        );
        let text = common::stdout(&o);
        let cycle = match dialect {
            "siemens840d" => "CYCLE84(",
            "heidenhain" => "CYCL DEF 207",
            _ => "G84 ",
        };
        assert!(text.contains(cycle), "{dialect}: no {cycle} in\n{text}");
    }
}

/// `cncc query` reaches the TAPPING attributes and `cncc diff` names a
/// changed one.
#[test]
fn query_and_diff_see_tapping_attributes() {
    let s = sample();
    let o = common::cncc(&["query", s.to_str().unwrap(), "/tapping/compensation_chuck"]);
    assert_eq!(common::stdout(&o), ".F.\n.F.\n", "{}", common::stderr(&o));
    let o = common::cncc(&["query", s.to_str().unwrap(), "/tap/hand_of_cut"]);
    assert_eq!(
        common::stdout(&o),
        ".RIGHT.\n.LEFT.\n",
        "{}",
        common::stderr(&o)
    );
    let chuck = variant(
        "diff-chuck.stp",
        "'TAP M6X1 LH',3.,$,#76,#83,#85,$,12.,5.,$,$,$,.F.)",
        "'TAP M6X1 LH',3.,$,#76,#83,#85,$,12.,5.,$,$,$,.T.)",
    );
    let o = common::cncc(&["diff", s.to_str().unwrap(), chuck.to_str().unwrap()]);
    let out = common::stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{out}{}", common::stderr(&o));
    assert!(
        out.contains("operation 'TAP M6X1 LH' / compensation_chuck: .F. → .T."),
        "{out}"
    );
}

/// THREAD_DRILLING reads, but no target has a cycle for it: posting it is
/// refused (E0900), never dropped.
#[test]
fn thread_drilling_is_refused_by_the_post() {
    let p = variant(
        "thread-drilling.stp",
        "#51=TAPPING($,$,'TAP M8X1.25',3.,$,#72,#81,#85,$,14.,6.8,$,$,$,.F.);",
        "#51=THREAD_DRILLING($,$,'TAP M8X1.25',3.,$,#72,#81,#85,$,14.,6.8,$,$,$,.F.);",
    );
    let o = common::cncc(&["post", p.to_str().unwrap(), "--to", "siemens840d"]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains("E0900") && err.contains("thread_drilling"),
        "{err}"
    );
}
