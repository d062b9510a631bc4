//! Reading the contour of a lathe profile cycle (G70/G71/G72, see
//! [`super::lathe_cycles`]): while the cycle's contour subroutine runs,
//! its blocks are not executed; each block's motion words add a line, an
//! arc, or a corner (A fillet, C chamfer) to the profile, in absolute
//! coordinates (rs274 reads the contour in G90 and G90.1 whatever is in
//! force, adding the programmed increments itself under G91; X and U are
//! diameters under G7 and halved, arc centres are not [?]). Control
//! flow and parameter assignments still run (the walker does them); feed,
//! speed and the other words of the contour's blocks are not used.

use super::{Interp, Stop};
use crate::diag::Code;
use crate::geom::turning::{Corner, Pt, Seg};
use crate::ir::{ArcDir, Arena, Block, Expr, Motion, MotionKind, StmtKind};

/// The contour read so far.
#[derive(Clone, Debug, Default)]
pub struct Contour {
    pub segs: Vec<Seg>,
    /// Where the next element starts (Z, X).
    pub at: Pt,
    /// The motion mode in force while the contour is read (`None`: none,
    /// under which a move adds nothing).
    pub motion: Option<MotionKind>,
    /// G91 and incremental arc centres when the cycle started.
    pub incremental: bool,
    pub arc_incremental: bool,
}

fn fail(it: &Interp<'_, '_>, msg: &str) -> Stop {
    it.error_at(it.span, Code::LatheProfileFailed, msg)
}

/// Adds the motion of one contour block.
pub fn record(
    it: &mut Interp<'_, '_>,
    c: &mut Contour,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let r = record_moves(it, c, block, exprs);
    it.lathe.reading_at = None;
    r
}

fn record_moves(
    it: &mut Interp<'_, '_>,
    c: &mut Contour,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    for s in &block.stmts {
        if let StmtKind::Motion(m) = &s.kind {
            it.span = s.span;
            it.lathe.reading_at = Some(c.at);
            motion(it, c, m, exprs)?;
        }
    }
    Ok(())
}

fn val(
    it: &mut Interp<'_, '_>,
    w: Option<&crate::ir::Coord>,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    w.map(|c| it.value(&c.value, exprs)).transpose()
}

fn motion(
    it: &mut Interp<'_, '_>,
    c: &mut Contour,
    m: &Motion,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if m.kind != MotionKind::Implicit {
        c.motion = Some(m.kind);
    }
    let t = &m.target;
    let (x, z) = (val(it, t.x.as_ref(), exprs)?, val(it, t.z.as_ref(), exprs)?);
    let (u, w) = (val(it, t.u.as_ref(), exprs)?, val(it, t.w.as_ref(), exprs)?);
    let start = c.at;
    let mut end = if c.incremental {
        Pt::new(0.0, 0.0)
    } else {
        start
    };
    if let Some(u) = u {
        if c.incremental {
            return Err(fail(
                it,
                "G7x error: Cannot use U in incremental mode (G91)",
            ));
        }
        if x.is_some() {
            return Err(fail(it, "G7x error: Cannot use U and X in the same block"));
        }
        end.im += if it.state.lathe_diameter { u / 2.0 } else { u };
    } else if let Some(x) = x {
        // rs274 halves X as it reads it in diameter mode (G7).
        end.im = if it.state.lathe_diameter { x / 2.0 } else { x };
    }
    if let Some(w) = w {
        if c.incremental {
            return Err(fail(
                it,
                "G7x error: Cannot use W in incremental mode (G91)",
            ));
        }
        if z.is_some() {
            return Err(fail(it, "G7x error: Cannot use W and Z in the same block"));
        }
        end.re += w;
    } else if let Some(z) = z {
        end.re = z;
    }
    if c.incremental {
        end += start;
    }
    if start == end {
        return Ok(());
    }
    let seg = match c.motion {
        Some(MotionKind::Rapid | MotionKind::Linear) => Some(Seg::line(start, end)),
        Some(MotionKind::Arc(dir)) => Some(arc(it, c, m, dir == ArcDir::Ccw, start, end, exprs)?),
        _ => None,
    };
    if let Some(seg) = seg {
        c.segs.push(seg);
        corner(it, c, m, end, exprs)?;
    }
    c.at = end;
    Ok(())
}

#[allow(clippy::too_many_arguments)]
fn arc(
    it: &mut Interp<'_, '_>,
    c: &Contour,
    m: &Motion,
    ccw: bool,
    start: Pt,
    end: Pt,
    exprs: &Arena<Expr>,
) -> Result<Seg, Stop> {
    let i = val(it, m.arc.i.as_ref(), exprs)?;
    let k = val(it, m.arc.k.as_ref(), exprs)?;
    let center = if let Some(r) = &m.arc.radius {
        if i.is_some() || k.is_some() {
            return Err(fail(it, "G7X error: both R and I or K flag used for arc"));
        }
        let r = it.value(r, exprs)?;
        let chord = end - start;
        let h = ((r * r - chord.norm_sqr() / 4.0) / chord.norm_sqr()).sqrt();
        let d = Pt::i() * h * chord;
        let mid = (start + end) / 2.0;
        if ccw {
            mid + d
        } else {
            mid - d
        }
    } else {
        if i.is_none() && k.is_none() {
            return Err(fail(it, "G7X error: either I or K must be present for arc"));
        }
        let centre = Pt::new(k.unwrap_or(0.0), i.unwrap_or(0.0));
        if c.arc_incremental {
            centre + start
        } else {
            centre
        }
    };
    Ok(Seg::arc(ccw, start, center, end))
}

/// A or C on a contour move: a fillet or chamfer at its end.
fn corner(
    it: &mut Interp<'_, '_>,
    c: &mut Contour,
    m: &Motion,
    end: Pt,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let a = val(it, m.target.a.as_ref(), exprs)?;
    let ch = val(it, m.target.c.as_ref(), exprs)?;
    match (a, ch) {
        (Some(_), Some(_)) => Err(fail(it, "G7X error: Both A and C parameters on a corner")),
        (Some(r), None) => {
            c.segs.push(Seg::corner(Corner::Fillet, r, end));
            Ok(())
        }
        (None, Some(l)) => {
            c.segs.push(Seg::corner(Corner::Chamfer, l, end));
            Ok(())
        }
        (None, None) => Ok(()),
    }
}
