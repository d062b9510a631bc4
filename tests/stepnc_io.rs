//! STEP-NC Part 21 reading and writing: every shared sample reads (the
//! AP238 AIM one is refused with its code), round-trips to the same model
//! and writes byte-identically twice; Example 1's facts; bad files' codes
//! at the right line:col; queries; differences; an independent reader.

use cncc::diag::{render, Code, Diagnostic};
use cncc::source::SourceMap;
use cncc::stepnc::{self, model::*};
use std::path::{Path, PathBuf};

fn samples_dir() -> Option<PathBuf> {
    let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/stepnc-samples");
    if d.is_dir() {
        Some(d)
    } else {
        eprintln!("note: ../shared/stepnc-samples is absent; STEP-NC sample tests skipped");
        None
    }
}

fn read(path: &Path) -> (SourceMap, stepnc::ReadResult) {
    let mut files = SourceMap::new();
    let r = stepnc::read_file(path, &mut files).expect("readable file");
    (files, r)
}

fn read_str(text: &str) -> stepnc::ReadResult {
    let mut files = SourceMap::new();
    let id = files.add("mem.stp", text.to_string());
    stepnc::read_text(text, id)
}

fn errors(d: &[Diagnostic]) -> Vec<&Diagnostic> {
    d.iter().filter(|d| d.is_error()).collect()
}

const ARM_SAMPLES: &[&str] = &["ex1.stp", "ex1E.stp", "furo.p21", "TesteFinalUNBLAB.p21"];

#[test]
fn every_arm_sample_reads_and_round_trips() {
    let Some(dir) = samples_dir() else { return };
    for name in ARM_SAMPLES {
        let (files, r) = read(&dir.join(name));
        let errs = errors(&r.diagnostics);
        assert!(
            errs.is_empty(),
            "{name}:\n{}",
            render::human(&r.diagnostics, &files, false)
        );
        let p1 = r.project.unwrap_or_else(|| panic!("{name}: no model"));
        let text1 = stepnc::write_project(&p1);
        let r2 = read_str(&text1);
        assert!(
            errors(&r2.diagnostics).is_empty(),
            "{name} rewritten: {:?}",
            r2.diagnostics
        );
        let p2 = r2.project.expect("model of the rewritten file");
        assert_eq!(p1, p2, "{name}: model changed through write/read");
        let text2 = stepnc::write_project(&p2);
        assert_eq!(text1, text2, "{name}: writing twice differs");
    }
}

#[test]
fn ap238_sample_reads_its_toolpath_with_the_files_units() {
    let Some(dir) = samples_dir() else { return };
    let (_, r) = read(&dir.join("test_program.stpnc"));
    assert!(
        !r.diagnostics.iter().any(|d| d.is_error()),
        "{:?}",
        r.diagnostics
    );
    // What is not read is named (W0807), never dropped silently.
    assert!(r.diagnostics.iter().any(|d| d.code == Code::Ap238NotRead));
    let p = r.project.expect("the AP238 plan reads");
    assert_eq!(p.id, "test program");
    let ws: Vec<_> = p
        .main_workplan
        .elements
        .iter()
        .filter_map(|e| match e {
            Executable::Workingstep(w) => Some(w),
            _ => None,
        })
        .collect();
    assert_eq!(ws.len(), 1);
    let op = p.operation(ws[0].operation);
    assert_eq!(op.id, "P1");
    // The file's context is in inches: 2000 in/min, a 10 in tool.
    assert_eq!(op.technology.feed, Some(2000.0 * 25.4));
    assert_eq!(op.technology.spindle, Some(-3000.0));
    assert_eq!(p.tool(op.tool).body.dimension.diameter, 254.0);
    let Some(Toolpath::CutterLocation { basic_curve, .. }) =
        op.toolpath.as_ref().and_then(|t| t.first())
    else {
        panic!("a cutter location toolpath");
    };
    let Curve::Polyline { points, .. } = basic_curve else {
        panic!("a polyline: {basic_curve:?}");
    };
    let xyz: Vec<[f64; 3]> = points.iter().map(|p| p.xyz).collect();
    assert_eq!(xyz[0], [254.0, 254.0, 0.0]);
    assert_eq!(xyz[1], [762.0, 254.0, 0.0]);
    assert_eq!(xyz.len(), 5);
}

fn ex1() -> Option<Project> {
    let dir = samples_dir()?;
    let (_, r) = read(&dir.join("ex1.stp"));
    Some(r.project.expect("ex1 reads"))
}

fn tol(t: &Toleranced) -> f64 {
    t.nominal
}

#[test]
fn ex1_features_read_as_the_file_states_them() {
    let Some(p) = ex1() else { return };
    assert_eq!(p.id, "EXECUTE EXAMPLE1");
    let steps: Vec<&MachiningWorkingstep> = p
        .main_workplan
        .elements
        .iter()
        .filter_map(|e| match e {
            Executable::Workingstep(w) => Some(w),
            _ => None,
        })
        .collect();
    assert_eq!(steps.len(), 5);
    assert_eq!(p.main_workplan.elements.len(), 5);
    let ids: Vec<&str> = steps.iter().map(|w| w.id.as_str()).collect();
    assert_eq!(
        ids,
        [
            "WS FINISH PLANAR FACE1",
            "WS DRILL HOLE1",
            "WS REAM HOLE1",
            "WS ROUGH POCKET1",
            "WS FINISH POCKET1"
        ]
    );
    assert_eq!(steps[0].secplane.position.location.xyz, [0.0, 0.0, 30.0]);
    assert_eq!(p.features.len(), 3);
    // PLANAR_FACE: 120 mm along +Y, 100 mm wide, 5 mm down from z=5.
    let face = p.feature(steps[0].feature);
    assert_eq!(face.id, "PLANAR FACE1");
    assert_eq!(face.placement.location.xyz, [0.0, 0.0, 5.0]);
    assert_eq!(
        face.depth.as_ref().unwrap().position.location.xyz,
        [0.0, 0.0, -5.0]
    );
    match &face.kind {
        FeatureKind::PlanarFace {
            course_of_travel:
                TravelPath::Linear {
                    distance,
                    direction,
                    ..
                },
            removal_boundary: OpenProfile::Linear { length, .. },
            face_boundary: None,
            ..
        } => {
            assert_eq!(tol(distance), 120.0);
            assert_eq!(direction.ratios, [0.0, 1.0, 0.0]);
            assert_eq!((length.value, length.unit.as_str()), (100.0, "MM"));
        }
        k => panic!("planar face read as {k:?}"),
    }
    // ROUND_HOLE: 22 mm through hole at (20, 60), 30 deep.
    let hole = p.feature(steps[1].feature);
    assert_eq!(
        steps[2].feature, steps[1].feature,
        "both hole steps share the feature"
    );
    assert_eq!(hole.id, "HOLE1 D=22MM");
    assert_eq!(hole.placement.location.xyz, [20.0, 60.0, 0.0]);
    assert_eq!(
        hole.depth.as_ref().unwrap().position.location.xyz,
        [0.0, 0.0, -30.0]
    );
    match &hole.kind {
        FeatureKind::RoundHole {
            diameter, bottom, ..
        } => {
            assert_eq!(tol(diameter), 22.0);
            assert_eq!(
                diameter.tolerance,
                Tolerance::PlusMinus {
                    upper: 0.3,
                    lower: 0.3,
                    significant_digits: 3
                }
            );
            assert_eq!(*bottom, HoleBottom::Through);
        }
        k => panic!("round hole read as {k:?}"),
    }
    assert_eq!(hole.operations.len(), 2);
    // CLOSED_POCKET: 50 x 80 rectangle, corner radius 10, 30 deep, planar bottom.
    let pocket = p.feature(steps[3].feature);
    assert_eq!(pocket.id, "POCKET1");
    assert_eq!(pocket.placement.location.xyz, [70.0, 70.0, 0.0]);
    assert_eq!(
        pocket.placement.ref_direction.as_ref().unwrap().ratios,
        [0.0, 1.0, 0.0]
    );
    match &pocket.kind {
        FeatureKind::ClosedPocket {
            pocket: pc,
            boundary:
                ClosedProfile::Rectangular {
                    width,
                    length,
                    placement: None,
                },
        } => {
            assert_eq!((tol(width), tol(length)), (50.0, 80.0));
            assert_eq!(pc.bottom, PocketBottom::Planar);
            assert_eq!(pc.planar_radius, None);
            assert_eq!(pc.orthogonal_radius.as_ref().map(tol), Some(10.0));
            assert!(pc.bosses.is_empty());
        }
        k => panic!("pocket read as {k:?}"),
    }
}

#[test]
fn ex1_operations_tools_and_technology() {
    let Some(p) = ex1() else { return };
    let steps: Vec<&MachiningWorkingstep> = p
        .main_workplan
        .elements
        .iter()
        .filter_map(|e| match e {
            Executable::Workingstep(w) => Some(w),
            _ => None,
        })
        .collect();
    let op = |k: usize| p.operation(steps[k].operation);
    // Plane finish milling: feed 0.04 m/s = 2400 mm/min, spindle -12 rev/s
    // (clockwise by ISO's sign) = +720 rpm (M3).
    let face = op(0);
    assert_eq!(face.id, "FINISH PLANAR FACE1");
    assert_eq!(face.retract_plane, Some(10.0));
    assert_eq!(face.technology.feed, Some(2400.0));
    assert_eq!(face.technology.spindle, Some(720.0));
    assert!(face.technology.feed_at_tcp);
    assert!(face.machine_functions.coolant && face.machine_functions.chip_removal);
    match &face.kind {
        OperationKind::PlaneMilling {
            finish: true,
            milling,
            axial_cutting_depth,
            allowance_bottom,
        } => {
            assert_eq!(*axial_cutting_depth, Some(2.5));
            assert_eq!(*allowance_bottom, None);
            assert_eq!(
                milling.approach,
                Some(ApproachRetract::PlungeToolaxis { orientation: None })
            );
            match &milling.strategy {
                Some(Strategy::Bidirectional {
                    base,
                    feed_direction,
                    stepover_direction,
                    stroke_connection,
                }) => {
                    assert_eq!(base.overlap, Some(0.05));
                    assert_eq!(base.allow_multiple_passes, Some(true));
                    assert_eq!(feed_direction.as_ref().unwrap().ratios, [0.0, 1.0, 0.0]);
                    assert_eq!(*stepover_direction, Some(LeftOrRight::Left));
                    assert_eq!(*stroke_connection, None);
                }
                s => panic!("strategy {s:?}"),
            }
        }
        k => panic!("face operation read as {k:?}"),
    }
    let tool = p.tool(face.tool);
    assert_eq!(tool.id, "MILL 18MM");
    assert_eq!(tool.body.kind, ToolBodyKind::TaperedEndmill);
    assert_eq!(tool.body.dimension.diameter, 18.0);
    assert_eq!(tool.body.number_of_teeth, Some(4));
    assert_eq!(tool.body.hand_of_cut, Some(Hand::Right));
    assert_eq!(tool.overall_assembly_length, Some(80.0));
    assert_eq!(tool.cutting_edges[0].tool_offset_length, Some(80.0));

    let drill = op(1);
    assert_eq!(drill.technology.feed, Some(1800.0));
    assert_eq!(drill.technology.spindle, Some(960.0));
    match &drill.kind {
        OperationKind::Drilling(d) => {
            let st = d.strategy.as_ref().unwrap();
            assert_eq!(st.reduced_cut_at_start, Some(0.75));
            assert_eq!(st.depth_of_end, Some(8.0));
        }
        k => panic!("drilling read as {k:?}"),
    }
    let dt = p.tool(drill.tool);
    assert_eq!(
        (dt.id.as_str(), &dt.body.kind),
        ("SPIRAL_DRILL_20MM", &ToolBodyKind::TwistDrill)
    );
    assert_eq!(dt.body.dimension.tip_half_angle, Some(31.0));
    assert_eq!(dt.body.pilot_length, Some(0.84));

    let ream = op(2);
    assert_eq!(ream.technology.spindle, Some(1080.0));
    assert!(matches!(
        ream.kind,
        OperationKind::Boring {
            reaming: true,
            spindle_stop_at_bottom: true,
            ..
        }
    ));
    assert_eq!(p.tool(ream.tool).body.kind, ToolBodyKind::TaperedReamer);

    match &op(3).kind {
        OperationKind::BottomAndSideMilling {
            finish: false,
            milling,
            axial_cutting_depth,
            radial_cutting_depth,
            allowance_side,
            allowance_bottom,
        } => {
            assert_eq!(
                (
                    *axial_cutting_depth,
                    *radial_cutting_depth,
                    *allowance_side,
                    *allowance_bottom
                ),
                (Some(6.5), Some(5.0), Some(1.0), Some(0.5))
            );
            assert_eq!(
                milling.strategy,
                Some(Strategy::ContourParallel {
                    base: StrategyBase::default(),
                    rotation: Some(RotDirection::Cw),
                    cutmode: Some(CutMode::Conventional),
                })
            );
        }
        k => panic!("rough pocket read as {k:?}"),
    }
    assert_eq!(op(3).technology.spindle, Some(1200.0));
    assert!(matches!(
        op(4).kind,
        OperationKind::BottomAndSideMilling { finish: true, .. }
    ));
    assert_eq!(p.tools.len(), 3);
    assert_eq!(p.operations.len(), 5);
}

/// Each bad file gives these codes at these places (line:col).
const BAD: &[(&str, &[(&str, &str)])] = &[
    ("syntax", &[("E0800", "9:18"), ("E0800", "10:28")]),
    ("unterminated", &[("E0801", "8:20")]),
    ("dangling", &[("E0802", "9:30")]),
    ("arity", &[("E0803", "8:4")]),
    ("type", &[("E0804", "9:14"), ("E0804", "10:27")]),
    ("unknown", &[("E0805", "9:4")]),
    ("aim", &[("E0806", "5:1")]),
    ("model", &[("E0807", "14:4")]),
    ("duplicate", &[("E0808", "9:1")]),
    ("truncated", &[("E0811", "9:1")]),
    ("complex", &[("E0809", "8:1")]),
    ("cycle", &[("E0812", "9:1")]),
    ("deep", &[("E0812", "8:87")]),
    ("bomb", &[("E0812", "102:31")]),
];

#[test]
fn bad_files_give_their_codes_at_line_and_column() {
    for (name, want) in BAD {
        let path = PathBuf::from(format!("tests/stepnc/bad/{name}.stp"));
        let (files, r) = read(&path);
        assert!(r.project.is_none(), "{name} gave a model");
        let got: Vec<(String, String)> = r
            .diagnostics
            .iter()
            .map(|d| {
                let span = d.span().expect("a place");
                let (l, c) = files.line_col(span.file, span.start as usize);
                (d.code.code().to_string(), format!("{l}:{c}"))
            })
            .collect();
        let want: Vec<(String, String)> = want
            .iter()
            .map(|(c, p)| (c.to_string(), p.to_string()))
            .collect();
        assert_eq!(got, want, "{name}");
        let rendered = render::human(&r.diagnostics, &files, false);
        insta::assert_snapshot!(format!("stepnc_bad_{name}"), rendered);
    }
}

#[test]
fn no_project_is_a_model_error() {
    let (_, r) = read(Path::new("tests/stepnc/bad/noproject.stp"));
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code.code()).collect();
    assert_eq!(codes, ["E0807"]);
}

#[test]
fn queries_answer_attribute_paths() {
    let Some(dir) = samples_dir() else { return };
    let (_, r) = read(&dir.join("ex1.stp"));
    let q = |path: &str| stepnc::query::query(&r.graph, path);
    assert_eq!(
        q("/project/its_workpieces[0]/its_id").unwrap(),
        ["SIMPLE WORKPIECE"]
    );
    assert_eq!(
        q("/project/main_workplan/its_elements[*]/its_feature/its_id").unwrap(),
        [
            "PLANAR FACE1",
            "HOLE1 D=22MM",
            "HOLE1 D=22MM",
            "POCKET1",
            "POCKET1"
        ]
    );
    assert_eq!(
        q("/#18").unwrap(),
        ["#18=CLOSED_POCKET('POCKET1',#4,(#22,#23),#84,#65,(),$,#27,$,#37,#28)"]
    );
    assert_eq!(
        q("/closed_pocket/feature_boundary/profile_length/theoretical_size").unwrap(),
        ["80."]
    );
    assert_eq!(q("/MILLING_TECHNOLOGY/spindle").unwrap().len(), 5);
    // The spelling variant reads under the schema's name.
    assert_eq!(q("/bidirectional/stepover_direction").unwrap(), [".LEFT."]);
    assert_eq!(q("/#1/its_workpieces").unwrap(), ["(#4)"]);
    let e = q("/project/its_workpieces/its_id").unwrap_err();
    assert!(e.contains("[*]"), "{e}");
    let e = q("/project/its_nothing").unwrap_err();
    assert!(e.contains("its_id, main_workplan"), "{e}");
    assert!(q("/project/its_workpieces[3]")
        .unwrap_err()
        .contains("past the end"));
    assert!(q("project").is_err());
}

fn temp_copy(name: &str, text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

#[test]
fn diff_ignores_numbering_and_finds_changes() {
    let Some(dir) = samples_dir() else { return };
    let a = dir.join("ex1.stp");
    let same = stepnc::diff::diff_files(&a, &a).ok().unwrap();
    assert!(same.same && same.lines.is_empty());
    // The normalised file has other numbers, order and spellings.
    let (_, r) = read(&a);
    let normal = stepnc::write_project(&r.project.unwrap());
    let (_t1, b) = temp_copy("normal.stp", &normal);
    let d = stepnc::diff::diff_files(&a, &b).ok().unwrap();
    assert!(d.same, "{:#?}", d.lines);
    // A changed feed, pocket width and tool diameter.
    let orig = std::fs::read_to_string(&a).unwrap();
    let changed = orig
        .replace(
            "#50= MILLING_TECHNOLOGY(0.040,",
            "#50= MILLING_TECHNOLOGY(0.050,",
        )
        .replace(
            "#122= TOLERANCED_LENGTH_MEASURE(50.000,#124);",
            "#122= TOLERANCED_LENGTH_MEASURE(55.000,#124);",
        )
        .replace(
            "#32= MILLING_TOOL_DIMENSION(20.000,",
            "#32= MILLING_TOOL_DIMENSION(21.000,",
        );
    let (_t2, c) = temp_copy("changed.stp", &changed);
    let d = stepnc::diff::diff_files(&a, &c).ok().unwrap();
    assert!(!d.same);
    let text = d.lines.join("\n");
    insta::assert_snapshot!("stepnc_diff_ex1_changed", text);
    assert!(
        text.contains(
            "feature 'POCKET1' / feature_boundary / profile_width / theoretical_size: 50. → 55."
        ),
        "{text}"
    );
    assert!(text.contains("2400 mm/min"), "{text}");
    assert!(text.contains("tool 'SPIRAL_DRILL_20MM'"), "{text}");
}

fn cncc(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .output()
        .expect("cncc runs")
}

#[test]
fn cli_stepnc_output_reads_back_with_check_and_an_independent_reader() {
    let Some(dir) = samples_dir() else { return };
    let out_dir = tempfile::tempdir().unwrap();
    for name in ARM_SAMPLES {
        let src = dir.join(name);
        let out = out_dir.path().join(format!("{name}.stp"));
        let o = cncc(&["stepnc", src.to_str().unwrap(), "-o", out.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let o = cncc(&["check", out.to_str().unwrap()]);
        assert_eq!(
            o.status.code(),
            Some(0),
            "{name} normalised: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let py = std::process::Command::new("python3")
            .arg("tests/part21_check.py")
            .arg(&out)
            .args([
                "PROJECT=6",
                "WORKPLAN=5",
                "MILLING_TECHNOLOGY=9",
                "CLOSED_POCKET=11",
                "ROUND_HOLE=8",
            ])
            .output();
        match py {
            Ok(py) => assert!(
                py.status.success(),
                "{name}: python reader: {}",
                String::from_utf8_lossy(&py.stdout)
            ),
            Err(_) => eprintln!("note: python3 not available; independent reader skipped"),
        }
    }
    let o = cncc(&["check", dir.join("test_program.stpnc").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&o.stderr).contains("W0807"));
}

#[test]
fn cli_query_prints_one_value_per_line() {
    let Some(dir) = samples_dir() else { return };
    let f = dir.join("ex1.stp");
    let o = cncc(&[
        "query",
        f.to_str().unwrap(),
        "/project/main_workplan/its_elements[*]/its_id",
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&o.stdout),
        "WS FINISH PLANAR FACE1\nWS DRILL HOLE1\nWS REAM HOLE1\nWS ROUGH POCKET1\nWS FINISH POCKET1\n"
    );
    let o = cncc(&["query", f.to_str().unwrap(), "/project/nope"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("E0810"));
}

#[test]
fn cli_stepnc_raises_a_program_and_its_output_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("subs.stp");
    let o = cncc(&[
        "stepnc",
        "tests/programs/linuxcnc/subs.ngc",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("ISO-10303-21;"));
    let c = cncc(&["check", out.to_str().unwrap()]);
    assert_eq!(
        c.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&c.stderr)
    );
}

#[test]
fn mangled_files_never_panic() {
    let Some(dir) = samples_dir() else { return };
    let text = std::fs::read_to_string(dir.join("ex1.stp")).unwrap();
    let bytes = text.as_bytes();
    // Every prefix at a coarse step, and single-character damage.
    for cut in (0..bytes.len()).step_by(97) {
        let r = read_str(&String::from_utf8_lossy(&bytes[..cut]));
        assert!(r.project.is_none());
        stepnc::fuzz_read_write(&bytes[..cut]);
    }
    let marks = ["'", "(", ")", ",", "#", ";", "$", "=", ".", "*", "9"];
    for (k, at) in (0..bytes.len()).step_by(61).enumerate() {
        let mut m = bytes.to_vec();
        m[at] = marks[k % marks.len()].as_bytes()[0];
        stepnc::fuzz_read_write(&m);
        let text = String::from_utf8_lossy(&m);
        let id = cncc::span::FileId(0);
        assert_eq!(
            stepnc::part21::parse::parse_with(&text, id, true),
            stepnc::part21::parse::parse_with(&text, id, false),
            "fast path and grammar differ after damage at {at}"
        );
    }
}

#[test]
fn normalised_ex1_snapshot() {
    let Some(dir) = samples_dir() else { return };
    let (_, r) = read(&dir.join("ex1.stp"));
    let text = stepnc::write_project_with_header(&r.project.unwrap(), &r.graph.header);
    insta::assert_snapshot!("stepnc_ex1_normalised", text);
}

#[test]
fn a_feature_kept_raw_still_round_trips() {
    let Some(dir) = samples_dir() else { return };
    // A mandatory reference left `$`: the pocket's placement has no
    // location. (A mandatory name left `$`, as GRIMA writes, reads as ''
    // with W0803 only: see `a_name_left_unset_reads_as_empty`.)
    let text = std::fs::read_to_string(dir.join("ex1.stp"))
        .unwrap()
        .replace(
            "#84= AXIS2_PLACEMENT_3D('POCKET1',#115,",
            "#84= AXIS2_PLACEMENT_3D('POCKET1',$,",
        );
    let r = read_str(&text);
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code.code()).collect();
    assert!(
        codes.contains(&"W0803") && codes.contains(&"W0802"),
        "{codes:?}"
    );
    let p1 = r.project.expect("reads with warnings");
    // The pocket's workingsteps are kept as written; the rest is typed.
    let raw = p1
        .main_workplan
        .elements
        .iter()
        .filter(|e| matches!(e, Executable::Other(_)))
        .count();
    assert_eq!(raw, 2);
    assert_eq!(p1.features.len(), 2);
    assert_eq!(p1.operations.len(), 3);
    let out = stepnc::write_project(&p1);
    let p2 = read_str(&out).project.expect("output reads");
    assert_eq!(p1, p2);
}

#[test]
fn fast_path_reads_exactly_what_the_grammar_reads() {
    use stepnc::part21::parse::parse_with;
    let mut paths: Vec<PathBuf> = std::fs::read_dir("tests/stepnc/bad")
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    if let Some(dir) = samples_dir() {
        for s in ARM_SAMPLES.iter().chain(["test_program.stpnc"].iter()) {
            paths.push(dir.join(s));
        }
    }
    paths.sort();
    for p in paths {
        let text = String::from_utf8_lossy(&std::fs::read(&p).unwrap()).into_owned();
        let id = cncc::span::FileId(0);
        let (fast, fd) = parse_with(&text, id, true);
        let (slow, sd) = parse_with(&text, id, false);
        assert_eq!(fast, slow, "{}", p.display());
        assert_eq!(fd, sd, "{}", p.display());
    }
}

#[test]
fn a_name_left_unset_reads_as_empty() {
    let Some(dir) = samples_dir() else { return };
    let text = std::fs::read_to_string(dir.join("ex1.stp"))
        .unwrap()
        .replace(
            "#84= AXIS2_PLACEMENT_3D('POCKET1',",
            "#84= AXIS2_PLACEMENT_3D($,",
        );
    let r = read_str(&text);
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code.code()).collect();
    assert_eq!(codes, vec!["W0803"], "{codes:?}");
    let p = r.project.expect("reads");
    assert!(p.features.iter().any(|f| f.placement.name.is_empty()));
}
