//! Look-ahead across moves against analytic answers: collinear moves run
//! as one, a corner is passed at the junction deviation model's speed
//! (`√(a·δ·sin(θ/2)/(1 − sin(θ/2)))`), tolerance 0 and a reversal stop,
//! a chain of short moves reaches the feed within a long enough window,
//! the path acceleration never passes its limit, and the set-points stay
//! on the path with exact pulse sums.

mod common;

use cncc::interpolate::{Interpolator, Sample, Settings};
use cncc::span::{FileId, Span};
use cncc::toolpath::{ArcGeom, CoolantState, Event, FeedMode, Move, MoveKind, P3};

fn mv(kind: MoveKind, from: P3, to: P3, feed: f64) -> Event {
    Event::Move(Move {
        kind,
        from,
        to,
        feed,
        feed_mode: FeedMode::PerMinute,
        tool: 1,
        spindle: 1000.0,
        coolant: CoolantState::default(),
        span: Span::new(FileId(0), 0, 0),
    })
}

fn line(from: P3, to: P3, feed: f64) -> Event {
    mv(MoveKind::Line, from, to, feed)
}

fn run(settings: Settings, events: &[Event]) -> (Vec<Sample>, f64) {
    let mut samples = Vec::new();
    let mut it = Interpolator::new(settings, |s: &Sample| samples.push(*s));
    for e in events {
        it.push(e);
    }
    assert!(it.error.is_none());
    let t = it.finish();
    (samples, t)
}

/// a = 500 mm/s², 1 ms, look-ahead 64, corner tolerance `delta`.
fn with(delta: f64) -> Settings {
    Settings {
        accel: 500.0,
        corner_tolerance: delta,
        ..Settings::default()
    }
}

fn close(got: f64, want: f64) {
    assert!((got - want).abs() / want < 1e-3, "{got} against {want}");
}

/// The time of a move of `len` mm at `v` mm/s entered at `v0` and left at
/// `v1`, acceleration `a`, when it reaches `v`.
fn trapezoid_time(len: f64, v0: f64, v: f64, v1: f64, a: f64) -> f64 {
    let (d0, d1) = ((v * v - v0 * v0) / (2.0 * a), (v * v - v1 * v1) / (2.0 * a));
    assert!(d0 + d1 <= len);
    (v - v0) / a + (v - v1) / a + (len - d0 - d1) / v
}

/// The slowest set-point within `window` s of `t`, mm/s.
fn slowest_near(samples: &[Sample], t: f64, window: f64) -> f64 {
    samples
        .iter()
        .filter(|s| (s.time - t).abs() <= window)
        .map(|s| s.speed / 60.0)
        .fold(f64::INFINITY, f64::min)
}

fn fastest(samples: &[Sample]) -> f64 {
    samples.iter().map(|s| s.speed / 60.0).fold(0.0, f64::max)
}

#[test]
fn two_collinear_moves_run_as_one() {
    // 50 + 50 mm at 50 mm/s, 500 mm/s²: the single 100 mm move's 2.1 s.
    let ev = [
        line([0.0; 3], [50.0, 0.0, 0.0], 3000.0),
        line([50.0, 0.0, 0.0], [100.0, 0.0, 0.0], 3000.0),
    ];
    let (samples, t) = run(with(0.0), &ev);
    close(t, 2.1);
    assert!(slowest_near(&samples, 1.05, 0.01) > 49.999);
    // Without look-ahead each stops: 2 × (50/50 + 0.1) s.
    let off = Settings {
        lookahead: 0,
        ..with(0.0)
    };
    close(run(off, &ev).1, 2.2);
    // Jerk-limited: the single move's 2.2 s (ramps of 0.2 s over 5 mm).
    let jerk = Settings {
        jerk: 5000.0,
        ..with(0.0)
    };
    let (samples, t) = run(jerk, &ev);
    close(t, 2.2);
    assert!(slowest_near(&samples, 1.1, 0.01) > 49.999);
}

#[test]
fn a_square_corner_with_tolerance_zero_stops() {
    let ev = [
        line([0.0; 3], [50.0, 0.0, 0.0], 3000.0),
        line([50.0, 0.0, 0.0], [50.0, 50.0, 0.0], 3000.0),
    ];
    let (samples, t) = run(with(0.0), &ev);
    close(t, 2.2);
    // At the corner (1.1 s) the speed is zero: within one period of it,
    // no more than a·period.
    assert!(slowest_near(&samples, 1.1, 0.0011) <= 500.0 * 0.001 + 1e-9);
}

#[test]
fn a_corner_is_passed_at_the_junction_deviation_speed() {
    let (a, v, len) = (500.0, 50.0, 50.0);
    for (turn_deg, delta) in [(90.0f64, 0.05), (30.0, 0.05), (90.0, 0.2), (135.0, 0.5)] {
        let turn = turn_deg.to_radians();
        let (c, s) = (turn.cos(), turn.sin());
        let corner = [len, 0.0, 0.0];
        let end = [len + len * c, len * s, 0.0];
        let ev = [line([0.0; 3], corner, 3000.0), line(corner, end, 3000.0)];
        // θ = 180° − turn; sin(θ/2) = cos(turn/2).
        let k = (turn / 2.0).cos();
        let vj = (a * delta * k / (1.0 - k)).sqrt();
        assert!(vj < v);
        let (samples, t) = run(with(delta), &ev);
        let t1 = trapezoid_time(len, 0.0, v, vj, a);
        close(t, 2.0 * t1);
        // The slowest point near the corner is the junction speed (to
        // a·period).
        let slow = slowest_near(&samples, t1, 0.0011);
        assert!(
            (slow - vj).abs() <= a * 0.001 + 1e-9,
            "{turn_deg}°: {slow} against {vj}"
        );
    }
}

#[test]
fn a_reversal_stops() {
    let ev = [
        line([0.0; 3], [50.0, 0.0, 0.0], 3000.0),
        line([50.0, 0.0, 0.0], [0.0, 0.0, 0.0], 3000.0),
    ];
    let (samples, t) = run(with(1.0), &ev);
    close(t, 2.2);
    assert!(slowest_near(&samples, 1.1, 0.0011) <= 0.5 + 1e-9);
}

#[test]
fn a_long_chain_of_short_moves_reaches_the_feed() {
    // 1000 collinear moves of 0.1 mm at 50 mm/s, 500 mm/s²: with 64 moves
    // (6.4 mm) of look-ahead the stopping distance (2.5 mm) fits, so the
    // run is the single 100 mm move's 2.1 s.
    let ev: Vec<Event> = (0..1000)
        .map(|i| {
            let x = i as f64 * 0.1;
            line([x, 0.0, 0.0], [x + 0.1, 0.0, 0.0], 3000.0)
        })
        .collect();
    let (samples, t) = run(with(0.01), &ev);
    close(t, 2.1);
    assert!((fastest(&samples) - 50.0).abs() < 1e-9);
    // A window of 8 moves (0.8 mm) caps the speed: the move run must end
    // where 8 moves can stop, √(2·a·8·0.1), and peaks within a move at
    // most √(v² + a·0.1).
    let short = Settings {
        lookahead: 8,
        ..with(0.01)
    };
    let (samples, _) = run(short, &ev);
    let cap = (2.0 * 500.0 * 8.5 * 0.1f64).sqrt();
    assert!(fastest(&samples) <= cap + 1e-9, "{}", fastest(&samples));
    assert!(fastest(&samples) > (2.0 * 500.0 * 8.0 * 0.1f64).sqrt() - 1e-6);
    // No look-ahead: 1000 triangles of 2·√(0.1/500) s.
    let off = Settings {
        lookahead: 0,
        ..with(0.01)
    };
    close(run(off, &ev).1, 1000.0 * 2.0 * (0.1f64 / 500.0).sqrt());
}

#[test]
fn a_slower_move_is_slowed_for_before_it_starts() {
    // 50 mm at 50 mm/s then 50 mm at 20 mm/s, collinear: the first move
    // slows to 20 mm/s by its end (0.06 s over 2.1 mm); the second runs
    // at 20 mm/s and stops (0.04 s over 0.4 mm).
    let ev = [
        line([0.0; 3], [50.0, 0.0, 0.0], 3000.0),
        line([50.0, 0.0, 0.0], [100.0, 0.0, 0.0], 1200.0),
    ];
    let (samples, t) = run(with(0.01), &ev);
    let t1 = trapezoid_time(50.0, 0.0, 50.0, 20.0, 500.0);
    close(t, t1 + trapezoid_time(50.0, 20.0, 20.0, 0.0, 500.0));
    assert!(samples
        .iter()
        .filter(|s| s.position.x >= 50.0)
        .all(|s| s.speed <= 1200.0 + 1e-9));
}

/// A zigzag of lines at several angles and feeds, an arc and short
/// moves.
fn mixed() -> Vec<Event> {
    let pts: [P3; 9] = [
        [0.0, 0.0, 0.0],
        [30.0, 0.0, 0.0],
        [31.0, 0.5, 0.0],
        [31.2, 0.6, -1.0],
        [10.0, 20.0, -1.0],
        [10.0, 20.3, -1.0],
        [40.0, 20.3, 2.0],
        [40.0, 20.3, 2.0],
        [-5.0, 3.0, 2.0],
    ];
    let mut ev: Vec<Event> = pts
        .windows(2)
        .enumerate()
        .map(|(i, w)| line(w[0], w[1], [3000.0, 900.0, 4000.0][i % 3]))
        .collect();
    let g = ArcGeom {
        axes: [0, 1, 2],
        centre: [-5.0, 13.0, 2.0],
        rotation: 1,
    };
    ev.push(mv(
        MoveKind::Arc(g),
        [-5.0, 3.0, 2.0],
        [-5.0, 23.0, 2.0],
        2000.0,
    ));
    ev.push(line([-5.0, 23.0, 2.0], [-25.0, 23.0, 2.0], 2000.0));
    ev
}

#[test]
fn the_path_acceleration_never_passes_its_limit() {
    for jerk in [0.0, 4000.0] {
        for delta in [0.0, 0.01, 0.5] {
            let s = Settings {
                jerk,
                ..with(delta)
            };
            let (samples, _) = run(s, &mixed());
            let v: Vec<f64> = samples.iter().map(|s| s.speed / 60.0).collect();
            for w in v.windows(2) {
                let acc = (w[1] - w[0]) / 0.001;
                assert!(
                    acc.abs() <= 500.0 * (1.0 + 1e-9) + 1e-6,
                    "{jerk} {delta}: {acc}"
                );
            }
            if jerk > 0.0 {
                for w in v.windows(3) {
                    let j = (w[2] - 2.0 * w[1] + w[0]) / 1e-6;
                    assert!(j.abs() <= jerk * 1.01, "{delta}: jerk {j}");
                }
            }
            // The speed never passes the fastest feed, and the run ends
            // at rest.
            assert!(v.iter().all(|&x| x <= 4000.0 / 60.0 + 1e-9));
            assert_eq!(v.last().copied(), Some(0.0));
        }
    }
}

#[test]
fn set_points_stay_on_the_path_and_pulses_sum_exactly() {
    // The lines of the mixed program at BLU 0.001: each grid point is
    // within 0.707 BLU of one of the lines (the path is not rounded at
    // corners), and the pulses sum to the displacement.
    let ev: Vec<Event> = mixed()
        .into_iter()
        .filter(|e| matches!(e, Event::Move(m) if m.kind == MoveKind::Line))
        .collect();
    let segs: Vec<(P3, P3)> = ev
        .iter()
        .map(|e| match e {
            Event::Move(m) => (m.from, m.to),
            _ => unreachable!(),
        })
        .collect();
    // The arc is left out: join its ends by a line.
    let mut ev = ev;
    ev.insert(8, line([-5.0, 3.0, 2.0], [-5.0, 23.0, 2.0], 2000.0));
    let mut segs = segs;
    segs.push(([-5.0, 3.0, 2.0], [-5.0, 23.0, 2.0]));
    let (samples, _) = run(with(0.5), &ev);
    let blu = 0.001;
    for s in &samples {
        let q = nalgebra::Vector3::new(s.grid[0] as f64, s.grid[1] as f64, s.grid[2] as f64) * blu;
        let best = segs
            .iter()
            .map(|(a, b)| {
                let (a, b) = (nalgebra::Vector3::from(*a), nalgebra::Vector3::from(*b));
                let d = b - a;
                if d.norm() == 0.0 {
                    return (q - a).norm();
                }
                let f = ((q - a).dot(&d) / d.norm_squared()).clamp(0.0, 1.0);
                (q - (a + d * f)).norm()
            })
            .fold(f64::INFINITY, f64::min);
        assert!(best <= blu * (0.5f64.sqrt() + 1e-6), "{:?}: {best}", s.grid);
    }
    let sum = samples.iter().fold([0i64; 3], |mut a, s| {
        for i in 0..3 {
            a[i] += s.pulses[i];
        }
        a
    });
    assert_eq!(sum, [-25_000, 23_000, 2_000]);
}

#[test]
fn cncc_interpolate_takes_lookahead_options() {
    let dir = common::root().join("target/tmp/interpolate_lookahead");
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("chain.ngc");
    let mut text = String::from("G21 G90 G17 F3000\nG1 X0 Y0\n");
    for i in 1..=200 {
        text.push_str(&format!("X{:.1}\n", i as f64 * 0.5));
    }
    text.push_str("M2\n");
    std::fs::write(&prog, text).unwrap();
    let time = |extra: &[&str]| -> f64 {
        let mut args = vec![
            "interpolate",
            prog.to_str().unwrap(),
            "--format",
            "pulses",
            "--accel",
            "500",
        ];
        args.extend_from_slice(extra);
        let o = common::cncc(&args);
        assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
        let e = common::stderr(&o);
        let t = e
            .split(" moves: ")
            .nth(1)
            .and_then(|r| r.split(' ').next())
            .unwrap();
        t.parse().unwrap()
    };
    // 100 mm at 50 mm/s: 2.1 s with look-ahead (the default); 200 stops
    // of 2·√(0.5/500) s without.
    close(time(&[]), 2.1);
    close(
        time(&["--lookahead", "0"]),
        200.0 * 2.0 * (0.5f64 / 500.0).sqrt(),
    );
    let bad = common::cncc(&[
        "interpolate",
        prog.to_str().unwrap(),
        "--corner-tolerance",
        "-1",
    ]);
    assert_eq!(bad.status.code(), Some(2));
}
