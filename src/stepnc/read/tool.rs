//! Reading cutting tools (ISO 14649-111): the tool, its body and
//! dimension, its cutting components.

use super::*;

impl<'f> Rd<'f> {
    /// A tool, read once and shared.
    pub fn tool(&mut self, i: &'f Instance) -> R<ToolId> {
        if let Some(&id) = self.tools.get(&i.id) {
            return Ok(id);
        }
        if expect(
            i,
            &["MILLING_CUTTING_TOOL", "CUTTING_TOOL"],
            "a MILLING_CUTTING_TOOL",
        )? == "CUTTING_TOOL"
        {
            self.diags.push(abstract_tool(i));
        }
        let b = self.inst(arg(i, 1)?)?;
        let body = self.body(b)?;
        let mut cutting_edges = Vec::new();
        for c in self.insts(arg(i, 2)?)? {
            cutting_edges.push(self.cutting_component(c)?);
        }
        let t = Tool {
            id: string(arg(i, 0)?)?,
            body,
            cutting_edges,
            overall_assembly_length: opt_real(arg(i, 3)?)?,
            direction_for_spindle_orientation: match i.params.get(4) {
                Some(p) => self.opt_direction(p)?,
                None => None,
            },
            holder_diameter_for_spindle_orientation: match i.params.get(5) {
                Some(p) => opt_real(p)?,
                None => None,
            },
        };
        let id = ToolId(self.p.tools.len() as u32);
        self.p.tools.push(t);
        self.tools.insert(i.id, id);
        Ok(id)
    }

    fn body(&mut self, i: &'f Instance) -> R<ToolBody> {
        let def = schema::entity(&i.entity);
        if def.and_then(|d| d.attr_index("hand_of_cut")) != Some(2) {
            return Err(fail(
                i.entity_span,
                format!("expected a tool body, found {}", i.entity),
            ));
        }
        let d = self.inst(arg(i, 0)?)?;
        let mut extra = Vec::new();
        for p in i.params.iter().skip(5) {
            extra.push(self.raw_value(p)?);
        }
        let hand = arg(i, 2)?;
        Ok(ToolBody {
            kind: body_kind(ent(i)),
            dimension: self.dimension(d)?,
            number_of_teeth: opt_int(arg(i, 1)?)?,
            hand_of_cut: match opt_enum(hand)? {
                None => None,
                Some("LEFT") => Some(Hand::Left),
                Some("RIGHT") => Some(Hand::Right),
                Some("NEUTRAL") => Some(Hand::Neutral),
                Some(_) => {
                    return Err(fail(
                        hand.span,
                        "hand_of_cut is .LEFT., .RIGHT. or .NEUTRAL.",
                    ))
                }
            },
            coolant_through_tool: opt_bool(arg(i, 3)?)?,
            pilot_length: opt_real(arg(i, 4)?)?,
            extra,
        })
    }

    fn dimension(&mut self, i: &'f Instance) -> R<ToolDimension> {
        expect(i, &["MILLING_TOOL_DIMENSION"], "a MILLING_TOOL_DIMENSION")?;
        let r = |k| opt_real(arg(i, k)?);
        Ok(ToolDimension {
            diameter: real(arg(i, 0)?)?,
            tip_half_angle: r(1)?,
            circumference_angle: r(2)?,
            cutting_edge_length: r(3)?,
            edge_radius: r(4)?,
            edge_center_vertical: r(5)?,
            edge_center_horizontal: r(6)?,
        })
    }

    fn cutting_component(&mut self, i: &'f Instance) -> R<CuttingComponent> {
        expect(i, &["CUTTING_COMPONENT"], "a CUTTING_COMPONENT")?;
        let technology = match i.params.get(4) {
            Some(p) => self.opt_technology(p)?,
            None => None,
        };
        Ok(CuttingComponent {
            tool_offset_length: opt_real(arg(i, 0)?)?,
            material: self.opt_raw(arg(i, 1)?)?,
            technological_data: self.opt_raw(arg(i, 2)?)?,
            expected_tool_life: opt_real(arg(i, 3)?)?,
            technology,
        })
    }
}

/// W0806: `CUTTING_TOOL` is abstract in ISO 14649-111; read as the
/// MILLING_CUTTING_TOOL it stands for (written back as one).
fn abstract_tool(i: &Instance) -> Diagnostic {
    Diagnostic::new(
        Code::AbstractInstance,
        format!(
            "#{} CUTTING_TOOL is an abstract entity of ISO 14649-111",
            i.id
        ),
    )
    .primary(i.entity_span, "read as a MILLING_CUTTING_TOOL")
    .help("write MILLING_CUTTING_TOOL(its_id, body, edges, length, $, $); cncc writes it so")
}

/// The body entity's kind; `CENTER_DRILL` reads as `CENTERDRILL`.
pub(crate) fn body_kind(e: &str) -> ToolBodyKind {
    match e {
        "ENDMILL" => ToolBodyKind::Endmill,
        "TAPERED_ENDMILL" => ToolBodyKind::TaperedEndmill,
        "BALL_ENDMILL" => ToolBodyKind::BallEndmill,
        "BULLNOSE_ENDMILL" => ToolBodyKind::BullnoseEndmill,
        "FACEMILL" => ToolBodyKind::Facemill,
        "TWIST_DRILL" => ToolBodyKind::TwistDrill,
        "TAPERED_DRILL" => ToolBodyKind::TaperedDrill,
        "CENTERDRILL" => ToolBodyKind::CenterDrill,
        "SPOTDRILL" => ToolBodyKind::Spotdrill,
        "COUNTERSINK" => ToolBodyKind::Countersink,
        "COUNTERBORE" => ToolBodyKind::Counterbore,
        "REAMER" => ToolBodyKind::Reamer,
        "TAPERED_REAMER" => ToolBodyKind::TaperedReamer,
        "TAP" => ToolBodyKind::Tap,
        "THREAD_MILL" => ToolBodyKind::ThreadMill,
        other => ToolBodyKind::Other(other.to_string()),
    }
}
