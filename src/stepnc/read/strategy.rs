//! Reading two5D milling strategies and approach/retract strategies.

use super::*;

impl<'f> Rd<'f> {
    pub fn strategy(&mut self, i: &'f Instance) -> R<Strategy> {
        let e = ent(i);
        let base = StrategyBase {
            overlap: opt_real(arg(i, 0)?)?,
            allow_multiple_passes: opt_bool(arg(i, 1)?)?,
        };
        let a = |k: usize| arg(i, 2 + k);
        Ok(match e {
            "UNIDIRECTIONAL" => Strategy::Unidirectional {
                base,
                feed_direction: self.opt_direction(a(0)?)?,
                cutmode: cutmode(a(1)?)?,
            },
            "BIDIRECTIONAL" => Strategy::Bidirectional {
                base,
                feed_direction: self.opt_direction(a(0)?)?,
                stepover_direction: left_right(a(1)?)?,
                stroke_connection: opt_enum(a(2)?)?.map(str::to_string),
            },
            "CONTOUR_PARALLEL" => Strategy::ContourParallel {
                base,
                rotation: rotation(a(0)?)?,
                cutmode: cutmode(a(1)?)?,
            },
            "BIDIRECTIONAL_CONTOUR" | "CONTOUR_BIDIRECTIONAL" => Strategy::BidirectionalContour {
                contour_first: e == "CONTOUR_BIDIRECTIONAL",
                base,
                feed_direction: self.opt_direction(a(0)?)?,
                stepover_direction: left_right(a(1)?)?,
                rotation: rotation(a(2)?)?,
                cutmode: cutmode(a(3)?)?,
            },
            "CONTOUR_SPIRAL" => Strategy::ContourSpiral {
                base,
                rotation: rotation(a(0)?)?,
                cutmode: cutmode(a(1)?)?,
            },
            "CENTER_MILLING" => Strategy::CenterMilling { base },
            "EXPLICIT_STRATEGY" => Strategy::Explicit { base },
            _ => {
                return Err(fail(
                    i.entity_span,
                    "not a two5D milling strategy cncc models",
                ))
            }
        })
    }

    pub fn opt_approach(&mut self, p: &'f Param) -> R<Option<ApproachRetract>> {
        match self.opt_inst(p)? {
            Some(i) => self
                .or_raw(i, |rd, i| rd.approach(i), ApproachRetract::Other)
                .map(Some),
            None => Ok(None),
        }
    }

    fn approach(&mut self, i: &'f Instance) -> R<ApproachRetract> {
        let orientation = self.opt_direction(arg(i, 0)?)?;
        let r = |k| real(arg(i, k)?);
        Ok(match ent(i) {
            "PLUNGE_TOOLAXIS" => ApproachRetract::PlungeToolaxis { orientation },
            "PLUNGE_RAMP" => ApproachRetract::PlungeRamp {
                orientation,
                angle: r(1)?,
            },
            "PLUNGE_HELIX" => ApproachRetract::PlungeHelix {
                orientation,
                radius: r(1)?,
                angle: r(2)?,
            },
            "PLUNGE_ZIGZAG" => ApproachRetract::PlungeZigzag {
                orientation,
                angle: r(1)?,
                width: r(2)?,
            },
            "AP_RETRACT_ANGLE" => ApproachRetract::RetractAngle {
                orientation,
                angle: r(1)?,
                travel_length: r(2)?,
            },
            "AP_RETRACT_TANGENT" => ApproachRetract::RetractTangent {
                orientation,
                radius: r(1)?,
            },
            "ALONG_PATH" => ApproachRetract::AlongPath {
                orientation,
                path: self.toolpath_list_at(arg(i, 1)?)?,
            },
            _ => return Err(fail(i.entity_span, "not an approach/retract strategy")),
        })
    }
}

fn cutmode(p: &Param) -> R<Option<CutMode>> {
    Ok(match opt_enum(p)? {
        None => None,
        Some("CLIMB") => Some(CutMode::Climb),
        Some("CONVENTIONAL") => Some(CutMode::Conventional),
        Some(_) => return Err(fail(p.span, "cutmode is .CLIMB. or .CONVENTIONAL.")),
    })
}

fn rotation(p: &Param) -> R<Option<RotDirection>> {
    Ok(match opt_enum(p)? {
        None => None,
        Some("CW") => Some(RotDirection::Cw),
        Some("CCW") => Some(RotDirection::Ccw),
        Some(_) => return Err(fail(p.span, "rotation_direction is .CW. or .CCW.")),
    })
}

fn left_right(p: &Param) -> R<Option<LeftOrRight>> {
    Ok(match opt_enum(p)? {
        None => None,
        Some("LEFT") => Some(LeftOrRight::Left),
        Some("RIGHT") => Some(LeftOrRight::Right),
        Some(_) => return Err(fail(p.span, "stepover_direction is .LEFT. or .RIGHT.")),
    })
}
