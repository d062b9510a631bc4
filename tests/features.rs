//! `cncc port --features` and the post → raise round trip: a program's
//! explicit toolpaths become the target's feature cycles, and a posted
//! program raised again to CC2 gives back the same features (compared by
//! meaning with `stepnc::diff::diff_projects`; operations, names and
//! tolerances are not compared: see `cncc::post::features`).

mod common;

use cncc::dialect::builtin;
use cncc::post::features::{round_trip, FeatureVerdict};
use cncc::stepnc::model::Project;
use std::path::{Path, PathBuf};

fn shared(rel: &str) -> Option<PathBuf> {
    let p = common::root().join("../shared").join(rel);
    if p.exists() {
        Some(p)
    } else {
        eprintln!("note: ../shared/{rel} is absent; skipped");
        None
    }
}

fn read_stp(path: &Path) -> Project {
    let mut files = cncc::source::SourceMap::new();
    let r = cncc::stepnc::read_file(path, &mut files).unwrap();
    assert!(
        !r.diagnostics.iter().any(|d| d.is_error()),
        "{:#?}",
        r.diagnostics
    );
    r.project.expect("a project")
}

fn trip(p: &Project, id: &str) -> (String, FeatureVerdict) {
    let spec = builtin(id).unwrap();
    round_trip(p, &spec).unwrap_or_else(|e| panic!("{id}: {e:#?}"))
}

fn demo() -> PathBuf {
    common::root().join("tests/programs/fanuc/port_demo.nc")
}

fn demo_table() -> PathBuf {
    common::root().join("tests/programs/fanuc/port_demo.tbl")
}

fn port_features(to: &str, verify: bool) -> std::process::Output {
    let (demo, table) = (demo(), demo_table());
    let mut args = vec![
        "port",
        demo.to_str().unwrap(),
        "--to",
        to,
        "--features",
        "--tool-table",
        table.to_str().unwrap(),
        "--machine-units",
        "mm",
    ];
    if verify {
        args.push("--verify");
    }
    common::cncc(&args)
}

#[test]
fn fanuc_demo_becomes_840d_feature_cycles_and_verifies() {
    let o = port_features("siemens840d", true);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("verify: OK: the same 7 feature(s)"), "{err}");
    assert!(err.contains("verify: material: the same part"), "{err}");
    let text = String::from_utf8(o.stdout).unwrap();
    for call in ["CYCLE71(", "MCALL CYCLE81(", "MCALL CYCLE83(", "POCKET1("] {
        assert!(text.contains(call), "{call} missing:\n{text}");
    }
    // The G81 holes went to Z-10 and the G83 hole to Z-20 (drill points).
    assert!(text.contains("MCALL CYCLE81(25,0,2,-10,)"), "{text}");
    assert!(text.contains("MCALL CYCLE83(25,0,2,-20,"), "{text}");
    // The pocket: 60 x 20 at the tool's centre + the 10 mm tool = 70 x 30
    // around (50, 25), 3 deep.
    assert!(
        text.contains("POCKET1(25,0,2,-3,,70,30,10,50,25,0,"),
        "{text}"
    );
}

#[test]
fn the_840d_port_checks_clean() {
    let o = port_features("siemens840d", false);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let dir = common::root().join("target/tmp/features-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("port_demo.mpf");
    std::fs::write(&p, &o.stdout).unwrap();
    let c = common::cncc(&["check", "--dialect", "siemens840d", p.to_str().unwrap()]);
    let err = common::stderr(&c);
    assert_eq!(c.status.code(), Some(0), "{err}");
    assert!(!err.contains("warning["), "{err}");
}

#[test]
fn fanuc_demo_ported_to_every_dialect_by_features_cuts_the_same_part() {
    for to in ["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"] {
        let o = port_features(to, true);
        let err = common::stderr(&o);
        assert_eq!(o.status.code(), Some(0), "{to}: {err}");
        assert!(err.contains("verify: OK"), "{to}: {err}");
        assert!(
            err.contains("verify: material: the same part within 0.01 mm"),
            "{to}: {err}"
        );
    }
}

/// The case: a contour round a rectangle (a ring: the 10 mm tool
/// leaves a 50 x 10 island) is raised as a closed pocket; the features
/// of the port agree, but the posted POCKET1 clears the island. The
/// material comparison refuses the port and shows where.
#[test]
fn a_ring_raised_as_a_pocket_is_refused_by_material() {
    let ring = common::root().join("tests/programs/fanuc/ring_as_pocket.nc");
    let table = demo_table();
    let o = common::cncc(&[
        "port",
        ring.to_str().unwrap(),
        "--to",
        "siemens840d",
        "--features",
        "--tool-table",
        table.to_str().unwrap(),
        "--machine-units",
        "mm",
        "--verify",
    ]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(o.stdout.is_empty(), "nothing is written");
    assert!(err.contains("error[E1002 material-differs]"), "{err}");
    assert!(err.contains("3 mm off at X25.05 Y20.05"), "{err}");
    // The island: the tool-centre rectangle less the tool's radius.
    assert!(err.contains("within X25.05..74.95 Y20.05..29.95"), "{err}");
    assert!(err.contains("port: last cut there, to Z-3"), "{err}");
    assert!(err.contains("POCKET1("), "{err}");
    assert!(err.contains("the source never cuts there"), "{err}");
    assert!(err.contains("only the port 1500 mm3"), "{err}");
}

#[test]
fn a_raised_part_posted_and_raised_again_gives_the_same_features() {
    // The CC2 part written to .stp, read back, posted and raised again.
    let stp = common::root().join("target/tmp/features-tests/port_demo.stp");
    std::fs::create_dir_all(stp.parent().unwrap()).unwrap();
    let o = common::cncc(&[
        "stepnc",
        "--cc2",
        "--tool-table",
        demo_table().to_str().unwrap(),
        "--machine-units",
        "mm",
        demo().to_str().unwrap(),
        "-o",
        stp.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let p = read_stp(&stp);
    for id in ["siemens840d", "fanuc", "heidenhain"] {
        let (text, v) = trip(&p, id);
        assert!(v.same, "{id}: {:#?}\n{text}", v.lines);
        assert_eq!(v.features, 7);
    }
}

#[test]
fn ex1_posted_and_raised_again_gives_the_same_holes_and_pockets() {
    let Some(ex1) = shared("stepnc-samples/ex1.stp") else {
        return;
    };
    let p = read_stp(&ex1);
    // Heidenhain is left out: its CYCL DEF 251 finishing pass (Q215=2), as
    // cncc's interpreter expands it, raises to a further pocket (a known
    // gap, reported); the port_demo part goes through Heidenhain below.
    for id in ["siemens840d", "fanuc"] {
        let (text, v) = trip(&p, id);
        assert_eq!(v.features, 3, "{id}");
        // Known gaps, reported: the face (F1) comes back at the cut's
        // level without a stock and with another extent; the through hole
        // (F2), drilled until the drill's point breaks out, comes back as
        // a conical hole 0.1 mm deeper (the round trip raises without the
        // stock, and a program does not say the hole goes through).
        // Everything else must agree.
        let rest: Vec<&String> = v
            .lines
            .iter()
            .filter(|l| !l.contains("feature 'F1'"))
            .filter(|l| !l.contains("feature 'F2' / bottom_condition"))
            .filter(|l| {
                !l.contains("feature 'F2' / depth / position / location / coordinates: (0.,0.,-30.) → (0.,0.,-30.100")
            })
            .collect();
        assert!(rest.is_empty(), "{id}: {rest:#?}\n{text}");
    }
}

/// `$TC_DP` tool data written by an 840D program are the data `D1` uses.
#[test]
fn tc_dp_tool_data_are_used_by_the_cutting_edge() {
    let dir = common::root().join("target/tmp/features-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("tcdp.mpf");
    std::fs::write(
        &p,
        "G71\n$TC_DP1[7,1]=120 $TC_DP3[7,1]=80 $TC_DP6[7,1]=9\nT7\nM6\nD1\nG41 G1 X10 Y0 Z0 F100\nG40 G0 Z10\nM30\n",
    )
    .unwrap();
    let o = common::cncc(&["canon", "--dialect", "siemens840d", p.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let out = String::from_utf8(o.stdout).unwrap();
    assert!(
        out.contains("USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 80.0000,"),
        "{out}"
    );
    // The radius 9 compensates the path: the G41 entry along +X ends 9 mm
    // to its left.
    assert!(
        out.contains("STRAIGHT_FEED(10.0000, 9.0000, 0.0000,"),
        "{out}"
    );
    std::fs::write(&p, "$TC_DP3[7,2]=80\nM30\n").unwrap();
    let c = common::cncc(&["check", "--dialect", "siemens840d", p.to_str().unwrap()]);
    assert!(common::stderr(&c).contains("is not simulated"));
}
