//! Small geometric facts about model values that the reader and writer
//! share.

use super::model::{Point, Raw, RawValue};

/// Whether going from `start` to `end` follows the direction of a LINE
/// kept as written (`LINE(name, pnt, VECTOR(name, DIRECTION(name, ratios),
/// magnitude))`): `Some(true)` along it, `Some(false)` against it, `None`
/// when the line's direction cannot be read or the points coincide along
/// it.
pub fn line_sense(line: &Raw, start: &Point, end: &Point) -> Option<bool> {
    let vector = instance(line.params.get(2)?)?;
    let direction = instance(vector.params.get(1)?)?;
    let RawValue::List(ratios) = direction.params.get(1)? else {
        return None;
    };
    let mut dot = 0.0;
    for (k, r) in ratios.iter().enumerate().take(3) {
        let v = match r {
            RawValue::Real(v) => *v,
            RawValue::Integer(i) => *i as f64,
            _ => return None,
        };
        dot += v * (end.xyz[k] - start.xyz[k]);
    }
    if dot > 0.0 {
        Some(true)
    } else if dot < 0.0 {
        Some(false)
    } else {
        None
    }
}

fn instance(v: &RawValue) -> Option<&Raw> {
    match v {
        RawValue::Instance(r) => Some(r),
        _ => None,
    }
}
