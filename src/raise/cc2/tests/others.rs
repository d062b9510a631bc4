//! Profiles, slots, steps, open pockets, holes and what stays a
//! toolpath feature.

use super::*;
use crate::stepnc::model::*;
use crate::toolpath::Event;

#[test]
fn a_loop_around_the_other_cuts_is_an_outside_profile() {
    let mut ev = path(
        &[
            z(50.0, 30.0, 5.0),
            z(50.0, 30.0, 2.0),
            z(50.0, 30.0, -8.0),
            z(50.0, 30.0, 5.0),
        ],
        &[true, false, true],
        2,
    );
    // Clockwise round a 100 x 60 outline with a 10 mm tool.
    let mut pts = vec![z(-5.0, -5.0, 5.0), z(-5.0, -5.0, -10.0)];
    pts.extend([
        z(-5.0, 65.0, -10.0),
        z(105.0, 65.0, -10.0),
        z(105.0, -5.0, -10.0),
        z(-5.0, -5.0, -10.0),
    ]);
    ev.extend(path(&[z(50.0, 30.0, 5.0), z(-5.0, -5.0, 5.0)], &[true], 3));
    ev.extend(path(&pts, &[false; 5], 3));
    let (p, _) = run(&ev, 10.0, None);
    assert!(matches!(
        p.features[0].kind,
        FeatureKind::RoundHole {
            bottom: HoleBottom::Conical { .. },
            ..
        }
    ));
    let FeatureKind::GeneralOutsideProfile {
        boundary: Profile::Closed(ClosedProfile::Rectangular { length, width, .. }),
        ..
    } = &p.features[1].kind
    else {
        panic!("{:?}", p.features[1].kind)
    };
    assert_eq!((length.nominal, width.nominal), (100.0, 60.0));
    let OperationKind::SideMilling { milling, .. } = &op(&p, 1, 0).kind else {
        panic!()
    };
    let Some(Strategy::ContourParallel { cutmode, .. }) = &milling.strategy else {
        panic!()
    };
    assert_eq!(*cutmode, Some(CutMode::Climb));
}

#[test]
fn a_slot_through_the_stock_edge_has_an_open_end() {
    let pts = [z(-5.0, 10.0, 2.0), z(-5.0, 10.0, -3.0), z(30.0, 10.0, -3.0)];
    let (p, _) = run(
        &path(&pts, &[false; 2], 5),
        6.0,
        Some(([0.0, 0.0, -10.0], [50.0, 20.0, 0.0])),
    );
    let FeatureKind::Slot { end_conditions, .. } = &p.features[0].kind else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!(end_conditions, &[SlotEnd::Open, SlotEnd::Radiused]);
}

#[test]
fn reaming_after_drilling_is_a_second_operation_of_the_hole() {
    let drill = path(
        &[z(5.0, 5.0, 2.0), z(5.0, 5.0, -12.0), z(5.0, 5.0, 2.0)],
        &[false, true],
        2,
    );
    let ream = path(
        &[z(5.0, 5.0, 2.0), z(5.0, 5.0, -10.0), z(5.0, 5.0, 2.0)],
        &[false, false],
        2,
    );
    let mut ev = drill;
    ev.push(Event::ToolChange {
        tool: 2,
        span: Default::default(),
    });
    ev.extend(ream);
    let (p, _) = run(&ev, 8.0, None);
    assert_eq!(p.features.len(), 1);
    assert_eq!(p.features[0].operations.len(), 2);
    assert!(matches!(
        op(&p, 0, 1).kind,
        OperationKind::Boring { reaming: true, .. }
    ));
}

#[test]
fn unrecognised_moves_stay_as_a_toolpath_feature() {
    let pts = [z(0.0, 0.0, 2.0), z(10.0, 5.0, -1.0), z(20.0, 0.0, 2.0)];
    let (p, notes) = run(&path(&pts, &[false; 2], 4), 6.0, None);
    assert_eq!(notes, 1);
    assert_eq!(p.features[0].kind, FeatureKind::ToolpathFeature);
    let o = op(&p, 0, 0);
    assert!(matches!(o.kind, OperationKind::Freeform { .. }));
    let Some(tps) = &o.toolpath else { panic!() };
    let Toolpath::CutterLocation {
        basic_curve: Curve::Polyline { points, .. },
        ..
    } = &tps[0]
    else {
        panic!()
    };
    assert_eq!(points.len(), 3);
    assert_eq!(p.main_workplan.elements.len(), 1);
}

#[test]
fn unknown_tool_diameter_keeps_the_moves() {
    let ctx = Cc2Context::default();
    let mut p = Project::default();
    let pts = [z(0.0, 0.0, 2.0), z(0.0, 0.0, -1.0), z(10.0, 0.0, -1.0)];
    let notes = recognise_report(&path(&pts, &[false; 2], 7), &mut p, &|_| ToolId(0), &ctx);
    assert_eq!(notes.len(), 1);
    assert_eq!(p.features[0].kind, FeatureKind::ToolpathFeature);
}

#[test]
fn strokes_along_one_stock_edge_are_a_step() {
    // Stock 50 x 40; a 10 mm tool cuts zig-zag along X at y = 2 and 8:
    // the wall is at y = 13, the step 13 wide, 3 deep.
    let pts = [
        z(-6.0, 2.0, 2.0),
        z(-6.0, 2.0, -3.0),
        z(56.0, 2.0, -3.0),
        z(56.0, 8.0, -3.0),
        z(-6.0, 8.0, -3.0),
    ];
    let (p, notes) = run(
        &path(&pts, &[false; 4], 3),
        10.0,
        Some(([0.0, 0.0, -10.0], [50.0, 40.0, 0.0])),
    );
    assert_eq!(notes, 0);
    let f = &p.features[0];
    let FeatureKind::Step {
        open_boundary:
            TravelPath::Linear {
                distance,
                direction,
                ..
            },
        ..
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!(
        (distance.nominal, direction.ratios),
        (50.0, [1.0, 0.0, 0.0])
    );
    assert_eq!(f.placement.location.xyz, [0.0, 13.0, 0.0]);
    assert_eq!(f.depth_z(), -3.0);
}

#[test]
fn a_pocket_through_a_stock_edge_is_an_open_pocket() {
    // Stock 50 x 40; loop (20..30, -2..10) with a 4 mm tool: wall box
    // 18..32 x -4..12, open at the bottom edge y = 0.
    let mut pts = vec![z(20.0, -2.0, 2.0)];
    pts.extend(rect(20.0, -2.0, 30.0, 10.0, -2.0));
    let (p, _) = run(
        &path(&pts, &[false; 5], 3),
        4.0,
        Some(([0.0, 0.0, -10.0], [50.0, 40.0, 0.0])),
    );
    let f = &p.features[0];
    let FeatureKind::OpenPocket {
        open_boundary:
            OpenProfile::General {
                shape: Curve::Polyline { points, .. },
                ..
            },
        pocket,
        ..
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!(f.placement.location.xyz, [25.0, 6.0, 0.0]);
    let xy: Vec<[f64; 2]> = points.iter().map(|p| [p.xyz[0], p.xyz[1]]).collect();
    assert_eq!(xy, [[7.0, -6.0], [7.0, 6.0], [-7.0, 6.0], [-7.0, -6.0]]);
    assert_eq!(
        pocket.orthogonal_radius.as_ref().map(|r| r.nominal),
        Some(2.0)
    );
}

#[test]
fn side_passes_widen_a_slot_and_a_later_pass_finishes_it() {
    // Rough: 6 mm tool, passes at y = 9.5 and 10.5 (width 7), 2 deep;
    // finish: passes at y = 9 and 11 (width 8), 2.2 deep, other feed.
    let pass = |y0: f64, y1: f64, zz: f64, feed: f64| {
        let pts = [
            z(20.0, y0, 2.0),
            z(20.0, y0, zz),
            z(60.0, y0, zz),
            z(60.0, y1, zz),
            z(20.0, y1, zz),
            z(20.0, y1, 2.0),
        ];
        let mut ev = path(&pts, &[false, false, false, false, true], 5);
        for e in ev.iter_mut() {
            if let Event::Move(m) = e {
                m.feed = feed;
            }
        }
        ev.extend(path(&[z(20.0, y1, 2.0), z(0.0, 0.0, 2.0)], &[true], 5));
        ev
    };
    let mut ev = pass(9.5, 10.5, -2.0, 400.0);
    ev.extend(pass(9.0, 11.0, -2.2, 200.0));
    let (p, notes) = run(&ev, 6.0, None);
    assert_eq!(notes, 0);
    assert_eq!(
        p.features.len(),
        1,
        "{}",
        crate::raise::cc2::listing::listing(&p)
    );
    let f = &p.features[0];
    assert_eq!(f.placement.location.xyz, [20.0, 10.0, 0.0]);
    let FeatureKind::Slot {
        course_of_travel: TravelPath::Linear { distance, .. },
        swept_shape: OpenProfile::SquareU { width, .. },
        ..
    } = &f.kind
    else {
        panic!("{:?}", f.kind)
    };
    assert_eq!((distance.nominal, width.nominal), (40.0, 8.0));
    assert_eq!(f.depth_z(), -2.2);
    let OperationKind::BottomAndSideMilling {
        finish: false,
        allowance_side,
        allowance_bottom,
        milling,
        ..
    } = &op(&p, 0, 0).kind
    else {
        panic!()
    };
    assert_eq!((*allowance_side, *allowance_bottom), (Some(0.5), Some(0.2)));
    assert!(
        matches!(milling.strategy, Some(Strategy::Bidirectional { .. })),
        "{:?}",
        milling.strategy
    );
    assert!(matches!(
        op(&p, 0, 1).kind,
        OperationKind::BottomAndSideMilling { finish: true, .. }
    ));
}

#[test]
fn a_second_loop_closer_in_finishes_the_outside_profile() {
    let mut ev = path(
        &[
            z(50.0, 30.0, 5.0),
            z(50.0, 30.0, 2.0),
            z(50.0, 30.0, -8.0),
            z(50.0, 30.0, 5.0),
        ],
        &[true, false, true],
        2,
    );
    for (off, feed) in [(5.3, 500.0), (5.0, 300.0)] {
        let (a, b, c, d) = (-off, -off, 100.0 + off, 60.0 + off);
        let mut pts = vec![z(a, b, 5.0), z(a, b, -10.0)];
        pts.extend([
            z(a, d, -10.0),
            z(c, d, -10.0),
            z(c, b, -10.0),
            z(a, b, -10.0),
        ]);
        ev.extend(path(&[z(50.0, 30.0, 5.0), z(a, b, 5.0)], &[true], 3));
        let mut lp = path(&pts, &[false; 5], 3);
        for e in lp.iter_mut() {
            if let Event::Move(m) = e {
                m.feed = feed;
            }
        }
        ev.extend(lp);
        ev.extend(path(&[z(a, b, -10.0), z(a, b, 5.0)], &[true], 3));
    }
    let (p, notes) = run(&ev, 10.0, None);
    assert_eq!(notes, 0);
    assert_eq!(
        p.features.len(),
        2,
        "{}",
        crate::raise::cc2::listing::listing(&p)
    );
    let FeatureKind::GeneralOutsideProfile {
        boundary: Profile::Closed(ClosedProfile::Rectangular { length, .. }),
        ..
    } = &p.features[1].kind
    else {
        panic!("{:?}", p.features[1].kind)
    };
    assert_eq!(length.nominal, 100.0);
    let OperationKind::SideMilling {
        finish: false,
        allowance_side,
        ..
    } = &op(&p, 1, 0).kind
    else {
        panic!("{}", crate::raise::cc2::listing::listing(&p))
    };
    assert_eq!(*allowance_side, Some(0.3));
    assert!(matches!(
        op(&p, 1, 1).kind,
        OperationKind::SideMilling { finish: true, .. }
    ));
}

#[test]
fn spindle_stopped_at_the_bottom_is_boring_a_dwell_and_rapid_out_is_drilling() {
    let mut ev = path(&[z(5.0, 5.0, 2.0), z(5.0, 5.0, -10.0)], &[false], 6);
    let mut out = path(&[z(5.0, 5.0, -10.0), z(5.0, 5.0, 2.0)], &[true], 6);
    if let Event::Move(m) = &mut out[0] {
        m.spindle = 0.0;
    }
    ev.extend(out);
    ev.extend(path(
        &[z(5.0, 5.0, 2.0), z(25.0, 5.0, 2.0), z(25.0, 5.0, -4.0)],
        &[true, false],
        6,
    ));
    ev.push(Event::Dwell {
        seconds: 1.5,
        span: Default::default(),
    });
    ev.extend(path(&[z(25.0, 5.0, -4.0), z(25.0, 5.0, 2.0)], &[true], 6));
    let (p, _) = run(&ev, 12.0, None);
    assert!(matches!(
        op(&p, 0, 0).kind,
        OperationKind::Boring {
            reaming: false,
            spindle_stop_at_bottom: true,
            ..
        }
    ));
    let OperationKind::Drilling(d) = &op(&p, 1, 0).kind else {
        panic!("{:?}", op(&p, 1, 0).kind)
    };
    assert_eq!(d.dwell_time_bottom, Some(1.5));
}

#[test]
fn tapping_is_a_round_hole_with_a_tapping_operation() {
    let mut ev = path(
        &[z(5.0, 5.0, 2.0), z(5.0, 5.0, -10.0), z(5.0, 5.0, 2.0)],
        &[false, false],
        7,
    );
    if let Event::Move(m) = &mut ev[1] {
        m.spindle = -m.spindle;
    }
    let (p, notes) = run(&ev, 6.0, None);
    assert_eq!(notes, 0);
    let FeatureKind::RoundHole {
        diameter, bottom, ..
    } = &p.features[0].kind
    else {
        panic!("{:?}", p.features[0].kind)
    };
    assert_eq!((diameter.nominal, bottom), (6.0, &HoleBottom::Flat));
    let o = op(&p, 0, 0);
    assert!(matches!(
        o.kind,
        OperationKind::Tapping {
            compensation_chuck: false,
            ..
        }
    ));
    assert!(o.technology.synchronize_spindle_with_feed);
    // The tool's kind and hand: tests/tapping.rs (no tools here).
}

/// Thousands of holes and a cut with tens of thousands of levels are
/// raised in time close to linear (a loose bound: the test would take
/// minutes if any step were quadratic).
#[test]
fn large_programs_raise_quickly() {
    let mut ev = Vec::new();
    for i in 0..20_000 {
        let (x, y) = ((i % 200) as f64 * 2.0, (i / 200) as f64 * 2.0);
        ev.extend(path(
            &[z(x, y, 2.0), z(x, y, -3.0), z(x, y, 2.0)],
            &[false, true],
            2,
        ));
        ev.extend(path(&[z(x, y, 2.0), z(x + 1.0, y + 0.5, 2.0)], &[true], 2));
    }
    ev.push(Event::ToolChange {
        tool: 3,
        span: Default::default(),
    });
    // 25000 levels 1 µm apart, one pass each, back and forth.
    let x = |i: usize| {
        if (i / 2).is_multiple_of(2) {
            [0.0, 10.0][i % 2]
        } else {
            [10.0, 0.0][i % 2]
        }
    };
    let pts: Vec<[f64; 3]> = (0..50_000)
        .map(|i| z(x(i), 0.0, -((i / 2) as f64) * 1e-3))
        .collect();
    ev.extend(path(&pts, &vec![false; pts.len() - 1], 3));
    let start = std::time::Instant::now();
    let (p, notes) = run(&ev, 1.0, None);
    let took = start.elapsed();
    eprintln!("raised {} features in {took:?}", p.features.len());
    assert_eq!(p.features.len(), 20_001);
    assert_eq!(notes, 0);
    assert!(matches!(p.features[20_000].kind, FeatureKind::Slot { .. }));
    assert!(took.as_secs() < 20, "{took:?}");
}

#[test]
fn a_hole_drilled_in_a_pocket_floor_starts_there() {
    let zz = -4.0;
    let mut pts = vec![z(10.0, 10.0, 2.0)];
    pts.extend(rect(10.0, 10.0, 30.0, 20.0, zz));
    let mut ev = path(&pts, &[false; 5], 3);
    ev.push(Event::ToolChange {
        tool: 2,
        span: Default::default(),
    });
    ev.extend(path(
        &[
            z(20.0, 15.0, -2.0),
            z(20.0, 15.0, -12.0),
            z(20.0, 15.0, 2.0),
        ],
        &[false, true],
        2,
    ));
    let (p, _) = run(&ev, 4.0, Some(([0.0, 0.0, -10.0], [50.0, 40.0, 0.0])));
    let hole = &p.features[1];
    assert_eq!(hole.placement.location.xyz, [20.0, 15.0, -4.0]);
    assert!(matches!(
        hole.kind,
        FeatureKind::RoundHole {
            bottom: HoleBottom::Through,
            ..
        }
    ));
    assert_eq!(hole.depth_z(), -6.0);
    assert_eq!(op(&p, 1, 0).retract_plane, Some(2.0));
}
