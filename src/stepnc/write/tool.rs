//! Writing cutting tools (ISO 14649-111).

use super::*;

impl<'p> W<'p> {
    pub fn tool(&mut self, id: ToolId) -> Value {
        if let Some(&n) = self.tools.get(&id) {
            return Value::Ref(n);
        }
        let n = self.reserve();
        self.tools.insert(id, n);
        let t = self.p.tool(id);
        let params = vec![
            s(&t.id),
            self.body(&t.body),
            list(
                t.cutting_edges
                    .iter()
                    .map(|c| self.cutting_component(c))
                    .collect(),
            ),
            or(t.overall_assembly_length),
            self.opt_direction(&t.direction_for_spindle_orientation),
            or(t.holder_diameter_for_spindle_orientation),
        ];
        self.fill(n, "MILLING_CUTTING_TOOL", params);
        Value::Ref(n)
    }

    fn body(&mut self, b: &ToolBody) -> Value {
        let d = &b.dimension;
        let dim = self.add(
            "MILLING_TOOL_DIMENSION",
            vec![
                r(d.diameter),
                or(d.tip_half_angle),
                or(d.circumference_angle),
                or(d.cutting_edge_length),
                or(d.edge_radius),
                or(d.edge_center_vertical),
                or(d.edge_center_horizontal),
            ],
        );
        let mut params = vec![
            dim,
            b.number_of_teeth.map_or(Value::Null, Value::Int),
            oe(b.hand_of_cut.map(|h| match h {
                Hand::Left => "LEFT",
                Hand::Right => "RIGHT",
                Hand::Neutral => "NEUTRAL",
            })),
            ob(b.coolant_through_tool),
            or(b.pilot_length),
        ];
        for v in &b.extra {
            let v = self.raw_value(v);
            params.push(v);
        }
        self.add(body_name(&b.kind), params)
    }

    fn cutting_component(&mut self, c: &CuttingComponent) -> Value {
        let params = vec![
            or(c.tool_offset_length),
            self.opt_raw(&c.material),
            self.opt_raw(&c.technological_data),
            or(c.expected_tool_life),
            opt(c.technology.as_ref().map(|t| self.technology(t))),
        ];
        self.add("CUTTING_COMPONENT", params)
    }
}

fn body_name(k: &ToolBodyKind) -> &str {
    match k {
        ToolBodyKind::Endmill => "ENDMILL",
        ToolBodyKind::TaperedEndmill => "TAPERED_ENDMILL",
        ToolBodyKind::BallEndmill => "BALL_ENDMILL",
        ToolBodyKind::BullnoseEndmill => "BULLNOSE_ENDMILL",
        ToolBodyKind::Facemill => "FACEMILL",
        ToolBodyKind::TwistDrill => "TWIST_DRILL",
        ToolBodyKind::TaperedDrill => "TAPERED_DRILL",
        // The schema's spelling; CENTER_DRILL (NIST, GRIMA) reads too.
        ToolBodyKind::CenterDrill => "CENTERDRILL",
        ToolBodyKind::Spotdrill => "SPOTDRILL",
        ToolBodyKind::Countersink => "COUNTERSINK",
        ToolBodyKind::Counterbore => "COUNTERBORE",
        ToolBodyKind::Reamer => "REAMER",
        ToolBodyKind::TaperedReamer => "TAPERED_REAMER",
        ToolBodyKind::Tap => "TAP",
        ToolBodyKind::ThreadMill => "THREAD_MILL",
        ToolBodyKind::Other(name) => name,
    }
}
