//! Round holes made by a milling operation (ISO 14649-11 `ROUND_HOLE`
//! with `BOTTOM_AND_SIDE_ROUGH_MILLING` / `_FINISH_MILLING`): a circular
//! pocket of the hole's diameter. Where the target has a circular pocket
//! cycle for the tool (840D `POCKET4` for any tool, `POCKET2` and
//! Heidenhain `CYCL DEF 252` for centre-cutting tools) the hole is that
//! cycle, entering on a helix where the operation's approach is
//! `PLUNGE_HELIX`; elsewhere (Fanuc, Haas, LinuxCNC, and a Heidenhain
//! without a centre-cutting tool) it is exact helical moves and a
//! finishing circle ([`super::paths::helix`]). Haas G12/G13 is not used:
//! it plunges at the centre. A flat or through bottom is milled; a flat
//! bottom's corner radius is the tool's; other bottoms (conical,
//! spherical) are refused: the floor of a milled hole is flat.

use super::milling::{explicit_moves, Cut};
use super::paths::helix::{self, HoleCut};
use super::paths::pocket::Shape;
use super::plan::Step;
use super::pockets::cuts_across_centre;
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    diameter: f64,
    bottom: &HoleBottom,
) -> Result<(), PostError> {
    match bottom {
        HoleBottom::Through | HoleBottom::Flat => {}
        HoleBottom::FlatWithRadius { .. } => {
            w.not_carried("the hole's bottom corner radius: the tool's corner makes it")?
        }
        HoleBottom::Conical { .. } | HoleBottom::Spherical { .. } | HoleBottom::Other(_) => {
            return Err(PostError::unsupported(
                &s.feature.id,
                "a milled round hole whose bottom is not flat (a milling operation leaves a flat floor)",
            ))
        }
    }
    let centre = cuts_across_centre(&s.tool.body.kind);
    let cycle = (w.post.has("pocket_circ.j2") && centre) || w.post.has("pocket_circ_any.j2");
    if cycle {
        w.comment("milled round hole: the target's circular pocket cycle")?;
        let shape = Shape::Circle { diameter };
        return super::pockets::write(w, s, c, &shape, &s.frame, true);
    }
    let d = s.tool.body.dimension.diameter;
    let cut = super::pockets::pocket_cut(s, c)?;
    let hr = helix::helix_radius(diameter, &cut);
    let pitch = pitch(c, hr, d / 2.0);
    let hc = HoleCut { cut, pitch };
    helix::check(diameter, &hc).map_err(|e| PostError::geometry(&s.feature.id, e))?;
    if !matches!(
        c.strategy,
        None | Some(Strategy::ContourParallel { .. }) | Some(Strategy::ContourSpiral { .. })
    ) {
        w.not_carried("the operation's strategy: the hole is cleared in rings from a helix")?;
    }
    w.comment(&format!(
        "milled round hole: helix of radius {} mm, {} mm a turn, then circles out to the wall",
        w.fmt.plain(hr, 3),
        w.fmt.plain(hc.pitch, 3)
    ))?;
    explicit_moves(w, s, &s.frame, |sink| helix::moves(diameter, &hc, sink))
}

/// The helix's descent per turn: from the approach's `PLUNGE_HELIX`
/// angle where given (its radius is the hole's, not the strategy's), else
/// the axial depth of cut up to the tool radius [?: a common shop rule,
/// not from ISO 14649].
fn pitch(c: &Cut<'_>, helix_radius: f64, tool_radius: f64) -> f64 {
    let from_angle = match c.approach {
        Some(ApproachRetract::PlungeHelix { angle, .. }) if *angle > 0.0 && *angle < 90.0 => {
            Some(std::f64::consts::TAU * helix_radius * angle.to_radians().tan())
        }
        _ => None,
    };
    from_angle.filter(|p| *p > 1e-3).unwrap_or_else(|| {
        c.ap.filter(|a| *a > 1e-3)
            .map_or(tool_radius, |a| a.min(tool_radius))
    })
}
