//! Fanuc/Haas coordinate transforms: G68/G69 rotation, G51/G50 scaling and
//! G51.1/G50.1 mirror image, run by mapping programmed points into the
//! work frame with the Siemens programmable-frame map
//! ([`super::siemens::frame::ProgFrame`]), which the target computation
//! already applies to every programmed point.
//!
//! Semantics (Fanuc 0i/30i operator's manuals, "coordinate system
//! rotation", "scaling", "programmable mirror image"):
//! * G68 X Y R: rotate by R degrees (counter-clockwise, positive) about the
//!   centre X Y of the active plane (G17 about Z, G18 about Y, G19 about
//!   X); a centre word left out is the current position; R left out is 0.
//! * G51 X Y Z P (or I J K per axis): scale by P about the centre; a
//!   centre word left out is the current position.
//! * G51.1 X Y Z: mirror the axes written about the positions written.
//! * G69, G50, G50.1 cancel their own transform only.
//! * Programmed point → work frame: mirror first, then scaling, then
//!   rotation (`base = R · S · M · p`).
//!
//! Centre words are read as absolute work coordinates (mm internally).

use super::siemens::frame::ProgFrame;
use super::state::State;
use super::{Interp, Stop};
use crate::canon::CanonPlane;
use crate::ir::{Arena, Axes, Expr, Transform, Value};

/// The Fanuc transforms in force (identity when off).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FanucXform {
    pub rotate: ProgFrame,
    pub scale: ProgFrame,
    pub mirror: ProgFrame,
}

impl FanucXform {
    /// The programmed → work map of all three.
    pub fn frame(&self) -> ProgFrame {
        self.rotate.then(&self.scale).then(&self.mirror)
    }
}

/// Runs a Fanuc transform statement (not `Transform::Frame`).
pub fn exec(it: &mut Interp<'_, '_>, t: &Transform, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let mut x = it.fanuc;
    match t {
        Transform::RotateOn { center, angle } => {
            let c = centre(it, center, exprs)?;
            let deg = opt(it, angle.as_ref(), exprs)?.unwrap_or(0.0);
            let axis = match it.state.plane {
                CanonPlane::XY => 2,
                CanonPlane::XZ => 1,
                CanonPlane::YZ => 0,
            };
            x.rotate = about(c, ProgFrame::rot_about(axis, deg));
        }
        Transform::RotateOff => x.rotate = ProgFrame::identity(),
        Transform::ScaleOn {
            center,
            factor,
            per_axis,
        } => {
            let c = centre(it, center, exprs)?;
            let p = opt(it, factor.as_ref(), exprs)?;
            let mut f = [p.unwrap_or(1.0); 3];
            for (letter, v) in per_axis {
                if let Some(i) = "IJK".find(letter.to_ascii_uppercase()) {
                    f[i] = it.value(v, exprs)?;
                }
            }
            x.scale = about(c, ProgFrame::scale(f));
        }
        Transform::ScaleOff => x.scale = ProgFrame::identity(),
        Transform::MirrorOn { axes } => {
            let c = centre(it, axes, exprs)?;
            let flip = ['X', 'Y', 'Z'].map(|l| axes.get(l).is_some());
            x.mirror = about(c, ProgFrame::mirror(flip));
        }
        Transform::MirrorOff => x.mirror = ProgFrame::identity(),
        Transform::Frame { .. } => return Ok(()),
    }
    it.fanuc = x;
    it.siemens.frame = x.frame();
    Ok(())
}

/// `g` acting about the point `c`: `T(c) · g · T(-c)`.
fn about(c: [f64; 3], g: ProgFrame) -> ProgFrame {
    ProgFrame::trans(c)
        .then(&g)
        .then(&ProgFrame::trans(c.map(|v| -v)))
}

/// The centre written (mm), the current work position for words left out.
fn centre(it: &mut Interp<'_, '_>, axes: &Axes, exprs: &Arena<Expr>) -> Result<[f64; 3], Stop> {
    let mut c = [it.state.pos[0], it.state.pos[1], it.state.pos[2]];
    for (i, l) in ['X', 'Y', 'Z'].iter().enumerate() {
        if let Some(coord) = axes.get(*l) {
            let v = it.value(&coord.value, exprs)?;
            c[i] = if State::is_linear(i) {
                it.state.to_mm(v)
            } else {
                v
            };
        }
    }
    Ok(c)
}

fn opt(
    it: &mut Interp<'_, '_>,
    v: Option<&Value>,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match v {
        Some(v) => Ok(Some(it.value(v, exprs)?)),
        None => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    //! Expected points derived by hand from the transform definitions.
    use crate::canon::{format_call, Canon};
    use crate::dialect::builtin::builtin;
    use crate::interp::{flow::NoLoader, run, Options};
    use crate::span::FileId;

    /// The motion calls of a Fanuc program (mm).
    fn moves(body: &str) -> Vec<String> {
        calls(body)
            .into_iter()
            .filter(|c| c.starts_with("STRAIGHT"))
            .collect()
    }

    /// Every call of a Fanuc program.
    fn calls(body: &str) -> Vec<String> {
        let spec = builtin("fanuc").expect("fanuc");
        let text = format!("%\nO1000\nG21 G17 G90 G54\n{body}M30\n%\n");
        let (program, diags) = crate::driver::read_program(&text, FileId(0), &spec);
        assert!(
            !diags.iter().any(|d| d.is_error()),
            "read errors: {diags:?}"
        );
        let mut calls = Vec::new();
        let mut sink = |c: Canon, _| calls.push(format_call(&c));
        let d = run(
            std::rc::Rc::new(program),
            &spec,
            &Options::default(),
            &mut NoLoader,
            &mut sink,
        );
        assert!(!d.iter().any(|d| d.is_error()), "run errors: {d:?}");
        calls
    }

    fn feed(x: &str, y: &str) -> String {
        format!("STRAIGHT_FEED({x}, {y}, 0.0000, 0.0000, 0.0000, 0.0000)")
    }

    #[test]
    fn g68_rotates_about_its_centre() {
        // (10,0) turned 90° about (5,0): (5,5); then (10,5) about the same: (0,5).
        let m = moves("G0 X0 Y0\nG68 X5. Y0 R90.\nG1 X10. Y0 F100.\nX10. Y5.\nG69\nX1. Y1.\n");
        assert_eq!(
            m[1..],
            [
                feed("5.0000", "5.0000"),
                feed("0.0000", "5.0000"),
                feed("1.0000", "1.0000")
            ]
        );
    }

    #[test]
    fn g51_scales_and_g51_1_mirrors() {
        // Scale 2 about (1,1): (3,2) -> (5,3). Mirror X about X2: (3,2) -> (1,2).
        let m = moves("G0 X0 Y0\nG51 X1. Y1. P2.\nG1 X3. Y2. F100.\nG50\nG51.1 X2.\nX3. Y2.\nG50.1\nX3. Y2.\n");
        assert_eq!(
            m[1..],
            [
                feed("5.0000", "3.0000"),
                feed("1.0000", "2.0000"),
                feed("3.0000", "2.0000")
            ]
        );
    }

    #[test]
    fn g54_1_reads_fanuc_7001_parameters() {
        // P2: X at #7021, Y at #7022.
        let c = calls("#7021 = 10.\n#7022 = 20.\nG54.1 P2\nG1 X1. Y1. F100.\n");
        assert!(
            c.contains(
                &"SET_G5X_OFFSET(102, 10.0000, 20.0000, 0.0000, 0.0000, 0.0000, 0.0000)"
                    .to_string()
            ),
            "{c:?}"
        );
        assert_eq!(
            moves("#7021 = 10.\n#7022 = 20.\nG54.1 P2\nG1 X1. Y1. F100.\n"),
            [feed("1.0000", "1.0000")]
        );
    }
}
