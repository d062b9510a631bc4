//! The project skeleton every raised program gets: PROJECT, the main
//! WORKPLAN with its SETUP (security plane from the highest rapid Z),
//! WORKPIECE 0 with its BLOCK bounding from the stock, and the tools.
//!
//! Tools are made when the run first uses them. Their geometry comes from
//! the tool table the run used (`--tool-table`, else the built-in one),
//! converted from machine units to mm. The body kind is a guess, from the
//! table's comment first ("ball" → BALL_ENDMILL, "bull" → BULLNOSE_ENDMILL,
//! "face" → FACEMILL, "spot"/"centre"/"center" → SPOTDRILL/CENTER_DRILL,
//! "chamfer"/"countersink" → COUNTERSINK, "ream" → REAMER, "tap" → TAP,
//! "drill" → TWIST_DRILL), else from what the program does with it: a tool
//! that only ever cuts in drilling cycles is a TWIST_DRILL, any other an
//! ENDMILL. ISO 14649 needs a body kind; the program seldom says it.

use super::stock::Stock;
use crate::diag::{Code, Diagnostic};
use crate::interp::tooltable::ToolTable;
use crate::span::Span;
use crate::stepnc::model::*;
use std::collections::HashMap;

/// A placement at `xyz` with the default axes (+Z up, +X reference).
pub fn placement(name: &str, xyz: P3) -> Axis2Placement {
    Axis2Placement {
        name: name.to_string(),
        location: Point {
            name: String::new(),
            xyz,
        },
        axis: Some(Direction {
            name: "AXIS".into(),
            ratios: [0.0, 0.0, 1.0],
        }),
        ref_direction: Some(Direction {
            name: "REF_DIRECTION".into(),
            ratios: [1.0, 0.0, 0.0],
        }),
    }
}

/// A horizontal plane at height `z`.
pub fn plane_at(name: &str, z: f64) -> Plane {
    Plane {
        name: name.to_string(),
        position: placement(name, [0.0, 0.0, z]),
    }
}

/// A new project with its workplan, setup and workpiece 0.
pub fn skeleton(name: &str, stock: Option<&Stock>) -> Project {
    let bounding = stock.map(|s| Bounding::Block {
        name: "STOCK".into(),
        position: placement("STOCK CORNER", s.corner),
        size: s.size,
    });
    let workpiece = Workpiece {
        id: format!("{name} WORKPIECE"),
        material: None,
        global_tolerance: None,
        rawpiece: None,
        geometry: None,
        bounding,
        clamping_positions: Vec::new(),
    };
    let setup = Setup {
        id: "SETUP1".into(),
        origin: Some(placement("SETUP1", [0.0; 3])),
        secplane: plane_at("SECURITY PLANE", 0.0),
        workpiece_setups: vec![WorkpieceSetup {
            workpiece: WorkpieceId(0),
            origin: placement("WORKPIECE", [0.0; 3]),
            offset: None,
            restricted_area: None,
            instructions: Vec::new(),
        }],
    };
    Project {
        id: name.to_string(),
        main_workplan: Workplan {
            id: "MAIN WORKPLAN".into(),
            elements: Vec::new(),
            channel: None,
            setup: Some(setup),
            effect: None,
        },
        its_workpieces: vec![WorkpieceId(0)],
        workpieces: vec![workpiece],
        ..Project::default()
    }
}

/// Sets the security plane of the setup and of every workingstep and
/// rapid movement at absolute `z` (one plane for the whole workplan, as in
/// ISO 14649-11 Example 1). ISO 14649-10 gives a workingstep's plane in
/// its feature's frame, so each workingstep's plane is written at `z`
/// less its feature's height (raised features are vertical); the setup's
/// is in setup coordinates and a rapid movement's in workpiece
/// coordinates (both identity here).
pub fn set_security_plane(project: &mut Project, z: f64) {
    let plane = plane_at("SECURITY PLANE", z);
    if let Some(setup) = project.main_workplan.setup.as_mut() {
        setup.secplane = plane.clone();
    }
    let features = &project.features;
    for e in &mut project.main_workplan.elements {
        match e {
            Executable::Workingstep(w) => {
                let top = features
                    .get(w.feature.index())
                    .map_or(0.0, |f| f.placement.location.xyz[2]);
                w.secplane = if top == 0.0 {
                    plane.clone()
                } else {
                    plane_at("SECURITY PLANE", z - top)
                };
            }
            Executable::Rapid(r) => r.secplane = plane.clone(),
            Executable::Workplan(_)
            | Executable::ProgramStop { .. }
            | Executable::OptionalStop { .. }
            | Executable::DisplayMessage { .. }
            | Executable::Other(_) => {}
        }
    }
}

/// The tools of a project, made on first use.
pub struct ToolRegistry {
    table: ToolTable,
    /// mm per tool-table unit.
    scale: f64,
    ids: HashMap<i64, ToolId>,
    /// Per tool: cuts made inside drilling cycles, cuts made elsewhere.
    uses: Vec<(usize, usize)>,
    pub diagnostics: Vec<Diagnostic>,
}

impl ToolRegistry {
    pub fn new(table: ToolTable, mm_per_unit: f64) -> Self {
        ToolRegistry {
            table,
            scale: mm_per_unit,
            ids: HashMap::new(),
            uses: Vec::new(),
            diagnostics: Vec::new(),
        }
    }

    /// The tool's diameter in mm, when the table has it.
    pub fn diameter(&self, number: i64) -> Option<f64> {
        self.table
            .get(number)
            .map(|t| t.diameter * self.scale)
            .filter(|d| *d > 0.0)
    }

    /// The project's tool for tool number `number`, made on first use
    /// (`span`: where it is first used, for the warning when the table
    /// does not know it).
    pub fn id(&mut self, project: &mut Project, number: i64, span: Span) -> ToolId {
        if let Some(id) = self.ids.get(&number) {
            return *id;
        }
        let id = ToolId(project.tools.len() as u32);
        project.tools.push(self.make(number, span));
        self.ids.insert(number, id);
        self.uses.push((0, 0));
        id
    }

    /// Counts a cut by the tool: in a drilling cycle or not.
    pub fn used(&mut self, id: ToolId, drilling: bool) {
        let u = &mut self.uses[id.index()];
        if drilling {
            u.0 += 1;
        } else {
            u.1 += 1;
        }
    }

    fn make(&mut self, number: i64, span: Span) -> Tool {
        let row = self.table.get(number);
        let diameter = self.diameter(number);
        if diameter.is_none() {
            let what = if number == 0 {
                "moves made with no tool in the spindle (T0)".to_string()
            } else {
                format!("tool T{number} has no diameter in the tool table")
            };
            self.diagnostics.push(
                Diagnostic::new(Code::RaiseToolWithoutDiameter, what)
                    .primary(span, "first used here")
                    .help("give a tool table with `--tool-table T.tbl` (LinuxCNC format: `T1 P1 Z50 D10 ;end mill`)"),
            );
        }
        let comment = row
            .map(|t| t.comment.trim().to_string())
            .unwrap_or_default();
        let length = row.map(|t| t.offset[2] * self.scale).unwrap_or(0.0);
        let id = if comment.is_empty() {
            format!("T{number}")
        } else {
            format!("T{number} {comment}")
        };
        Tool {
            id,
            body: ToolBody {
                kind: kind_from_comment(&comment).unwrap_or(ToolBodyKind::Endmill),
                dimension: ToolDimension {
                    diameter: diameter.unwrap_or(0.0),
                    ..ToolDimension::default()
                },
                number_of_teeth: None,
                hand_of_cut: None,
                coolant_through_tool: None,
                pilot_length: None,
                extra: Vec::new(),
            },
            cutting_edges: vec![CuttingComponent {
                tool_offset_length: Some(length),
                material: None,
                technological_data: None,
                expected_tool_life: None,
                technology: None,
            }],
            overall_assembly_length: None,
            direction_for_spindle_orientation: None,
            holder_diameter_for_spindle_orientation: None,
        }
    }

    /// Gives the tools without a kind from their comment the kind their
    /// use suggests (only drilling cycles → TWIST_DRILL).
    pub fn settle_kinds(&self, project: &mut Project) {
        for (i, tool) in project.tools.iter_mut().enumerate() {
            let comment = tool.id.split_once(' ').map(|(_, c)| c).unwrap_or("");
            if kind_from_comment(comment).is_some() || tool.body.kind == ToolBodyKind::Tap {
                continue;
            }
            let (drilling, other) = self.uses[i];
            if drilling > 0 && other == 0 {
                tool.body.kind = ToolBodyKind::TwistDrill;
            }
        }
    }
}

/// The body kind a tool table comment names, if it names one.
fn kind_from_comment(comment: &str) -> Option<ToolBodyKind> {
    let c = comment.to_ascii_lowercase();
    let has = |w: &str| c.contains(w);
    Some(if has("ball") {
        ToolBodyKind::BallEndmill
    } else if has("bull") {
        ToolBodyKind::BullnoseEndmill
    } else if has("face") {
        ToolBodyKind::Facemill
    } else if has("spot") {
        ToolBodyKind::Spotdrill
    } else if has("centre") || has("center") {
        ToolBodyKind::CenterDrill
    } else if has("chamfer") || has("countersink") {
        ToolBodyKind::Countersink
    } else if has("ream") {
        ToolBodyKind::Reamer
    } else if has("tap") && !has("taper") {
        ToolBodyKind::Tap
    } else if has("drill") {
        ToolBodyKind::TwistDrill
    } else if has("end mill") || has("endmill") {
        ToolBodyKind::Endmill
    } else {
        return None;
    })
}
