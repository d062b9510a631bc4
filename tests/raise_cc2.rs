//! CC2 feature recognition on one part programmed twice
//! (`tests/programs/raise2/`): a Fanuc program and the same process plan
//! posted for a Siemens 840D (drilling cycles instead of G81/G83, other
//! approach points). Both must give the same features and operations,
//! and exactly the ones the part has: a faced top, three through holes, a
//! rectangular pocket roughed in three layers and finished (0.2 mm side,
//! 0.1 mm floor allowance), a peck-drilled blind hole, a straight slot.

use cncc::raise::cc2::{listing::listing, recognise_report, Cc2Context};
use cncc::stepnc::model::*;
use std::path::Path;

fn raise(file: &str, dialect: &str) -> Project {
    raise_events(file, dialect).0
}

/// The project a program gives, with the run's events.
fn raise_events(file: &str, dialect: &str) -> (Project, Vec<cncc::toolpath::Event>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/programs/raise2")
        .join(file);
    let spec = cncc::dialect::builtin::builtin(dialect).expect("builtin dialect");
    let mut files = cncc::source::SourceMap::new();
    let id = files.add_sparse(path.display().to_string(), Vec::new());
    let opts = cncc::interp::Options::default();
    let (events, diags) =
        cncc::toolpath::events_of_file(&path, id, &spec, &opts, &mut files).expect("readable");
    assert!(diags.iter().all(|d| !d.is_error()), "{file}: {diags:?}");
    let ctx = Cc2Context {
        tool_diameter: Box::new(|t| match t {
            1 => Some(20.0),
            2 => Some(8.0),
            3 => Some(10.0),
            4 => Some(6.0),
            5 => Some(8.0),
            _ => None,
        }),
        stock: Some(([0.0, 0.0, -20.0], [120.0, 80.0, 1.0])),
        secplane_z: 30.0,
    };
    let mut project = skeleton();
    let notes = recognise_report(&events, &mut project, &|t| ToolId(t as u32), &ctx);
    assert!(
        notes.is_empty(),
        "{file}: moves left unrecognised: {notes:?}"
    );
    (project, events)
}

/// What the CC1 side makes before recognition: the project, its main
/// workplan with a setup, workpiece 0 and the tools (index = number).
fn skeleton() -> Project {
    skeleton_with(&[
        ("T1 FACE MILL", ToolBodyKind::Facemill, 20.0),
        ("T2 DRILL", ToolBodyKind::TwistDrill, 8.0),
        ("T3 END MILL", ToolBodyKind::Endmill, 10.0),
        ("T4 DRILL", ToolBodyKind::TwistDrill, 6.0),
        ("T5 END MILL", ToolBodyKind::Endmill, 8.0),
    ])
}

/// A skeleton with tools 1.. as given (index 0 unused).
fn skeleton_with(tools: &[(&str, ToolBodyKind, f64)]) -> Project {
    let origin = Axis2Placement {
        name: "ORIGIN".into(),
        location: Point {
            name: "ORIGIN".into(),
            xyz: [0.0; 3],
        },
        axis: None,
        ref_direction: None,
    };
    let plane = Plane {
        name: "SECURITY PLANE".into(),
        position: origin.clone(),
    };
    let tool = |id: &str, kind: ToolBodyKind, diameter: f64| Tool {
        id: id.into(),
        body: ToolBody {
            kind,
            dimension: ToolDimension {
                diameter,
                ..ToolDimension::default()
            },
            number_of_teeth: None,
            hand_of_cut: None,
            coolant_through_tool: None,
            pilot_length: None,
            extra: Vec::new(),
        },
        cutting_edges: vec![CuttingComponent {
            tool_offset_length: Some(50.0),
            material: None,
            technological_data: None,
            expected_tool_life: None,
            technology: None,
        }],
        overall_assembly_length: None,
        direction_for_spindle_orientation: None,
        holder_diameter_for_spindle_orientation: None,
    };
    Project {
        id: "CC2 PART".into(),
        main_workplan: Workplan {
            id: "MAIN WORKPLAN".into(),
            elements: Vec::new(),
            channel: None,
            setup: Some(Setup {
                id: "SETUP".into(),
                origin: None,
                secplane: plane,
                workpiece_setups: vec![WorkpieceSetup {
                    workpiece: WorkpieceId(0),
                    origin: origin.clone(),
                    offset: None,
                    restricted_area: None,
                    instructions: Vec::new(),
                }],
            }),
            effect: None,
        },
        its_workpieces: vec![WorkpieceId(0)],
        workpieces: vec![Workpiece {
            id: "PART".into(),
            material: None,
            global_tolerance: None,
            rawpiece: None,
            geometry: None,
            bounding: None,
            clamping_positions: Vec::new(),
        }],
        tools: std::iter::once(tool("T0", ToolBodyKind::Endmill, 1.0))
            .chain(tools.iter().map(|(n, k, d)| tool(n, k.clone(), *d)))
            .collect(),
        ..Project::default()
    }
}

fn kinds(p: &Project) -> Vec<String> {
    p.features
        .iter()
        .map(|f| {
            format!("{:?}", f.kind)
                .split([' ', '{', '('])
                .next()
                .unwrap()
                .to_string()
        })
        .collect()
}

#[test]
fn fanuc_and_siemens_programs_give_the_same_features_and_operations() {
    let (fanuc, fanuc_events) = raise_events("cc2part.nc", "fanuc");
    let (siemens, siemens_events) = raise_events("cc2part.mpf", "siemens840d");
    // The programs move differently (approach points, cycle retracts)...
    let moves = |ev: &[cncc::toolpath::Event]| {
        ev.iter()
            .filter_map(|e| match e {
                cncc::toolpath::Event::Move(m) => Some((m.from, m.to)),
                _ => None,
            })
            .collect::<Vec<_>>()
    };
    assert_ne!(moves(&fanuc_events), moves(&siemens_events));
    // ...and give the same features and operations.
    assert_eq!(listing(&fanuc), listing(&siemens));
    assert_eq!(fanuc.features, siemens.features);
    assert_eq!(fanuc.operations, siemens.operations);
    assert_eq!(fanuc.main_workplan, siemens.main_workplan);
}

/// The same process plan for a Heidenhain TNC (`cc2part.h`): the drilling
/// by CYCL DEF 200 called at each hole (M99, CYCL CALL), the pocket, face
/// and slot by explicit L moves. It gives the same features, workplan and
/// operations as the Fanuc program except, legitimately, the pecked
/// hole's `first_depth` (from the hole's top) and `retract_distance`
/// (from the first peck's bottom up to the R plane): G83's Q4 counts the
/// first peck from R (R2: to Z-2), cycle 200's Q202=4 from the surface
/// (Q203=0: to Z-4).
#[test]
fn fanuc_and_heidenhain_programs_give_the_same_features_and_operations() {
    let fanuc = raise("cc2part.nc", "fanuc");
    let tnc = raise("cc2part.h", "heidenhain");
    assert_eq!(kinds(&tnc), kinds(&fanuc));
    assert_eq!(tnc.features, fanuc.features);
    assert_eq!(tnc.main_workplan, fanuc.main_workplan);
    let report = cncc::stepnc::diff::diff_projects(&fanuc, &tnc);
    assert_eq!(
        report.lines,
        [
            "~ operation 'PECK DRILL HOLE4' / first_depth: 2. → 4.",
            "~ operation 'PECK DRILL HOLE4' / retract_distance: 4. → 6."
        ],
        "{}",
        report.lines.join("\n")
    );
    let peck = |p: &Project| {
        p.operations
            .iter()
            .filter(|o| matches!(o.kind, OperationKind::MultistepDrilling { .. }))
            .count()
    };
    assert_eq!((peck(&fanuc), peck(&tnc)), (1, 1));
}

#[test]
fn the_part_gives_exactly_its_features() {
    let p = raise("cc2part.nc", "fanuc");
    assert_eq!(
        kinds(&p),
        [
            "PlanarFace",
            "RoundHole",
            "RoundHole",
            "RoundHole",
            "ClosedPocket",
            "RoundHole",
            "Slot"
        ]
    );
    // Workplan: program order, one workingstep per operation.
    let ws: Vec<String> = p
        .main_workplan
        .elements
        .iter()
        .map(|e| match e {
            Executable::Workingstep(w) => w.id.clone(),
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(
        ws,
        [
            "WS FACE PLANAR FACE1",
            "WS DRILL HOLE1",
            "WS DRILL HOLE2",
            "WS DRILL HOLE3",
            "WS ROUGH POCKET1",
            "WS FINISH POCKET1",
            "WS PECK DRILL HOLE4",
            "WS MILL SLOT1"
        ]
    );
    face(&p.features[0], &p);
    through_holes(&p);
    pocket(&p.features[4], &p);
    peck_hole(&p.features[5], &p);
    slot(&p.features[6], &p);
}

fn depth(f: &Feature) -> f64 {
    -f.depth_z()
}

fn face(f: &Feature, p: &Project) {
    assert_eq!(f.placement.location.xyz, [0.0, 0.0, 1.0]);
    assert_eq!(depth(f), 1.0);
    let FeatureKind::PlanarFace {
        course_of_travel:
            TravelPath::Linear {
                distance,
                direction,
                ..
            },
        removal_boundary: OpenProfile::Linear { length, .. },
        ..
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!(
        (distance.nominal, direction.ratios, length.value),
        (120.0, [1.0, 0.0, 0.0], 80.0)
    );
    assert_eq!(f.operations.len(), 1);
    let op = p.operation(f.operations[0]);
    let OperationKind::PlaneMilling {
        finish: true,
        milling,
        axial_cutting_depth: Some(ap),
        ..
    } = &op.kind
    else {
        panic!("{:?}", op.kind)
    };
    assert_eq!(*ap, 1.0);
    let Some(Strategy::Bidirectional {
        feed_direction: Some(d),
        stepover_direction,
        base,
        ..
    }) = &milling.strategy
    else {
        panic!("{:?}", milling.strategy)
    };
    assert_eq!(d.ratios, [1.0, 0.0, 0.0]);
    assert_eq!(*stepover_direction, Some(LeftOrRight::Left));
    assert_eq!(base.overlap, Some(0.25));
    assert_eq!(
        (op.technology.feed, op.technology.spindle),
        (Some(800.0), Some(3000.0))
    );
    assert!(!op.machine_functions.coolant);
    assert_eq!(op.tool, ToolId(1));
}

fn through_holes(p: &Project) {
    for (f, xy) in p.features[1..4]
        .iter()
        .zip([[10.0, 10.0], [110.0, 10.0], [10.0, 70.0]])
    {
        assert_eq!(f.placement.location.xyz, [xy[0], xy[1], 0.0]);
        assert_eq!(depth(f), 20.0, "{}", f.id);
        let FeatureKind::RoundHole {
            diameter,
            bottom: HoleBottom::Through,
            ..
        } = &f.kind
        else {
            panic!("{:?}", f.kind)
        };
        assert_eq!(diameter.nominal, 8.0);
        let op = p.operation(f.operations[0]);
        assert!(
            matches!(op.kind, OperationKind::Drilling(_)),
            "{:?}",
            op.kind
        );
        assert_eq!(op.retract_plane, Some(2.0));
        assert!(op.machine_functions.coolant);
        assert_eq!(
            (op.technology.feed, op.technology.spindle),
            (Some(150.0), Some(2000.0))
        );
    }
}

fn pocket(f: &Feature, p: &Project) {
    assert_eq!(f.placement.location.xyz, [60.0, 40.0, 0.0]);
    assert_eq!(depth(f), 6.0);
    let FeatureKind::ClosedPocket {
        pocket,
        boundary: ClosedProfile::Rectangular { width, length, .. },
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!((length.nominal, width.nominal), (40.0, 30.0));
    assert_eq!(
        pocket.orthogonal_radius.as_ref().map(|r| r.nominal),
        Some(5.0)
    );
    assert_eq!(f.operations.len(), 2);
    let rough = &p.operation(f.operations[0]).kind;
    let OperationKind::BottomAndSideMilling {
        finish: false,
        milling,
        axial_cutting_depth,
        radial_cutting_depth,
        allowance_side,
        allowance_bottom,
    } = rough
    else {
        panic!("{rough:?}")
    };
    assert_eq!((*allowance_side, *allowance_bottom), (Some(0.2), Some(0.1)));
    assert_eq!(
        (*axial_cutting_depth, *radial_cutting_depth),
        (Some(2.0), Some(8.0))
    );
    assert_eq!(
        milling.strategy,
        Some(Strategy::ContourParallel {
            base: StrategyBase::default(),
            rotation: Some(RotDirection::Ccw),
            cutmode: Some(CutMode::Climb)
        })
    );
    assert_eq!(
        milling.approach,
        Some(ApproachRetract::PlungeToolaxis { orientation: None })
    );
    let fin = p.operation(f.operations[1]);
    let OperationKind::BottomAndSideMilling {
        finish: true,
        allowance_side: None,
        allowance_bottom: None,
        ..
    } = &fin.kind
    else {
        panic!("{:?}", fin.kind)
    };
    assert_eq!(
        (fin.technology.feed, fin.technology.spindle),
        (Some(300.0), Some(4500.0))
    );
}

fn peck_hole(f: &Feature, p: &Project) {
    assert_eq!(f.placement.location.xyz, [110.0, 70.0, 0.0]);
    let FeatureKind::RoundHole {
        diameter,
        bottom: HoleBottom::Conical { tip_angle, .. },
        ..
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!((diameter.nominal, *tip_angle), (6.0, 118.0));
    // The tip at Z-15; the cone of a 118° point on a 6 mm drill is
    // 3 / tan 59° = 1.802569 mm high; the depth ends where it starts.
    assert!(
        (depth(f) - (15.0 - 3.0 / 59f64.to_radians().tan())).abs() < 1e-6,
        "{}",
        depth(f)
    );
    let op = p.operation(f.operations[0]);
    let OperationKind::MultistepDrilling {
        first_depth,
        depth_of_step,
        retract_distance,
        ..
    } = &op.kind
    else {
        panic!("{:?}", op.kind)
    };
    assert_eq!(
        (*first_depth, *depth_of_step, *retract_distance),
        (2.0, 4.0, 4.0),
        "G83 R2 Q4: the first peck ends at Z-2, 2 below the top at 0"
    );
}

fn slot(f: &Feature, p: &Project) {
    assert_eq!(f.placement.location.xyz, [30.0, 10.0, 0.0]);
    assert_eq!(depth(f), 4.0);
    let FeatureKind::Slot {
        course_of_travel:
            TravelPath::Linear {
                distance,
                direction,
                ..
            },
        swept_shape: OpenProfile::SquareU { width, .. },
        end_conditions,
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!(
        (distance.nominal, direction.ratios, width.nominal),
        (60.0, [1.0, 0.0, 0.0], 8.0)
    );
    assert_eq!(end_conditions, &[SlotEnd::Radiused, SlotEnd::Radiused]);
    let op = p.operation(f.operations[0]);
    let OperationKind::BottomAndSideMilling {
        milling,
        axial_cutting_depth,
        ..
    } = &op.kind
    else {
        panic!("{:?}", op.kind)
    };
    assert_eq!(*axial_cutting_depth, Some(2.0));
    assert!(matches!(
        milling.strategy,
        Some(Strategy::CenterMilling { .. })
    ));
}

/// Both programs give the same Part 21 file, which reads back into the
/// same model.
#[test]
fn part21_files_are_the_same_and_read_back() {
    let text = cncc::stepnc::write_project(&raise("cc2part.nc", "fanuc"));
    assert_eq!(
        text,
        cncc::stepnc::write_project(&raise("cc2part.mpf", "siemens840d"))
    );
    for entity in [
        "PLANAR_FACE(",
        "ROUND_HOLE(",
        "CLOSED_POCKET(",
        "SLOT(",
        "MULTISTEP_DRILLING(",
        "BOTTOM_AND_SIDE_ROUGH_MILLING(",
        "BOTTOM_AND_SIDE_FINISH_MILLING(",
        "CONTOUR_PARALLEL(",
        "BIDIRECTIONAL",
    ] {
        assert!(text.contains(entity), "no {entity} in\n{text}");
    }
    let mut files = cncc::source::SourceMap::new();
    let id = files.add("cc2part.stp", text.clone());
    let back = cncc::stepnc::read_text(&text, id);
    assert!(
        back.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        back.diagnostics
    );
    let p = back.project.expect("a model");
    assert_eq!(p.features, raise("cc2part.nc", "fanuc").features);
    assert_eq!(cncc::stepnc::write_project(&p), text);
}

#[test]
fn listing_snapshot() {
    insta::assert_snapshot!("cc2part_features", listing(&raise("cc2part.nc", "fanuc")));
}

/// Every corpus program (`../shared/corpus`) is raised without a panic,
/// and every run with cutting moves gives workingsteps; prints what each
/// gives.
#[test]
fn corpus_programs_raise() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    if !root.is_dir() {
        eprintln!("note: {} absent, corpus raising not tested", root.display());
        return;
    }
    for (dir, dialect) in [
        ("fanuc", "fanuc"),
        ("haas", "haas"),
        ("linuxcnc", "linuxcnc"),
        ("siemens840d", "siemens840d"),
    ] {
        let Ok(entries) = std::fs::read_dir(root.join(dir)) else {
            continue;
        };
        let mut paths: Vec<_> = entries.flatten().map(|e| e.path()).collect();
        paths.sort();
        for path in paths {
            if std::env::var("CC2_ONLY").is_ok_and(|o| !path.display().to_string().contains(&o)) {
                continue;
            }
            let spec = cncc::dialect::builtin::builtin(dialect).unwrap();
            let mut files = cncc::source::SourceMap::new();
            let id = files.add_sparse(path.display().to_string(), Vec::new());
            // Bounded runs: the test is about raising, not about long loops.
            let mut opts = cncc::interp::Options::default();
            opts.limits.blocks = 200_000;
            opts.limits.loop_iterations = 20_000;
            let Ok((events, _)) =
                cncc::toolpath::events_of_file(&path, id, &spec, &opts, &mut files)
            else {
                continue;
            };
            let ctx = Cc2Context {
                tool_diameter: Box::new(|_| Some(10.0)),
                ..Cc2Context::default()
            };
            let mut p = Project::default();
            let start = std::time::Instant::now();
            let notes = recognise_report(&events, &mut p, &|_| ToolId(0), &ctx);
            eprintln!("recognised in {:?}", start.elapsed());
            if std::env::var("CC2_ONLY").is_ok() {
                eprintln!("{}", listing(&p));
            }
            let feeds = events
                .iter()
                .filter(|e| matches!(e, cncc::toolpath::Event::Move(m) if m.is_feed()))
                .count();
            if feeds > 0 {
                assert!(!p.main_workplan.elements.is_empty(), "{}", path.display());
            }
            eprintln!(
                "{}: {} feed moves, features {:?}, {} left as toolpaths",
                path.display(),
                feeds,
                kinds(&p),
                notes.len()
            );
        }
    }
}

/// A part as a CAM system posts it: spot drilling then drilling at the
/// same holes, a pocket roughed with a helical entry and zig-zag inside
/// a contour in two layers then finished along a contour with corner
/// arcs, an outside profile in two layers. Tool diameters come from the
/// project's tools only.
#[test]
fn cam_like_program_gives_its_features() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/raise2/camlike.nc");
    let spec = cncc::dialect::builtin::builtin("fanuc").unwrap();
    let mut files = cncc::source::SourceMap::new();
    let id = files.add_sparse(path.display().to_string(), Vec::new());
    let (events, diags) =
        cncc::toolpath::events_of_file(&path, id, &spec, &Default::default(), &mut files).unwrap();
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:?}");
    let mut p = skeleton_with(&[
        ("T1 SPOT DRILL", ToolBodyKind::Spotdrill, 6.0),
        ("T2 DRILL", ToolBodyKind::TwistDrill, 5.0),
        ("T3 END MILL", ToolBodyKind::Endmill, 8.0),
        ("T4 END MILL", ToolBodyKind::Endmill, 10.0),
    ]);
    let ctx = Cc2Context {
        stock: Some(([0.0, 0.0, -15.0], [80.0, 60.0, 0.0])),
        secplane_z: 15.0,
        ..Cc2Context::default()
    };
    let notes = recognise_report(&events, &mut p, &|t| ToolId(t as u32), &ctx);
    assert!(notes.is_empty(), "{notes:?}");
    let text = listing(&p);
    assert_eq!(
        kinds(&p),
        [
            "RoundHole",
            "RoundHole",
            "ClosedPocket",
            "GeneralOutsideProfile"
        ],
        "{text}"
    );
    for f in &p.features[..2] {
        let FeatureKind::RoundHole {
            diameter,
            bottom: HoleBottom::Through,
            ..
        } = &f.kind
        else {
            panic!("{text}")
        };
        assert_eq!((diameter.nominal, depth(f)), (5.0, 15.0));
        let ops: Vec<_> = f.operations.iter().map(|o| &p.operation(*o).kind).collect();
        assert!(
            matches!(
                ops[..],
                [OperationKind::CenterDrilling(_), OperationKind::Drilling(_)]
            ),
            "{text}"
        );
    }
    let pocket = &p.features[2];
    let FeatureKind::ClosedPocket {
        pocket: common,
        boundary: ClosedProfile::Rectangular { length, width, .. },
    } = &pocket.kind
    else {
        panic!("{text}")
    };
    assert_eq!(
        (length.nominal, width.nominal, depth(pocket)),
        (30.0, 20.0, 5.0)
    );
    assert_eq!(
        common.orthogonal_radius.as_ref().map(|r| r.nominal),
        Some(6.0)
    );
    let rough = &p.operation(pocket.operations[0]).kind;
    let OperationKind::BottomAndSideMilling {
        finish: false,
        milling,
        allowance_side,
        allowance_bottom,
        axial_cutting_depth,
        radial_cutting_depth,
    } = rough
    else {
        panic!("{text}")
    };
    assert_eq!(
        (
            *allowance_side,
            *allowance_bottom,
            *axial_cutting_depth,
            *radial_cutting_depth
        ),
        (Some(0.3), Some(0.2), Some(2.4), Some(3.0))
    );
    assert!(
        matches!(
            milling.strategy,
            Some(Strategy::BidirectionalContour {
                contour_first: false,
                ..
            })
        ),
        "{text}"
    );
    assert!(
        matches!(milling.approach, Some(ApproachRetract::PlungeHelix { radius, .. }) if radius == 1.5),
        "{text}"
    );
    let profile = &p.features[3];
    let FeatureKind::GeneralOutsideProfile {
        boundary: Profile::Closed(ClosedProfile::Rectangular { length, width, .. }),
        ..
    } = &profile.kind
    else {
        panic!("{text}")
    };
    assert_eq!(
        (length.nominal, width.nominal, depth(profile)),
        (76.0, 56.0, 15.0)
    );
    let OperationKind::SideMilling {
        milling,
        axial_cutting_depth,
        ..
    } = &p.operation(profile.operations[0]).kind
    else {
        panic!("{text}")
    };
    assert_eq!(*axial_cutting_depth, Some(7.5));
    assert!(
        matches!(
            milling.strategy,
            Some(Strategy::ContourParallel {
                rotation: Some(RotDirection::Cw),
                cutmode: Some(CutMode::Climb),
                ..
            })
        ),
        "{text}"
    );
    insta::assert_snapshot!("camlike_features", text);
}

/// Moves no recogniser explains stay a TOOLPATH_FEATURE whose explicit
/// toolpath (polylines, an arc as a trimmed circle, a helix as a
/// polyline, rapids) is written to Part 21 and read back unchanged.
#[test]
fn toolpath_features_round_trip_through_part21() {
    use cncc::toolpath::{ArcGeom, CoolantState, Event, FeedMode, Move, MoveKind};
    let mv = |kind, from, to| {
        Event::Move(Move {
            kind,
            from,
            to,
            feed: 300.0,
            feed_mode: FeedMode::PerMinute,
            tool: 3,
            spindle: 2000.0,
            coolant: CoolantState {
                flood: true,
                mist: false,
            },
            span: Default::default(),
        })
    };
    let arc = |c: [f64; 3], rotation| {
        MoveKind::Arc(ArcGeom {
            axes: [0, 1, 2],
            centre: c,
            rotation,
        })
    };
    let events = vec![
        mv(MoveKind::Rapid, [0.0, 0.0, 5.0], [0.0, 0.0, 2.0]),
        mv(MoveKind::Line, [0.0, 0.0, 2.0], [5.0, 3.0, -1.0]),
        mv(
            arc([5.0, 8.0, -1.0], 1),
            [5.0, 3.0, -1.0],
            [10.0, 8.0, -1.0],
        ),
        mv(
            arc([5.0, 8.0, -1.0], 1),
            [10.0, 8.0, -1.0],
            [0.0, 8.0, -2.0],
        ),
        mv(MoveKind::Rapid, [0.0, 8.0, -2.0], [0.0, 8.0, 5.0]),
    ];
    let mut p = skeleton();
    let ctx = Cc2Context {
        tool_diameter: Box::new(|_| Some(6.0)),
        ..Cc2Context::default()
    };
    let notes = recognise_report(&events, &mut p, &|t| ToolId(t as u32), &ctx);
    assert_eq!(notes.len(), 1);
    assert_eq!(notes[0].code.code(), "W0870");
    assert_eq!(kinds(&p), ["ToolpathFeature"]);
    let Some(tps) = &p.operations[0].toolpath else {
        panic!()
    };
    // Rapid in, line, arc, helix, rapid out.
    assert_eq!(tps.len(), 5, "{tps:?}");
    let text = cncc::stepnc::write_project(&p);
    for entity in [
        "TOOLPATH_FEATURE(",
        "FREEFORM_OPERATION(",
        "CUTTER_LOCATION_TRAJECTORY(",
        "TRIMMED_CURVE(",
        "POLYLINE(",
    ] {
        assert!(text.contains(entity), "no {entity} in\n{text}");
    }
    let mut files = cncc::source::SourceMap::new();
    let id = files.add("tp.stp", text.clone());
    let back = cncc::stepnc::read_text(&text, id);
    assert!(
        back.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        back.diagnostics
    );
    let q = back.project.expect("a model");
    assert_eq!(q.features, p.features);
    // Tools are renumbered by the reader and rpm go through rev/s: the
    // toolpaths and the operation's kind are compared.
    assert_eq!(q.operations[0].toolpath, p.operations[0].toolpath);
    assert_eq!(q.operations[0].kind, p.operations[0].kind);
}

/// The Part 21 that `cncc stepnc --cc2` writes for the test part, as a new
/// user would ask for it (tool table, stock, mm machine units): planar
/// face (bidirectional), through holes (drilling), a rectangular pocket
/// (contour-parallel rough in layers + finish with allowances), a peck
/// hole (multistep drilling, conical bottom) and a slot (centre milling).
#[test]
fn cli_part21_snapshot() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/raise2");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args([
            "stepnc",
            "--cc2",
            "--machine-units",
            "mm",
            "--stock",
            "120x80x21+0+0-20",
        ])
        .arg("--tool-table")
        .arg(dir.join("cc2part.tbl"))
        .arg(dir.join("cc2part.nc"))
        .output()
        .expect("cncc runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    // The header's time stamp and file name vary: the data section is compared.
    let data = &text[text.find("DATA;").expect("a DATA section")..];
    insta::assert_snapshot!("cc2part_part21", data);
}

/// The same command without `--machine-units mm`: the table is read in
/// inches (LinuxCNC's default), its 20 mm face mill would be 508 mm
/// across, and W0864 says so on the table's line; with mm it is silent.
#[test]
fn a_metric_table_read_in_inches_is_named() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/raise2");
    let run = |units: &[&str]| {
        std::process::Command::new(env!("CARGO_BIN_EXE_cncc"))
            .args(["stepnc", "--cc2", "--stock", "120x80x21+0+0-20"])
            .args(units)
            .arg("--tool-table")
            .arg(dir.join("cc2part.tbl"))
            .arg(dir.join("cc2part.nc"))
            .env("NO_COLOR", "1")
            .output()
            .expect("cncc runs")
    };
    let inch = run(&[]);
    let err = String::from_utf8_lossy(&inch.stderr);
    assert_eq!(inch.status.code(), Some(0), "{err}");
    assert!(err.contains("warning[W0864 tool-table-units]"), "{err}");
    assert!(err.contains("tool 1 is 508.0 mm across"), "{err}");
    assert!(err.contains("cc2part.tbl:1:1"), "{err}");
    assert!(err.contains("--machine-units mm"), "{err}");
    let mm = run(&["--machine-units", "mm"]);
    let err = String::from_utf8_lossy(&mm.stderr);
    assert!(!err.contains("W0864"), "{err}");
}
