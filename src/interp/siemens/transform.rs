//! Running `TRANS`/`ATRANS`, `ROT`/`AROT`, `SCALE`/`ASCALE`,
//! `MIRROR`/`AMIRROR` (see [`super::frame`] for the semantics and sources).
//!
//! Only the geometry axes X Y Z take part; values for other axes are
//! ignored [?: 840D also translates rotary axes; rs274's canon has no
//! place for it in a programmable frame].

use super::frame::ProgFrame;
use crate::canon::CanonPlane;
use crate::diag::Code;
use crate::interp::{Interp, Stop};
use crate::ir::{Arena, Axes, Expr, FrameOp, Value};

/// The X Y Z values written (None: not written).
fn xyz(
    it: &mut Interp<'_, '_>,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<[Option<f64>; 3], Stop> {
    let mut out = [None; 3];
    for (i, letter) in ['X', 'Y', 'Z'].into_iter().enumerate() {
        if let Some(c) = axes.get(letter) {
            out[i] = Some(it.value(&c.value, exprs)?);
        }
    }
    Ok(out)
}

fn normal_axis(plane: CanonPlane) -> usize {
    match plane {
        CanonPlane::XY => 2,
        CanonPlane::XZ => 1,
        CanonPlane::YZ => 0,
    }
}

/// Runs one frame instruction.
pub fn exec(
    it: &mut Interp<'_, '_>,
    op: FrameOp,
    additive: bool,
    axes: &Axes,
    rpl: Option<&Value>,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let v = xyz(it, axes, exprs)?;
    let rpl = match rpl {
        Some(r) => Some(it.value(r, exprs)?),
        None => None,
    };
    let given = v.iter().any(Option::is_some) || rpl.is_some();
    if !given {
        // A bare absolute instruction clears the programmable frame; a bare
        // additive one changes nothing [?].
        if !additive {
            it.siemens.frame = ProgFrame::identity();
        }
        return Ok(());
    }
    let step = match op {
        FrameOp::Trans => ProgFrame::trans(v.map(|x| it.state.to_mm(x.unwrap_or(0.0)))),
        FrameOp::Rot => match rpl {
            Some(deg) => ProgFrame::rot_about(normal_axis(it.state.plane), deg),
            None => ProgFrame::rot_xyz(v.map(|x| x.unwrap_or(0.0))),
        },
        FrameOp::Scale => {
            let f = v.map(|x| x.unwrap_or(1.0));
            if f.iter().any(|k| *k == 0.0 || !k.is_finite()) {
                return Err(it.error_at(
                    it.span,
                    Code::DomainError,
                    "a scale factor of 0 collapses the coordinate system",
                ));
            }
            ProgFrame::scale(f)
        }
        FrameOp::Mirror => ProgFrame::mirror(v.map(|x| x.is_some())),
    };
    let base = if additive {
        it.siemens.frame
    } else {
        ProgFrame::identity()
    };
    it.siemens.frame = base.then(&step);
    Ok(())
}
