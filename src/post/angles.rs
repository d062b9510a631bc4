//! Plane angles of a STEP-NC plan. ISO 14649 gives them in degrees (the
//! model holds them as written), but generators write radians: the GRIMA
//! field files' `VEE_PROFILE(#p,#r,1.5707963267948966,0.7853981633974483)`
//! and `SQUARE_U_PROFILE(...,0.5235987755982988,...)` are 90°, 45°, 30°.
//! An angle that is not a whole number but is one (to 1e-7) once read as
//! radians and turned into degrees is read as radians, with a warning
//! (W0905) naming the feature and the attribute; every other angle is
//! degrees. [?] A plan in degrees whose angle is, say, 57.29577951308232
//! (1 radian in degrees) would be misread; no real plan was seen to.

use super::Writer;
use crate::diag::{Code, Diagnostic};

/// The angle in degrees, and whether it was read as radians.
pub fn classify(v: f64) -> (f64, bool) {
    if v.fract().abs() < 1e-12 || !v.is_finite() {
        return (v, false);
    }
    let d = v.to_degrees();
    if (d - d.round()).abs() < 1e-7 && d.round() != 0.0 {
        (d.round(), true)
    } else {
        (v, false)
    }
}

/// The angle in degrees (see the module doc).
pub fn degrees(v: f64) -> f64 {
    classify(v).0
}

/// The angle in degrees; a warning when it was read as radians.
pub fn read_angle(w: &mut Writer<'_>, id: &str, what: &str, v: f64) -> f64 {
    let (d, radians) = classify(v);
    if radians {
        let msg = format!("`{id}`: the {what} {v} is read as radians ({d}°)");
        if !w.warnings.iter().any(|x| x.message == msg) {
            w.warnings.push(
                Diagnostic::new(Code::AngleRadians, msg)
                    .help("ISO 14649 gives plane angles in degrees; this value is a whole number of degrees only as radians, as the plan's generator writes them"),
            );
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::classify;

    #[test]
    fn radians_of_whole_degrees_are_read_as_radians() {
        assert_eq!(classify(1.5707963267948966), (90.0, true));
        assert_eq!(classify(0.5235987755982988), (30.0, true));
        assert_eq!(classify(1.2217304763960306), (70.0, true));
        assert_eq!(classify(30.0), (30.0, false));
        assert_eq!(classify(0.5), (0.5, false));
        assert_eq!(classify(0.0), (0.0, false));
    }
}
