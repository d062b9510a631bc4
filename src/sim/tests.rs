use super::*;
use crate::toolpath::{ArcGeom, CoolantState, Stock};

fn mv(kind: MoveKind, from: P3, to: P3) -> Event {
    Event::Move(Move {
        kind,
        from,
        to,
        feed: 100.0,
        feed_mode: FeedMode::PerMinute,
        tool: 1,
        spindle: 1000.0,
        coolant: CoolantState::default(),
        span: Span::default(),
    })
}

fn sim(stock: &str, cell: f64, radius: f64) -> Simulation {
    let s: Stock = stock.parse().unwrap();
    let mut cutters = Cutters::default();
    cutters.by_tool.insert(1, Cutter::flat(radius));
    Simulation::new(HeightField::new(&s, cell).unwrap(), cutters)
}

#[test]
fn a_full_circle_cuts_an_annulus() {
    let mut s = sim("40x40x10-20-20-10", 0.05, 2.0);
    let arc = ArcGeom {
        axes: [0, 1, 2],
        centre: [0.0, 0.0, -1.0],
        rotation: 1,
    };
    s.push(&mv(
        MoveKind::Arc(arc),
        [10.0, 0.0, -1.0],
        [10.0, 0.0, -1.0],
    ));
    let exact = std::f64::consts::PI * (144.0 - 64.0);
    assert!(
        (s.removed() - exact).abs() / exact < 0.005,
        "{}",
        s.removed()
    );
    assert!((s.tools[0].feed_minutes - 20.0 * std::f64::consts::PI / 100.0).abs() < 1e-9);
}

#[test]
fn a_rapid_into_the_stock_is_a_hit_and_one_in_the_cut_is_not() {
    let mut s = sim("40x40x10-20-20-10", 0.1, 3.0);
    s.check_rapids = true;
    s.push(&mv(MoveKind::Line, [-10.0, 0.0, -2.0], [10.0, 0.0, -2.0]));
    s.push(&mv(MoveKind::Rapid, [10.0, 0.0, -2.0], [-10.0, 0.0, -2.0]));
    assert!(s.rapid_hits.is_empty(), "{:?}", s.rapid_hits);
    s.push(&mv(
        MoveKind::Rapid,
        [-10.0, 0.0, -2.0],
        [-10.0, 10.0, -2.0],
    ));
    assert_eq!(s.rapid_hits.len(), 1);
    assert!((s.rapid_hits[0].depth - 2.0).abs() < 1e-6);
}
