//! The scene's simplification: shape kept, detail below the pixel dropped.

use super::*;
use crate::plot::layer::dist;
use crate::toolpath::{CoolantState, FeedMode};

fn line(from: P3, to: P3) -> Event {
    Event::Move(Move {
        kind: MoveKind::Line,
        from,
        to,
        feed: 100.0,
        feed_mode: FeedMode::PerMinute,
        tool: 1,
        spindle: 1000.0,
        coolant: CoolantState::default(),
        span: Default::default(),
    })
}

fn scene_of(points: &[P3]) -> Scene {
    let mut b = Bounds::default();
    b.add([0.0, 0.0, -1.0]);
    b.add([100.0, 100.0, 1.0]);
    let mut s = Scene::new(vec![View::Top], 600.0, b);
    for w in points.windows(2) {
        s.push(0, &line(w[0], w[1]));
    }
    s.finish();
    s
}

fn segs(s: &Scene) -> &[Seg] {
    &s.layers.values().next().unwrap().segs
}

#[test]
fn many_collinear_moves_become_one_line() {
    let pts: Vec<P3> = (0..=10_000).map(|i| [i as f64 / 100.0, 5.0, 0.0]).collect();
    let s = scene_of(&pts);
    assert_eq!(segs(&s), &[Seg::Move((0.0, 5.0)), Seg::Line((100.0, 5.0))]);
}

#[test]
fn a_finely_divided_circle_keeps_its_shape() {
    let pts: Vec<P3> = (0..=20_000)
        .map(|i| {
            let a = i as f64 / 20_000.0 * std::f64::consts::TAU;
            [50.0 + 40.0 * a.cos(), 50.0 + 40.0 * a.sin(), 0.0]
        })
        .collect();
    let s = scene_of(&pts);
    let kept: Vec<Pt> = segs(&s)
        .iter()
        .map(|g| match g {
            Seg::Move(p) | Seg::Line(p) => *p,
            other => panic!("{other:?}"),
        })
        .collect();
    assert!(kept.len() < 400, "{} points kept", kept.len());
    // Every original point lies within half a pixel of the drawn path.
    let half_px = s.half_px;
    for p in &pts {
        let q = (p[0], p[1]);
        let near = kept.windows(2).any(|w| {
            let (a, b) = (w[0], w[1]);
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let t = (((q.0 - a.0) * dx + (q.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
            dist(q, (a.0 + t * dx, a.1 + t * dy)) <= half_px
        });
        assert!(near, "{q:?} lost");
    }
}

#[test]
fn the_scale_only_falls_as_the_box_grows() {
    let views = [View::Top, View::Side, View::Iso];
    let mut b = Bounds::default();
    let mut last = f64::INFINITY;
    for p in [
        [0.0, 0.0, 0.0],
        [0.3, 0.0, 0.0],
        [5.0, 1.0, -2.0],
        [200.0, 3.0, 0.0],
        [10.0, 900.0, 40.0],
    ] {
        b.add(p);
        let s = Layout::scale(&views, &b, 1200.0);
        assert!(s <= last, "{s} > {last}");
        last = s;
    }
}
