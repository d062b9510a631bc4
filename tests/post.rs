//! `cncc post`: ISO 14649 Example 1 (the hand-built fixture until the
//! Part 21 reader is merged) posted to the 840D, Fanuc, Haas and LinuxCNC:
//! the cycles carry the features' and operations' values, every output
//! reads back and runs clean with `cncc check`, and the LinuxCNC output
//! runs in LinuxCNC's own interpreter.

mod common;

use cncc::dialect::builtin;
use cncc::post::{fixture, post};
use std::path::{Path, PathBuf};
use std::process::Command;

fn posted(id: &str) -> cncc::post::Posted {
    let spec = builtin(id).unwrap();
    post(&fixture::ex1(), &spec).unwrap_or_else(|e| panic!("{id}: {e:#?}"))
}

fn lines(text: &str) -> Vec<&str> {
    text.lines().collect()
}

/// Writes `text` to a fresh file in the target folder.
fn save(name: &str, text: &str) -> PathBuf {
    let dir = common::root().join("target/tmp/post-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The 840D text, `$TC_DP` tool data included, must read and run
/// without any warning.
fn siemens_runs_clean(name: &str, text: &str) {
    let err = check_clean(&save(name, text), "siemens840d");
    assert!(!err.contains("warning["), "{err}");
}

/// LinuxCNC's own interpreter runs the program without error (skipped,
/// with a note, where it is not installed).
fn runs_in_rs274(path: &Path) {
    let oracle = common::root().join("../shared/tools/rs274-canon");
    if !oracle.exists() {
        eprintln!("note: ../shared/tools/rs274-canon is absent; not running LinuxCNC");
        return;
    }
    let ngc = path.with_extension("ngc");
    std::fs::copy(path, &ngc).unwrap();
    let o = Command::new(&oracle).arg(&ngc).output().unwrap();
    match o.status.code() {
        Some(2) => eprintln!("note: rs274 is not installed; not running LinuxCNC"),
        c => assert_eq!(c, Some(0), "rs274: {}", String::from_utf8_lossy(&o.stderr)),
    }
}

/// ISO 14649's Example 1 from ../shared (None, with a note, without it).
fn ex1_stp() -> Option<PathBuf> {
    let file = common::shared()?.join("stepnc-samples/ex1.stp");
    if !file.exists() {
        eprintln!("note: ex1.stp is absent; skipping");
        return None;
    }
    Some(file)
}

fn check_clean(path: &Path, dialect: &str) -> String {
    let o = common::cncc(&["check", "--dialect", dialect, path.to_str().unwrap()]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{dialect}: {err}");
    err
}

#[test]
fn siemens_cycles_carry_the_features() {
    let p = posted("siemens840d");
    let l = lines(&p.text);
    // Face: RTP 35 (the shared security plane at z 30 in the face's frame,
    // whose top is at z 5: ISO 14649-10 gives a workingstep's security
    // plane in its feature's frame), RFP 5 (face top), SDIS 10 (retract
    // plane), DP 0, corner (0,0), 100 x 120, MID 2.5, MIDA 18*(1-0.05),
    // finishing allowance 0, F 2400, VARI 41 (roughing mode, 2nd axis
    // alternating).
    assert!(l.contains(&"CYCLE71(35,5,10,0,0,0,100,120,0,2.5,17.1,9,0,2400,41,0.9)"));
    assert!(l.contains(&"MCALL CYCLE81(30,0,10,-36.109,)"));
    assert!(l.contains(&"MCALL CYCLE85(30,0,10,-30,,0,1800,1800)"));
    // Rough: LENG 80 WID 50 CRAD 10 at (70,70), long axis along Y (90),
    // MID 6.5, CDIR 2 (conventional with M3 = G2), FAL 1, VARI 1.
    assert!(
        l.contains(&"POCKET1(30,0,15,-30,,80,50,10,70,70,90,2400,2400,6.5,2,1,1,6.5,2400,1200)")
    );
    // Finish: MID 2, FAL 1 (what the roughing left), VARI 2.
    assert!(l.contains(&"POCKET1(30,0,15,-30,,80,50,10,70,70,90,2400,2400,2,2,1,2,2,2400,1200)"));
    assert!(l.contains(&"CYCLE832(0.01,102003)") && l.contains(&"CYCLE832(0.01,102001)"));
    assert!(l.contains(&"$TC_DP1[1,1]=120 $TC_DP3[1,1]=80 $TC_DP6[1,1]=9"));
    assert!(
        l.contains(&";WS(4) WS ROUGH POCKET1 Feature=closed_pocket POCKET1")
            || l.contains(&"; WS(4) WS ROUGH POCKET1 Feature=closed_pocket POCKET1")
    );
    // The drilling strategy and the reamer's spindle stop are named; the
    // workpiece of ex1 gives no BLOCK, so the stock check says it could
    // not be made (W0903).
    assert_eq!(p.warnings.len(), 4, "{:#?}", p.warnings);
    assert!(p
        .warnings
        .iter()
        .any(|d| d.code == cncc::diag::Code::StockUnknown));
    assert!(p.text.contains("NOT POSTED: drilling strategy"));
    insta::assert_snapshot!("ex1_siemens840d", p.text);
}

#[test]
fn siemens_output_checks_clean() {
    let p = posted("siemens840d");
    // The $TC_DP tool data are taken into the run's tool table: no
    // warning at all.
    siemens_runs_clean("ex1.mpf", &p.text);
}

#[test]
fn fanuc_cycles_and_explicit_pocket() {
    let p = posted("fanuc");
    let path = save("ex1.nc", &p.text);
    let l = lines(&p.text);
    assert!(l.contains(&"G98 G81 X20. Y60. Z-36.109 R10. F1800"));
    assert!(l.contains(&"G98 G85 X20. Y60. Z-30. R10. F1800"));
    assert!(!l
        .iter()
        .any(|x| x.starts_with("POCKET") || x.contains("CYCLE")));
    // The pocket's moves stay inside it (70 +- 25, 70 +- 40 less the tool
    // radius 9) and reach the bottom; the face's reach z 0.
    let (mut lowest, mut inside) = (f64::MAX, true);
    let after = p.text.split_once("WS[4]").unwrap().1;
    for line in after.lines().filter(|l| l.starts_with("G1 ")) {
        let w = |c: char| {
            line.split_whitespace()
                .find(|t| t.starts_with(c))
                .map(|t| t[1..].parse::<f64>().unwrap())
        };
        let (x, y, z) = (w('X').unwrap(), w('Y').unwrap(), w('Z').unwrap());
        lowest = lowest.min(z);
        inside &= (x - 70.0).abs() <= 16.0 + 1e-9 && (y - 70.0).abs() <= 31.0 + 1e-9;
    }
    assert_eq!(lowest, -30.0);
    assert!(inside);
    let err = check_clean(&path, "fanuc");
    assert!(!err.contains("warning["), "{err}");
    insta::assert_snapshot!("ex1_fanuc", p.text);
}

#[test]
fn haas_output_checks_clean() {
    let p = posted("haas");
    let path = save("ex1-haas.nc", &p.text);
    let err = check_clean(&path, "haas");
    assert!(!err.contains("warning["), "{err}");
}

#[test]
fn linuxcnc_output_runs_in_rs274() {
    let p = posted("linuxcnc");
    let path = save("ex1.ngc", &p.text);
    let err = check_clean(&path, "linuxcnc");
    assert!(!err.contains("warning["), "{err}");
    insta::assert_snapshot!("ex1_linuxcnc", p.text);
    let oracle = common::root().join("../shared/tools/rs274-canon");
    if !oracle.exists() {
        eprintln!("note: ../shared/tools/rs274-canon is absent; not running LinuxCNC");
        return;
    }
    let o = Command::new(&oracle).arg(&path).output().unwrap();
    match o.status.code() {
        Some(2) => eprintln!("note: rs274 is not installed; not running LinuxCNC"),
        c => assert_eq!(c, Some(0), "rs274: {}", String::from_utf8_lossy(&o.stderr)),
    }
}

#[test]
fn a_missing_file_is_a_usage_error() {
    let o = common::cncc(&["post", "no-such.stp", "--to", "fanuc"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn ex1_stp_posts_like_the_fixture() {
    let Some(file) = ex1_stp() else {
        return;
    };
    for id in ["siemens840d", "fanuc", "haas", "linuxcnc"] {
        let o = common::cncc(&["post", file.to_str().unwrap(), "--to", id]);
        assert_eq!(o.status.code(), Some(0), "{id}: {}", common::stderr(&o));
        assert_eq!(common::stdout(&o), posted(id).text, "{id}");
        // Three values the targets cannot carry are named, as warnings.
        assert_eq!(
            common::stderr(&o).matches("W0900").count(),
            if id == "siemens840d" { 3 } else { 2 },
            "{id}"
        );
    }
}

#[test]
fn post_writes_the_output_file_whole() {
    let Some(shared) = common::shared() else {
        return;
    };
    let file = shared.join("stepnc-samples/ex1.stp");
    let out = common::root().join("target/tmp/post-tests/ex1-cli.mpf");
    let _ = std::fs::remove_file(&out);
    let o = common::cncc(&[
        "post",
        file.to_str().unwrap(),
        "--to",
        "840d",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        posted("siemens840d").text
    );
    // A feature the post cannot write: exit 1, nothing written.
    let bad = shared.join("stepnc-samples/TesteFinalUNBLAB.p21");
    let out2 = common::root().join("target/tmp/post-tests/bad.nc");
    let _ = std::fs::remove_file(&out2);
    let o = common::cncc(&[
        "post",
        bad.to_str().unwrap(),
        "--to",
        "fanuc",
        "-o",
        out2.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    // The validator runs first: its U slot lies outside the block (E0908).
    assert!(common::stderr(&o).contains("E0908"));
    assert!(!out2.exists());
}

/// Example 1 with the drilling repeated at `more` further places, each
/// its own hole feature and workingstep right after the first drilling.
fn ex1_with_holes(more: &[[f64; 2]]) -> cncc::stepnc::model::Project {
    use cncc::stepnc::model::*;
    let mut p = fixture::ex1();
    let hole = p.features[1].clone();
    let Executable::Workingstep(drill) = p.main_workplan.elements[1].clone() else {
        unreachable!()
    };
    for (k, at) in more.iter().enumerate() {
        let mut f = hole.clone();
        f.id = format!("HOLE{}", k + 2);
        f.placement.location.xyz = [at[0], at[1], 0.0];
        p.features.push(f);
        let mut ws = drill.clone();
        ws.id = format!("WS DRILL HOLE{}", k + 2);
        ws.feature = FeatureId(p.features.len() as u32 - 1);
        p.main_workplan
            .elements
            .insert(2 + k, Executable::Workingstep(ws));
    }
    p
}

#[test]
fn holes_in_a_row_become_one_cycle_with_a_pattern() {
    let project = ex1_with_holes(&[[40.0, 60.0], [60.0, 60.0], [80.0, 60.0]]);
    let siemens = post(&project, &builtin("siemens840d").unwrap()).unwrap();
    let l = lines(&siemens.text);
    let at = l
        .iter()
        .position(|x| *x == "MCALL CYCLE81(30,0,10,-36.109,)")
        .unwrap();
    assert_eq!(&l[at + 1..at + 3], &["HOLES1(20,60,0,0,20,4)", "MCALL"]);
    assert_eq!(l.iter().filter(|x| x.contains("CYCLE81")).count(), 1);
    assert!(siemens
        .text
        .contains("; WS(5) WS DRILL HOLE4 Feature=round_hole HOLE4"));
    siemens_runs_clean("row.mpf", &siemens.text);

    let fanuc = post(&project, &builtin("fanuc").unwrap()).unwrap();
    let l = lines(&fanuc.text);
    let at = l
        .iter()
        .position(|x| *x == "G98 G81 X20. Y60. Z-36.109 R10. F1800")
        .unwrap();
    assert_eq!(
        &l[at + 1..at + 5],
        &["X40. Y60.", "X60. Y60.", "X80. Y60.", "G80"]
    );
    let err = check_clean(&save("row.nc", &fanuc.text), "fanuc");
    assert!(!err.contains("warning["), "{err}");
}

#[test]
fn holes_on_a_circle_and_in_a_grid() {
    let circle = ex1_with_holes(&[[30.0, 70.0], [40.0, 60.0], [30.0, 50.0]]);
    let text = post(&circle, &builtin("siemens840d").unwrap())
        .unwrap()
        .text;
    assert!(text.contains("\nHOLES2(30,60,10,180,-90,4)\n"), "{text}");
    siemens_runs_clean("circle.mpf", &text);
    let grid = ex1_with_holes(&[[40.0, 60.0], [20.0, 80.0], [40.0, 80.0]]);
    let text = post(&grid, &builtin("siemens840d").unwrap()).unwrap().text;
    assert!(text.contains("\nCYCLE801(20,60,0,20,20,2,2)\n"), "{text}");
    siemens_runs_clean("grid.mpf", &text);
}

/// Example 1 with its pocket made circular (diameter 60).
fn ex1_round_pocket() -> cncc::stepnc::model::Project {
    use cncc::stepnc::model::*;
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
fn a_circular_pocket_is_pocket2_or_rings_of_arcs() {
    let p = ex1_round_pocket();
    let siemens = post(&p, &builtin("siemens840d").unwrap()).unwrap().text;
    let l = lines(&siemens);
    // PRAD 30 at (70,70), MID 6.5, CDIR 2, FAL 1, VARI 1 then 2.
    assert!(l.contains(&"POCKET2(30,0,15,-30,,30,70,70,2400,2400,6.5,2,1,1,6.5,2400,1200)"));
    assert!(l.contains(&"POCKET2(30,0,15,-30,,30,70,70,2400,2400,2,2,1,2,2,2400,1200)"));
    assert!(l.contains(&"CYCLE832(0.01,102003)"));
    siemens_runs_clean("round.mpf", &siemens);

    let tnc = post(&p, &builtin("heidenhain").unwrap()).unwrap().text;
    let l = lines(&tnc);
    // Diameter 60, 30 deep, roughing then finishing, called at (70, 70).
    assert!(l.iter().any(|x| x.starts_with(
        "CYCL DEF 252 CIRCULAR POCKET Q215=1 Q223=60 Q368=1 Q207=2400 Q351=-1 Q201=-30 Q202=6.5"
    )));
    assert!(l
        .iter()
        .any(|x| x.starts_with("CYCL DEF 252 CIRCULAR POCKET Q215=2 Q223=60")));
    assert!(l.contains(&"L X70 Y70 R0 FMAX M99"));
    let err = check_clean(&save("round.h", &tnc), "heidenhain");
    assert!(!err.contains("warning["), "{err}");

    let ngc = post(&p, &builtin("linuxcnc").unwrap()).unwrap().text;
    assert!(ngc.lines().any(|x| x.starts_with("G2 X")));
    let path = save("round.ngc", &ngc);
    let err = check_clean(&path, "linuxcnc");
    assert!(!err.contains("warning["), "{err}");
    let oracle = common::root().join("../shared/tools/rs274-canon");
    if oracle.exists() {
        let o = Command::new(&oracle).arg(&path).output().unwrap();
        assert!(
            matches!(o.status.code(), Some(0) | Some(2)),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
}

#[test]
fn a_tool_that_does_not_cut_across_its_centre_gets_pocket3() {
    let mut p = fixture::ex1();
    p.tools[0].body.kind = cncc::stepnc::model::ToolBodyKind::Facemill;
    let text = post(&p, &builtin("siemens840d").unwrap()).unwrap().text;
    let l = lines(&text);
    // FAL 1 FALD 0.5 (roughing), CDIR 1 conventional, VARI 11 (vertical
    // insertion, roughing), MIDA 5 (radial depth); then the finish removes
    // what the roughing left: FAL 1 FALD 0.5, VARI 12, MIDA 10.
    assert!(
        l.contains(&"POCKET3(30,0,15,-30,80,50,10,70,70,90,6.5,1,0.5,2400,2400,1,11,5,0,0,0,0,0)"),
        "{text}"
    );
    assert!(
        l.contains(&"POCKET3(30,0,15,-30,80,50,10,70,70,90,2,1,0.5,2400,2400,1,12,10,0,0,0,0,0)"),
        "{text}"
    );
    assert!(l.contains(&"$TC_DP1[1,1]=140 $TC_DP3[1,1]=80 $TC_DP6[1,1]=9"));
    assert!(text.contains("does not cut across its centre"));
}

/// Example 1 plus a straight slot with radiused ends, 24 wide, travel 40
/// along X from (50, 10), 5 deep, roughed with the 18 mm end mill.
fn ex1_with_slot() -> cncc::stepnc::model::Project {
    use cncc::stepnc::model::*;
    let mut p = fixture::ex1();
    let tol = |v: f64| Toleranced {
        nominal: v,
        tolerance: Tolerance::PlusMinus {
            upper: 0.1,
            lower: 0.1,
            significant_digits: 3,
        },
    };
    let mut f = p.features[2].clone();
    f.id = "SLOT1".into();
    f.placement.location.xyz = [50.0, 10.0, 0.0];
    f.placement.ref_direction.as_mut().unwrap().ratios = [1.0, 0.0, 0.0];
    f.depth.as_mut().unwrap().position.location.xyz = [0.0, 0.0, -5.0];
    f.kind = FeatureKind::Slot {
        course_of_travel: TravelPath::Linear {
            placement: None,
            distance: tol(40.0),
            direction: p.features[0].placement.ref_direction.clone().unwrap(),
        },
        swept_shape: OpenProfile::RoundedU {
            placement: None,
            width: tol(24.0),
        },
        end_conditions: vec![SlotEnd::Radiused, SlotEnd::Radiused],
    };
    p.features.push(f);
    let mut op = p.operations[3].clone();
    op.id = "ROUGH SLOT1".into();
    if let OperationKind::BottomAndSideMilling {
        axial_cutting_depth,
        allowance_side,
        allowance_bottom,
        ..
    } = &mut op.kind
    {
        *axial_cutting_depth = Some(2.5);
        *allowance_side = None;
        *allowance_bottom = None;
    }
    p.operations.push(op);
    p.main_workplan
        .elements
        .push(Executable::Workingstep(MachiningWorkingstep {
            id: "WS SLOT1".into(),
            secplane: p.main_workplan.setup.as_ref().unwrap().secplane.clone(),
            feature: FeatureId(3),
            operation: OperationId(5),
            effect: None,
        }));
    p
}

#[test]
fn a_slot_becomes_an_explicit_toolpath_inside_its_outline() {
    let p = ex1_with_slot();
    // (The 840D gets SLOT1 for this slot: tests/post_slots.rs.)
    for id in ["fanuc", "linuxcnc"] {
        let text = post(&p, &builtin(id).unwrap()).unwrap().text;
        let slot = text.split_once("WS SLOT1").unwrap().1;
        let (mut lowest, mut moves) = (f64::MAX, 0);
        for line in slot.lines().filter(|l| l.starts_with("G1 ")) {
            let w = |c: char| {
                line.split_whitespace()
                    .find(|t| t.starts_with(c))
                    .map(|t| t[1..].trim_end_matches('.').parse::<f64>().unwrap())
                    .unwrap()
            };
            let (x, y) = (w('X'), w('Y'));
            lowest = lowest.min(w('Z'));
            moves += 1;
            // Inside the stadium less the tool radius: centre line from
            // x 50 to 90 at y 10, half width 12 - 9 = 3.
            let dx = (x - 70.0).abs() - 20.0;
            let off = if dx > 0.0 {
                (dx * dx + (y - 10.0).powi(2)).sqrt()
            } else {
                (y - 10.0).abs()
            };
            assert!(off <= 3.0 + 1e-3, "{id}: {line}");
        }
        assert_eq!(lowest, -5.0, "{id}");
        assert!(moves > 6, "{id}");
        let path = save(&format!("slot-{id}.nc"), &text);
        let err = check_clean(&path, id);
        assert!(!err.contains("warning["), "{err}");
        if id == "linuxcnc" {
            runs_in_rs274(&path);
        }
    }
}

#[test]
fn dwell_peck_and_bore_cycles_on_every_target() {
    use cncc::stepnc::model::*;
    let mut p = fixture::ex1();
    // Drill with a 0.5 s dwell; ream becomes boring with a spindle stop;
    // add a multistep drilling (first 6, steps 5) before them.
    if let OperationKind::Drilling(d) = &mut p.operations[1].kind {
        d.dwell_time_bottom = Some(0.5);
        d.strategy = None;
    }
    if let OperationKind::Boring { reaming, .. } = &mut p.operations[2].kind {
        *reaming = false;
    }
    let mut peck = p.operations[1].clone();
    peck.id = "PECK HOLE1".into();
    peck.kind = OperationKind::MultistepDrilling {
        drill: DrillCommon::default(),
        retract_distance: 1.0,
        first_depth: 6.0,
        depth_of_step: 5.0,
        dwell_time_step: None,
    };
    p.operations.push(peck);
    p.main_workplan.elements.insert(
        1,
        Executable::Workingstep(MachiningWorkingstep {
            id: "WS PECK HOLE1".into(),
            secplane: p.main_workplan.setup.as_ref().unwrap().secplane.clone(),
            feature: FeatureId(1),
            operation: OperationId(5),
            effect: None,
        }),
    );
    let want = [
        (
            "siemens840d",
            [
                "MCALL CYCLE83(30,0,10,-36.109,,-6,,5,0,0,1,1)",
                "MCALL CYCLE82(30,0,10,-36.109,,0.5)",
                "MCALL CYCLE86(30,0,10,-30,,0,3,0,0,0,0)",
            ],
        ),
        (
            "fanuc",
            [
                "G98 G83 X20. Y60. Z-36.109 R10. Q5. F1800",
                "G98 G82 X20. Y60. Z-36.109 R10. P500 F1800",
                "G98 G86 X20. Y60. Z-30. R10. P0 F1800",
            ],
        ),
        (
            "haas",
            [
                "G98 G83 X20. Y60. Z-36.109 R10. Q5. F1800",
                "G98 G82 X20. Y60. Z-36.109 R10. P500 F1800",
                "G98 G86 X20. Y60. Z-30. R10. P0 F1800",
            ],
        ),
        (
            "linuxcnc",
            [
                "G98 G83 X20 Y60 Z-36.108606 R10 Q5 F1800",
                "G98 G82 X20 Y60 Z-36.108606 R10 P0.5 F1800",
                "G98 G86 X20 Y60 Z-30 R10 P0 F1800",
            ],
        ),
    ];
    for (id, cycles) in want {
        let posted = post(&p, &builtin(id).unwrap()).unwrap_or_else(|e| panic!("{id}: {e:#?}"));
        let l = lines(&posted.text);
        for c in cycles {
            assert!(l.contains(&c), "{id}: {c}\n{}", posted.text);
        }
        // The peck's retract distance and, where the cycle pecks evenly,
        // its first depth are named.
        assert!(
            posted.text.contains("NOT POSTED: retract distance 1 mm"),
            "{id}"
        );
        assert_eq!(
            posted.text.contains("NOT POSTED: first depth 6 mm"),
            id != "siemens840d",
            "{id}"
        );
        if id == "siemens840d" {
            siemens_runs_clean("cycles.mpf", &posted.text);
        } else {
            let path = save(&format!("cycles-{id}.nc"), &posted.text);
            let err = check_clean(&path, id);
            assert!(!err.contains("warning["), "{id}: {err}");
            if id == "linuxcnc" {
                runs_in_rs274(&path);
            }
        }
    }
}

#[test]
fn heidenhain_cycles_carry_the_features_and_check_clean() {
    let p = posted("heidenhain");
    let l = lines(&p.text);
    assert_eq!(l.first(), Some(&"BEGIN PGM 1000 MM"));
    assert_eq!(l.last(), Some(&"END PGM 1000 MM"));
    // Drilling 30 deep from the surface Z0, set-up clearance 10, 2nd
    // set-up clearance 30 above the surface (the security plane), one
    // plunge; called at the hole with M99.
    assert!(l.contains(
        &"CYCL DEF 200 DRILLING Q200=10 Q201=-36.1086 Q206=1800 Q202=36.1086 Q210=0 Q203=0 Q204=30 Q211=0"
    ));
    assert!(l.contains(
        &"CYCL DEF 201 REAMING Q200=10 Q201=-30 Q206=1800 Q211=0 Q208=1800 Q203=0 Q204=30"
    ));
    assert!(l.contains(&"L X20 Y60 R0 FMAX M99"));
    // The pocket: roughing (Q215 1) then finishing (Q215 2), 80 x 50, R10,
    // turned 90 degrees, centre (70, 70).
    assert!(l.iter().any(|x| x.starts_with(
        "CYCL DEF 251 RECTANGULAR POCKET Q215=1 Q218=80 Q219=50 Q220=10 Q368=1 Q224=90"
    )));
    assert!(l
        .iter()
        .any(|x| x.starts_with("CYCL DEF 251 RECTANGULAR POCKET Q215=2")));
    assert!(l.contains(&"L X70 Y70 R0 FMAX M99"));
    assert!(l.contains(&"CYCL DEF 32.1 T0.01"));
    // The tool is defined in the program and called with its speed.
    assert!(l.contains(&"TOOL DEF 1 L80 R9"));
    assert!(l.contains(&"TOOL CALL 1 Z S720"));
    let err = check_clean(&save("ex1.h", &p.text), "heidenhain");
    assert!(!err.contains("warning["), "{err}");
}

#[test]
fn heidenhain_blk_form_comes_from_the_workpiece_block() {
    use cncc::stepnc::model::{Axis2Placement, Bounding, Point};
    let mut p = fixture::ex1();
    p.workpieces[0].bounding = Some(Bounding::Block {
        name: "STOCK".into(),
        position: Axis2Placement {
            name: "STOCK".into(),
            location: Point {
                name: String::new(),
                xyz: [0.0, 0.0, -40.0],
            },
            axis: None,
            ref_direction: None,
        },
        size: [140.0, 140.0, 45.0],
    });
    let text = post(&p, &builtin("heidenhain").unwrap()).unwrap().text;
    let l = lines(&text);
    assert_eq!(
        l[..3],
        [
            "BEGIN PGM 1000 MM",
            "BLK FORM 0.1 Z X0 Y0 Z-40",
            "BLK FORM 0.2 X140 Y140 Z5"
        ]
    );
    check_clean(&save("blk.h", &text), "heidenhain");
    // Without a block, no BLK FORM; other targets ignore the block.
    assert!(!posted("heidenhain").text.contains("BLK FORM"));
    let siemens = post(&p, &builtin("siemens840d").unwrap()).unwrap().text;
    assert_eq!(siemens, posted("siemens840d").text);
}

/// Explicit (CC1) toolpaths post as they are: the CC2 test part raised
/// with `--cc1` (freeform operations of polylines and arcs, rapid
/// movements with their own paths, drilling as holes) posts to every
/// dialect, each output checks clean, and `cncc diff` finds it cuts what
/// the source program cuts, feeds included. The LinuxCNC output also
/// runs in rs274.
#[test]
fn explicit_toolpaths_post_and_cut_what_the_source_cuts() {
    let dir = common::root().join("tests/programs/raise2");
    let src = dir.join("cc2part.nc");
    let o = common::cncc(&[
        "stepnc",
        "--cc1",
        "--machine-units",
        "mm",
        "--tool-table",
        dir.join("cc2part.tbl").to_str().unwrap(),
        src.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let stp = save("cc1-part.stp", &common::stdout(&o));
    assert!(common::stdout(&o).contains("FREEFORM_OPERATION"));
    for (d, ext) in [
        ("fanuc", "nc"),
        ("haas", "nc"),
        ("linuxcnc", "ngc"),
        ("siemens840d", "mpf"),
        ("heidenhain", "h"),
    ] {
        // Not `.ngc`: `runs_in_rs274` copies the file to that name.
        let out = common::root().join(format!("target/tmp/post-tests/cc1-part-{d}.{ext}.txt"));
        let o = common::cncc(&[
            "post",
            stp.to_str().unwrap(),
            "--to",
            d,
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{d}: {}", common::stderr(&o));
        check_clean(&out, d);
        let o = common::cncc(&[
            "diff",
            "--dialect-a",
            "fanuc",
            "--dialect-b",
            d,
            src.to_str().unwrap(),
            out.to_str().unwrap(),
        ]);
        let said = common::stdout(&o);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{d}: {said}{}",
            common::stderr(&o)
        );
        assert!(
            said.contains("same: the programs cut the same"),
            "{d}: {said}"
        );
        if d == "linuxcnc" {
            runs_in_rs274(&out);
        }
    }
}

/// ISO 14649 Example 1 in explicit form (NIST's ex1E): its helical ramps
/// (NIST `HELIX` curves, kept raw by the reader) post as pieces of at
/// most half a turn (`G2 .. Z..` / `CP IPA.. IZ..`), the reamer's way out
/// (a trimmed line whose sense contradicts its direction) from one trim to
/// the other. Every output checks clean, all five cut the same, and
/// rs274 runs the LinuxCNC one.
#[test]
fn ex1e_posts_to_every_dialect_and_all_cut_the_same() {
    let Some(shared) = common::shared() else {
        return;
    };
    let stp = shared.join("stepnc-samples/ex1E.stp");
    let out = |d: &str| common::root().join(format!("target/tmp/post-tests/ex1e-{d}.txt"));
    for d in ["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"] {
        let o = common::cncc(&[
            "post",
            stp.to_str().unwrap(),
            "--to",
            d,
            "-o",
            out(d).to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{d}: {}", common::stderr(&o));
        check_clean(&out(d), d);
        if d != "fanuc" {
            let o = common::cncc(&[
                "diff",
                "--dialect-a",
                "fanuc",
                "--dialect-b",
                d,
                out("fanuc").to_str().unwrap(),
                out(d).to_str().unwrap(),
            ]);
            assert_eq!(o.status.code(), Some(0), "{d}: {}", common::stdout(&o));
        }
    }
    let fanuc = std::fs::read_to_string(out("fanuc")).unwrap();
    // The first ramp: 2.62 turns from z 15 down to z -5.9 about the pocket
    // centre (70, 55) in six pieces, the start point's offset to the
    // centre from the written start.
    assert!(
        fanuc.contains("G0 X64.754 Y50.069 Z15.\nG2 X72.926 Y61.579 Z11.517 I5.246 J4.931 F2400\n"),
        "{fanuc}"
    );
    assert!(
        fanuc.contains("G2 X77.2 Y55. Z-5.9 I6.638 J-2.79 F2400\n"),
        "{fanuc}"
    );
    let tnc = std::fs::read_to_string(out("heidenhain")).unwrap();
    assert!(
        tnc.contains("CP IPA-157.205 IZ-3.4833 DR- R0 F2400"),
        "{tnc}"
    );
    runs_in_rs274(&out("linuxcnc"));
}

/// `post --summary` says what each workingstep became: the 840D's pocket
/// cycle where Fanuc has none and writes the moves (issue 15, point 5);
/// with `-o` the program is written too, and it is the one `post` writes.
#[test]
fn summary_lists_what_each_workingstep_was_posted_as() {
    let Some(file) = ex1_stp() else {
        return;
    };
    let f = file.to_str().unwrap();
    let summary = |id: &str, extra: &[&str]| {
        let mut args = vec!["post", f, "--to", id, "--summary"];
        args.extend(extra);
        let o = common::cncc(&args);
        assert_eq!(o.status.code(), Some(0), "{id}: {}", common::stderr(&o));
        common::stdout(&o)
    };
    let siemens = summary("siemens840d", &[]);
    let pocket = siemens
        .lines()
        .find(|l| l.contains("ROUGH POCKET1"))
        .unwrap();
    assert!(pocket.ends_with("-> cycle `pocket_rect`"), "{siemens}");
    assert!(
        siemens.contains("WS(2) WS DRILL HOLE1: round_hole"),
        "{siemens}"
    );
    assert_eq!(
        siemens.lines().count(),
        6,
        "a title and five workingsteps: {siemens}"
    );
    let out = save("summary_fanuc.nc", "");
    let fanuc = summary("fanuc", &["-o", out.to_str().unwrap()]);
    let pocket = fanuc.lines().find(|l| l.contains("ROUGH POCKET1")).unwrap();
    assert!(pocket.contains("-> explicit toolpath, "), "{fanuc}");
    assert!(fanuc.contains("-> cycle `drill`"), "{fanuc}");
    assert_eq!(std::fs::read_to_string(&out).unwrap(), posted("fanuc").text);
}
