//! Planar faces: strategies, rough and finish passes.

use super::*;
use crate::stepnc::model::*;
use crate::toolpath::Event;

#[test]
fn one_way_strokes_over_the_stock_are_a_unidirectional_face() {
    let mut ev = Vec::new();
    for y in [0.0, 8.0, 16.0] {
        ev.extend(path(
            &[
                z(-6.0, y, 5.0),
                z(-6.0, y, 0.0),
                z(56.0, y, 0.0),
                z(56.0, y, 5.0),
                z(-6.0, y + 8.0, 5.0),
            ],
            &[true, false, false, true, true],
            1,
        ));
    }
    let (p, notes) = run(&ev, 10.0, Some(([0.0, 0.0, -10.0], [50.0, 16.0, 0.5])));
    assert_eq!(notes, 0);
    assert_eq!(p.features.len(), 1);
    assert!(matches!(p.features[0].kind, FeatureKind::PlanarFace { .. }));
    let OperationKind::PlaneMilling { milling, .. } = &op(&p, 0, 0).kind else {
        panic!()
    };
    let Some(Strategy::Unidirectional {
        feed_direction: Some(d),
        ..
    }) = &milling.strategy
    else {
        panic!("{:?}", milling.strategy)
    };
    assert_eq!(d.ratios, [1.0, 0.0, 0.0]);
}

#[test]
fn a_second_face_pass_finishes_and_the_first_leaves_its_allowance() {
    let face = |zz: f64, feed: f64| {
        let mut pts = vec![z(-6.0, 0.0, 5.0)];
        for (i, y) in [0.0, 8.0, 16.0].iter().enumerate() {
            let (x0, x1) = if i % 2 == 0 {
                (-6.0, 56.0)
            } else {
                (56.0, -6.0)
            };
            pts.push(z(x0, *y, zz));
            pts.push(z(x1, *y, zz));
        }
        let n = pts.len() - 1;
        let mut ev = path(&pts, &vec![false; n], 1);
        for e in ev.iter_mut() {
            if let Event::Move(m) = e {
                m.feed = feed;
            }
        }
        ev.extend(path(
            &[z(-6.0, 16.0, zz), z(-6.0, 16.0, 5.0), z(-6.0, 0.0, 5.0)],
            &[true, true],
            1,
        ));
        ev
    };
    let mut ev = face(0.5, 1000.0);
    ev.extend(face(0.0, 600.0));
    let (p, _) = run(&ev, 10.0, Some(([0.0, 0.0, -10.0], [50.0, 16.0, 1.0])));
    assert_eq!(p.features.len(), 1);
    assert_eq!(p.features[0].depth_z(), -1.0);
    let OperationKind::PlaneMilling {
        finish: false,
        allowance_bottom: Some(a),
        ..
    } = op(&p, 0, 0).kind
    else {
        panic!()
    };
    assert_eq!(a, 0.5);
    assert!(matches!(
        op(&p, 0, 1).kind,
        OperationKind::PlaneMilling { finish: true, .. }
    ));
}

#[test]
fn one_pass_of_a_wide_cutter_is_a_face_strokes_too_far_apart_are_not() {
    let stock = Some(([0.0, 0.0, -10.0], [50.0, 30.0, 1.0]));
    let one = path(
        &[
            z(-60.0, 15.0, 5.0),
            z(-60.0, 15.0, 0.0),
            z(110.0, 15.0, 0.0),
        ],
        &[false; 2],
        1,
    );
    let (p, notes) = run(&one, 50.0, stock);
    assert_eq!(notes, 0);
    assert!(
        matches!(p.features[0].kind, FeatureKind::PlanarFace { .. }),
        "{:?}",
        p.features[0].kind
    );
    let OperationKind::PlaneMilling { milling, .. } = &op(&p, 0, 0).kind else {
        panic!()
    };
    assert!(matches!(
        milling.strategy,
        Some(Strategy::Unidirectional { .. })
    ));
    // A 10 mm tool with strokes 12 mm apart leaves ridges: no face.
    let pts = [
        z(-6.0, -2.0, 0.0),
        z(56.0, -2.0, 0.0),
        z(56.0, 10.0, 0.0),
        z(-6.0, 10.0, 0.0),
        z(-6.0, 22.0, 0.0),
        z(56.0, 22.0, 0.0),
        z(56.0, 34.0, 0.0),
        z(-6.0, 34.0, 0.0),
    ];
    let (p, _) = run(&path(&pts, &[false; 7], 1), 10.0, stock);
    assert!(!matches!(
        p.features[0].kind,
        FeatureKind::PlanarFace { .. }
    ));
}

#[test]
fn the_course_of_a_face_does_not_depend_on_the_feed_direction() {
    let stock = Some(([0.0, 0.0, -10.0], [50.0, 16.0, 0.5]));
    let pts = [
        z(56.0, 0.0, 0.0),
        z(-6.0, 0.0, 0.0),
        z(-6.0, 8.0, 0.0),
        z(56.0, 8.0, 0.0),
        z(56.0, 16.0, 0.0),
        z(-6.0, 16.0, 0.0),
    ];
    let (p, _) = run(&path(&pts, &[false; 5], 1), 10.0, stock);
    let FeatureKind::PlanarFace {
        course_of_travel: TravelPath::Linear { direction, .. },
        ..
    } = &p.features[0].kind
    else {
        panic!()
    };
    assert_eq!(direction.ratios, [1.0, 0.0, 0.0]);
    let OperationKind::PlaneMilling { milling, .. } = &op(&p, 0, 0).kind else {
        panic!()
    };
    let Some(Strategy::Bidirectional {
        feed_direction: Some(f),
        stepover_direction,
        ..
    }) = &milling.strategy
    else {
        panic!()
    };
    assert_eq!(
        (f.ratios, *stepover_direction),
        ([-1.0, 0.0, 0.0], Some(LeftOrRight::Right))
    );
}
