//! Straight slots posted to the 840D as SLOT1 (wider than the tool) or
//! LONGHOLE (as wide as the tool), explicit moves where neither fits
//! (with the reason in the comment), and the posted program read back:
//! it runs clean, and `cncc stepnc --cc2` of it finds the slot again.

mod common;

use cncc::dialect::builtin;
use cncc::post::{fixture, post};
use cncc::stepnc::model::*;
use std::path::PathBuf;

fn tol(v: f64) -> Toleranced {
    Toleranced {
        nominal: v,
        tolerance: Tolerance::PlusMinus {
            upper: 0.1,
            lower: 0.1,
            significant_digits: 3,
        },
    }
}

/// Example 1 plus one straight slot: `width` wide, travel 40 from
/// (50, 10) along `dir`, 5 deep, cut with the 18 mm end mill (roughing
/// operation of Example 1, without allowances, 2.5 per layer).
fn with_slot(width: f64, dir: [f64; 3], ends: Vec<SlotEnd>) -> Project {
    with_slots(width, &[([50.0, 10.0], dir)], ends)
}

/// Example 1 plus alike slots, one workingstep each (ids `SLOT A`,
/// `SLOT B`...), each from its origin along its direction.
fn with_slots(width: f64, slots: &[([f64; 2], [f64; 3])], ends: Vec<SlotEnd>) -> Project {
    let mut p = fixture::ex1();
    let mut op = p.operations[3].clone();
    op.id = "ROUGH SLOT".into();
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
    let op_id = OperationId(p.operations.len() as u32 - 1);
    for (k, (at, dir)) in slots.iter().enumerate() {
        let name = format!("SLOT {}", (b'A' + k as u8) as char);
        let mut f = p.features[2].clone();
        f.id = name.clone();
        f.placement.location.xyz = [at[0], at[1], 0.0];
        f.placement.ref_direction.as_mut().unwrap().ratios = [1.0, 0.0, 0.0];
        f.depth.as_mut().unwrap().position.location.xyz = [0.0, 0.0, -5.0];
        let mut direction = p.features[0].placement.ref_direction.clone().unwrap();
        direction.ratios = *dir;
        f.kind = FeatureKind::Slot {
            course_of_travel: TravelPath::Linear {
                placement: None,
                distance: tol(40.0),
                direction,
            },
            swept_shape: OpenProfile::RoundedU {
                placement: None,
                width: tol(width),
            },
            end_conditions: ends.clone(),
        };
        p.features.push(f);
        let feature = FeatureId(p.features.len() as u32 - 1);
        p.main_workplan
            .elements
            .push(Executable::Workingstep(MachiningWorkingstep {
                id: format!("WS {name}"),
                secplane: p.main_workplan.setup.as_ref().unwrap().secplane.clone(),
                feature,
                operation: op_id,
                effect: None,
            }));
    }
    p
}

fn radiused() -> Vec<SlotEnd> {
    vec![SlotEnd::Radiused, SlotEnd::Radiused]
}

fn siemens(p: &Project) -> String {
    post(p, &builtin::builtin("siemens840d").unwrap())
        .unwrap_or_else(|e| panic!("{e:#?}"))
        .text
}

/// The workingstep's part of the program.
fn slot_part(text: &str) -> &str {
    text.split_once("WS SLOT A").unwrap().1
}

fn save(name: &str, text: &str) -> PathBuf {
    let dir = common::root().join("target/tmp/post-slot-tests");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// `cncc check` is clean (no warning) and `cncc stepnc --cc2` runs (with
/// Example 1's tools in a table and a stock round the part); its Part 21
/// text.
fn check_and_raise(name: &str, text: &str, dialect: &str) -> String {
    let path = save(name, text);
    let table = save(
        &format!("{name}.tbl"),
        "T1 P1 D18 Z80\nT2 P2 D20 Z90\nT3 P3 D22 Z100\n",
    );
    let path = path.to_str().unwrap();
    let o = common::cncc(&["check", "--dialect", dialect, path]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("warning["), "{err}");
    let o = common::cncc(&[
        "stepnc",
        "--cc2",
        "--machine-units",
        "mm",
        "--stock",
        "300x300x40-50-50-35",
        "--tool-table",
        table.to_str().unwrap(),
        "--dialect",
        dialect,
        path,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    common::stdout(&o)
}

#[test]
fn a_slot_wider_than_the_tool_is_one_slot1() {
    let text = siemens(&with_slot(24.0, [1.0, 0.0, 0.0], radiused()));
    let part = slot_part(&text);
    // LENG 40 + 24, WID 24, inner end at x 50 - 12, STA1 0, NUM 1, RAD 0,
    // MID 2.5, CDIR 2 (M3, conventional as the pockets), VARI 1 (rough).
    assert!(
        part.contains("SLOT1(30,0,15,-5,,1,64,24,38,10,0,0,0,2400,2400,2.5,2,0,1,2.5,2400,1200)"),
        "{part}"
    );
    assert!(!part.lines().any(|l| l.starts_with("G1 ")), "{part}");
    // Raised back: the stadium 64 x 24 (corner radius 12) centred at
    // (70, 10), floor 10 below the stock top (z -5). The recogniser types
    // it as a closed pocket with that outline (it takes slots only from
    // straight passes), exactly as it types the explicit moves the other
    // targets get for the same slot.
    let stadium = [
        "CLOSED_POCKET(",
        ",(70.,10.,5.));",
        "DEPTH',(0.,0.,-10.));",
        "RECTANGULAR_CLOSED_PROFILE(",
        "TOLERANCED_LENGTH_MEASURE(24.,",
        "TOLERANCED_LENGTH_MEASURE(64.,",
        "TOLERANCED_LENGTH_MEASURE(12.,",
    ];
    let p21 = check_and_raise("slot1.mpf", &text, "siemens840d");
    let fanuc = post(
        &with_slot(24.0, [1.0, 0.0, 0.0], radiused()),
        &builtin::builtin("fanuc").unwrap(),
    );
    let explicit = check_and_raise("slot-fanuc.nc", &fanuc.unwrap().text, "fanuc");
    for s in stadium {
        let raised = |p: &str| {
            let l: Vec<&str> = p.lines().collect();
            let at = l
                .iter()
                .position(|x| x.contains("(70.,10.,5.)"))
                .unwrap_or(0);
            l[at.saturating_sub(4)..(at + 10).min(l.len())]
                .iter()
                .any(|x| x.contains(s))
        };
        assert!(raised(&p21), "{s}:\n{p21}");
        assert!(raised(&explicit), "{s}:\n{explicit}");
    }
}

#[test]
fn a_slot_as_wide_as_the_tool_is_a_longhole() {
    // Travel along Y: STA1 90, inner end 9 below the start.
    let text = siemens(&with_slot(18.0, [0.0, 1.0, 0.0], radiused()));
    let part = slot_part(&text);
    assert!(
        part.contains("LONGHOLE(30,0,15,-5,,1,58,50,1,0,90,0,2400,2400,2.5)"),
        "{part}"
    );
    // Raised back as the slot: from (50, 10) over 40 along Y, 18 wide,
    // radiused ends, floor 10 below the stock top (z -5).
    let p21 = check_and_raise("longhole.mpf", &text, "siemens840d");
    let slot: Vec<&str> = p21
        .lines()
        .skip_while(|l| !l.contains("=SLOT("))
        .take(16)
        .collect();
    let slot = slot.join("\n");
    for s in [
        ",(50.,10.,5.));",
        "DEPTH',(0.,0.,-10.));",
        "LINEAR_PATH(",
        "TOLERANCED_LENGTH_MEASURE(40.,",
        "'COURSE OF TRAVEL',(0.,1.,0.)",
        "SQUARE_U_PROFILE(",
        "TOLERANCED_LENGTH_MEASURE(18.,",
        "RADIUSED_SLOT_END_TYPE()",
    ] {
        assert!(slot.contains(s), "{s}:\n{p21}");
    }
}

#[test]
fn open_ends_stay_explicit_moves_and_say_why() {
    let text = siemens(&with_slot(
        24.0,
        [1.0, 0.0, 0.0],
        vec![SlotEnd::Open, SlotEnd::Open],
    ));
    let part = slot_part(&text);
    assert!(!part.contains("SLOT1("), "{part}");
    assert!(
        part.contains("slot: explicit toolpath (SLOT1/LONGHOLE cut round ends"),
        "{part}"
    );
    assert!(part.lines().any(|l| l.starts_with("G1 ")), "{part}");
}

#[test]
fn other_targets_keep_explicit_moves() {
    let p = with_slot(24.0, [1.0, 0.0, 0.0], radiused());
    for id in ["fanuc", "haas", "linuxcnc"] {
        let text = post(&p, &builtin::builtin(id).unwrap()).unwrap().text;
        let part = slot_part(&text);
        assert!(
            part.contains("the target has no slot cycle"),
            "{id}: {part}"
        );
    }
    // Heidenhain has its own slot cycle (tests/post_heidenhain.rs).
    let text = post(&p, &builtin::builtin("heidenhain").unwrap())
        .unwrap()
        .text;
    assert!(
        slot_part(&text).contains("CYCL DEF 253 SLOT MILLING"),
        "{text}"
    );
}

/// `cncc port --features --to siemens840d` of the CC2 test part: its
/// tool-wide slot (60 long, 4 deep in two layers, 8 mm end mill) becomes
/// one LONGHOLE, and the ported program raises to the same SLOT; with
/// `--verify` the port raises to the same features and cuts the same part
/// (its through holes are drilled until the drill's point breaks out).
#[test]
fn port_features_writes_the_test_parts_slot_as_a_longhole() {
    let dir = common::root().join("tests/programs/raise2");
    let table = dir.join("cc2part.tbl");
    let table = table.to_str().unwrap();
    let raise = |file: &str, dialect: &str| {
        let o = common::cncc(&[
            "stepnc",
            "--cc2",
            "--machine-units",
            "mm",
            "--tool-table",
            table,
            "--stock",
            "120x80x21+0+0-20",
            "--dialect",
            dialect,
            file,
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
        let text = common::stdout(&o);
        let l: Vec<String> = text.lines().map(str::to_string).collect();
        let at = l.iter().position(|x| x.contains("=SLOT(")).expect("a slot");
        // The slot's own entities, without the ids that number them.
        l[at..at + 17]
            .iter()
            .map(|x| x.split_once('=').map_or(x.as_str(), |(_, r)| r).to_string())
            .filter(|x| !x.starts_with("MILLING_TECHNOLOGY") && !x.starts_with("SETUP"))
            .collect::<Vec<_>>()
    };
    let src = dir.join("cc2part.nc");
    let o = common::cncc(&[
        "port",
        "--features",
        "--to",
        "siemens840d",
        "--from",
        "fanuc",
        "--machine-units",
        "mm",
        "--tool-table",
        table,
        "--stock",
        "120x80x21+0+0-20",
        "--verify",
        src.to_str().unwrap(),
    ]);
    let err = common::stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("verify: OK: the same 7 feature(s)"), "{err}");
    assert!(err.contains("verify: material: the same part"), "{err}");
    let text = common::stdout(&o);
    assert!(
        text.contains("LONGHOLE(25,0,2,-4,,1,68,26,10,0,0,0,250,250,2)"),
        "{text}"
    );
    assert!(text.contains("MCALL CYCLE81(25,0,2,-22.503,)"), "{text}");
    let ported = save("cc2part-slot.mpf", &text);
    let a = raise(src.to_str().unwrap(), "fanuc");
    let b = raise(ported.to_str().unwrap(), "siemens840d");
    let geometry = |v: &[String]| {
        v.iter()
            .filter(|x| {
                x.starts_with("CARTESIAN_POINT")
                    || x.starts_with("TOLERANCED_LENGTH_MEASURE")
                    || x.starts_with("DIRECTION('COURSE")
                    || x.starts_with("RADIUSED")
                    || x.starts_with("SQUARE_U")
            })
            .map(|x| x.split(",#").next().unwrap().to_string())
            .collect::<Vec<_>>()
    };
    assert!(geometry(&a).len() >= 6, "{a:#?}");
    assert_eq!(geometry(&a), geometry(&b), "{a:#?}\n{b:#?}");
}

/// Four alike slots 24 wide pointing out from (100, 100), their inner ends
/// 20 from it, 90 degrees apart: one SLOT1 with NUM 4, RAD 20, INDA 90.
#[test]
fn alike_slots_on_a_circle_are_one_slot1() {
    let slots: Vec<([f64; 2], [f64; 3])> = (0..4)
        .map(|k| {
            let a = (k as f64 * 90.0_f64).to_radians();
            let (c, s) = (a.cos().round(), a.sin().round());
            // The course of travel starts at the first end arc's centre:
            // 20 + 12 out from the circle's centre.
            ([100.0 + 32.0 * c, 100.0 + 32.0 * s], [c, s, 0.0])
        })
        .collect();
    let text = siemens(&with_slots(24.0, &slots, radiused()));
    let calls: Vec<&str> = text.lines().filter(|l| l.starts_with("SLOT1(")).collect();
    assert_eq!(
        calls,
        ["SLOT1(30,0,15,-5,,4,64,24,100,100,20,0,90,2400,2400,2.5,2,0,1,2.5,2400,1200)"],
        "{text}"
    );
    assert!(text.contains("4 slots on a circle"), "{text}");
    // Raised back: four 64 x 24 stadiums centred 52 out from the centre.
    let p21 = check_and_raise("slot1-circle.mpf", &text, "siemens840d");
    for centre in [
        "(152.,100.,5.)",
        "(100.,152.,5.)",
        "(48.,100.,5.)",
        "(100.,48.,5.)",
    ] {
        assert!(p21.contains(centre), "{centre}:\n{p21}");
    }
    // Two of them are not a circle of four: each its own SLOT1.
    let text = siemens(&with_slots(
        24.0,
        &slots[..1]
            .iter()
            .chain(&slots[2..3])
            .cloned()
            .collect::<Vec<_>>(),
        radiused(),
    ));
    let n = text.lines().filter(|l| l.starts_with("SLOT1(")).count();
    assert_eq!(n, 1, "opposite slots form a circle of two:\n{text}");
    let parallel = [
        ([50.0, 10.0], [1.0, 0.0, 0.0]),
        ([50.0, 50.0], [1.0, 0.0, 0.0]),
    ];
    let text = siemens(&with_slots(24.0, &parallel, radiused()));
    let n = text.lines().filter(|l| l.starts_with("SLOT1(")).count();
    assert_eq!(n, 2, "{text}");
    assert!(
        text.contains("2 alike slots, one by one: the slots do not lie radially"),
        "{text}"
    );
}
