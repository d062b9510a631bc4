//! Tests of the sweep: the fast paths against the exact per-cell solve.

use super::*;
use crate::toolpath::Stock;

fn field() -> HeightField {
    let s: Stock = "100x50x20".parse().unwrap();
    HeightField::new(&s, 0.1).unwrap()
}

fn sweep(c: &Cutter, a: [f64; 3], b: [f64; 3]) -> Sweep<'_> {
    Sweep {
        cutter: c,
        a: Vector3::from(a),
        b: Vector3::from(b),
        reach: c.radius,
    }
}

#[test]
fn a_flat_slot_is_exact() {
    let mut f = field();
    let c = Cutter::flat(5.0);
    let v = sweep(&c, [10.0, 20.0, -3.0], [60.0, 20.0, -3.0]).cut(&mut f);
    let exact = 3.0 * (50.0 * 10.0 + std::f64::consts::PI * 25.0);
    assert!((v - exact).abs() / exact < 0.005, "{v} vs {exact}");
    assert!((f.removed() - v).abs() < 1e-6 * exact);
}

#[test]
fn a_ball_ramp_cuts_a_round_groove() {
    let mut f = field();
    let c = Cutter {
        radius: 3.0,
        shape: Shape::Ball,
    };
    sweep(&c, [10.0, 20.0, 0.0], [60.0, 20.0, -5.0]).cut(&mut f);
    // Halfway along, 2 mm beside the path: the ball's surface.
    let z = f.at(35.05, 22.05).unwrap();
    // The lowest of the ball over that point, by brute force.
    let expect = (0..=200_000)
        .map(|k| {
            let x = 10.0 + 50.0 * k as f64 / 200_000.0;
            let rho2 = (x - 35.05).powi(2) + 2.05f64.powi(2);
            (rho2 <= 9.0).then(|| -(x - 10.0) / 10.0 + 3.0 - (9.0 - rho2).sqrt())
        })
        .flatten()
        .fold(f64::MAX, f64::min);
    assert!((z - expect).abs() < 0.01, "{z} vs {expect}");
}

#[test]
fn a_probe_finds_material_and_does_not_cut() {
    let mut f = field();
    let c = Cutter::flat(5.0);
    let hit = sweep(&c, [10.0, 20.0, 5.0], [60.0, 20.0, -1.0])
        .probe(&mut f)
        .unwrap();
    assert!((hit.depth - 1.0).abs() < 0.01, "{hit:?}");
    assert_eq!(f.removed(), 0.0);
    assert!(sweep(&c, [10.0, 20.0, 5.0], [60.0, 20.0, 1.0])
        .probe(&mut f)
        .is_none());
}

#[test]
fn the_ball_closed_form_agrees_with_the_bisection() {
    let ball = Cutter {
        radius: 3.0,
        shape: Shape::Ball,
    };
    let moves = [
        ([0.0, 0.0, 0.0], [10.0, 4.0, -5.0]),
        ([0.0, 0.0, -2.0], [1.0, -0.5, 3.0]),
        ([5.0, 5.0, 0.0], [5.5, 5.0, -20.0]),
        ([0.0, 0.0, 0.0], [0.3, 0.1, -0.01]),
    ];
    for (a, b) in moves {
        let seg = Segment::new(Vector3::from(a), Vector3::from(b));
        for k in 0..400 {
            let p = Vector2::new(-4.0 + 0.037 * k as f64, -3.0 + 0.029 * k as f64);
            let w = p - seg.a.xy();
            let t0 = w.dot(&seg.d2) / seg.l2;
            let e2 = (w - seg.d2 * t0).norm_squared();
            if e2 >= 9.0 {
                continue;
            }
            let half = ((9.0 - e2) / seg.l2).sqrt();
            let (lo, hi) = ((t0 - half).max(0.0), (t0 + half).min(1.0));
            if lo > hi {
                continue;
            }
            let z = |t: f64| {
                let rho = (e2 + seg.l2 * (t - t0).powi(2)).sqrt();
                seg.a.z + t * seg.dz + ball.profile(rho)
            };
            let closed = z(seg.ball_lowest(3.0, w).unwrap().clamp(lo, hi));
            let bisected = z(seg.lowest(&ball, e2, t0, lo, hi));
            assert!(
                (closed - bisected).abs() < 1e-7,
                "{a:?} {b:?} {p:?}: {closed} {bisected}"
            );
        }
    }
}

/// Every cell by the exact surface, no tile, row or bound skipped.
fn brute_force(c: &Cutter, a: Vector3<f64>, b: Vector3<f64>, reach: f64, f: &mut HeightField) {
    let seg = Segment::new(a, b);
    for j in 0..f.ny {
        for i in 0..f.nx {
            let (x, y) = f.centre(i, j);
            if let Some(s) = seg.surface(c, reach, Vector2::new(x, y)) {
                let h = &mut f.z[j * f.nx + i];
                let s = s.max(f.bottom);
                if s < *h as f64 {
                    *h = s as f32;
                }
            }
        }
    }
}

#[test]
fn skipping_tiles_rows_and_bounded_cells_cuts_what_every_cell_cuts() {
    let s: Stock = "12x9x10-1-1-10".parse().unwrap();
    let cutters = [
        Cutter::flat(1.5),
        Cutter {
            radius: 1.2,
            shape: Shape::Ball,
        },
        Cutter {
            radius: 2.0,
            shape: Shape::Bull { corner: 0.5 },
        },
        Cutter {
            radius: 1.0,
            shape: Shape::Cone { angle: 118.0 },
        },
        Cutter::flat(0.0),
    ];
    // A walk of short and long moves, ramps, plunges and climbs, so
    // that later moves cross cells and tiles earlier ones cut.
    let mut seed = 7u64;
    let mut next = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut fast = HeightField::new(&s, 0.1).unwrap();
    let mut slow = fast.clone();
    let mut p = Vector3::new(2.0, 2.0, -1.0);
    for k in 0..300 {
        let c = &cutters[k / 60];
        let q = if k % 7 == 3 {
            Vector3::new(p.x, p.y, -4.0 * next())
        } else {
            let len = if k % 5 == 0 { 6.0 } else { 0.4 };
            Vector3::new(
                (p.x + len * (next() - 0.5)).clamp(-2.0, 12.0),
                (p.y + len * (next() - 0.5)).clamp(-2.0, 9.0),
                (p.z + 0.6 * (next() - 0.55)).clamp(-6.0, 0.5),
            )
        };
        let reach = c.radius.max(0.0707);
        Sweep {
            cutter: c,
            a: p,
            b: q,
            reach,
        }
        .cut(&mut fast);
        brute_force(c, p, q, reach, &mut slow);
        p = q;
    }
    assert!(fast.removed() > 10.0, "{}", fast.removed());
    let worst = fast
        .z
        .iter()
        .zip(&slow.z)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert_eq!(worst, 0.0);
    // Each tile's peak still bounds its cells.
    for (k, h) in fast.z.iter().enumerate() {
        let (i, j) = (k % fast.nx, k / fast.nx);
        assert!(*h <= fast.peaks[(j / TILE) * fast.tiles_x + i / TILE]);
    }
}

/// A small random generator for the tests (an LCG).
fn lcg(seed: u64) -> impl FnMut() -> f64 {
    let mut seed = seed;
    move || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[test]
fn every_cell_of_a_flat_plateau_solves_to_its_height() {
    let mut next = lcg(11);
    let mut checked = 0;
    for k in 0..4000 {
        let c = Cutter::flat([0.0, 0.8, 2.381, 6.0][k % 4]);
        let reach = c.radius.max(0.035);
        let a = Vector3::new(50.0 * next(), 50.0 * next(), -10.0 * next());
        // Lines, ramps down and up, nearly level, plunges, climbs,
        // and very short and long moves.
        let len = [0.0, 1e-10, 0.01, 0.3, 2.0, 80.0][k % 6];
        let angle = 6.3 * next();
        let dz = match k % 5 {
            0 => 0.0,
            1 => 1e-13 * (next() - 0.5),
            2 => -3.0 * next(),
            3 => 3.0 * next(),
            _ => -0.007,
        };
        let b = a + Vector3::new(len * angle.cos(), len * angle.sin(), dz);
        let seg = Segment::new(a, b);
        let plateau = Plateau::new(&c, &seg, reach).unwrap();
        for _ in 0..40 {
            let y =
                a.y.min(b.y) - reach + (b.y - a.y).abs().max(0.0) * next() + 2.0 * reach * next();
            let Some((x0, x1)) = plateau.row(&seg, y) else {
                continue;
            };
            for x in [x0, x1, x0 + (x1 - x0) * next()] {
                let s = seg.surface(&c, reach, Vector2::new(x, y));
                assert_eq!(
                    s.map(f64::to_bits),
                    Some(plateau.z.to_bits()),
                    "{a:?} {b:?} reach {reach}: at ({x}, {y}) {s:?}, plateau {}",
                    plateau.z
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 50_000, "{checked}");
    // The plateau is the region the fast path claims: a ramp's lower
    // end, not its upper one.
    let c = Cutter::flat(2.0);
    let seg = Segment::new(Vector3::new(0.0, 0.0, 0.0), Vector3::new(10.0, 0.0, -1.0));
    let p = Plateau::new(&c, &seg, 2.0).unwrap();
    assert_eq!(p.z, -1.0);
    assert!(p
        .row(&seg, 0.0)
        .is_some_and(|(lo, hi)| lo > 7.9 && hi < 12.1));
    assert!(seg.surface(&c, 2.0, Vector2::new(1.0, 0.0)).unwrap() > -0.5);
}

#[test]
fn flat_tools_cut_and_probe_as_every_cell_solved() {
    // dx != dy, a walk of flat tools only: level lines, ramps both
    // ways, plunges, climbs, repeated passes over cut cells.
    let s: Stock = "13x9x10-1-1-10".parse().unwrap();
    let mut next = lcg(3);
    let mut fast = HeightField::new(&s, 0.07).unwrap();
    let mut slow = fast.clone();
    let mut p = Vector3::new(4.0, 4.0, 0.5);
    let (mut v_fast, mut hits) = (0.0, 0);
    for k in 0..600 {
        let c = Cutter::flat([2.0, 0.5, 1.2, 0.0][k / 150]);
        let reach = c.radius.max(0.0707);
        let q = match k % 6 {
            0 => Vector3::new(p.x, p.y, -5.0 * next()),
            1 | 2 => Vector3::new(
                (p.x + 6.0 * (next() - 0.5)).clamp(-2.0, 13.0),
                (p.y + 6.0 * (next() - 0.5)).clamp(-2.0, 9.0),
                p.z,
            ),
            _ => Vector3::new(
                (p.x + 0.6 * (next() - 0.5)).clamp(-2.0, 13.0),
                (p.y + 0.6 * (next() - 0.5)).clamp(-2.0, 9.0),
                (p.z + 0.4 * (next() - 0.55)).clamp(-6.0, 0.5),
            ),
        };
        // A probe (as a rapid's, with play) before the cut finds
        // the same deepest material as a look at every cell.
        let probe = Sweep {
            cutter: &c,
            a: p,
            b: q,
            reach: (reach - 0.02).max(0.0707),
        };
        let found = probe.probe(&mut fast);
        let mut deepest = 0.0f64;
        let seg = Segment::new(p, q);
        for j in 0..slow.ny {
            for i in 0..slow.nx {
                let (x, y) = slow.centre(i, j);
                if let Some(s) = seg.surface(&c, probe.reach, Vector2::new(x, y)) {
                    deepest = deepest.max(slow.z[j * slow.nx + i] as f64 - s.max(slow.bottom));
                }
            }
        }
        assert_eq!(found.map_or(0.0, |h| h.depth), deepest, "move {k}");
        hits += found.is_some() as usize;
        v_fast += Sweep {
            cutter: &c,
            a: p,
            b: q,
            reach,
        }
        .cut(&mut fast);
        brute_force(&c, p, q, reach, &mut slow);
        p = q;
    }
    assert!(
        fast.removed() > 100.0 && hits > 50,
        "{} {hits}",
        fast.removed()
    );
    assert!((v_fast - slow.removed()).abs() < 1e-6 * v_fast, "{v_fast}");
    let worst = fast
        .z
        .iter()
        .zip(&slow.z)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0f32, f32::max);
    assert_eq!(worst, 0.0);
    for (k, h) in fast.z.iter().enumerate() {
        let (i, j) = (k % fast.nx, k / fast.nx);
        assert!(*h <= fast.peaks[(j / TILE) * fast.tiles_x + i / TILE]);
    }
}

#[test]
fn the_ball_fast_path_agrees_with_the_bisection() {
    let ball = Cutter {
        radius: 3.0,
        shape: Shape::Ball,
    };
    let moves = [
        ([0.0, 0.0, 0.0], [10.0, 4.0, -5.0]),
        ([0.0, 0.0, -2.0], [1.0, -0.5, 3.0]),
        ([5.0, 5.0, 0.0], [5.5, 5.0, -20.0]),
        ([5.0, 5.0, 0.0], [5.0 + 1e-7, 5.0, -20.0]),
        ([0.0, 0.0, 0.0], [0.3, 0.1, -0.01]),
    ];
    for (a, b) in moves {
        let seg = Segment::new(Vector3::from(a), Vector3::from(b));
        for k in 0..400 {
            let p = Vector2::new(-4.0 + 0.037 * k as f64, -3.0 + 0.029 * k as f64);
            let w = p - seg.a.xy();
            let t0 = w.dot(&seg.d2) / seg.l2;
            let e2 = (w - seg.d2 * t0).norm_squared();
            let Some(fast) = seg.ball_surface(3.0, w) else {
                continue;
            };
            let half = ((9.0 - e2) / seg.l2).sqrt();
            let (lo, hi) = ((t0 - half).max(0.0), (t0 + half).min(1.0));
            let t = seg.lowest(&ball, e2, t0, lo, hi);
            let rho = (e2 + seg.l2 * (t - t0).powi(2)).sqrt();
            let bisected = seg.a.z + t * seg.dz + ball.profile(rho);
            assert!(
                (fast - bisected).abs() < 1e-7,
                "{a:?} {b:?} {p:?}: {fast} {bisected}"
            );
        }
    }
}
