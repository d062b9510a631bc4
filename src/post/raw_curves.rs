//! Toolpath curves the STEP-NC reader keeps as written (W0802) that the
//! post can still follow, read from their Part 21 values:
//!
//! * a `TRIMMED_CURVE` of a `LINE` whose `sense_agreement` contradicts the
//!   line's direction (NIST `ex1E.stp`, the reamer's way out): between two
//!   points a line has one path, so it is posted from `trim_1` to `trim_2`;
//! * a `TRIMMED_CURVE` of a NIST `HELIX(name, position, radius, pitch)`
//!   about the tool axis: `sense_agreement` .T. turns counter-clockwise
//!   about the helix axis (rising by `pitch` a turn), .F. clockwise. The
//!   turns between the trims come from the rise (`|dz| / |pitch|`) and must
//!   agree with the trims' angles; the helix is posted as pieces of at most
//!   half a turn, each an arc with its end z.

use super::frame::Frame;
use super::toolpaths::PathMove;
use super::PostError;
use crate::stepnc::model::{Raw, RawValue};
use std::f64::consts::{PI, TAU};

/// How far (mm) a trim point may be off the helix it trims.
const ON_CURVE: f64 = 1e-3;

/// The most turns a posted helix may make (a tiny pitch must not write
/// an endless program).
const MAX_TURNS: f64 = 1000.0;

/// The moves of a raw curve, or E0900 naming it.
pub fn moves(
    frame: &Frame,
    raw: &Raw,
    feed: Option<f64>,
    owner: &str,
    out: &mut Vec<PathMove>,
) -> Result<(), PostError> {
    let cannot = || PostError::unsupported(owner, &format!("a toolpath curve {}", raw.entity));
    if raw.entity != "TRIMMED_CURVE" {
        return Err(cannot());
    }
    let parts = (
        instance(raw.params.get(1)),
        trim_point(raw.params.get(2)),
        trim_point(raw.params.get(3)),
        raw.params.get(4),
    );
    let (Some(basis), Some(p1), Some(p2), Some(RawValue::Bool(sense))) = parts else {
        return Err(cannot());
    };
    let (p1, p2) = (frame.apply(p1), frame.apply(p2));
    match basis.entity.as_str() {
        "LINE" => {
            out.push(PathMove::Straight { to: p1, feed });
            out.push(PathMove::Straight { to: p2, feed });
            Ok(())
        }
        "HELIX" => {
            let Some(f) = feed else {
                return Err(PostError::unsupported(owner, "a rapid along a helix"));
            };
            let helix = Helix::read(basis, frame).ok_or_else(cannot)?;
            helix.pieces(p1, p2, *sense, f, owner, out)
        }
        _ => Err(cannot()),
    }
}

/// A NIST helix placed in workpiece coordinates (its axis along +Z or -Z).
struct Helix {
    centre: [f64; 2],
    radius: f64,
    pitch: f64,
    /// The helix axis is +Z (false: -Z).
    up: bool,
}

impl Helix {
    fn read(basis: &Raw, frame: &Frame) -> Option<Helix> {
        let place = instance(basis.params.get(1))?;
        let location = point(instance(place.params.get(1))?)?;
        let axis = match instance(place.params.get(2)) {
            Some(d) => frame.rotate(point(d)?),
            None => frame.rotate([0.0, 0.0, 1.0]),
        };
        if axis[0].abs() > 1e-9 || axis[1].abs() > 1e-9 {
            return None;
        }
        let c = frame.apply(location);
        Some(Helix {
            centre: [c[0], c[1]],
            radius: real(basis.params.get(2))?,
            pitch: real(basis.params.get(3))?,
            up: axis[2] > 0.0,
        })
    }

    fn angle(&self, p: [f64; 3]) -> f64 {
        (p[1] - self.centre[1]).atan2(p[0] - self.centre[0])
    }

    fn on(&self, p: [f64; 3]) -> bool {
        let r = (p[0] - self.centre[0]).hypot(p[1] - self.centre[1]);
        (r - self.radius).abs() < ON_CURVE
    }

    /// The pieces from `p1` to `p2`.
    fn pieces(
        &self,
        p1: [f64; 3],
        p2: [f64; 3],
        sense: bool,
        feed: f64,
        owner: &str,
        out: &mut Vec<PathMove>,
    ) -> Result<(), PostError> {
        let off = || PostError::broken(owner, "its helix's trims are not on the helix");
        if !self.on(p1) || !self.on(p2) || self.pitch == 0.0 {
            return Err(off());
        }
        // Counter-clockwise seen from +Z.
        let ccw = sense == self.up;
        let dz = p2[2] - p1[2];
        let mut base = if ccw {
            self.angle(p2) - self.angle(p1)
        } else {
            self.angle(p1) - self.angle(p2)
        };
        base = base.rem_euclid(TAU);
        let turns = dz.abs() / self.pitch.abs();
        if !turns.is_finite() || turns > MAX_TURNS {
            return Err(PostError::unsupported(
                owner,
                &format!("a helix of more than {MAX_TURNS} turns"),
            ));
        }
        let full = ((turns * TAU - base) / TAU).round().max(0.0);
        let sweep = base + full * TAU;
        if sweep < 1e-9 || (sweep - turns * TAU).abs() * self.radius > ON_CURVE * 10.0 {
            return Err(off());
        }
        let n = (sweep / PI).ceil().max(1.0) as usize;
        let a1 = self.angle(p1);
        let dir = if ccw { 1.0 } else { -1.0 };
        out.push(PathMove::Straight {
            to: p1,
            feed: Some(feed),
        });
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let to = if k == n {
                p2
            } else {
                let a = a1 + dir * sweep * t;
                [
                    self.centre[0] + self.radius * a.cos(),
                    self.centre[1] + self.radius * a.sin(),
                    p1[2] + dz * t,
                ]
            };
            out.push(PathMove::Arc {
                to,
                centre: self.centre,
                ccw,
                feed,
            });
        }
        Ok(())
    }
}

fn instance(v: Option<&RawValue>) -> Option<&Raw> {
    match v? {
        RawValue::Instance(r) => Some(r),
        _ => None,
    }
}

fn real(v: Option<&RawValue>) -> Option<f64> {
    match v? {
        RawValue::Real(r) => Some(*r),
        RawValue::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// `CARTESIAN_POINT(name, (x, y, z))` or `DIRECTION(name, (x, y, z))`.
fn point(r: &Raw) -> Option<[f64; 3]> {
    let RawValue::List(xyz) = r.params.get(1)? else {
        return None;
    };
    match xyz.as_slice() {
        [x, y, z] => Some([real(Some(x))?, real(Some(y))?, real(Some(z))?]),
        _ => None,
    }
}

/// A trim select list holding one cartesian point.
fn trim_point(v: Option<&RawValue>) -> Option<[f64; 3]> {
    let RawValue::List(items) = v? else {
        return None;
    };
    match items.as_slice() {
        [one] => point(instance(Some(one))?),
        _ => None,
    }
}
