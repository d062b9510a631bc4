//! Reading manufacturing features, their profiles, paths and bottom and
//! end conditions. A feature whose own attributes do not fit keeps them
//! as `FeatureKind::Other(Raw)`: the entity and the parameters after the
//! five every machining feature has.

use super::*;

/// Parameters every machining feature starts with.
pub(crate) const FEATURE_COMMON: usize = 5;

/// Features of ISO 14649-10/11 read and carried as written (region and
/// transition features, bosses, compound holes, spherical caps): their
/// workingsteps are kept raw and posting refuses them by name.
const CARRIED_FEATURES: &[&str] = &[
    "REGION_SURFACE_LIST",
    "REGION_PROJECTION",
    "BOSS",
    "SPHERICAL_CAP",
    "CHAMFER",
    "EDGE_ROUND",
    "COUNTERBORE_HOLE",
    "COUNTERSUNK_HOLE",
];

impl<'f> Rd<'f> {
    /// A feature, read once and shared.
    pub fn feature(&mut self, i: &'f Instance) -> R<FeatureId> {
        if let Some(&id) = self.features.get(&i.id) {
            return Ok(id);
        }
        if CARRIED_FEATURES.contains(&ent(i)) {
            // Not invalid: the workingstep is kept as written (W0802) and
            // posting names it.
            return Err(fail(
                i.entity_span,
                format!(
                    "{} (#{}) is an ISO 14649 feature cncc carries but does not model",
                    i.entity, i.id
                ),
            ));
        }
        expect(
            i,
            &[
                "PLANAR_FACE",
                "ROUND_HOLE",
                "CLOSED_POCKET",
                "OPEN_POCKET",
                "SLOT",
                "STEP",
                "GENERAL_OUTSIDE_PROFILE",
                "TOOLPATH_FEATURE",
            ],
            "a machining feature",
        )?;
        if !self.open.insert(i.id) {
            return Err(fail(i.span, "the feature refers back to itself"));
        }
        let f = self.feature_body(i);
        self.open.remove(&i.id);
        let f = f?;
        self.ids.push((f.id.clone(), "feature", i.span));
        let id = FeatureId(self.p.features.len() as u32);
        self.p.features.push(f);
        self.features.insert(i.id, id);
        Ok(id)
    }

    fn feature_body(&mut self, i: &'f Instance) -> R<Feature> {
        let id = string(arg(i, 0)?)?;
        let workpiece = match arg(i, 1)?.value {
            // Mandatory, but `$` in some generators' files: the project's
            // one workpiece is the only one it can mean (W0803 says so).
            Value::Null => self.sole_workpiece(arg(i, 1)?)?,
            _ => {
                let w = self.inst(arg(i, 1)?)?;
                self.workpiece(w)?
            }
        };
        let mut operations = Vec::new();
        for o in self.insts(arg(i, 2)?)? {
            operations.push(self.operation(o)?);
        }
        let pl = self.inst(arg(i, 3)?)?;
        let placement = self.placement(pl)?;
        let depth = match self.opt_inst(arg(i, 4)?)? {
            Some(d) => Some(self.plane(d)?),
            None => None,
        };
        let kind = self.feature_kind(i)?;
        Ok(Feature {
            id,
            workpiece,
            operations,
            placement,
            depth,
            kind,
        })
    }

    /// The workpiece of a feature whose its_workpiece is `$` (`p`): the
    /// PROJECT's one workpiece, or the `$` error when it has several or
    /// none.
    fn sole_workpiece(&mut self, p: &'f Param) -> R<WorkpieceId> {
        let file = self.file;
        let listed = file
            .instances
            .iter()
            .find(|i| i.entity.eq_ignore_ascii_case("PROJECT"))
            .and_then(|proj| proj.params.get(2))
            .and_then(|l| list(l).ok())
            .filter(|l| l.len() == 1)
            .map(|l| &l[0]);
        match listed {
            Some(q) => {
                let w = self.inst(q)?;
                self.workpiece(w)
            }
            None => self.inst(p).map(|_| WorkpieceId(0)),
        }
    }

    fn feature_kind(&mut self, i: &'f Instance) -> R<FeatureKind> {
        let kept = self.diags.len();
        match self.typed_feature_kind(i) {
            Ok(k) => Ok(k),
            Err(f) if f.invalid => Err(f),
            Err(f) => {
                self.diags.truncate(kept);
                let mut params = Vec::new();
                for p in i.params.iter().skip(FEATURE_COMMON) {
                    params.push(self.raw_value(p)?);
                }
                self.diags.push(
                    Diagnostic::new(
                        Code::KeptRaw,
                        format!("the {} attributes of #{} are kept as written: {}", i.entity, i.id, f.msg),
                    )
                    .primary(f.span, "not as ISO 14649 gives it")
                    .help("they are carried to the output unchanged but take no part in checks, differences or posting"),
                );
                Ok(FeatureKind::Other(Raw {
                    entity: i.entity.clone(),
                    params,
                }))
            }
        }
    }

    fn typed_feature_kind(&mut self, i: &'f Instance) -> R<FeatureKind> {
        let a = |k: usize| arg(i, FEATURE_COMMON + k);
        Ok(match ent(i) {
            "PLANAR_FACE" => FeatureKind::PlanarFace {
                course_of_travel: self.travel_path_at(a(0)?)?,
                removal_boundary: self.open_profile_at(a(1)?)?,
                face_boundary: match self.opt_inst(a(2)?)? {
                    Some(c) => Some(self.closed_profile(c)?),
                    None => None,
                },
                bosses: self.raw_list(a(3)?)?,
            },
            "ROUND_HOLE" => FeatureKind::RoundHole {
                diameter: self.toleranced_at(a(0)?)?,
                change_in_diameter: self.opt_raw(a(1)?)?,
                bottom: {
                    let b = self.inst(a(2)?)?;
                    self.or_raw(b, |rd, b| rd.hole_bottom(b), HoleBottom::Other)?
                },
            },
            "CLOSED_POCKET" => FeatureKind::ClosedPocket {
                pocket: self.pocket(i)?,
                boundary: {
                    let b = self.inst(a(5)?)?;
                    self.closed_profile(b)?
                },
            },
            "OPEN_POCKET" => FeatureKind::OpenPocket {
                pocket: self.pocket(i)?,
                open_boundary: self.open_profile_at(a(5)?)?,
                wall_boundary: match self.opt_inst(a(6)?)? {
                    Some(w) => Some(self.open_profile(w)?),
                    None => None,
                },
            },
            "SLOT" => {
                let mut end_conditions = Vec::new();
                for e in self.insts(a(2)?)? {
                    end_conditions.push(self.or_raw(e, |rd, e| rd.slot_end(e), SlotEnd::Other)?);
                }
                FeatureKind::Slot {
                    course_of_travel: self.travel_path_at(a(0)?)?,
                    swept_shape: self.open_profile_at(a(1)?)?,
                    end_conditions,
                }
            }
            "STEP" => FeatureKind::Step {
                open_boundary: self.travel_path_at(a(0)?)?,
                wall_boundary: match self.opt_inst(a(1)?)? {
                    Some(w) => Some(self.open_profile(w)?),
                    None => None,
                },
                bosses: self.raw_list(a(2)?)?,
            },
            "GENERAL_OUTSIDE_PROFILE" => FeatureKind::GeneralOutsideProfile {
                swept_shape: self.travel_path_at(a(0)?)?,
                boundary: {
                    let b = self.inst(a(1)?)?;
                    if ent(b).ends_with("_CLOSED_PROFILE") || ent(b) == "NGON_PROFILE" {
                        Profile::Closed(self.closed_profile(b)?)
                    } else {
                        Profile::Open(self.open_profile(b)?)
                    }
                },
            },
            "TOOLPATH_FEATURE" => FeatureKind::ToolpathFeature,
            _ => return Err(fail(i.entity_span, "not a feature cncc models")),
        })
    }

    fn pocket(&mut self, i: &'f Instance) -> R<PocketCommon> {
        let a = |k: usize| arg(i, FEATURE_COMMON + k);
        let b = self.inst(a(2)?)?;
        Ok(PocketCommon {
            bosses: self.raw_list(a(0)?)?,
            slope: opt_real(a(1)?)?,
            bottom: self.or_raw(b, |_, b| pocket_bottom(b), PocketBottom::Other)?,
            planar_radius: self.opt_toleranced(a(3)?)?,
            orthogonal_radius: self.opt_toleranced(a(4)?)?,
        })
    }

    fn hole_bottom(&mut self, i: &'f Instance) -> R<HoleBottom> {
        Ok(match ent(i) {
            "THROUGH_BOTTOM_CONDITION" => HoleBottom::Through,
            "FLAT_HOLE_BOTTOM" => HoleBottom::Flat,
            "FLAT_WITH_RADIUS_HOLE_BOTTOM" => HoleBottom::FlatWithRadius {
                corner_radius: self.toleranced_at(arg(i, 0)?)?,
            },
            "CONICAL_HOLE_BOTTOM" => HoleBottom::Conical {
                tip_angle: real(arg(i, 0)?)?,
                tip_radius: self.opt_toleranced(arg(i, 1)?)?,
            },
            "SPHERICAL_HOLE_BOTTOM" => HoleBottom::Spherical {
                radius: self.toleranced_at(arg(i, 0)?)?,
            },
            _ => return Err(fail(i.entity_span, "not a hole bottom condition")),
        })
    }

    fn slot_end(&mut self, i: &'f Instance) -> R<SlotEnd> {
        Ok(match ent(i) {
            "OPEN_SLOT_END_TYPE" => SlotEnd::Open,
            "RADIUSED_SLOT_END_TYPE" => SlotEnd::Radiused,
            "LOOP_SLOT_END_TYPE" => SlotEnd::Loop,
            "FLAT_SLOT_END_TYPE" => SlotEnd::Flat {
                corner_radius1: self.toleranced_at(arg(i, 0)?)?,
                corner_radius2: self.toleranced_at(arg(i, 1)?)?,
            },
            "WOODRUFF_SLOT_END_TYPE" => SlotEnd::Woodruff {
                radius: self.toleranced_at(arg(i, 0)?)?,
            },
            _ => return Err(fail(i.entity_span, "not a slot end type")),
        })
    }

    // ------------------------------------------------------------ profiles

    pub fn closed_profile(&mut self, i: &'f Instance) -> R<ClosedProfile> {
        self.or_raw(i, |rd, i| rd.typed_closed(i), ClosedProfile::Other)
    }

    fn typed_closed(&mut self, i: &'f Instance) -> R<ClosedProfile> {
        let placement = self.opt_placement(arg(i, 0)?)?;
        Ok(match ent(i) {
            "RECTANGULAR_CLOSED_PROFILE" => ClosedProfile::Rectangular {
                placement,
                width: self.toleranced_at(arg(i, 1)?)?,
                length: self.toleranced_at(arg(i, 2)?)?,
            },
            "CIRCULAR_CLOSED_PROFILE" => ClosedProfile::Circular {
                placement,
                diameter: self.toleranced_at(arg(i, 1)?)?,
            },
            "GENERAL_CLOSED_PROFILE" => ClosedProfile::General {
                placement,
                shape: {
                    let c = self.inst(arg(i, 1)?)?;
                    self.curve(c)?
                },
            },
            _ => return Err(fail(i.entity_span, "not a closed profile cncc models")),
        })
    }

    pub fn open_profile_at(&mut self, p: &'f Param) -> R<OpenProfile> {
        let i = self.inst(p)?;
        self.open_profile(i)
    }

    pub fn open_profile(&mut self, i: &'f Instance) -> R<OpenProfile> {
        self.or_raw(i, |rd, i| rd.typed_open(i), OpenProfile::Other)
    }

    fn typed_open(&mut self, i: &'f Instance) -> R<OpenProfile> {
        let placement = self.opt_placement(arg(i, 0)?)?;
        Ok(match ent(i) {
            "LINEAR_PROFILE" => OpenProfile::Linear {
                placement,
                length: {
                    let n = self.inst(arg(i, 1)?)?;
                    self.numeric_parameter(n)?
                },
            },
            "SQUARE_U_PROFILE" => OpenProfile::SquareU {
                placement,
                width: self.toleranced_at(arg(i, 1)?)?,
                first_radius: match self.opt_inst(arg(i, 2)?)? {
                    Some(t) => Some(self.toleranced(t)?),
                    None => None,
                },
                first_angle: opt_real(arg(i, 3)?)?,
                second_radius: match self.opt_inst(arg(i, 4)?)? {
                    Some(t) => Some(self.toleranced(t)?),
                    None => None,
                },
                second_angle: opt_real(arg(i, 5)?)?,
            },
            "ROUNDED_U_PROFILE" => OpenProfile::RoundedU {
                placement,
                width: self.toleranced_at(arg(i, 1)?)?,
            },
            "VEE_PROFILE" => OpenProfile::Vee {
                placement,
                radius: self.toleranced_at(arg(i, 1)?)?,
                angle: real(arg(i, 2)?)?,
                tilt_angle: real(arg(i, 3)?)?,
            },
            "PARTIAL_CIRCULAR_PROFILE" => OpenProfile::PartialCircular {
                placement,
                radius: self.toleranced_at(arg(i, 1)?)?,
                sweep_angle: real(arg(i, 2)?)?,
            },
            "GENERAL_PROFILE" => OpenProfile::General {
                placement,
                shape: {
                    let c = self.inst(arg(i, 1)?)?;
                    self.curve(c)?
                },
            },
            _ => return Err(fail(i.entity_span, "not an open profile cncc models")),
        })
    }

    pub fn travel_path_at(&mut self, p: &'f Param) -> R<TravelPath> {
        let i = self.inst(p)?;
        self.or_raw(i, |rd, i| rd.typed_travel(i), TravelPath::Other)
    }

    fn typed_travel(&mut self, i: &'f Instance) -> R<TravelPath> {
        let placement = self.opt_placement(arg(i, 0)?)?;
        Ok(match ent(i) {
            "LINEAR_PATH" => TravelPath::Linear {
                placement,
                distance: self.toleranced_at(arg(i, 1)?)?,
                direction: {
                    let d = self.inst(arg(i, 2)?)?;
                    self.direction(d)?
                },
            },
            "GENERAL_PATH" => TravelPath::General {
                placement,
                path: {
                    let c = self.inst(arg(i, 1)?)?;
                    self.curve(c)?
                },
            },
            _ => return Err(fail(i.entity_span, "not a travel path cncc models")),
        })
    }
}

fn pocket_bottom(i: &Instance) -> R<PocketBottom> {
    Ok(match ent(i) {
        "PLANAR_POCKET_BOTTOM_CONDITION" => PocketBottom::Planar,
        "THROUGH_POCKET_BOTTOM_CONDITION" => PocketBottom::Through,
        // RADIUSED_POCKET_BOTTOM_CONDITION carries a centre and a radius
        // the model's unit variant cannot hold: kept as written.
        _ => {
            return Err(fail(
                i.entity_span,
                "not a pocket bottom condition cncc models",
            ))
        }
    })
}
