//! Writing operations, technology (converted back to file units),
//! machine functions, strategies, toolpaths and tools.

use super::*;
use crate::stepnc::units;

impl<'p> W<'p> {
    pub fn operation(&mut self, id: OperationId) -> Value {
        if let Some(&n) = self.operations.get(&id) {
            return Value::Ref(n);
        }
        let n = self.reserve();
        self.operations.insert(id, n);
        let o = self.p.operation(id);
        let taken = self.take_toolpath(id);
        let toolpath = self.opt_toolpath_list(if taken.is_some() { &taken } else { &o.toolpath });
        drop(taken);
        let mut params = vec![
            toolpath,
            self.opt_raw(&o.tool_direction),
            s(&o.id),
            or(o.retract_plane),
            self.opt_point(&o.start_point),
            self.tool(o.tool),
            self.technology(&o.technology),
            self.machine_functions(&o.machine_functions),
            or(o.overcut_length),
        ];
        let entity = self.operation_kind(&o.kind, &mut params);
        self.fill(n, &entity, params);
        Value::Ref(n)
    }

    fn operation_kind(&mut self, k: &OperationKind, out: &mut Vec<Value>) -> String {
        let finish_name =
            |finish: bool, rough: &str, fin: &str| if finish { fin } else { rough }.to_string();
        match k {
            OperationKind::PlaneMilling {
                finish,
                milling,
                axial_cutting_depth,
                allowance_bottom,
            } => {
                self.milling(milling, out);
                out.extend([or(*axial_cutting_depth), or(*allowance_bottom)]);
                finish_name(*finish, "PLANE_ROUGH_MILLING", "PLANE_FINISH_MILLING")
            }
            OperationKind::SideMilling {
                finish,
                milling,
                axial_cutting_depth,
                radial_cutting_depth,
                allowance_side,
            } => {
                self.milling(milling, out);
                out.extend([
                    or(*axial_cutting_depth),
                    or(*radial_cutting_depth),
                    or(*allowance_side),
                ]);
                finish_name(*finish, "SIDE_ROUGH_MILLING", "SIDE_FINISH_MILLING")
            }
            OperationKind::BottomAndSideMilling {
                finish,
                milling,
                axial_cutting_depth,
                radial_cutting_depth,
                allowance_side,
                allowance_bottom,
            } => {
                self.milling(milling, out);
                out.extend([
                    or(*axial_cutting_depth),
                    or(*radial_cutting_depth),
                    or(*allowance_side),
                    or(*allowance_bottom),
                ]);
                finish_name(
                    *finish,
                    "BOTTOM_AND_SIDE_ROUGH_MILLING",
                    "BOTTOM_AND_SIDE_FINISH_MILLING",
                )
            }
            OperationKind::Freeform {
                approach,
                retract,
                strategy,
            } => {
                out.push(self.opt_approach(approach));
                out.push(self.opt_approach(retract));
                out.push(self.opt_raw(strategy));
                "FREEFORM_OPERATION".into()
            }
            OperationKind::Drilling(d) => {
                self.drill(d, out);
                "DRILLING".into()
            }
            OperationKind::CenterDrilling(d) => {
                self.drill(d, out);
                "CENTER_DRILLING".into()
            }
            OperationKind::CounterSinking(d) => {
                self.drill(d, out);
                "COUNTER_SINKING".into()
            }
            OperationKind::MultistepDrilling {
                drill,
                retract_distance,
                first_depth,
                depth_of_step,
                dwell_time_step,
            } => {
                self.drill(drill, out);
                out.extend([
                    r(*retract_distance),
                    r(*first_depth),
                    r(*depth_of_step),
                    or(*dwell_time_step),
                ]);
                "MULTISTEP_DRILLING".into()
            }
            OperationKind::Boring {
                reaming,
                drill,
                spindle_stop_at_bottom,
                depth_of_testcut,
                waiting_position,
            } => {
                self.drill(drill, out);
                out.push(bool_value(*spindle_stop_at_bottom));
                out.push(or(*depth_of_testcut));
                out.push(self.opt_point(waiting_position));
                if *reaming { "REAMING" } else { "BORING" }.into()
            }
            OperationKind::Tapping {
                drill,
                compensation_chuck,
            } => {
                self.drill(drill, out);
                out.push(bool_value(*compensation_chuck));
                "TAPPING".into()
            }
            OperationKind::ThreadDrilling {
                drill,
                helical_movement_on_forward,
            } => {
                self.drill(drill, out);
                out.push(bool_value(*helical_movement_on_forward));
                "THREAD_DRILLING".into()
            }
            OperationKind::Other(raw) => {
                for v in &raw.params {
                    let v = self.raw_value(v);
                    out.push(v);
                }
                raw.entity.clone()
            }
        }
    }

    fn milling(&mut self, m: &MillingCommon, out: &mut Vec<Value>) {
        out.push(self.opt_approach(&m.approach));
        out.push(self.opt_approach(&m.retract));
        out.push(opt(m.strategy.as_ref().map(|st| self.strategy(st))));
    }

    fn drill(&mut self, d: &DrillCommon, out: &mut Vec<Value>) {
        out.extend([
            or(d.cutting_depth),
            or(d.previous_diameter),
            or(d.dwell_time_bottom),
            or(d.feed_on_retract),
        ]);
        out.push(opt(d.strategy.as_ref().map(|st| {
            self.add(
                "DRILLING_TYPE_STRATEGY",
                vec![
                    or(st.reduced_cut_at_start),
                    or(st.reduced_feed_at_start),
                    or(st.depth_of_start),
                    or(st.reduced_cut_at_end),
                    or(st.reduced_feed_at_end),
                    or(st.depth_of_end),
                ],
            )
        })));
    }

    pub fn technology(&mut self, t: &Technology) -> Value {
        let params = vec![
            or(t.feed.map(units::feed_to_file)),
            e(if t.feed_at_tcp { "TCP" } else { "CCP" }),
            or(t.cut_speed.map(units::cut_speed_to_file)),
            or(t.spindle.map(units::spindle_to_file)),
            or(t.feed_per_tooth),
            bool_value(t.synchronize_spindle_with_feed),
            bool_value(t.inhibit_feedrate_override),
            bool_value(t.inhibit_spindle_override),
            self.opt_raw(&t.adaptive_control),
        ];
        self.add("MILLING_TECHNOLOGY", params)
    }

    pub fn machine_functions(&mut self, m: &MachineFunctions) -> Value {
        let params = vec![
            bool_value(m.coolant),
            or(m.coolant_pressure),
            ob(m.mist),
            bool_value(m.through_spindle_coolant),
            or(m.through_pressure),
            list(m.axis_clamping.iter().map(|a| s(a)).collect()),
            bool_value(m.chip_removal),
            self.opt_direction(&m.oriented_spindle_stop),
            self.opt_raw(&m.process_model),
            self.raw_list(&m.other_functions),
        ];
        self.add("MILLING_MACHINE_FUNCTIONS", params)
    }

    fn strategy(&mut self, st: &Strategy) -> Value {
        let base = |b: &StrategyBase| vec![or(b.overlap), ob(b.allow_multiple_passes)];
        let (name, mut params, rest) = match st {
            Strategy::Unidirectional {
                base: b,
                feed_direction,
                cutmode,
            } => (
                "UNIDIRECTIONAL",
                base(b),
                vec![self.opt_direction(feed_direction), oe(cutmode.map(cut))],
            ),
            Strategy::Bidirectional {
                base: b,
                feed_direction,
                stepover_direction,
                stroke_connection,
            } => (
                "BIDIRECTIONAL",
                base(b),
                vec![
                    self.opt_direction(feed_direction),
                    oe(stepover_direction.map(side)),
                    oe(stroke_connection.as_deref()),
                ],
            ),
            Strategy::ContourParallel {
                base: b,
                rotation,
                cutmode,
            } => (
                "CONTOUR_PARALLEL",
                base(b),
                vec![oe(rotation.map(rot)), oe(cutmode.map(cut))],
            ),
            Strategy::BidirectionalContour {
                contour_first,
                base: b,
                feed_direction,
                stepover_direction,
                rotation,
                cutmode,
            } => (
                if *contour_first {
                    "CONTOUR_BIDIRECTIONAL"
                } else {
                    "BIDIRECTIONAL_CONTOUR"
                },
                base(b),
                vec![
                    self.opt_direction(feed_direction),
                    oe(stepover_direction.map(side)),
                    oe(rotation.map(rot)),
                    oe(cutmode.map(cut)),
                ],
            ),
            Strategy::ContourSpiral {
                base: b,
                rotation,
                cutmode,
            } => (
                "CONTOUR_SPIRAL",
                base(b),
                vec![oe(rotation.map(rot)), oe(cutmode.map(cut))],
            ),
            Strategy::CenterMilling { base: b } => ("CENTER_MILLING", base(b), vec![]),
            Strategy::Explicit { base: b } => ("EXPLICIT_STRATEGY", base(b), vec![]),
            Strategy::Other(raw) => return self.raw(raw),
        };
        params.extend(rest);
        self.add(name, params)
    }

    fn opt_approach(&mut self, a: &Option<ApproachRetract>) -> Value {
        let Some(a) = a else { return Value::Null };
        let (name, o, rest): (&str, &Option<Direction>, Vec<Value>) = match a {
            ApproachRetract::PlungeToolaxis { orientation } => {
                ("PLUNGE_TOOLAXIS", orientation, vec![])
            }
            ApproachRetract::PlungeRamp { orientation, angle } => {
                ("PLUNGE_RAMP", orientation, vec![r(*angle)])
            }
            ApproachRetract::PlungeHelix {
                orientation,
                radius,
                angle,
            } => ("PLUNGE_HELIX", orientation, vec![r(*radius), r(*angle)]),
            ApproachRetract::PlungeZigzag {
                orientation,
                angle,
                width,
            } => ("PLUNGE_ZIGZAG", orientation, vec![r(*angle), r(*width)]),
            ApproachRetract::RetractAngle {
                orientation,
                angle,
                travel_length,
            } => (
                "AP_RETRACT_ANGLE",
                orientation,
                vec![r(*angle), r(*travel_length)],
            ),
            ApproachRetract::RetractTangent {
                orientation,
                radius,
            } => ("AP_RETRACT_TANGENT", orientation, vec![r(*radius)]),
            ApproachRetract::AlongPath { orientation, path } => {
                let l = self.toolpath_list(path);
                ("ALONG_PATH", orientation, vec![l])
            }
            ApproachRetract::Other(raw) => return self.raw(raw),
        };
        let mut params = vec![self.opt_direction(o)];
        params.extend(rest);
        self.add(name, params)
    }
}

fn cut(c: CutMode) -> &'static str {
    match c {
        CutMode::Climb => "CLIMB",
        CutMode::Conventional => "CONVENTIONAL",
    }
}

fn rot(r: RotDirection) -> &'static str {
    match r {
        RotDirection::Cw => "CW",
        RotDirection::Ccw => "CCW",
    }
}

fn side(s: LeftOrRight) -> &'static str {
    match s {
        LeftOrRight::Left => "LEFT",
        LeftOrRight::Right => "RIGHT",
    }
}
