//! Writing geometry and toleranced measures.

use super::*;

impl<'p> W<'p> {
    /// Written straight as text: points are most of a toolpath file.
    pub fn point(&mut self, p: &Point) -> Value {
        self.add_reals("CARTESIAN_POINT", &p.name, &p.xyz)
    }

    pub fn opt_point(&mut self, p: &Option<Point>) -> Value {
        opt(p.as_ref().map(|p| self.point(p)))
    }

    pub fn direction(&mut self, d: &Direction) -> Value {
        self.add_reals("DIRECTION", &d.name, &d.ratios)
    }

    pub fn opt_direction(&mut self, d: &Option<Direction>) -> Value {
        opt(d.as_ref().map(|d| self.direction(d)))
    }

    pub fn placement(&mut self, a: &Axis2Placement) -> Value {
        let params = vec![
            s(&a.name),
            self.point(&a.location),
            self.opt_direction(&a.axis),
            self.opt_direction(&a.ref_direction),
        ];
        self.add("AXIS2_PLACEMENT_3D", params)
    }

    pub fn opt_placement(&mut self, a: &Option<Axis2Placement>) -> Value {
        opt(a.as_ref().map(|a| self.placement(a)))
    }

    /// Always written as PLANE (reference/stepnc.md 3.10).
    pub fn plane(&mut self, p: &Plane) -> Value {
        let pos = self.placement(&p.position);
        self.add("PLANE", vec![s(&p.name), pos])
    }

    pub fn toleranced(&mut self, t: &Toleranced) -> Value {
        let tol = match &t.tolerance {
            Tolerance::PlusMinus {
                upper,
                lower,
                significant_digits,
            } => self.add(
                "PLUS_MINUS_VALUE",
                vec![r(*upper), r(*lower), Value::Int(*significant_digits)],
            ),
            Tolerance::LimitsAndFits {
                deviation,
                grade,
                fitting,
            } => self.add(
                "LIMITS_AND_FITS",
                vec![r(*deviation), r(*grade), oe(fitting.as_deref())],
            ),
            Tolerance::Other(raw) => self.raw(raw),
            Tolerance::Unset => Value::Null,
        };
        self.add("TOLERANCED_LENGTH_MEASURE", vec![r(t.nominal), tol])
    }

    pub fn opt_toleranced(&mut self, t: &Option<Toleranced>) -> Value {
        opt(t.as_ref().map(|t| self.toleranced(t)))
    }

    pub fn curve(&mut self, c: &Curve) -> Value {
        match c {
            Curve::Polyline { name, points } => {
                let pts = list(points.iter().map(|p| self.point(p)).collect());
                self.add("POLYLINE", vec![s(name), pts])
            }
            Curve::Arc {
                name,
                circle,
                circle_name,
                radius,
                start,
                end,
                sense,
            } => {
                let pos = self.placement(circle);
                let basis = self.add("CIRCLE", vec![s(circle_name), pos, r(*radius)]);
                self.trimmed(name, basis, start, end, *sense)
            }
            Curve::Line {
                name,
                start,
                end,
                basis,
            } => {
                let sense =
                    crate::stepnc::model_geom::line_sense(basis, start, end).unwrap_or(true);
                let basis = self.raw(basis);
                self.trimmed(name, basis, start, end, sense)
            }
            Curve::Composite {
                name,
                segments,
                self_intersect,
            } => {
                let segs = segments
                    .iter()
                    .map(|sg| {
                        let c = self.curve(&sg.curve);
                        self.add(
                            "COMPOSITE_CURVE_SEGMENT",
                            vec![e(&sg.transition), bool_value(sg.same_sense), c],
                        )
                    })
                    .collect();
                let si = match self_intersect {
                    Some(b) => bool_value(*b),
                    None => e("U"),
                };
                self.add("COMPOSITE_CURVE", vec![s(name), list(segs), si])
            }
            Curve::Other(raw) => self.raw(raw),
        }
    }

    pub fn opt_curve(&mut self, c: &Option<Curve>) -> Value {
        opt(c.as_ref().map(|c| self.curve(c)))
    }

    fn trimmed(
        &mut self,
        name: &str,
        basis: Value,
        start: &Point,
        end: &Point,
        sense: bool,
    ) -> Value {
        let t1 = self.point(start);
        let t2 = self.point(end);
        self.add(
            "TRIMMED_CURVE",
            vec![
                s(name),
                basis,
                list(vec![t1]),
                list(vec![t2]),
                bool_value(sense),
                e("CARTESIAN"),
            ],
        )
    }
}
