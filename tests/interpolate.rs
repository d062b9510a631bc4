//! The interpolator against analytic answers: a 3D line and a circle at
//! BLU 1 (the exaggerated case of Ibrahim et al. 2015) keep every grid
//! set-point within 0.707 BLU of the path; pulses sum exactly to each
//! axis's displacement; a move's time with its acceleration phases is the
//! analytic one; and `cncc interpolate` runs programs and STEP-NC plans.

mod common;

use cncc::interpolate::{Interpolator, Sample, Settings};
use cncc::span::{FileId, Span};
use cncc::toolpath::{ArcGeom, CoolantState, Event, FeedMode, Move, MoveKind, P3};

const HALF_SQRT2: f64 = std::f64::consts::FRAC_1_SQRT_2;

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

/// Runs events through the interpolator: the samples and the total time.
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

fn blu1(accel: f64) -> Settings {
    Settings {
        period: 0.001,
        blu: 1.0,
        accel,
        jerk: 0.0,
        rapid_rate: 10_000.0,
        ..Settings::default()
    }
}

fn sums(samples: &[Sample]) -> [i64; 3] {
    samples.iter().fold([0; 3], |mut a, s| {
        for i in 0..3 {
            a[i] += s.pulses[i];
        }
        a
    })
}

#[test]
fn a_3d_line_at_blu_1_stays_within_0_707_blu() {
    let (from, to) = ([3.0, -7.0, 11.0], [1003.0, 610.0, -378.0]);
    let (samples, _) = run(blu1(2000.0), &[mv(MoveKind::Line, from, to, 6000.0)]);
    assert!(samples.len() > 1000);
    let a = nalgebra::Vector3::from(from);
    let u = (nalgebra::Vector3::from(to) - a).normalize();
    let mut worst: f64 = 0.0;
    for s in &samples {
        let q = nalgebra::Vector3::new(s.grid[0] as f64, s.grid[1] as f64, s.grid[2] as f64);
        let d = q - a;
        worst = worst.max((d - u * d.dot(&u)).norm());
        // The set-point itself is on the line.
        let e = s.position - a;
        assert!((e - u * e.dot(&u)).norm() < 1e-9);
    }
    assert!(worst <= HALF_SQRT2 + 1e-12, "worst {worst}");
    assert_eq!(sums(&samples), [1000, 617, -389]);
}

#[test]
fn a_circle_at_blu_1_stays_within_0_707_blu() {
    let g = ArcGeom {
        axes: [0, 1, 2],
        centre: [0.0, 0.0, -5.0],
        rotation: 1,
    };
    let start = [100.0, 0.0, -5.0];
    let (samples, _) = run(blu1(1000.0), &[mv(MoveKind::Arc(g), start, start, 3000.0)]);
    assert!(samples.len() > 10_000);
    let mut worst: f64 = 0.0;
    for s in &samples {
        let (x, y) = (s.grid[0] as f64, s.grid[1] as f64);
        worst = worst.max((x.hypot(y) - 100.0).abs());
        assert_eq!(s.grid[2], -5);
        assert!((s.position.x.hypot(s.position.y) - 100.0).abs() < 1e-9);
    }
    assert!(worst <= HALF_SQRT2 + 1e-12, "worst {worst}");
    assert_eq!(sums(&samples), [0, 0, 0]);
    // A clockwise quarter, then a counter-clockwise half: sums are the
    // displacement.
    let cw = ArcGeom {
        axes: [0, 1, 2],
        centre: [0.0, 0.0, 0.0],
        rotation: -1,
    };
    let (q, _) = run(
        blu1(1000.0),
        &[
            mv(
                MoveKind::Arc(cw),
                [0.0, 50.0, 0.0],
                [50.0, 0.0, 0.0],
                2000.0,
            ),
            mv(
                MoveKind::Arc(g),
                [50.0, 0.0, 0.0],
                [-50.0, 0.0, 7.0],
                2000.0,
            ),
        ],
    );
    assert_eq!(sums(&q), [-50, -50, 7]);
}

#[test]
fn pulse_sums_are_exact_over_many_moves_at_a_fine_blu() {
    let s = Settings {
        blu: 0.001,
        ..Settings::default()
    };
    let pts: Vec<P3> = (0..200)
        .map(|i| {
            let t = i as f64 * 0.37;
            [
                (10.0 * t.sin() * 1000.0).round() / 1000.0,
                (7.0 * t.cos() * 1000.0).round() / 1000.0,
                (-(i as f64) * 0.013 * 1000.0).round() / 1000.0,
            ]
        })
        .collect();
    let events: Vec<Event> = pts
        .windows(2)
        .map(|w| mv(MoveKind::Line, w[0], w[1], 1500.0))
        .collect();
    let (samples, _) = run(s, &events);
    let (a, b) = (pts[0], pts[pts.len() - 1]);
    let want: Vec<i64> = (0..3)
        .map(|i| ((b[i] - a[i]) * 1000.0).round() as i64)
        .collect();
    assert_eq!(sums(&samples).to_vec(), want);
    // No period asks an axis for more than the feed allows (plus one
    // pulse of rounding).
    let most = (1500.0 / 60.0 * 0.001 / 0.001f64).ceil() as i64 + 1;
    assert!(samples
        .iter()
        .all(|s| s.pulses.iter().all(|p| p.abs() <= most)));
}

#[test]
fn the_time_of_a_move_with_acceleration_phases_is_the_analytic_one() {
    // 100 mm at 3000 mm/min (50 mm/s), 500 mm/s²: 0.1 s to reach the
    // feed, 0.1 s to stop, 2.5 mm each; 95 mm at 50 mm/s: 2.1 s.
    let (samples, t) = run(
        Settings {
            period: 0.001,
            blu: 0.001,
            accel: 500.0,
            jerk: 0.0,
            rapid_rate: 10_000.0,
            ..Settings::default()
        },
        &[mv(MoveKind::Line, [0.0; 3], [100.0, 0.0, 0.0], 3000.0)],
    );
    assert!((t - 2.1).abs() / 2.1 < 1e-3, "{t}");
    let last = samples.last().unwrap();
    assert!((last.time - 2.1).abs() / 2.1 < 1e-3, "{}", last.time);
    // Half way through the acceleration phase (0.05 s): 0.625 mm.
    let s = samples.iter().find(|s| s.index == 50).unwrap();
    assert!((s.position.x - 0.625).abs() < 1e-9);
    assert!((s.speed - 1500.0).abs() < 1e-6);
    // A short move never reaches the feed: a triangle, 2·sqrt(L/a).
    let (_, t) = run(
        Settings {
            accel: 500.0,
            ..Settings::default()
        },
        &[mv(MoveKind::Line, [0.0; 3], [0.0, 2.0, 0.0], 3000.0)],
    );
    let want = 2.0 * (2.0f64 / 500.0).sqrt();
    assert!((t - want).abs() / want < 1e-3, "{t} {want}");
    // A helix: its length over the feed plus the two phases.
    let g = ArcGeom {
        axes: [0, 1, 2],
        centre: [0.0; 3],
        rotation: 2,
    };
    let (_, t) = run(
        Settings {
            accel: 500.0,
            ..Settings::default()
        },
        &[mv(
            MoveKind::Arc(g),
            [10.0, 0.0, 0.0],
            [10.0, 0.0, -6.0],
            3000.0,
        )],
    );
    let len = (2.0 * std::f64::consts::TAU * 10.0f64).hypot(6.0);
    let want = len / 50.0 + 50.0 / 500.0;
    assert!((t - want).abs() / want < 1e-3, "{t} {want}");
}

#[test]
fn cncc_interpolate_a_program_and_a_plan() {
    let dir = common::root().join("target/tmp/interpolate");
    std::fs::create_dir_all(&dir).unwrap();
    let prog = dir.join("square.ngc");
    std::fs::write(
        &prog,
        "G21 G90 G17\nG0 X0 Y0 Z1\nG1 Z-1 F300\nX20\nY10\nG3 X0 Y10 I-10 J0\nG1 Y0\nG0 Z5\nM2\n",
    )
    .unwrap();
    let o = common::cncc(&["interpolate", prog.to_str().unwrap(), "--format", "pulses"]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    let text = common::stdout(&o);
    assert!(text.starts_with("period,x,y,z\n"));
    let mut sum = [0i64; 3];
    for l in text.lines().skip(1) {
        let v: Vec<i64> = l.split(',').map(|x| x.parse().unwrap()).collect();
        for i in 0..3 {
            sum[i] += v[i + 1];
        }
    }
    // From the start (the origin, as rs274 starts) to X0 Y0 Z5, in
    // micrometres.
    assert_eq!(sum, [0, 0, 5000]);
    let csv = common::cncc(&["interpolate", prog.to_str().unwrap(), "--period", "2ms"]);
    assert_eq!(csv.status.code(), Some(0));
    let csv = common::stdout(&csv);
    assert!(csv.starts_with("t,x,y,z,speed\n0.000000,"));
    let plan = common::root().join("tests/programs/stepnc/tapped_holes.stp");
    let p = common::cncc(&["interpolate", plan.to_str().unwrap(), "--period", "5ms"]);
    assert_eq!(p.status.code(), Some(0), "{}", common::stderr(&p));
    assert!(common::stdout(&p).lines().count() > 100);
    let bad = common::cncc(&["interpolate", prog.to_str().unwrap(), "--period", "1"]);
    assert_eq!(bad.status.code(), Some(2));
}

#[test]
fn a_dwell_passes_time_standing_still() {
    let s = Settings {
        accel: 0.0,
        ..Settings::default()
    };
    let dwell = Event::Dwell {
        seconds: 0.25,
        span: Span::new(FileId(0), 0, 0),
    };
    let (samples, t) = run(
        s,
        &[
            mv(MoveKind::Line, [0.0; 3], [10.0, 0.0, 0.0], 600.0),
            dwell,
            mv(MoveKind::Line, [10.0, 0.0, 0.0], [10.0, 5.0, 0.0], 600.0),
        ],
    );
    // 1 s, 0.25 s still, 0.5 s: no acceleration limit.
    assert!((t - 1.75).abs() < 1e-9, "{t}");
    let still: Vec<&Sample> = samples
        .iter()
        .filter(|s| s.time > 1.0 + 1e-9 && s.time < 1.25 - 1e-9)
        .collect();
    assert!(!still.is_empty());
    assert!(still
        .iter()
        .all(|s| s.pulses == [0, 0, 0] && s.speed == 0.0));
    assert_eq!(sums(&samples), [10_000, 5_000, 0]);
}

#[test]
fn a_jerk_limited_move_takes_its_analytic_time_and_ends_exactly() {
    // 100 mm at 3000 mm/min (50 mm/s), 500 mm/s², 5000 mm/s³: each ramp
    // takes 50/500 + 500/5000 = 0.2 s over 5 mm; 90 mm cruise, 1.8 s:
    // 2.2 s in all (the trapezoid takes 2.1 s).
    let s = Settings {
        accel: 500.0,
        jerk: 5000.0,
        ..Settings::default()
    };
    let (samples, t) = run(
        s,
        &[mv(MoveKind::Line, [0.0; 3], [100.0, 0.0, 0.0], 3000.0)],
    );
    assert!((t - 2.2).abs() / 2.2 < 1e-3, "{t}");
    assert_eq!(sums(&samples), [100_000, 0, 0]);
    // The speed rises smoothly: after 0.1 s (the first jerk phase) it is
    // j t^2 / 2 = 25 mm/s, 1500 mm/min.
    let at = samples.iter().find(|s| s.index == 100).unwrap();
    assert!((at.speed - 1500.0).abs() < 1e-6, "{}", at.speed);
    // The acceleration never steps: speed changes per period stay under
    // a·period and change by at most j·period² between periods.
    let v: Vec<f64> = samples.iter().map(|s| s.speed / 60.0).collect();
    for w in v.windows(3) {
        let (a1, a2) = ((w[1] - w[0]) / 0.001, (w[2] - w[1]) / 0.001);
        assert!(a1.abs() <= 500.0 + 1e-6 && ((a2 - a1) / 0.001).abs() <= 5000.0 * 1.01);
    }
}
