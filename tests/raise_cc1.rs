//! CC1 raising (`cncc stepnc --cc1`) of our own test part, written for
//! Fanuc and for Siemens 840D (`tests/programs/raise/`): a face, four G81
//! holes, a G83 peck hole, a reamed (G85), a bored (G86) and a spot-faced
//! (G82) hole (Fanuc only), a pocket written as explicit moves with arcs,
//! and a slot with an arc.

use cncc::dialect::builtin::builtin;
use cncc::interp::{tooltable::ToolTable, Options};
use cncc::ir::LengthUnit;
use cncc::raise::{raise_file, summary::summary, Level, RaiseOptions, Raised, Stock};
use cncc::source::SourceMap;
use cncc::stepnc::model::*;
use std::path::Path;

fn raise(file: &str, dialect: &str) -> Raised {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/raise");
    let table_text = std::fs::read_to_string(root.join("part.tbl")).unwrap();
    let mut files = SourceMap::default();
    let tid = files.add("part.tbl", table_text.clone());
    let (table, d) = ToolTable::parse(&table_text, tid);
    assert!(d.is_empty());
    let mut run = Options::default();
    run.tool_table = table.clone();
    run.machine_units = LengthUnit::Mm;
    let mut opts = RaiseOptions::new(Level::Cc1, "part");
    opts.stock = Some(Stock::parse("120x80x30").unwrap());
    opts.tool_table = table;
    opts.table_units = LengthUnit::Mm;
    let path = root.join(file);
    let id = files.add_sparse(file.to_string(), Vec::new());
    let spec = builtin(dialect).unwrap();
    raise_file(&path, id, &spec, &run, &opts, &mut files).unwrap()
}

fn steps(p: &Project) -> Vec<&MachiningWorkingstep> {
    p.main_workplan
        .elements
        .iter()
        .filter_map(|e| match e {
            Executable::Workingstep(w) => Some(w),
            _ => None,
        })
        .collect()
}

fn curves(op: &Operation) -> Vec<&Curve> {
    op.toolpath
        .as_deref()
        .unwrap_or(&[])
        .iter()
        .filter_map(|t| match t {
            Toolpath::CutterLocation { basic_curve, .. } => Some(basic_curve),
            _ => None,
        })
        .collect()
}

fn hole_ops(p: &Project) -> Vec<(&Feature, &Operation)> {
    steps(p)
        .into_iter()
        .map(|w| (p.feature(w.feature), p.operation(w.operation)))
        .filter(|(f, _)| matches!(f.kind, FeatureKind::RoundHole { .. }))
        .collect()
}

#[test]
fn fanuc_part_workingsteps_tools_and_technology() {
    let r = raise("part.nc", "fanuc");
    assert!(
        !r.diagnostics.iter().any(|d| d.is_error()),
        "{:?}",
        r.diagnostics
    );
    let p = &r.project;
    // face, 4 drilled + 1 pecked, ream/bore/spot-face, pocket, slot
    assert_eq!(steps(p).len(), 11);
    let kinds: Vec<_> = p
        .tools
        .iter()
        .map(|t| {
            (
                t.id.as_str(),
                t.body.kind.clone(),
                t.body.dimension.diameter,
            )
        })
        .collect();
    assert_eq!(
        kinds,
        [
            ("T1 face mill 50", ToolBodyKind::Facemill, 50.0),
            ("T2 drill 8", ToolBodyKind::TwistDrill, 8.0),
            ("T4 boring bar 8.5", ToolBodyKind::TwistDrill, 8.5),
            ("T3 end mill 10", ToolBodyKind::Endmill, 10.0),
        ]
    );
    let setup = p.main_workplan.setup.as_ref().unwrap();
    assert_eq!(setup.secplane.position.location.xyz[2], 30.0);
    let face = p.operation(steps(p)[0].operation);
    assert_eq!(face.technology.feed, Some(600.0));
    assert_eq!(face.technology.spindle, Some(1200.0));
    assert!(face.machine_functions.coolant);
    assert!(matches!(curves(face)[..], [Curve::Polyline { ref points, .. }] if points.len() == 7));
    let Some(Bounding::Block { size, position, .. }) = &p.workpiece(WorkpieceId(0)).bounding else {
        panic!()
    };
    assert_eq!(
        (*size, position.location.xyz),
        ([120.0, 80.0, 30.0], [0.0, 0.0, -30.0])
    );
}

#[test]
fn fanuc_pocket_keeps_arcs_and_feed_changes() {
    let r = raise("part.nc", "fanuc");
    let p = &r.project;
    let pocket = p.operation(steps(p)[9].operation);
    assert_eq!(steps(p)[9].id, "WS 10 POCKET END MILL 10");
    assert!(matches!(pocket.kind, OperationKind::Freeform { .. }));
    assert_eq!(pocket.technology.feed, Some(150.0));
    let tps = pocket.toolpath.as_ref().unwrap();
    assert_eq!(tps.len(), 2, "the plunge at F150, the contour at F400");
    let Toolpath::CutterLocation {
        base,
        basic_curve: Curve::Composite { segments, .. },
        ..
    } = &tps[1]
    else {
        panic!("{:?}", tps[1])
    };
    assert_eq!(base.technology.as_ref().and_then(|t| t.feed), Some(400.0));
    let arcs: Vec<_> = segments
        .iter()
        .filter_map(|s| match &s.curve {
            Curve::Arc { radius, sense, .. } => Some((*radius, *sense)),
            _ => None,
        })
        .collect();
    assert_eq!(arcs, vec![(5.0, true); 5]);
    assert_eq!(segments.len(), 11);
    // the slot's end arc is clockwise
    let slot = p.operation(steps(p)[10].operation);
    let Toolpath::CutterLocation {
        basic_curve: Curve::Composite { segments, .. },
        ..
    } = &slot.toolpath.as_ref().unwrap()[1]
    else {
        panic!()
    };
    assert!(matches!(segments[1].curve, Curve::Arc { sense: false, radius, .. } if radius == 5.0));
}

#[test]
fn fanuc_holes_are_round_holes_with_their_operation() {
    let r = raise("part.nc", "fanuc");
    let holes = hole_ops(&r.project);
    let names: Vec<_> = holes
        .iter()
        .map(|(_, op)| match &op.kind {
            OperationKind::Drilling(_) => "DRILLING",
            OperationKind::MultistepDrilling { .. } => "MULTISTEP_DRILLING",
            OperationKind::Boring { reaming: true, .. } => "REAMING",
            OperationKind::Boring { .. } => "BORING",
            _ => "other",
        })
        .collect();
    assert_eq!(
        names,
        [
            "DRILLING",
            "DRILLING",
            "DRILLING",
            "DRILLING",
            "MULTISTEP_DRILLING",
            "REAMING",
            "BORING",
            "DRILLING"
        ]
    );
    let (f, op) = &holes[4];
    assert_eq!(f.placement.location.xyz, [60.0, 40.0, 0.0]);
    let FeatureKind::RoundHole {
        diameter, bottom, ..
    } = &f.kind
    else {
        panic!()
    };
    assert_eq!(diameter.nominal, 8.0);
    assert!(matches!(bottom, HoleBottom::Conical { tip_angle, .. } if *tip_angle == 118.0));
    let OperationKind::MultistepDrilling {
        first_depth,
        depth_of_step,
        drill,
        ..
    } = &op.kind
    else {
        panic!()
    };
    assert_eq!(
        (*first_depth, *depth_of_step, drill.cutting_depth),
        (4.0, 6.0, Some(25.0)),
        "G83 R2 Q6: the first peck ends at Z-4, 4 below the top at 0"
    );
    assert_eq!(op.retract_plane, Some(2.0));
    assert_eq!(op.technology.feed, Some(100.0));
    let OperationKind::Boring {
        spindle_stop_at_bottom,
        ..
    } = &holes[6].1.kind
    else {
        panic!()
    };
    assert!(*spindle_stop_at_bottom);
    let OperationKind::Drilling(spot) = &holes[7].1.kind else {
        panic!()
    };
    assert_eq!(spot.dwell_time_bottom, Some(0.5));
    // toolpaths in the hole's frame
    let Curve::Polyline { points, .. } = curves(holes[0].1)[0] else {
        panic!()
    };
    assert_eq!(points[0].xyz, [0.0, 0.0, 2.0]);
    assert_eq!(points[1].xyz, [0.0, 0.0, -12.0]);
}

#[test]
fn siemens_part_gives_the_same_holes_and_cuts() {
    let f = raise("part.nc", "fanuc");
    let s = raise("part.mpf", "siemens840d");
    assert!(
        !s.diagnostics.iter().any(|d| d.is_error()),
        "{:?}",
        s.diagnostics
    );
    let holes = |r: &Raised| {
        hole_ops(&r.project)
            .iter()
            .map(|(f, _)| (f.placement.location.xyz, -f.depth_z()))
            .take(5)
            .collect::<Vec<_>>()
    };
    assert_eq!(holes(&f), holes(&s));
    let s_steps = steps(&s.project);
    assert_eq!(s_steps.len(), 8);
    let pocket = s.project.operation(s_steps[6].operation);
    let Toolpath::CutterLocation {
        basic_curve: Curve::Composite { segments, .. },
        ..
    } = &pocket.toolpath.as_ref().unwrap()[1]
    else {
        panic!()
    };
    assert_eq!(segments.len(), 11);
    let OperationKind::MultistepDrilling { first_depth, .. } =
        &s.project.operation(s_steps[5].operation).kind
    else {
        panic!()
    };
    assert_eq!(*first_depth, 6.0, "CYCLE83 FDEP -6: 6 below the top at 0");
}

#[test]
fn summaries() {
    insta::assert_snapshot!(
        "fanuc_part_cc1",
        summary(&raise("part.nc", "fanuc").project)
    );
    insta::assert_snapshot!(
        "siemens_part_cc1",
        summary(&raise("part.mpf", "siemens840d").project)
    );
}

#[test]
fn part21_of_the_fanuc_part() {
    let p = raise("part.nc", "fanuc").project;
    let text = cncc::stepnc::write_project(&p);
    assert!(text.contains("FILE_SCHEMA(('MACHINING_SCHEMA','MILLING_SCHEMA'));"));
    for entity in [
        "FREEFORM_OPERATION(",
        "TOOLPATH_LIST(",
        "CUTTER_LOCATION_TRAJECTORY(",
        "POLYLINE(",
        "TRIMMED_CURVE(",
        "CIRCLE(",
        "COMPOSITE_CURVE(",
        "RAPID_MOVEMENT(",
        "ROUND_HOLE(",
        "MULTISTEP_DRILLING(",
        "REAMING(",
        "BORING(",
        "TWIST_DRILL(",
    ] {
        assert!(text.contains(entity), "no {entity} in the Part 21");
    }
    insta::assert_snapshot!("fanuc_part_cc1_part21", text);
}
