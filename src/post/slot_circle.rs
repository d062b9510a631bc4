//! Alike slots placed radially on one circle, as SLOT1/LONGHOLE place
//! theirs: slot k's axis points away from the centre at STA1 + k·INDA and
//! its inner end (the end of its outline behind the course of travel's
//! origin) lies RAD from the centre ([?] our reading of the cycles'
//! pictures, the interpreter's too: `interp/siemens/milling/slots.rs`).

use super::slots::Parts;

const EPS: f64 = 1e-6;

/// Where the cycle puts the slots.
#[derive(Clone, Debug, PartialEq)]
pub struct SlotCircle {
    pub centre: [f64; 2],
    pub rad: f64,
    /// Degrees: the first slot's direction, and the step to the next.
    pub sta: f64,
    pub inda: f64,
    pub num: usize,
}

/// A slot's inner end and unit direction in the plane.
fn axis(p: &Parts<'_>) -> ([f64; 2], [f64; 2]) {
    let g = &p.geom;
    let half = (g.travel + g.width) / 2.0;
    let u = [g.frame.x[0], g.frame.x[1]];
    (
        [
            g.frame.origin[0] - u[0] * half,
            g.frame.origin[1] - u[1] * half,
        ],
        u,
    )
}

fn wrap(deg: f64) -> f64 {
    let d = deg.rem_euclid(360.0);
    if d > 180.0 {
        d - 360.0
    } else {
        d
    }
}

/// The point behind both inner ends, equally far (RAD) from both along
/// their axes: where the axes cross, or midway between two opposite
/// slots on one line.
fn centre(p0: [f64; 2], u0: [f64; 2], p1: [f64; 2], u1: [f64; 2]) -> Option<([f64; 2], f64)> {
    let det = u1[0] * u0[1] - u0[0] * u1[1];
    let (dx, dy) = (p0[0] - p1[0], p0[1] - p1[1]);
    if det.abs() < 1e-9 {
        if u0[0] * u1[0] + u0[1] * u1[1] > 0.0 {
            return None;
        }
        let c = [(p0[0] + p1[0]) / 2.0, (p0[1] + p1[1]) / 2.0];
        let rad = (p0[0] - c[0]) * u0[0] + (p0[1] - c[1]) * u0[1];
        return (rad > -EPS).then_some((c, rad.max(0.0)));
    }
    // p0 - a u0 = p1 - b u1.
    let a = (u1[0] * dy - dx * u1[1]) / det;
    let b = (u0[0] * dy - u0[1] * dx) / det;
    if a < -EPS || (a - b).abs() > EPS {
        return None;
    }
    let rad = a.max(0.0);
    Some(([p0[0] - rad * u0[0], p0[1] - rad * u0[1]], rad))
}

/// The circle the slots form, if they are alike and radial on one (two
/// slots at least).
pub fn circle(all: &[Parts<'_>]) -> Option<SlotCircle> {
    if all.len() < 2 {
        return None;
    }
    let first = &all[0].geom;
    let alike = all.iter().all(|p| {
        p.geom.frame.is_vertical()
            && (p.geom.travel - first.travel).abs() < EPS
            && (p.geom.width - first.width).abs() < EPS
            && (p.geom.frame.origin[2] - first.frame.origin[2]).abs() < EPS
    });
    if !alike {
        return None;
    }
    let (p0, u0) = axis(&all[0]);
    let (p1, u1) = axis(&all[1]);
    let (centre, rad) = centre(p0, u0, p1, u1)?;
    let ang = |u: [f64; 2]| u[1].atan2(u[0]).to_degrees();
    let sta = ang(u0);
    let inda = wrap(ang(u1) - sta);
    let n = all.len();
    let on_circle = all.iter().enumerate().all(|(k, p)| {
        let (q, u) = axis(p);
        let expect = [centre[0] + rad * u[0], centre[1] + rad * u[1]];
        (q[0] - expect[0]).abs() < EPS
            && (q[1] - expect[1]).abs() < EPS
            && wrap(ang(u) - sta - inda * k as f64).abs() < 1e-6
    });
    (on_circle && inda.abs() > 1e-6 && inda.abs() * ((n - 1) as f64) < 360.0 - 1e-6).then_some(
        SlotCircle {
            centre,
            rad,
            sta,
            inda,
            num: n,
        },
    )
}
