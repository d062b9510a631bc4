//! Milled features: closed rectangular pockets (POCKET1/POCKET3 where the
//! target has them, explicit contour-parallel toolpaths otherwise) and
//! planar faces (CYCLE71, or explicit zigzag toolpaths).

use super::frame::Frame;
use super::names::operation_kind;
use super::paths::{self, pocket, MoveSink};
use super::plan::Step;
use super::step::{feed, spindle_rpm};
use super::{explicit, PostError, Writer};
use crate::stepnc::model::*;

/// The workingstep `steps[0]` (several only for alike slots, which are
/// written together).
pub fn write(w: &mut Writer<'_>, project: &Project, steps: &[&Step<'_>]) -> Result<(), PostError> {
    let s = steps[0];
    let (finish, milling, ap, ae, allow_side, allow_bottom) = match &s.op.kind {
        OperationKind::BottomAndSideMilling {
            finish,
            milling,
            axial_cutting_depth,
            radial_cutting_depth,
            allowance_side,
            allowance_bottom,
        } => (
            *finish,
            milling,
            *axial_cutting_depth,
            *radial_cutting_depth,
            allowance_side.unwrap_or(0.0),
            allowance_bottom.unwrap_or(0.0),
        ),
        OperationKind::PlaneMilling {
            finish,
            milling,
            axial_cutting_depth,
            allowance_bottom,
        } => (
            *finish,
            milling,
            *axial_cutting_depth,
            None,
            0.0,
            allowance_bottom.unwrap_or(0.0),
        ),
        _ => {
            return Err(PostError::unsupported(
                &s.op.id,
                &format!(
                    "a {} on a {}",
                    operation_kind(&s.op.kind),
                    super::names::feature_kind(&s.feature.kind)
                ),
            ))
        }
    };
    let cut = Cut {
        finish,
        strategy: milling.strategy.as_ref(),
        approach: milling.approach.as_ref(),
        ap,
        ae,
        allow_side,
        allow_bottom,
    };
    match &s.feature.kind {
        FeatureKind::ClosedPocket { pocket, boundary } => {
            let (placement, shape) = match (&s.op.kind, boundary) {
                (
                    OperationKind::BottomAndSideMilling { .. },
                    ClosedProfile::Rectangular {
                        placement,
                        width,
                        length,
                    },
                ) => (
                    placement,
                    pocket::Shape::Rect(pocket::RectPocket {
                        length: length.nominal,
                        width: width.nominal,
                        corner_radius: pocket
                            .orthogonal_radius
                            .as_ref()
                            .map_or(0.0, |r| r.nominal),
                    }),
                ),
                (
                    OperationKind::BottomAndSideMilling { .. },
                    ClosedProfile::Circular {
                        placement,
                        diameter,
                    },
                ) => (
                    placement,
                    pocket::Shape::Circle {
                        diameter: diameter.nominal,
                    },
                ),
                (
                    OperationKind::BottomAndSideMilling { .. },
                    ClosedProfile::General { placement, shape },
                ) => {
                    let frame = match placement {
                        Some(p) => s.frame.then(&Frame::from_placement(p)),
                        None => s.frame,
                    };
                    pocket_notes(w, s, pocket)?;
                    return super::pocket_general::write(w, s, &cut, pocket, shape, &frame);
                }
                _ => {
                    return Err(PostError::unsupported(
                        &s.feature.id,
                        "a pocket whose outline cncc does not read, or not cut by bottom and side milling,",
                    ))
                }
            };
            let frame = match placement {
                Some(p) => s.frame.then(&Frame::from_placement(p)),
                None => s.frame,
            };
            pocket_notes(w, s, pocket)?;
            super::pockets::write(w, s, &cut, &shape, &frame, true)
        }
        FeatureKind::PlanarFace { .. } => super::faces::write(w, s, &cut),
        FeatureKind::RoundHole {
            diameter, bottom, ..
        } if matches!(s.op.kind, OperationKind::BottomAndSideMilling { .. }) => {
            super::hole_mill::write(w, s, &cut, diameter.nominal, bottom)
        }
        FeatureKind::Slot { .. } if super::prismatic::is_profiled_slot(&s.feature.kind) => {
            for st in steps {
                let ctx = context(project, st);
                super::prismatic::write_slot(w, st, &cut, &ctx)?;
            }
            Ok(())
        }
        FeatureKind::Step { .. } => super::prismatic::write_step(w, s, &cut, &context(project, s)),
        FeatureKind::Slot { .. } => {
            if w.post.has("slot.j2") && super::slot_cycle::write(w, s, &cut)? {
                return Ok(());
            }
            super::slots::write_group(w, steps, &cut)
        }
        _ => Err(PostError::unsupported(
            &s.op.id,
            &format!(
                "a {} on a {}",
                operation_kind(&s.op.kind),
                super::names::feature_kind(&s.feature.kind)
            ),
        )),
    }
}

/// The tolerance, stock and later cuts of a prismatic feature's step.
fn context(project: &Project, s: &Step<'_>) -> super::prismatic::Context {
    let base = super::plan::setup_frame(project);
    super::prismatic::Context {
        tol: super::step::tolerance(project, s).unwrap_or(super::prismatic::DEFAULT_TOL),
        stock: s
            .tilt
            .is_none()
            .then(|| super::validate::stock(project, s.feature.workpiece, &base))
            .flatten(),
        later: s.later,
    }
}

/// What a milling operation asks, read once.
pub struct Cut<'p> {
    pub finish: bool,
    pub strategy: Option<&'p Strategy>,
    pub approach: Option<&'p ApproachRetract>,
    pub ap: Option<f64>,
    pub ae: Option<f64>,
    pub allow_side: f64,
    pub allow_bottom: f64,
}

impl Cut<'_> {
    /// The strategy's overlap as a ratio (values over 1 read as percent).
    pub fn overlap(&self) -> Option<f64> {
        let base = match self.strategy? {
            Strategy::Unidirectional { base, .. }
            | Strategy::Bidirectional { base, .. }
            | Strategy::ContourParallel { base, .. }
            | Strategy::BidirectionalContour { base, .. }
            | Strategy::ContourSpiral { base, .. }
            | Strategy::CenterMilling { base }
            | Strategy::Explicit { base } => base,
            Strategy::Other(_) => return None,
        };
        base.overlap.map(|o| if o > 1.0 { o / 100.0 } else { o })
    }

    /// The stepover: the radial depth, else the diameter less the overlap,
    /// else half the diameter.
    pub fn stepover(&self, diameter: f64) -> f64 {
        match (self.ae, self.overlap()) {
            (Some(ae), _) => ae,
            (None, Some(o)) => diameter * (1.0 - o),
            (None, None) => diameter / 2.0,
        }
    }

    /// Loops counter-clockwise? The cut mode decides when given (climb =
    /// counter-clockwise inside a pocket with the spindle clockwise), else
    /// the rotation direction (default counter-clockwise).
    pub fn ccw(&self, spindle_cw: bool) -> bool {
        let (rotation, cutmode) = match self.strategy {
            Some(Strategy::ContourParallel {
                rotation, cutmode, ..
            })
            | Some(Strategy::ContourSpiral {
                rotation, cutmode, ..
            })
            | Some(Strategy::BidirectionalContour {
                rotation, cutmode, ..
            }) => (*rotation, *cutmode),
            _ => (None, None),
        };
        match cutmode {
            Some(CutMode::Climb) => spindle_cw,
            Some(CutMode::Conventional) => !spindle_cw,
            None => rotation != Some(RotDirection::Cw),
        }
    }
}

fn pocket_notes(w: &mut Writer<'_>, s: &Step<'_>, p: &PocketCommon) -> Result<(), PostError> {
    if !p.bosses.is_empty() {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a pocket with bosses",
        ));
    }
    if p.slope.is_some_and(|a| a.abs() > 1e-9) {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a pocket with sloped walls",
        ));
    }
    match &p.bottom {
        PocketBottom::Planar | PocketBottom::Through => {}
        PocketBottom::Radiused | PocketBottom::Other(_) => {
            return Err(PostError::unsupported(
                &s.feature.id,
                "a pocket with this bottom",
            ))
        }
    }
    if p.planar_radius.as_ref().is_some_and(|r| r.nominal > 0.0) {
        w.not_carried("the pocket's bottom fillet (planar radius): the tool's corner makes it")?;
    }
    Ok(())
}

/// The spindle turns clockwise (M3)?
pub fn spindle_cw(s: &Step<'_>) -> Result<bool, PostError> {
    Ok(spindle_rpm(s)? >= 0.0)
}

/// Writes explicit moves after generating them with `gen`.
pub fn explicit_moves(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    frame: &Frame,
    gen: impl FnOnce(&mut MoveSink<'_>),
) -> Result<(), PostError> {
    let mut sink = MoveSink::new(frame);
    gen(&mut sink);
    w.comment(&format!("explicit toolpath: {} moves", sink.moves.len()))?;
    explicit::write(w, &sink.moves, feed(s)?)
}

/// The layers of a cut from the top to the bottom plus allowance.
pub fn layers(s: &Step<'_>, c: &Cut<'_>, bottom_allowance: f64) -> Vec<f64> {
    paths::levels(s.top, s.bottom + bottom_allowance, c.ap)
}
