//! ISO 14649-11 Example 1 (`shared/stepnc-samples/ex1.stp`, NIST's
//! corrected version) built by hand in the model's units, as a fixture
//! for posting tests until the Part 21 reader is merged: a planar face,
//! a through hole drilled and reamed, a rectangular pocket roughed and
//! finished. Feeds 0.04 / 0.03 m/s = 2400 / 1800 mm/min; spindles -12,
//! -16, -18, -20 rev/s = 720, 960, 1080, 1200 rpm clockwise (M3).

use crate::stepnc::model::*;

fn pt(xyz: P3) -> Point {
    Point {
        name: String::new(),
        xyz,
    }
}

fn dir(r: P3) -> Direction {
    Direction {
        name: String::new(),
        ratios: r,
    }
}

fn place(at: P3, x: P3) -> Axis2Placement {
    Axis2Placement {
        name: String::new(),
        location: pt(at),
        axis: Some(dir([0.0, 0.0, 1.0])),
        ref_direction: Some(dir(x)),
    }
}

fn plane(name: &str, at: P3) -> Plane {
    Plane {
        name: name.into(),
        position: place(at, [1.0, 0.0, 0.0]),
    }
}

fn tol(nominal: f64, pm: f64) -> Toleranced {
    Toleranced {
        nominal,
        tolerance: Tolerance::PlusMinus {
            upper: pm,
            lower: pm,
            significant_digits: 3,
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

fn tool(id: &str, kind: ToolBodyKind, d: f64, teeth: i64, len: f64, edge: f64) -> Tool {
    Tool {
        id: id.into(),
        body: ToolBody {
            kind,
            dimension: ToolDimension {
                diameter: d,
                cutting_edge_length: Some(edge),
                ..ToolDimension::default()
            },
            number_of_teeth: Some(teeth),
            hand_of_cut: Some(Hand::Right),
            coolant_through_tool: Some(false),
            pilot_length: None,
            extra: Vec::new(),
        },
        cutting_edges: vec![CuttingComponent {
            tool_offset_length: Some(len),
            material: None,
            technological_data: None,
            expected_tool_life: None,
            technology: None,
        }],
        overall_assembly_length: Some(len),
        direction_for_spindle_orientation: None,
        holder_diameter_for_spindle_orientation: None,
    }
}

fn op(id: &str, retract: f64, t: u32, technology: Technology, kind: OperationKind) -> Operation {
    Operation {
        id: id.into(),
        toolpath: None,
        tool_direction: None,
        retract_plane: Some(retract),
        start_point: None,
        tool: ToolId(t),
        technology,
        machine_functions: MachineFunctions {
            coolant: true,
            chip_removal: true,
            ..MachineFunctions::default()
        },
        overcut_length: None,
        kind,
    }
}

fn ws(id: &str, f: u32, o: u32) -> Executable {
    Executable::Workingstep(MachiningWorkingstep {
        id: id.into(),
        secplane: plane("SECURITY PLANE", [0.0, 0.0, 30.0]),
        feature: FeatureId(f),
        operation: OperationId(o),
        effect: None,
    })
}

fn contour(overlap: Option<f64>) -> Option<Strategy> {
    Some(Strategy::ContourParallel {
        base: StrategyBase {
            overlap,
            allow_multiple_passes: overlap.map(|_| true),
        },
        rotation: Some(RotDirection::Cw),
        cutmode: Some(CutMode::Conventional),
    })
}

fn features() -> Vec<Feature> {
    vec![
        Feature {
            id: "PLANAR FACE1".into(),
            workpiece: WorkpieceId(0),
            operations: vec![OperationId(0)],
            placement: place([0.0, 0.0, 5.0], [1.0, 0.0, 0.0]),
            depth: Some(plane("PLANAR FACE1-DEPTH PLANE", [0.0, 0.0, -5.0])),
            kind: FeatureKind::PlanarFace {
                course_of_travel: TravelPath::Linear {
                    placement: None,
                    distance: tol(120.0, 0.3),
                    direction: dir([0.0, 1.0, 0.0]),
                },
                removal_boundary: OpenProfile::Linear {
                    placement: None,
                    length: NumericParameter {
                        name: "PROFILE LENGTH".into(),
                        value: 100.0,
                        unit: "MM".into(),
                    },
                },
                face_boundary: None,
                bosses: Vec::new(),
            },
        },
        Feature {
            id: "HOLE1 D=22MM".into(),
            workpiece: WorkpieceId(0),
            operations: vec![OperationId(1), OperationId(2)],
            placement: place([20.0, 60.0, 0.0], [1.0, 0.0, 0.0]),
            depth: Some(plane("DEPTH SURFACE FOR ROUND HOLE1", [0.0, 0.0, -30.0])),
            kind: FeatureKind::RoundHole {
                diameter: tol(22.0, 0.3),
                change_in_diameter: None,
                bottom: HoleBottom::Through,
            },
        },
        Feature {
            id: "POCKET1".into(),
            workpiece: WorkpieceId(0),
            operations: vec![OperationId(3), OperationId(4)],
            placement: place([70.0, 70.0, 0.0], [0.0, 1.0, 0.0]),
            depth: Some(plane("DEPTH SURFACE FOR POCKET1", [0.0, 0.0, -30.0])),
            kind: FeatureKind::ClosedPocket {
                pocket: PocketCommon {
                    bosses: Vec::new(),
                    slope: None,
                    bottom: PocketBottom::Planar,
                    planar_radius: None,
                    orthogonal_radius: Some(tol(10.0, 0.1)),
                },
                boundary: ClosedProfile::Rectangular {
                    placement: None,
                    width: tol(50.0, 0.1),
                    length: tol(80.0, 0.1),
                },
            },
        },
    ]
}

fn drill_strategy() -> DrillingStrategy {
    DrillingStrategy {
        reduced_cut_at_start: Some(0.75),
        reduced_feed_at_start: Some(0.5),
        depth_of_start: Some(2.0),
        reduced_cut_at_end: Some(0.5),
        reduced_feed_at_end: Some(0.75),
        depth_of_end: Some(8.0),
    }
}

fn operations() -> Vec<Operation> {
    let face = OperationKind::PlaneMilling {
        finish: true,
        milling: MillingCommon {
            approach: Some(ApproachRetract::PlungeToolaxis { orientation: None }),
            retract: Some(ApproachRetract::PlungeToolaxis { orientation: None }),
            strategy: Some(Strategy::Bidirectional {
                base: StrategyBase {
                    overlap: Some(0.05),
                    allow_multiple_passes: Some(true),
                },
                feed_direction: Some(dir([0.0, 1.0, 0.0])),
                stepover_direction: Some(LeftOrRight::Left),
                stroke_connection: None,
            }),
        },
        axial_cutting_depth: Some(2.5),
        allowance_bottom: None,
    };
    let drill = DrillCommon {
        strategy: Some(drill_strategy()),
        ..DrillCommon::default()
    };
    let ream = OperationKind::Boring {
        reaming: true,
        drill: DrillCommon {
            strategy: Some(DrillingStrategy::default()),
            ..DrillCommon::default()
        },
        spindle_stop_at_bottom: true,
        depth_of_testcut: None,
        waiting_position: None,
    };
    let pocket = |finish, ap, ae, side, bottom, overlap| OperationKind::BottomAndSideMilling {
        finish,
        milling: MillingCommon {
            approach: None,
            retract: None,
            strategy: contour(overlap),
        },
        axial_cutting_depth: Some(ap),
        radial_cutting_depth: Some(ae),
        allowance_side: side,
        allowance_bottom: bottom,
    };
    vec![
        op("FINISH PLANAR FACE1", 10.0, 0, tech(2400.0, 720.0), face),
        op(
            "DRILL HOLE1",
            10.0,
            1,
            tech(1800.0, 960.0),
            OperationKind::Drilling(drill),
        ),
        op("REAM HOLE1", 10.0, 2, tech(1800.0, 1080.0), ream),
        op(
            "ROUGH POCKET1",
            15.0,
            0,
            tech(2400.0, 1200.0),
            pocket(false, 6.5, 5.0, Some(1.0), Some(0.5), None),
        ),
        op(
            "FINISH POCKET1",
            15.0,
            0,
            tech(2400.0, 1200.0),
            pocket(true, 2.0, 10.0, None, None, Some(0.05)),
        ),
    ]
}

/// Example 1 as the model holds it.
pub fn ex1() -> Project {
    Project {
        id: "EXECUTE EXAMPLE1".into(),
        main_workplan: Workplan {
            id: "MAIN WORKPLAN".into(),
            elements: vec![
                ws("WS FINISH PLANAR FACE1", 0, 0),
                ws("WS DRILL HOLE1", 1, 1),
                ws("WS REAM HOLE1", 1, 2),
                ws("WS ROUGH POCKET1", 2, 3),
                ws("WS FINISH POCKET1", 2, 4),
            ],
            channel: None,
            setup: Some(Setup {
                id: "SETUP1".into(),
                origin: Some(place([0.0; 3], [1.0, 0.0, 0.0])),
                secplane: plane("SECURITY PLANE", [0.0, 0.0, 30.0]),
                workpiece_setups: vec![WorkpieceSetup {
                    workpiece: WorkpieceId(0),
                    origin: place([0.0; 3], [1.0, 0.0, 0.0]),
                    offset: None,
                    restricted_area: None,
                    instructions: Vec::new(),
                }],
            }),
            effect: None,
        },
        its_workpieces: vec![WorkpieceId(0)],
        owner: None,
        release: None,
        status: None,
        workpieces: vec![Workpiece {
            id: "SIMPLE WORKPIECE".into(),
            material: None,
            global_tolerance: Some(0.01),
            rawpiece: None,
            geometry: None,
            bounding: None,
            clamping_positions: Vec::new(),
        }],
        features: features(),
        operations: operations(),
        tools: vec![
            tool(
                "MILL 18MM",
                ToolBodyKind::TaperedEndmill,
                18.0,
                4,
                80.0,
                29.0,
            ),
            tool(
                "SPIRAL_DRILL_20MM",
                ToolBodyKind::TwistDrill,
                20.0,
                2,
                90.0,
                45.0,
            ),
            tool(
                "REAMER_22MM",
                ToolBodyKind::TaperedReamer,
                22.0,
                6,
                100.0,
                40.0,
            ),
        ],
    }
}
