//! Unit tests of the turning kernel: placement round trips, offsets and
//! a roughing run on a step.

use super::*;

/// Records the moves as (kind, Z, X).
#[derive(Default)]
struct Log(Vec<(char, f64, f64)>);

impl Motion for Log {
    fn rapid(&mut self, to: Pt) -> Result<(), TurnError> {
        self.0.push(('r', to.re, to.im));
        Ok(())
    }
    fn feed(&mut self, to: Pt) -> Result<(), TurnError> {
        self.0.push(('f', to.re, to.im));
        Ok(())
    }
    fn arc(&mut self, _: bool, _: Pt, to: Pt) -> Result<(), TurnError> {
        self.0.push(('a', to.re, to.im));
        Ok(())
    }
}

#[test]
fn placement_maps_back_what_the_profile_was_given() {
    let p = Pt::new(3.0, -7.0);
    for turned in [false, true] {
        for mirror_x in [false, true] {
            for mirror_z in [false, true] {
                let mut prof = Profile {
                    segs: vec![Seg::line(p, p)],
                    ..Profile::default()
                };
                if turned {
                    prof.turn();
                }
                if mirror_x {
                    prof.map(|q| q.conj(), true);
                    prof.place.mirror_x = true;
                }
                if mirror_z {
                    prof.map(|q| -q.conj(), true);
                    prof.place.mirror_z = true;
                }
                let back = prof.place.back(prof.segs[0].start);
                assert!((back - p).norm() < 1e-12, "{:?}", prof.place);
            }
        }
    }
}

#[test]
fn a_line_towards_minus_z_offsets_up_in_x() {
    let mut s = Seg::line(Pt::new(0.0, 0.0), Pt::new(-10.0, 0.0));
    s.offset(1.0);
    assert!((s.start - Pt::new(0.0, 1.0)).norm() < 1e-12);
}

#[test]
fn a_step_is_roughed_in_levels_of_the_depth_of_cut() {
    // start X10 Z1; contour X6 Z0 -> Z-5 -> X10 (a shoulder)
    let segs = vec![
        Seg::line(Pt::new(1.0, 10.0), Pt::new(0.0, 6.0)),
        Seg::line(Pt::new(0.0, 6.0), Pt::new(-5.0, 6.0)),
        Seg::line(Pt::new(-5.0, 6.0), Pt::new(-5.0, 10.0)),
    ];
    let c = Rough {
        start: Pt::new(1.0, 10.0),
        shift: Pt::new(0.0, 0.0),
        allowance: 0.0,
        depth: 2.0,
        retract: 0.5,
        pockets: Pockets::All,
        facing: false,
    };
    let mut log = Log::default();
    Profile {
        segs,
        ..Profile::default()
    }
    .rough(&c, &mut log)
    .unwrap();
    let cuts: Vec<_> = log
        .0
        .iter()
        .filter(|(k, z, _)| *k == 'f' && (*z + 5.0).abs() < 1e-9)
        .map(|m| m.2)
        .collect();
    assert!(cuts.contains(&8.0) && cuts.contains(&6.0), "{:?}", log.0);
}

#[test]
fn a_contour_turning_back_is_refused() {
    let segs = vec![
        Seg::line(Pt::new(1.0, 10.0), Pt::new(0.0, 6.0)),
        Seg::line(Pt::new(0.0, 6.0), Pt::new(-5.0, 6.0)),
        Seg::line(Pt::new(-5.0, 6.0), Pt::new(-3.0, 8.0)),
    ];
    let c = Rough {
        start: Pt::new(1.0, 10.0),
        shift: Pt::new(0.0, 0.0),
        allowance: 0.0,
        depth: 1.0,
        retract: 0.5,
        pockets: Pockets::All,
        facing: false,
    };
    let r = Profile {
        segs,
        ..Profile::default()
    }
    .rough(&c, &mut Log::default());
    assert_eq!(r, Err(TurnError::Geometry("Not monotonic")));
}
