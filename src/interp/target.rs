//! Where axis words send the tool: absolute or incremental per axis
//! (G90/G91, Siemens AC/IC), or machine coordinates (G53). Positions are
//! in the program frame, mm (angles in degrees), as [`super::state::State`]
//! keeps them.

use super::state::State;
use super::{Interp, Stop};
use crate::ir::{Arena, Axes, Coord, DimMode, Expr};

/// How the axis words of a block are read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Frame {
    /// The program frame, in the distance mode in force.
    Program,
    /// G53: machine coordinates, absolute.
    Machine,
}

/// The target of `axes` from the current position.
pub fn target(
    it: &mut Interp<'_, '_>,
    axes: &Axes,
    exprs: &Arena<Expr>,
    frame: Frame,
) -> Result<[f64; 9], Stop> {
    // Under a Siemens programmable frame, words are read in the programmed
    // system and the point is mapped to the work-offset frame after.
    let framed = frame == Frame::Program && !it.siemens.frame.is_identity();
    let mut to = it.state.pos;
    let place = it.state.placement();
    // G53 under a rotation: the words replace machine coordinates of the
    // current point, and the whole point is turned back (rs274 `find_ends`).
    let rotated_machine = frame == Frame::Machine && place.rotation != 0.0;
    if rotated_machine {
        to = place.to_machine(&to);
    }
    if framed {
        let p = super::siemens::from_base(it, [to[0], to[1], to[2]]);
        to[..3].copy_from_slice(&p);
    }
    for (i, c) in slots(axes).into_iter().enumerate() {
        let Some(c) = c else { continue };
        let v = it.value(&c.value, exprs)?;
        let v = if i == 0 && it.state.lathe_diameter {
            v / 2.0
        } else {
            v
        };
        let v = if State::is_linear(i) {
            it.state.to_mm(v)
        } else {
            v
        };
        let absolute = match c.dim {
            Some(d) => d == DimMode::Absolute,
            None => it.state.absolute,
        };
        to[i] = match frame {
            Frame::Machine if rotated_machine => v,
            Frame::Machine => v - place.origin()[i],
            Frame::Program if absolute => v,
            Frame::Program => to[i] + v,
        };
    }
    if rotated_machine {
        to = place.from_machine(&to);
    }
    if framed {
        let b = super::siemens::to_base(it, [to[0], to[1], to[2]]);
        to[..3].copy_from_slice(&b);
    }
    Ok(to)
}

/// The axis values written (program units, as written), by index.
pub fn written(
    it: &mut Interp<'_, '_>,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<[Option<f64>; 9], Stop> {
    let mut out = [None; 9];
    for (i, c) in slots(axes).into_iter().enumerate() {
        if let Some(c) = c {
            out[i] = Some(it.value(&c.value, exprs)?);
        }
    }
    Ok(out)
}

/// The axis words by index, in the order of [`crate::ir::AXIS_LETTERS`].
fn slots(axes: &Axes) -> [Option<&Coord>; 9] {
    let Axes {
        x,
        y,
        z,
        a,
        b,
        c,
        u,
        v,
        w,
    } = axes;
    [x, y, z, a, b, c, u, v, w].map(Option::as_ref)
}
