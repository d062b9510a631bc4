//! Reading operations, technology (with the unit conversion), machine
//! functions, strategies, approach/retract strategies and explicit
//! toolpaths. An operation whose own attributes do not fit keeps them as
//! `OperationKind::Other(Raw)`: the entity and the parameters after the
//! nine every milling machining operation has.

use super::*;
use crate::stepnc::units;

/// Parameters every milling machining operation starts with.
pub(crate) const OPERATION_COMMON: usize = 9;

impl<'f> Rd<'f> {
    /// An operation, read once and shared.
    pub fn operation(&mut self, i: &'f Instance) -> R<OperationId> {
        if let Some(&id) = self.operations.get(&i.id) {
            return Ok(id);
        }
        if schema::entity(&i.entity).and_then(|d| d.attr_index("its_tool")) != Some(5) {
            return Err(fail(
                i.entity_span,
                format!(
                    "expected a machining operation, found {} (#{})",
                    i.entity, i.id
                ),
            ));
        }
        let o = self.operation_body(i)?;
        self.ids.push((o.id.clone(), "operation", i.span));
        let id = OperationId(self.p.operations.len() as u32);
        self.p.operations.push(o);
        self.operations.insert(i.id, id);
        Ok(id)
    }

    fn operation_body(&mut self, i: &'f Instance) -> R<Operation> {
        let toolpath = self.opt_toolpath_list(arg(i, 0)?)?;
        let tool_direction = self.opt_raw(arg(i, 1)?)?;
        let id = string(arg(i, 2)?)?;
        let retract_plane = opt_real(arg(i, 3)?)?;
        let start_point = self.opt_point(arg(i, 4)?)?;
        let t = self.inst(arg(i, 5)?)?;
        let tool = self.tool(t)?;
        let te = self.inst(arg(i, 6)?)?;
        let technology = self.technology(te)?;
        let mf = self.inst(arg(i, 7)?)?;
        let machine_functions = self.machine_functions(mf)?;
        let overcut_length = opt_real(arg(i, 8)?)?;
        let kept = self.diags.len();
        let kind = match self.operation_kind(i) {
            Ok(k) => k,
            Err(f) => {
                self.diags.truncate(kept);
                let mut params = Vec::new();
                for p in i.params.iter().skip(OPERATION_COMMON) {
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
                OperationKind::Other(Raw {
                    entity: i.entity.clone(),
                    params,
                })
            }
        };
        Ok(Operation {
            id,
            toolpath,
            tool_direction,
            retract_plane,
            start_point,
            tool,
            technology,
            machine_functions,
            overcut_length,
            kind,
        })
    }

    fn operation_kind(&mut self, i: &'f Instance) -> R<OperationKind> {
        let a = |k: usize| arg(i, OPERATION_COMMON + k);
        let e = ent(i);
        let finish = e.contains("_FINISH_");
        Ok(match e {
            "PLANE_ROUGH_MILLING" | "PLANE_FINISH_MILLING" => OperationKind::PlaneMilling {
                finish,
                milling: self.milling(i)?,
                axial_cutting_depth: opt_real(a(3)?)?,
                allowance_bottom: opt_real(a(4)?)?,
            },
            "SIDE_ROUGH_MILLING" | "SIDE_FINISH_MILLING" => OperationKind::SideMilling {
                finish,
                milling: self.milling(i)?,
                axial_cutting_depth: opt_real(a(3)?)?,
                radial_cutting_depth: opt_real(a(4)?)?,
                allowance_side: opt_real(a(5)?)?,
            },
            "BOTTOM_AND_SIDE_ROUGH_MILLING" | "BOTTOM_AND_SIDE_FINISH_MILLING" => {
                OperationKind::BottomAndSideMilling {
                    finish,
                    milling: self.milling(i)?,
                    axial_cutting_depth: opt_real(a(3)?)?,
                    radial_cutting_depth: opt_real(a(4)?)?,
                    allowance_side: opt_real(a(5)?)?,
                    allowance_bottom: opt_real(a(6)?)?,
                }
            }
            "FREEFORM_OPERATION" => OperationKind::Freeform {
                approach: self.opt_approach(a(0)?)?,
                retract: self.opt_approach(a(1)?)?,
                strategy: self.opt_raw(a(2)?)?,
            },
            "DRILLING" => OperationKind::Drilling(self.drill(i)?),
            "CENTER_DRILLING" => OperationKind::CenterDrilling(self.drill(i)?),
            "COUNTER_SINKING" => OperationKind::CounterSinking(self.drill(i)?),
            "MULTISTEP_DRILLING" => OperationKind::MultistepDrilling {
                drill: self.drill(i)?,
                retract_distance: real(a(5)?)?,
                first_depth: real(a(6)?)?,
                depth_of_step: real(a(7)?)?,
                dwell_time_step: opt_real(a(8)?)?,
            },
            "REAMING" | "BORING" => OperationKind::Boring {
                reaming: e == "REAMING",
                drill: self.drill(i)?,
                spindle_stop_at_bottom: boolean(a(5)?)?,
                depth_of_testcut: opt_real(a(6)?)?,
                waiting_position: self.opt_point(a(7)?)?,
            },
            _ => return Err(fail(i.entity_span, "not an operation cncc models")),
        })
    }

    fn milling(&mut self, i: &'f Instance) -> R<MillingCommon> {
        let a = |k: usize| arg(i, OPERATION_COMMON + k);
        Ok(MillingCommon {
            approach: self.opt_approach(a(0)?)?,
            retract: self.opt_approach(a(1)?)?,
            strategy: match self.opt_inst(a(2)?)? {
                Some(s) => Some(self.or_raw(s, |rd, s| rd.strategy(s), Strategy::Other)?),
                None => None,
            },
        })
    }

    fn drill(&mut self, i: &'f Instance) -> R<DrillCommon> {
        let a = |k: usize| arg(i, OPERATION_COMMON + k);
        Ok(DrillCommon {
            cutting_depth: opt_real(a(0)?)?,
            previous_diameter: opt_real(a(1)?)?,
            dwell_time_bottom: opt_real(a(2)?)?,
            feed_on_retract: opt_real(a(3)?)?,
            strategy: match self.opt_inst(a(4)?)? {
                Some(s) => {
                    expect(s, &["DRILLING_TYPE_STRATEGY"], "a DRILLING_TYPE_STRATEGY")?;
                    let r = |k| opt_real(arg(s, k)?);
                    Some(DrillingStrategy {
                        reduced_cut_at_start: r(0)?,
                        reduced_feed_at_start: r(1)?,
                        depth_of_start: r(2)?,
                        reduced_cut_at_end: r(3)?,
                        reduced_feed_at_end: r(4)?,
                        depth_of_end: r(5)?,
                    })
                }
                None => None,
            },
        })
    }

    // ------------------------------------------------------------ technology

    /// MILLING_TECHNOLOGY in model units.
    pub fn technology(&mut self, i: &'f Instance) -> R<Technology> {
        expect(i, &["MILLING_TECHNOLOGY"], "a MILLING_TECHNOLOGY")?;
        let reference = arg(i, 1)?;
        let feed_at_tcp = match enumeration(reference)? {
            "TCP" => true,
            "CCP" => false,
            _ => return Err(fail(reference.span, "feedrate_reference is .TCP. or .CCP.")),
        };
        Ok(Technology {
            feed: opt_real(arg(i, 0)?)?.map(units::feed_from_file),
            feed_at_tcp,
            cut_speed: opt_real(arg(i, 2)?)?.map(units::cut_speed_from_file),
            spindle: opt_real(arg(i, 3)?)?.map(units::spindle_from_file),
            feed_per_tooth: opt_real(arg(i, 4)?)?,
            synchronize_spindle_with_feed: boolean(arg(i, 5)?)?,
            inhibit_feedrate_override: boolean(arg(i, 6)?)?,
            inhibit_spindle_override: boolean(arg(i, 7)?)?,
            adaptive_control: self.opt_raw(arg(i, 8)?)?,
        })
    }

    pub fn opt_technology(&mut self, p: &'f Param) -> R<Option<Technology>> {
        match self.opt_inst(p)? {
            Some(i) => self.technology(i).map(Some),
            None => Ok(None),
        }
    }

    pub fn machine_functions(&mut self, i: &'f Instance) -> R<MachineFunctions> {
        expect(
            i,
            &["MILLING_MACHINE_FUNCTIONS"],
            "MILLING_MACHINE_FUNCTIONS",
        )?;
        Ok(MachineFunctions {
            coolant: boolean(arg(i, 0)?)?,
            coolant_pressure: opt_real(arg(i, 1)?)?,
            mist: opt_bool(arg(i, 2)?)?,
            through_spindle_coolant: boolean(arg(i, 3)?)?,
            through_pressure: opt_real(arg(i, 4)?)?,
            axis_clamping: list(arg(i, 5)?)?
                .iter()
                .map(string)
                .collect::<R<Vec<_>>>()?,
            chip_removal: boolean(arg(i, 6)?)?,
            oriented_spindle_stop: self.opt_direction(arg(i, 7)?)?,
            process_model: self.opt_raw(arg(i, 8)?)?,
            other_functions: self.raw_list(arg(i, 9)?)?,
        })
    }

    fn opt_machine_functions(&mut self, p: &'f Param) -> R<Option<MachineFunctions>> {
        match self.opt_inst(p)? {
            Some(i) => self.machine_functions(i).map(Some),
            None => Ok(None),
        }
    }

    // ------------------------------------------------------------ strategies

    fn strategy(&mut self, i: &'f Instance) -> R<Strategy> {
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

    fn opt_approach(&mut self, p: &'f Param) -> R<Option<ApproachRetract>> {
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

    // ------------------------------------------------------------ toolpaths

    pub fn opt_toolpath_list(&mut self, p: &'f Param) -> R<Option<Vec<Toolpath>>> {
        match p.value {
            Value::Null => Ok(None),
            _ => self.toolpath_list_at(p).map(Some),
        }
    }

    fn toolpath_list_at(&mut self, p: &'f Param) -> R<Vec<Toolpath>> {
        let l = self.inst(p)?;
        expect(l, &["TOOLPATH_LIST"], "a TOOLPATH_LIST")?;
        let mut out = Vec::new();
        for t in self.insts(arg(l, 0)?)? {
            out.push(self.or_raw(t, |rd, t| rd.toolpath(t), Toolpath::Other)?);
        }
        Ok(out)
    }

    fn toolpath(&mut self, i: &'f Instance) -> R<Toolpath> {
        let e = ent(i);
        if e != "CUTTER_LOCATION_TRAJECTORY" && e != "FEEDSTOP" {
            return Err(fail(i.entity_span, "not a toolpath cncc models"));
        }
        let base = ToolpathBase {
            priority: boolean(arg(i, 0)?)?,
            kind: toolpath_type(enumeration(arg(i, 1)?)?),
            speed: self.speed(arg(i, 2)?)?,
            technology: self.opt_technology(arg(i, 3)?)?,
            machine_functions: self.opt_machine_functions(arg(i, 4)?)?,
        };
        Ok(if e == "FEEDSTOP" {
            Toolpath::Feedstop {
                base,
                dwell: real(arg(i, 5)?)?,
            }
        } else {
            let c = self.inst(arg(i, 6)?)?;
            Toolpath::CutterLocation {
                base,
                direction: opt_bool(arg(i, 5)?)?,
                basic_curve: self.curve(c)?,
                tool_axis: self.opt_curve(arg(i, 7)?)?,
                surface_normal: self.opt_curve(arg(i, 8)?)?,
            }
        })
    }

    fn speed(&mut self, p: &'f Param) -> R<Option<ToolpathSpeed>> {
        Ok(Some(match &p.value {
            Value::Null => return Ok(None),
            Value::Typed(t, inner) if t == "POSITIVE_RATIO_MEASURE" => {
                ToolpathSpeed::Ratio(real(inner)?)
            }
            Value::Typed(t, inner) if t == "SPEED_NAME" => {
                ToolpathSpeed::Named(enumeration(inner)?.to_string())
            }
            Value::Ref(_) => {
                let i = self.inst(p)?;
                ToolpathSpeed::Other(self.raw(i)?)
            }
            _ => {
                return Err(fail(
                    p.span,
                    "its_speed is TOOLPATH_SPEED, POSITIVE_RATIO_MEASURE(..) or SPEED_NAME(..)",
                ))
            }
        }))
    }
}

fn toolpath_type(e: &str) -> ToolpathType {
    match e {
        "APPROACH" => ToolpathType::Approach,
        "LIFT" => ToolpathType::Lift,
        "CONNECT" => ToolpathType::Connect,
        "NON_CONTACT" => ToolpathType::NonContact,
        "CONTACT" => ToolpathType::Contact,
        "TRAJECTORY_PATH" => ToolpathType::TrajectoryPath,
        other => ToolpathType::Other(other.to_string()),
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
