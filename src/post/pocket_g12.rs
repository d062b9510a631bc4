//! A circular pocket posted as Haas G12 (clockwise) / G13 (counter-
//! clockwise), where the target has `pocket_circ_g12.j2`: one cycle call
//! per depth level, each at the pocket's centre, with D0 so that the radii
//! are the tool centre's (the program does not depend on the machine's
//! diameter offsets): I the first circle (at most the tool radius out, so
//! the centre is cleared), Q the stepover, K the last circle (the wall
//! less the tool radius and the side allowance). A finishing operation
//! after a roughing one cuts only the wall circle on the upper levels and
//! the whole floor at the bottom (as the explicit path does). The path
//! between the circles is the control's ([?], see
//! `interp/haas_pocket.rs` for how cncc runs it).

use super::frame::Frame;
use super::milling::Cut;
use super::paths::pocket::PocketCut;
use super::plan::Step;
use super::step::feed;
use super::values::Vals;
use super::{PostError, Writer};

pub fn write(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    diameter: f64,
    frame: &Frame,
    pcut: &PocketCut,
) -> Result<(), PostError> {
    let last = diameter / 2.0 - pcut.tool_radius - pcut.allowance_side;
    if last <= 1e-6 {
        return Err(PostError::geometry(
            &s.feature.id,
            format!("the tool leaves no circle to cut in a pocket of diameter {diameter}"),
        ));
    }
    let first = last.min(pcut.tool_radius).min(pcut.stepover);
    let f = w.fmt.feed(feed(s)?);
    let g = if pcut.ccw { "13" } else { "12" };
    w.comment(&format!(
        "circular pocket: G{g}, D0 (radii of the tool centre), one call per level"
    ))?;
    if !matches!(
        c.strategy,
        None | Some(crate::stepnc::model::Strategy::ContourParallel { .. })
            | Some(crate::stepnc::model::Strategy::ContourSpiral { .. })
    ) {
        w.not_carried("the operation's strategy: G12/G13 cut circles from the centre out")?;
    }
    w.emit(
        "rapid.j2",
        Vals::new()
            .set("x", w.fmt.len(frame.origin[0]))
            .set("y", w.fmt.len(frame.origin[1]))
            .set("z", w.fmt.len(pcut.r_plane)),
    )?;
    let bottom = pcut.levels.last().copied();
    for z in &pcut.levels {
        let walls_only = pcut.walls_only_above_bottom && Some(*z) != bottom;
        let (i, rings) = if walls_only || (last - first).abs() < 1e-6 {
            (last, false)
        } else {
            (first, true)
        };
        let v = Vals::new()
            .set("g", g)
            .set("i", w.fmt.len(i))
            .set("rings", if rings { "1" } else { "" })
            .set("k", w.fmt.len(last))
            .set("q", w.fmt.len(pcut.stepover))
            .set("z", w.fmt.len(*z))
            .set("f", f.clone());
        w.emit("pocket_circ_g12.j2", v)?;
    }
    Ok(())
}
