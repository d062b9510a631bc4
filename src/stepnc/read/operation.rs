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
            return Err(invalid(
                i.entity_span,
                format!(
                    "expected a machining operation, found {} (#{})",
                    i.entity, i.id
                ),
            ));
        }
        let o = self.operation_body(i)?;
        self.check_tapping(&o, i);
        self.ids.push((o.id.clone(), "operation", i.span));
        let id = OperationId(self.p.operations.len() as u32);
        self.p.operations.push(o);
        self.operations.insert(i.id, id);
        Ok(id)
    }

    /// A tapping operation needs a pitch (feed over speed, synchronised)
    /// and a tap of the spindle's hand: warnings W0804, W0805.
    fn check_tapping(&mut self, o: &Operation, i: &'f Instance) {
        if !matches!(
            o.kind,
            OperationKind::Tapping { .. } | OperationKind::ThreadDrilling { .. }
        ) {
            return;
        }
        if o.thread_pitch().is_none() || !o.technology.synchronize_spindle_with_feed {
            self.diags.push(
                Diagnostic::new(
                    Code::TappingWithoutPitch,
                    format!("{} '{}' gives no thread pitch", i.entity, o.id),
                )
                .primary(i.span, "its technology needs a feedrate and a spindle speed, synchronised")
                .help("the pitch is the feed over the spindle speed: give both and set synchronize_spindle_with_feed to .T."),
            );
        }
        let hand = self
            .p
            .tools
            .get(o.tool.index())
            .and_then(|t| t.body.hand_of_cut);
        let left = o.technology.spindle.is_some_and(|s| s < 0.0);
        let clash = match hand {
            Some(Hand::Left) => o.technology.spindle.is_some() && !left,
            Some(Hand::Right) => left,
            Some(Hand::Neutral) | None => false,
        };
        if clash {
            self.diags.push(
                Diagnostic::new(
                    Code::TapHandAgainstSpindle,
                    format!("{} '{}': the tap's hand_of_cut disagrees with the spindle direction", i.entity, o.id),
                )
                .primary(i.span, "the spindle turns the other way than the tap cuts")
                .help("a right-hand tap turns clockwise (a negative speed in the file), a left-hand tap counter-clockwise"),
            );
        }
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
            Err(f) if f.invalid => return Err(f),
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
            "TAPPING" => OperationKind::Tapping {
                drill: self.drill(i)?,
                compensation_chuck: boolean(a(5)?)?,
            },
            "THREAD_DRILLING" => OperationKind::ThreadDrilling {
                drill: self.drill(i)?,
                helical_movement_on_forward: boolean(a(5)?)?,
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
        // `$` (unset, W0803) reads as the tool centre point, the reference
        // every posted cycle and path uses.
        let feed_at_tcp = match opt_enum(reference)?.unwrap_or("TCP") {
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

    pub fn opt_machine_functions(&mut self, p: &'f Param) -> R<Option<MachineFunctions>> {
        match self.opt_inst(p)? {
            Some(i) => self.machine_functions(i).map(Some),
            None => Ok(None),
        }
    }
}
