//! The validator every post runs first (issue 15, point 2), and the
//! values the target can write: a feature outside the stock is refused
//! with both boxes and the cause; a profile that repeats its feature's
//! placement is named, and `--profiles-absolute` reads it so; an
//! implausible chip load is warned about; Fanuc and Haas get whole rpm.

use cncc::diag::Code;
use cncc::post::fixture::ex1;
use cncc::stepnc::model::*;

fn post(p: &Project, to: &str) -> Result<cncc::post::Posted, Vec<cncc::diag::Diagnostic>> {
    cncc::post::post(p, &cncc::dialect::builtin(to).expect("dialect"))
}

/// ex1 gives its workpiece no BLOCK: one large enough for the part.
fn ex1_with_block() -> Project {
    let mut p = ex1();
    let position = p.features[0].placement.clone();
    let mut position = position;
    position.location.xyz = [0.0, 0.0, -50.0];
    p.workpieces[0].bounding = Some(Bounding::Block {
        name: "STOCK".into(),
        position,
        size: [100.0, 120.0, 50.0],
    });
    p
}

fn pocket(p: &mut Project) -> &mut Feature {
    p.features
        .iter_mut()
        .find(|f| matches!(f.kind, FeatureKind::ClosedPocket { .. }))
        .expect("ex1 has a pocket")
}

fn profile_placement(f: &mut Feature) -> &mut Option<Axis2Placement> {
    match &mut f.kind {
        FeatureKind::ClosedPocket {
            boundary: ClosedProfile::Rectangular { placement, .. },
            ..
        } => placement,
        _ => panic!("a rectangular pocket"),
    }
}

#[test]
fn a_pocket_outside_the_block_is_refused_with_both_boxes() {
    let mut p = ex1_with_block();
    pocket(&mut p).placement.location.xyz[0] += 500.0;
    let errs = post(&p, "fanuc").expect_err("outside the stock");
    let e = errs
        .iter()
        .find(|d| d.code == Code::PostOutsideStock)
        .expect("E0908");
    assert!(
        e.message.contains("lies outside the stock"),
        "{}",
        e.message
    );
    assert!(
        e.message.contains("stock (x 0..100, y 0..120, z -50..0)"),
        "{}",
        e.message
    );
}

#[test]
fn a_repeated_profile_placement_is_named_and_can_be_read_as_absolute() {
    let mut p = ex1_with_block();
    let f = pocket(&mut p);
    let at = f.placement.clone();
    *profile_placement(f) = Some(at);
    let errs = post(&p, "linuxcnc").expect_err("the two placements add up");
    assert!(errs
        .iter()
        .any(|d| d.code == Code::ProfilePlacementRepeated));
    let e = errs
        .iter()
        .find(|d| d.code == Code::PostOutsideStock)
        .expect("E0908");
    assert!(e
        .help
        .as_deref()
        .unwrap_or("")
        .contains("--profiles-absolute"));
    cncc::post::validate::profiles_absolute(&mut p);
    let ok = post(&p, "linuxcnc").expect("posts once read as absolute");
    assert!(ok.warnings.iter().all(|d| d.code != Code::PostOutsideStock));
}

#[test]
fn fanuc_and_haas_write_whole_rpm_and_say_so() {
    let mut p = ex1();
    for o in &mut p.operations {
        o.technology.spindle = Some(350.141);
    }
    for t in ["fanuc", "haas"] {
        let posted = post(&p, t).expect("posts");
        assert!(!posted.text.contains("S350.141"), "{t}");
        assert!(
            posted.text.contains("S350 ") || posted.text.contains("S350\n"),
            "{t}"
        );
        assert!(
            posted
                .warnings
                .iter()
                .any(|d| d.message.contains("350.141")),
            "{t}"
        );
    }
    let siemens = post(&p, "siemens840d").expect("posts");
    assert!(siemens.text.contains("S350.141"));
}

#[test]
fn a_drill_fed_70_mm_per_revolution_is_warned_about() {
    let mut p = ex1();
    for o in &mut p.operations {
        if matches!(o.kind, OperationKind::Drilling(_)) {
            o.technology.feed = Some(14700.0);
            o.technology.spindle = Some(210.0);
        }
    }
    let posted = post(&p, "fanuc").expect("posts, with a warning");
    assert!(posted.warnings.iter().any(|d| d.code == Code::StockUnknown));
    let w = posted
        .warnings
        .iter()
        .find(|d| d.code == Code::ImplausibleFeed)
        .expect("W0901");
    assert!(w.message.contains("70 mm per revolution"), "{}", w.message);
}

/// ISO 14649-111's BORING_TOOL (field files drill with one): the 840D
/// tool data gets the boring bar's type 210, where it had no type code.
#[test]
fn a_boring_tool_gets_the_840d_boring_bar_type() {
    let mut p = ex1();
    for t in &mut p.tools {
        if matches!(t.body.kind, ToolBodyKind::TwistDrill) {
            t.body.kind = ToolBodyKind::Other("BORING_TOOL".into());
        }
    }
    let posted = post(&p, "siemens840d").expect("posts");
    assert!(posted.text.contains("$TC_DP1[2,1]=210 "), "{}", posted.text);
}

/// A feature whose its_workpiece is `$` (mandatory; some generators
/// leave it out) in a project of one workpiece is read as on that one,
/// with the W0803 warning saying so, and posts.
#[test]
fn a_feature_without_its_workpiece_is_on_the_projects_only_one() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/stepnc/planes.stp");
    let text = std::fs::read_to_string(path)
        .unwrap()
        .replace("#40=ROUND_HOLE('HOLE A',#10,", "#40=ROUND_HOLE('HOLE A',$,");
    let mut map = cncc::source::SourceMap::new();
    let id = map.add("no_workpiece.stp", text.clone());
    let r = cncc::stepnc::read_text(&text, id);
    assert!(
        r.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        r.diagnostics
    );
    let w = r
        .diagnostics
        .iter()
        .find(|d| d.message == "ROUND_HOLE.its_workpiece is mandatory but `$`")
        .expect("W0803");
    assert!(w
        .help
        .as_deref()
        .unwrap_or("")
        .contains("the project's workpiece"));
    let p = r.project.expect("a model");
    assert_eq!(p.features[0].workpiece, WorkpieceId(0));
    post(&p, "linuxcnc").expect("posts");
}
