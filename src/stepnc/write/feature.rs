//! Writing features, profiles, paths and bottom/end conditions.

use super::*;

impl<'p> W<'p> {
    pub fn feature(&mut self, id: FeatureId) -> Value {
        if let Some(&n) = self.features.get(&id) {
            return Value::Ref(n);
        }
        let n = self.reserve();
        self.features.insert(id, n);
        let f = self.p.feature(id);
        let mut params = vec![
            s(&f.id),
            self.workpiece(f.workpiece),
            list(f.operations.iter().map(|&o| self.operation(o)).collect()),
            self.placement(&f.placement),
            opt(f.depth.as_ref().map(|d| self.plane(d))),
        ];
        let entity = self.feature_kind(&f.kind, &mut params);
        self.fill(n, &entity, params);
        Value::Ref(n)
    }

    /// Appends the kind's own parameters; returns the entity name.
    fn feature_kind(&mut self, k: &FeatureKind, out: &mut Vec<Value>) -> String {
        let name = match k {
            FeatureKind::PlanarFace {
                course_of_travel,
                removal_boundary,
                face_boundary,
                bosses,
            } => {
                out.push(self.travel_path(course_of_travel));
                out.push(self.open_profile(removal_boundary));
                out.push(opt(face_boundary.as_ref().map(|c| self.closed_profile(c))));
                out.push(self.raw_list(bosses));
                "PLANAR_FACE"
            }
            FeatureKind::RoundHole {
                diameter,
                change_in_diameter,
                bottom,
            } => {
                out.push(self.toleranced(diameter));
                out.push(self.opt_raw(change_in_diameter));
                out.push(self.hole_bottom(bottom));
                "ROUND_HOLE"
            }
            FeatureKind::ClosedPocket { pocket, boundary } => {
                self.pocket(pocket, out);
                out.push(self.closed_profile(boundary));
                "CLOSED_POCKET"
            }
            FeatureKind::OpenPocket {
                pocket,
                open_boundary,
                wall_boundary,
            } => {
                self.pocket(pocket, out);
                out.push(self.open_profile(open_boundary));
                out.push(opt(wall_boundary.as_ref().map(|w| self.open_profile(w))));
                "OPEN_POCKET"
            }
            FeatureKind::Slot {
                course_of_travel,
                swept_shape,
                end_conditions,
            } => {
                out.push(self.travel_path(course_of_travel));
                out.push(self.open_profile(swept_shape));
                out.push(list(
                    end_conditions.iter().map(|e| self.slot_end(e)).collect(),
                ));
                "SLOT"
            }
            FeatureKind::Step {
                open_boundary,
                wall_boundary,
                bosses,
            } => {
                out.push(self.travel_path(open_boundary));
                out.push(opt(wall_boundary.as_ref().map(|w| self.open_profile(w))));
                out.push(self.raw_list(bosses));
                "STEP"
            }
            FeatureKind::GeneralOutsideProfile {
                swept_shape,
                boundary,
            } => {
                out.push(self.travel_path(swept_shape));
                out.push(match boundary {
                    Profile::Closed(c) => self.closed_profile(c),
                    Profile::Open(o) => self.open_profile(o),
                });
                "GENERAL_OUTSIDE_PROFILE"
            }
            FeatureKind::ToolpathFeature => "TOOLPATH_FEATURE",
            FeatureKind::Other(raw) => {
                for v in &raw.params {
                    let v = self.raw_value(v);
                    out.push(v);
                }
                return raw.entity.clone();
            }
        };
        name.to_string()
    }

    fn pocket(&mut self, p: &PocketCommon, out: &mut Vec<Value>) {
        out.push(self.raw_list(&p.bosses));
        out.push(or(p.slope));
        out.push(match &p.bottom {
            PocketBottom::Planar => self.add("PLANAR_POCKET_BOTTOM_CONDITION", vec![]),
            PocketBottom::Through => self.add("THROUGH_POCKET_BOTTOM_CONDITION", vec![]),
            // The model's unit variant has no centre or radius to write
            // (the reader keeps such files' conditions as Other).
            PocketBottom::Radiused => self.add(
                "RADIUSED_POCKET_BOTTOM_CONDITION",
                vec![Value::Null, Value::Null],
            ),
            PocketBottom::Other(raw) => self.raw(raw),
        });
        out.push(self.opt_toleranced(&p.planar_radius));
        out.push(self.opt_toleranced(&p.orthogonal_radius));
    }

    fn hole_bottom(&mut self, b: &HoleBottom) -> Value {
        match b {
            HoleBottom::Through => self.add("THROUGH_BOTTOM_CONDITION", vec![]),
            HoleBottom::Flat => self.add("FLAT_HOLE_BOTTOM", vec![]),
            HoleBottom::FlatWithRadius { corner_radius } => {
                let t = self.toleranced(corner_radius);
                self.add("FLAT_WITH_RADIUS_HOLE_BOTTOM", vec![t])
            }
            HoleBottom::Conical {
                tip_angle,
                tip_radius,
            } => {
                let t = self.opt_toleranced(tip_radius);
                self.add("CONICAL_HOLE_BOTTOM", vec![r(*tip_angle), t])
            }
            HoleBottom::Spherical { radius } => {
                let t = self.toleranced(radius);
                self.add("SPHERICAL_HOLE_BOTTOM", vec![t])
            }
            HoleBottom::Other(raw) => self.raw(raw),
        }
    }

    fn slot_end(&mut self, e: &SlotEnd) -> Value {
        match e {
            SlotEnd::Open => self.add("OPEN_SLOT_END_TYPE", vec![]),
            SlotEnd::Radiused => self.add("RADIUSED_SLOT_END_TYPE", vec![]),
            SlotEnd::Loop => self.add("LOOP_SLOT_END_TYPE", vec![]),
            SlotEnd::Flat {
                corner_radius1,
                corner_radius2,
            } => {
                let a = self.toleranced(corner_radius1);
                let b = self.toleranced(corner_radius2);
                self.add("FLAT_SLOT_END_TYPE", vec![a, b])
            }
            SlotEnd::Woodruff { radius } => {
                let t = self.toleranced(radius);
                self.add("WOODRUFF_SLOT_END_TYPE", vec![t])
            }
            SlotEnd::Other(raw) => self.raw(raw),
        }
    }

    fn closed_profile(&mut self, c: &ClosedProfile) -> Value {
        match c {
            ClosedProfile::Rectangular {
                placement,
                width,
                length,
            } => {
                let params = vec![
                    self.opt_placement(placement),
                    self.toleranced(width),
                    self.toleranced(length),
                ];
                self.add("RECTANGULAR_CLOSED_PROFILE", params)
            }
            ClosedProfile::Circular {
                placement,
                diameter,
            } => {
                let params = vec![self.opt_placement(placement), self.toleranced(diameter)];
                self.add("CIRCULAR_CLOSED_PROFILE", params)
            }
            ClosedProfile::General { placement, shape } => {
                let params = vec![self.opt_placement(placement), self.curve(shape)];
                self.add("GENERAL_CLOSED_PROFILE", params)
            }
            ClosedProfile::Other(raw) => self.raw(raw),
        }
    }

    fn open_profile(&mut self, o: &OpenProfile) -> Value {
        match o {
            OpenProfile::Linear { placement, length } => {
                let pl = self.opt_placement(placement);
                let n = self.add(
                    "NUMERIC_PARAMETER",
                    vec![s(&length.name), r(length.value), s(&length.unit)],
                );
                self.add("LINEAR_PROFILE", vec![pl, n])
            }
            OpenProfile::SquareU {
                placement,
                width,
                first_radius,
                first_angle,
                second_radius,
                second_angle,
            } => {
                let params = vec![
                    self.opt_placement(placement),
                    self.toleranced(width),
                    opt(first_radius.as_ref().map(|t| self.toleranced(t))),
                    or(*first_angle),
                    opt(second_radius.as_ref().map(|t| self.toleranced(t))),
                    or(*second_angle),
                ];
                self.add("SQUARE_U_PROFILE", params)
            }
            OpenProfile::RoundedU { placement, width } => {
                let params = vec![self.opt_placement(placement), self.toleranced(width)];
                self.add("ROUNDED_U_PROFILE", params)
            }
            OpenProfile::Vee {
                placement,
                radius,
                angle,
                tilt_angle,
            } => {
                let params = vec![
                    self.opt_placement(placement),
                    self.toleranced(radius),
                    r(*angle),
                    r(*tilt_angle),
                ];
                self.add("VEE_PROFILE", params)
            }
            OpenProfile::PartialCircular {
                placement,
                radius,
                sweep_angle,
            } => {
                let params = vec![
                    self.opt_placement(placement),
                    self.toleranced(radius),
                    r(*sweep_angle),
                ];
                self.add("PARTIAL_CIRCULAR_PROFILE", params)
            }
            OpenProfile::General { placement, shape } => {
                let params = vec![self.opt_placement(placement), self.curve(shape)];
                self.add("GENERAL_PROFILE", params)
            }
            OpenProfile::Other(raw) => self.raw(raw),
        }
    }

    fn travel_path(&mut self, t: &TravelPath) -> Value {
        match t {
            TravelPath::Linear {
                placement,
                distance,
                direction,
            } => {
                let params = vec![
                    self.opt_placement(placement),
                    self.toleranced(distance),
                    self.direction(direction),
                ];
                self.add("LINEAR_PATH", params)
            }
            TravelPath::General { placement, path } => {
                let params = vec![self.opt_placement(placement), self.curve(path)];
                self.add("GENERAL_PATH", params)
            }
            TravelPath::Other(raw) => self.raw(raw),
        }
    }
}
