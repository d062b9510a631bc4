//! Reading geometry (points, directions, placements, planes, curves) and
//! toleranced measures.

use super::*;

impl<'f> Rd<'f> {
    pub fn point(&mut self, i: &'f Instance) -> R<Point> {
        expect(i, &["CARTESIAN_POINT"], "a CARTESIAN_POINT")?;
        Ok(Point {
            name: string(arg(i, 0)?)?,
            xyz: triple(arg(i, 1)?)?,
        })
    }

    pub fn opt_point(&mut self, p: &'f Param) -> R<Option<Point>> {
        match self.opt_inst(p)? {
            Some(i) => self.point(i).map(Some),
            None => Ok(None),
        }
    }

    pub fn direction(&mut self, i: &'f Instance) -> R<Direction> {
        expect(i, &["DIRECTION"], "a DIRECTION")?;
        Ok(Direction {
            name: string(arg(i, 0)?)?,
            ratios: triple(arg(i, 1)?)?,
        })
    }

    pub fn opt_direction(&mut self, p: &'f Param) -> R<Option<Direction>> {
        match self.opt_inst(p)? {
            Some(i) => self.direction(i).map(Some),
            None => Ok(None),
        }
    }

    pub fn placement(&mut self, i: &'f Instance) -> R<Axis2Placement> {
        expect(i, &["AXIS2_PLACEMENT_3D"], "an AXIS2_PLACEMENT_3D")?;
        let loc = self.inst(arg(i, 1)?)?;
        Ok(Axis2Placement {
            name: string(arg(i, 0)?)?,
            location: self.point(loc)?,
            axis: self.opt_direction(arg(i, 2)?)?,
            ref_direction: self.opt_direction(arg(i, 3)?)?,
        })
    }

    pub fn opt_placement(&mut self, p: &'f Param) -> R<Option<Axis2Placement>> {
        match self.opt_inst(p)? {
            Some(i) => self.placement(i).map(Some),
            None => Ok(None),
        }
    }

    /// PLANE or ELEMENTARY_SURFACE (same two attributes).
    pub fn plane(&mut self, i: &'f Instance) -> R<Plane> {
        expect(i, &["PLANE", "ELEMENTARY_SURFACE"], "a PLANE")?;
        let pos = self.inst(arg(i, 1)?)?;
        Ok(Plane {
            name: string(arg(i, 0)?)?,
            position: self.placement(pos)?,
        })
    }

    pub fn toleranced(&mut self, i: &'f Instance) -> R<Toleranced> {
        expect(
            i,
            &["TOLERANCED_LENGTH_MEASURE"],
            "a TOLERANCED_LENGTH_MEASURE",
        )?;
        let tolerance = match self.opt_inst(arg(i, 1)?)? {
            Some(t) => self.or_raw(t, |rd, t| rd.tolerance(t), Tolerance::Other)?,
            // `$` (W0803): the nominal size holds, with no tolerance given.
            None => Tolerance::Unset,
        };
        Ok(Toleranced {
            nominal: real(arg(i, 0)?)?,
            tolerance,
        })
    }

    pub fn toleranced_at(&mut self, p: &'f Param) -> R<Toleranced> {
        let i = self.inst(p)?;
        self.toleranced(i)
    }

    pub fn opt_toleranced(&mut self, p: &'f Param) -> R<Option<Toleranced>> {
        match self.opt_inst(p)? {
            Some(i) => self.toleranced(i).map(Some),
            None => Ok(None),
        }
    }

    fn tolerance(&mut self, i: &'f Instance) -> R<Tolerance> {
        Ok(match ent(i) {
            "PLUS_MINUS_VALUE" => Tolerance::PlusMinus {
                upper: real(arg(i, 0)?)?,
                lower: real(arg(i, 1)?)?,
                significant_digits: int(arg(i, 2)?)?,
            },
            "LIMITS_AND_FITS" => Tolerance::LimitsAndFits {
                deviation: real(arg(i, 0)?)?,
                grade: real(arg(i, 1)?)?,
                fitting: opt_enum(arg(i, 2)?)?.map(str::to_string),
            },
            _ => {
                return Err(fail(
                    i.entity_span,
                    "expected PLUS_MINUS_VALUE or LIMITS_AND_FITS",
                ))
            }
        })
    }

    pub fn numeric_parameter(&mut self, i: &'f Instance) -> R<NumericParameter> {
        expect(i, &["NUMERIC_PARAMETER"], "a NUMERIC_PARAMETER")?;
        Ok(NumericParameter {
            name: string(arg(i, 0)?)?,
            value: real(arg(i, 1)?)?,
            unit: string(arg(i, 2)?)?,
        })
    }

    // ------------------------------------------------------------ curves

    pub fn curve(&mut self, i: &'f Instance) -> R<Curve> {
        self.enter(i.span)?;
        let c = self.or_raw(i, |rd, i| rd.typed_curve(i), Curve::Other);
        self.leave();
        c
    }

    pub fn opt_curve(&mut self, p: &'f Param) -> R<Option<Curve>> {
        match self.opt_inst(p)? {
            Some(i) => self.curve(i).map(Some),
            None => Ok(None),
        }
    }

    fn typed_curve(&mut self, i: &'f Instance) -> R<Curve> {
        match ent(i) {
            "POLYLINE" => {
                let mut points = Vec::new();
                for q in self.insts(arg(i, 1)?)? {
                    points.push(self.point(q)?);
                }
                Ok(Curve::Polyline {
                    name: string(arg(i, 0)?)?,
                    points,
                })
            }
            "TRIMMED_CURVE" => self.trimmed(i),
            "COMPOSITE_CURVE" => {
                let mut segments = Vec::new();
                for s in self.insts(arg(i, 1)?)? {
                    expect(s, &["COMPOSITE_CURVE_SEGMENT"], "a COMPOSITE_CURVE_SEGMENT")?;
                    let c = self.inst(arg(s, 2)?)?;
                    segments.push(CompositeSegment {
                        transition: enumeration(arg(s, 0)?)?.to_string(),
                        same_sense: boolean(arg(s, 1)?)?,
                        curve: self.curve(c)?,
                    });
                }
                Ok(Curve::Composite {
                    name: string(arg(i, 0)?)?,
                    segments,
                    self_intersect: logical(arg(i, 2)?)?,
                })
            }
            _ => Err(fail(i.entity_span, "not a curve cncc models")),
        }
    }

    /// A TRIMMED_CURVE of a CIRCLE (an arc) or a LINE, trimmed by one
    /// cartesian point at each end, with the cartesian preference.
    fn trimmed(&mut self, i: &'f Instance) -> R<Curve> {
        let name = string(arg(i, 0)?)?;
        let start = self.trim_point(arg(i, 2)?)?;
        let end = self.trim_point(arg(i, 3)?)?;
        let sense = boolean(arg(i, 4)?)?;
        if enumeration(arg(i, 5)?)? != "CARTESIAN" {
            return Err(fail(
                arg(i, 5)?.span,
                "only the .CARTESIAN. trimming preference is modelled",
            ));
        }
        let basis = self.inst(arg(i, 1)?)?;
        match ent(basis) {
            "CIRCLE" => {
                let pos = self.inst(arg(basis, 1)?)?;
                Ok(Curve::Arc {
                    name,
                    circle: self.placement(pos)?,
                    circle_name: string(arg(basis, 0)?)?,
                    radius: real(arg(basis, 2)?)?,
                    start,
                    end,
                    sense,
                })
            }
            "LINE" => {
                // The model keeps no sense flag for a line: it is the one
                // the geometry gives (start → end along the line's vector
                // or against it), and the writer derives it again.
                let basis = self.raw(basis)?;
                if crate::stepnc::model_geom::line_sense(&basis, &start, &end).unwrap_or(true)
                    != sense
                {
                    return Err(fail(
                        arg(i, 4)?.span,
                        "sense_agreement disagrees with the line's direction",
                    ));
                }
                Ok(Curve::Line {
                    name,
                    start,
                    end,
                    basis,
                })
            }
            _ => Err(fail(
                basis.entity_span,
                "a trimmed curve of this basis is not modelled",
            )),
        }
    }

    fn trim_point(&mut self, p: &'f Param) -> R<Point> {
        match list(p)? {
            [one] => {
                let i = self.inst(one)?;
                self.point(i)
            }
            _ => Err(fail(p.span, "expected one cartesian point as trim")),
        }
    }
}

/// A LOGICAL: .T., .F. or .U. (None).
fn logical(p: &Param) -> R<Option<bool>> {
    match &p.value {
        Value::Enum(e) if e == "U" => Ok(None),
        _ => boolean(p).map(Some),
    }
}

/// Three coordinates; a 2D point or direction gets z = 0 only if the
/// writer can say so again, so it is refused (kept raw) instead.
fn triple(p: &Param) -> R<P3> {
    match list(p)? {
        [x, y, z] => Ok([real(x)?, real(y)?, real(z)?]),
        _ => Err(fail(p.span, "expected three coordinates")),
    }
}
