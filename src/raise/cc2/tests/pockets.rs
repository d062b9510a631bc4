//! Closed pockets: circles, contours with strokes, polygons, spirals.

use super::*;
use crate::stepnc::model::*;
use crate::toolpath::Event;

#[test]
fn concentric_circles_are_a_circular_pocket_cut_clockwise() {
    let mut ev = path(&[z(52.0, 50.0, 2.0), z(52.0, 50.0, -3.0)], &[false], 3);
    ev.push(circle([50.0, 50.0], z(52.0, 50.0, -3.0), false, 3));
    ev.extend(path(
        &[z(52.0, 50.0, -3.0), z(56.0, 50.0, -3.0)],
        &[false],
        3,
    ));
    ev.push(circle([50.0, 50.0], z(56.0, 50.0, -3.0), false, 3));
    let (p, _) = run(&ev, 6.0, None);
    let FeatureKind::ClosedPocket {
        boundary: ClosedProfile::Circular { diameter, .. },
        ..
    } = &p.features[0].kind
    else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!(diameter.nominal, 18.0);
    assert_eq!(p.features[0].placement.location.xyz, [50.0, 50.0, 0.0]);
    let OperationKind::BottomAndSideMilling {
        milling,
        radial_cutting_depth,
        ..
    } = &op(&p, 0, 0).kind
    else {
        panic!()
    };
    assert_eq!(*radial_cutting_depth, Some(4.0));
    assert_eq!(
        milling.strategy,
        Some(Strategy::ContourParallel {
            base: StrategyBase::default(),
            rotation: Some(RotDirection::Cw),
            cutmode: Some(CutMode::Conventional)
        })
    );
}

#[test]
fn strokes_inside_a_contour_are_bidirectional_contour() {
    let zz = -2.0;
    let mut pts = vec![
        z(12.0, 12.0, 2.0),
        z(12.0, 12.0, zz),
        z(28.0, 12.0, zz),
        z(28.0, 16.0, zz),
        z(12.0, 16.0, zz),
    ];
    pts.extend(rect(10.0, 10.0, 30.0, 20.0, zz));
    let n = pts.len() - 1;
    let (p, _) = run(&path(&pts, &vec![false; n], 3), 4.0, None);
    let OperationKind::BottomAndSideMilling { milling, .. } = &op(&p, 0, 0).kind else {
        panic!()
    };
    assert!(
        matches!(
            milling.strategy,
            Some(Strategy::BidirectionalContour {
                contour_first: false,
                ..
            })
        ),
        "{:?}",
        milling.strategy
    );
    let FeatureKind::ClosedPocket {
        boundary: ClosedProfile::Rectangular { length, width, .. },
        ..
    } = &p.features[0].kind
    else {
        panic!()
    };
    assert_eq!((length.nominal, width.nominal), (24.0, 14.0));
}

#[test]
fn a_triangle_loop_is_a_general_pocket() {
    let zz = -1.0;
    let pts = [
        z(0.0, 0.0, 2.0),
        z(0.0, 0.0, zz),
        z(30.0, 0.0, zz),
        z(0.0, 30.0, zz),
        z(0.0, 0.0, zz),
    ];
    let (p, _) = run(&path(&pts, &[false; 4], 3), 2.0, None);
    let FeatureKind::ClosedPocket {
        boundary:
            ClosedProfile::General {
                shape: Curve::Polyline { points, .. },
                ..
            },
        ..
    } = &p.features[0].kind
    else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!(points.len(), 4);
}

#[test]
fn a_growing_spiral_is_a_pocket_with_contour_spiral() {
    use crate::toolpath::{ArcGeom, MoveKind};
    let zz = -2.0;
    let mut ev = path(&[z(51.0, 50.0, 2.0), z(51.0, 50.0, zz)], &[false], 3);
    let halves = [
        (50.0, 51.0, 49.0),
        (50.5, 49.0, 52.0),
        (50.0, 52.0, 48.0),
        (50.5, 48.0, 53.0),
    ];
    for (cx, x0, x1) in halves {
        let geom = ArcGeom {
            axes: [0, 1, 2],
            centre: [cx, 50.0, zz],
            rotation: 1,
        };
        ev.push(Event::Move(crate::raise::cc2::segment::tests::mv(
            MoveKind::Arc(geom),
            z(x0, 50.0, zz),
            z(x1, 50.0, zz),
            3,
        )));
    }
    let strategy = |p: &Project| {
        let OperationKind::BottomAndSideMilling { milling, .. } = &op(p, 0, 0).kind else {
            panic!()
        };
        milling.strategy.clone()
    };
    // The spiral alone: its box (5 x 4.5: the last half turn is below).
    let (p, notes) = run(&ev, 2.0, None);
    assert_eq!(notes, 0);
    let FeatureKind::ClosedPocket {
        boundary: ClosedProfile::Rectangular { length, width, .. },
        ..
    } = &p.features[0].kind
    else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!((length.nominal, width.nominal), (7.0, 6.5));
    assert!(matches!(
        strategy(&p),
        Some(Strategy::ContourSpiral {
            rotation: Some(RotDirection::Ccw),
            ..
        })
    ));
    // Ending in a full circle: a circular pocket.
    ev.push(circle([50.5, 50.0], z(53.0, 50.0, zz), true, 3));
    let (p, _) = run(&ev, 2.0, None);
    let FeatureKind::ClosedPocket {
        boundary: ClosedProfile::Circular { diameter, .. },
        ..
    } = &p.features[0].kind
    else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!(diameter.nominal, 7.0);
    assert!(
        matches!(
            strategy(&p),
            Some(Strategy::ContourSpiral {
                cutmode: Some(CutMode::Climb),
                ..
            })
        ),
        "{:?}",
        strategy(&p)
    );
}
