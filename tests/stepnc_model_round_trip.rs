//! A model built in code with the variants the samples do not use (open
//! pocket, slot, step, general outside profile, every profile, strategy,
//! approach, drilling operation and toolpath kind) writes and reads back
//! to the same model, and the written file passes the schema checks.
//! (The arenas are built in the order the reader meets them, depth-first
//! from the project, so that equality by value is exact.)

use cncc::source::SourceMap;
use cncc::stepnc::{self, model::*};

fn pt(x: f64, y: f64, z: f64) -> Point {
    Point {
        name: String::new(),
        xyz: [x, y, z],
    }
}

fn dir(x: f64, y: f64, z: f64) -> Direction {
    Direction {
        name: String::new(),
        ratios: [x, y, z],
    }
}

fn place(x: f64, y: f64, z: f64) -> Axis2Placement {
    Axis2Placement {
        name: String::new(),
        location: pt(x, y, z),
        axis: Some(dir(0.0, 0.0, 1.0)),
        ref_direction: Some(dir(1.0, 0.0, 0.0)),
    }
}

fn plane(z: f64) -> Plane {
    Plane {
        name: "PLANE".into(),
        position: place(0.0, 0.0, z),
    }
}

fn tl(v: f64) -> Toleranced {
    Toleranced {
        nominal: v,
        tolerance: Tolerance::PlusMinus {
            upper: 0.1,
            lower: 0.05,
            significant_digits: 2,
        },
    }
}

fn tech(feed: f64, rpm: f64) -> Technology {
    Technology {
        feed: Some(feed),
        feed_at_tcp: true,
        spindle: Some(rpm),
        ..Technology::default()
    }
}

fn arc() -> Curve {
    Curve::Arc {
        name: "ARC".into(),
        circle: place(10.0, 0.0, 0.0),
        circle_name: "C".into(),
        radius: 10.0,
        start: pt(0.0, 0.0, 0.0),
        end: pt(20.0, 0.0, 0.0),
        sense: false,
    }
}

fn polyline() -> Curve {
    Curve::Polyline {
        name: "PL".into(),
        points: vec![pt(0.0, 0.0, 0.0), pt(5.5, 1.25, -2.0)],
    }
}

/// A line along +Z walked downwards (sense_agreement .F. in the file).
fn line_down() -> Curve {
    let raw_point = Raw {
        entity: "CARTESIAN_POINT".into(),
        params: vec![
            RawValue::String("P".into()),
            RawValue::List(vec![RawValue::Real(0.0); 3]),
        ],
    };
    let raw_dir = Raw {
        entity: "DIRECTION".into(),
        params: vec![
            RawValue::String("UP".into()),
            RawValue::List(vec![
                RawValue::Real(0.0),
                RawValue::Real(0.0),
                RawValue::Real(1.0),
            ]),
        ],
    };
    let vector = Raw {
        entity: "VECTOR".into(),
        params: vec![
            RawValue::String("V".into()),
            RawValue::Instance(Box::new(raw_dir)),
            RawValue::Real(10.0),
        ],
    };
    Curve::Line {
        name: "PLUNGE".into(),
        start: pt(0.0, 0.0, 5.0),
        end: pt(0.0, 0.0, -5.0),
        basis: Raw {
            entity: "LINE".into(),
            params: vec![
                RawValue::String("AXIS".into()),
                RawValue::Instance(Box::new(raw_point)),
                RawValue::Instance(Box::new(vector)),
            ],
        },
    }
}

fn base(kind: ToolpathType) -> ToolpathBase {
    ToolpathBase {
        priority: true,
        kind,
        speed: Some(ToolpathSpeed::Ratio(0.5)),
        technology: Some(tech(1234.5, -800.0)),
        machine_functions: None,
    }
}

fn operation(id: &str, tool: u32, kind: OperationKind) -> Operation {
    Operation {
        id: id.into(),
        toolpath: None,
        tool_direction: None,
        retract_plane: Some(5.0),
        start_point: Some(pt(1.0, 2.0, 3.0)),
        tool: ToolId(tool),
        technology: tech(600.0, 3000.0),
        machine_functions: MachineFunctions {
            coolant: true,
            mist: Some(false),
            axis_clamping: vec!["C".into()],
            oriented_spindle_stop: Some(dir(1.0, 0.0, 0.0)),
            ..MachineFunctions::default()
        },
        overcut_length: None,
        kind,
    }
}

fn milling(strategy: Strategy, approach: ApproachRetract) -> MillingCommon {
    MillingCommon {
        approach: Some(approach),
        retract: Some(ApproachRetract::RetractTangent {
            orientation: None,
            radius: 3.0,
        }),
        strategy: Some(strategy),
    }
}

fn sb() -> StrategyBase {
    StrategyBase {
        overlap: Some(0.3),
        allow_multiple_passes: Some(false),
    }
}

fn feature(id: &str, ops: &[u32], kind: FeatureKind) -> Feature {
    Feature {
        id: id.into(),
        workpiece: WorkpieceId(0),
        operations: ops.iter().map(|&o| OperationId(o)).collect(),
        placement: place(10.0, 20.0, 0.0),
        depth: Some(plane(-8.0)),
        kind,
    }
}

fn tool(id: &str, kind: ToolBodyKind, d: f64) -> Tool {
    Tool {
        id: id.into(),
        body: ToolBody {
            kind,
            dimension: ToolDimension {
                diameter: d,
                edge_radius: Some(0.5),
                ..ToolDimension::default()
            },
            number_of_teeth: Some(3),
            hand_of_cut: Some(Hand::Left),
            coolant_through_tool: Some(true),
            pilot_length: None,
            extra: vec![],
        },
        cutting_edges: vec![CuttingComponent {
            tool_offset_length: Some(60.0),
            material: None,
            technological_data: None,
            expected_tool_life: Some(900.0),
            technology: Some(tech(100.0, 200.0)),
        }],
        overall_assembly_length: Some(75.0),
        direction_for_spindle_orientation: None,
        holder_diameter_for_spindle_orientation: None,
    }
}

fn project() -> Project {
    let strategies = [
        Strategy::Unidirectional {
            base: sb(),
            feed_direction: Some(dir(1.0, 0.0, 0.0)),
            cutmode: Some(CutMode::Climb),
        },
        Strategy::BidirectionalContour {
            contour_first: true,
            base: sb(),
            feed_direction: None,
            stepover_direction: Some(LeftOrRight::Right),
            rotation: Some(RotDirection::Ccw),
            cutmode: None,
        },
        Strategy::ContourSpiral {
            base: sb(),
            rotation: None,
            cutmode: Some(CutMode::Conventional),
        },
        Strategy::CenterMilling {
            base: StrategyBase::default(),
        },
        Strategy::Explicit { base: sb() },
    ];
    let approaches = [
        ApproachRetract::PlungeRamp {
            orientation: None,
            angle: 5.0,
        },
        ApproachRetract::PlungeHelix {
            orientation: None,
            radius: 4.0,
            angle: 3.0,
        },
        ApproachRetract::PlungeZigzag {
            orientation: None,
            angle: 2.0,
            width: 6.0,
        },
        ApproachRetract::RetractAngle {
            orientation: Some(dir(0.0, 0.0, 1.0)),
            angle: 45.0,
            travel_length: 3.0,
        },
        ApproachRetract::AlongPath {
            orientation: None,
            path: vec![Toolpath::Feedstop {
                base: base(ToolpathType::Approach),
                dwell: 0.5,
            }],
        },
    ];
    let mut operations: Vec<Operation> = strategies
        .into_iter()
        .zip(approaches)
        .enumerate()
        .map(|(k, (s, a))| {
            let kind = match k {
                0 => OperationKind::SideMilling {
                    finish: false,
                    milling: milling(s, a),
                    axial_cutting_depth: Some(2.0),
                    radial_cutting_depth: Some(1.0),
                    allowance_side: Some(0.2),
                },
                1 => OperationKind::PlaneMilling {
                    finish: false,
                    milling: milling(s, a),
                    axial_cutting_depth: None,
                    allowance_bottom: Some(0.1),
                },
                _ => OperationKind::BottomAndSideMilling {
                    finish: k == 2,
                    milling: milling(s, a),
                    axial_cutting_depth: Some(1.5),
                    radial_cutting_depth: None,
                    allowance_side: None,
                    allowance_bottom: None,
                },
            };
            operation(&format!("MILL{k}"), 0, kind)
        })
        .collect();
    let drill = DrillCommon {
        cutting_depth: Some(12.0),
        previous_diameter: Some(4.0),
        dwell_time_bottom: Some(0.25),
        feed_on_retract: Some(0.8),
        strategy: Some(DrillingStrategy {
            depth_of_start: Some(1.0),
            ..DrillingStrategy::default()
        }),
    };
    operations.push(operation(
        "CENTER",
        1,
        OperationKind::CenterDrilling(drill.clone()),
    ));
    operations.push(operation(
        "SINK",
        1,
        OperationKind::CounterSinking(DrillCommon::default()),
    ));
    operations.push(operation(
        "PECK",
        1,
        OperationKind::MultistepDrilling {
            drill: drill.clone(),
            retract_distance: 1.0,
            first_depth: 3.0,
            depth_of_step: 2.0,
            dwell_time_step: None,
        },
    ));
    operations.push(operation(
        "BORE",
        2,
        OperationKind::Boring {
            reaming: false,
            drill,
            spindle_stop_at_bottom: false,
            depth_of_testcut: Some(0.5),
            waiting_position: Some(pt(0.0, 0.0, 10.0)),
        },
    ));
    let mut free = operation(
        "FREE",
        0,
        OperationKind::Freeform {
            approach: None,
            retract: None,
            strategy: None,
        },
    );
    free.toolpath = Some(vec![
        Toolpath::CutterLocation {
            base: base(ToolpathType::Contact),
            direction: Some(true),
            basic_curve: Curve::Composite {
                name: "CC".into(),
                segments: vec![
                    CompositeSegment {
                        transition: "CONTINUOUS".into(),
                        same_sense: true,
                        curve: arc(),
                    },
                    CompositeSegment {
                        transition: "DISCONTINUOUS".into(),
                        same_sense: false,
                        curve: polyline(),
                    },
                    CompositeSegment {
                        transition: "CONTINUOUS".into(),
                        same_sense: true,
                        curve: line_down(),
                    },
                ],
                self_intersect: None,
            },
            tool_axis: None,
            surface_normal: None,
        },
        Toolpath::CutterLocation {
            base: ToolpathBase {
                speed: Some(ToolpathSpeed::Named("RAPID".into())),
                ..base(ToolpathType::NonContact)
            },
            direction: None,
            basic_curve: polyline(),
            tool_axis: Some(polyline()),
            surface_normal: None,
        },
    ]);
    operations.push(free);
    let features = vec![
        feature(
            "OPEN",
            &[0],
            FeatureKind::OpenPocket {
                pocket: PocketCommon {
                    bosses: vec![],
                    slope: Some(2.0),
                    bottom: PocketBottom::Through,
                    planar_radius: Some(tl(1.0)),
                    orthogonal_radius: None,
                },
                open_boundary: OpenProfile::SquareU {
                    placement: None,
                    width: tl(20.0),
                    first_radius: Some(tl(2.0)),
                    first_angle: Some(90.0),
                    second_radius: Some(tl(2.5)),
                    second_angle: Some(85.0),
                },
                wall_boundary: Some(OpenProfile::Vee {
                    placement: Some(place(0.0, 0.0, 0.0)),
                    radius: tl(1.0),
                    angle: 60.0,
                    tilt_angle: 0.0,
                }),
            },
        ),
        feature(
            "SLOT",
            &[1],
            FeatureKind::Slot {
                course_of_travel: TravelPath::General {
                    placement: None,
                    path: arc(),
                },
                swept_shape: OpenProfile::RoundedU {
                    placement: None,
                    width: tl(8.0),
                },
                end_conditions: vec![
                    SlotEnd::Radiused,
                    SlotEnd::Flat {
                        corner_radius1: tl(1.0),
                        corner_radius2: tl(1.5),
                    },
                ],
            },
        ),
        feature(
            "STEP",
            &[2],
            FeatureKind::Step {
                open_boundary: TravelPath::Linear {
                    placement: None,
                    distance: tl(50.0),
                    direction: dir(0.0, 1.0, 0.0),
                },
                wall_boundary: Some(OpenProfile::PartialCircular {
                    placement: None,
                    radius: tl(3.0),
                    sweep_angle: 90.0,
                }),
                bosses: vec![],
            },
        ),
        feature(
            "OUTSIDE",
            &[3, 4],
            FeatureKind::GeneralOutsideProfile {
                swept_shape: TravelPath::Linear {
                    placement: None,
                    distance: tl(10.0),
                    direction: dir(0.0, 0.0, -1.0),
                },
                boundary: Profile::Closed(ClosedProfile::General {
                    placement: None,
                    shape: polyline(),
                }),
            },
        ),
        feature(
            "HOLE",
            &[5, 6, 7, 8],
            FeatureKind::RoundHole {
                diameter: Toleranced {
                    nominal: 6.0,
                    tolerance: Tolerance::LimitsAndFits {
                        deviation: 0.01,
                        grade: 7.0,
                        fitting: Some("HOLE".into()),
                    },
                },
                change_in_diameter: None,
                bottom: HoleBottom::Conical {
                    tip_angle: 118.0,
                    tip_radius: None,
                },
            },
        ),
        feature(
            "POCKET",
            &[],
            FeatureKind::ClosedPocket {
                pocket: PocketCommon {
                    bosses: vec![],
                    slope: None,
                    bottom: PocketBottom::Planar,
                    planar_radius: None,
                    orthogonal_radius: Some(tl(4.0)),
                },
                boundary: ClosedProfile::Circular {
                    placement: None,
                    diameter: tl(30.0),
                },
            },
        ),
        feature("PATHS", &[9], FeatureKind::ToolpathFeature),
    ];
    let ws = |k: usize, op: u32| {
        Executable::Workingstep(MachiningWorkingstep {
            id: format!("WS{k}-{op}"),
            secplane: plane(50.0),
            feature: FeatureId(k as u32),
            operation: OperationId(op),
            effect: None,
        })
    };
    let mut elements: Vec<Executable> = vec![ws(0, 0), ws(1, 1), ws(2, 2), ws(3, 3), ws(3, 4)];
    elements.extend([5u32, 6, 7, 8].map(|o| ws(4, o)));
    elements.push(ws(5, 4));
    elements.push(ws(6, 9));
    elements.push(Executable::Rapid(RapidMovement {
        id: "RAPID".into(),
        secplane: plane(50.0),
        toolpath: None,
        tool_direction: None,
    }));
    elements.push(Executable::DisplayMessage {
        id: "MSG".into(),
        text: "Check it's clamped \\ ok".into(),
    });
    elements.push(Executable::OptionalStop { id: "M1".into() });
    elements.push(Executable::Workplan(Workplan {
        id: "SUB".into(),
        elements: vec![Executable::ProgramStop { id: "M0".into() }],
        channel: None,
        setup: None,
        effect: None,
    }));
    Project {
        id: "ALL VARIANTS".into(),
        main_workplan: Workplan {
            id: "MAIN".into(),
            elements,
            channel: None,
            setup: Some(Setup {
                id: "SETUP".into(),
                origin: None,
                secplane: plane(60.0),
                workpiece_setups: vec![WorkpieceSetup {
                    workpiece: WorkpieceId(0),
                    origin: place(0.0, 0.0, 0.0),
                    offset: None,
                    restricted_area: None,
                    instructions: vec![],
                }],
            }),
            effect: None,
        },
        its_workpieces: vec![WorkpieceId(0)],
        workpieces: vec![Workpiece {
            id: "BLANK".into(),
            material: Some(Material {
                standard_identifier: "EN".into(),
                material_identifier: "AlMg3".into(),
                properties: vec![],
            }),
            global_tolerance: Some(0.05),
            rawpiece: None,
            geometry: None,
            bounding: Some(Bounding::Block {
                name: "STOCK".into(),
                position: place(0.0, 0.0, -20.0),
                size: [100.0, 80.0, 20.0],
            }),
            clamping_positions: vec![pt(0.0, 0.0, 0.0)],
        }],
        features,
        operations,
        tools: vec![
            tool("MILL", ToolBodyKind::BullnoseEndmill, 10.0),
            tool("DRILL", ToolBodyKind::CenterDrill, 6.0),
            tool("BORE", ToolBodyKind::Tap, 12.0),
        ],
        owner: None,
        release: None,
        status: None,
    }
}

#[test]
fn every_variant_writes_and_reads_back() {
    let p1 = project();
    let text = stepnc::write_project(&p1);
    let mut files = SourceMap::new();
    let id = files.add("variants.stp", text.clone());
    let r = stepnc::read_text(&text, id);
    assert!(
        r.diagnostics.is_empty(),
        "{}",
        cncc::diag::render::human(&r.diagnostics, &files, false)
    );
    let p2 = r.project.expect("reads back");
    if p1 != p2 {
        let (a, b) = (format!("{p1:?}"), format!("{p2:?}"));
        let at = a
            .bytes()
            .zip(b.bytes())
            .position(|(x, y)| x != y)
            .unwrap_or(0);
        let from = at.saturating_sub(300);
        panic!(
            "models differ at byte {at}:\n  written: ...{}\n  read:    ...{}",
            &a[from..(at + 200).min(a.len())],
            &b[from..(at + 200).min(b.len())]
        );
    }
    assert_eq!(stepnc::write_project(&p2), text);
    assert!(text.contains("TRIMMED_CURVE('PLUNGE',"), "{text}");
    let plunge = text
        .lines()
        .find(|l| l.contains("TRIMMED_CURVE('PLUNGE',"))
        .unwrap();
    assert!(plunge.ends_with(",.F.,.CARTESIAN.);"), "{plunge}");
}
