//! The post's plan: the project's workingsteps in execution order, each
//! resolved to its feature, operation and tool, placed in workpiece
//! coordinates (mm), with the planes every target needs.
//!
//! Planes (reference/stepnc.md §4.3): the workingstep's security plane is
//! the clearance height (`clear`: Fanuc initial level with G98, Siemens
//! RTP, Heidenhain Q204); the operation's `retract_plane` is feature-local,
//! a height above the feature's top, and becomes the R plane (Fanuc R =
//! top + retract, Siemens SDIS = retract above RFP = top). NIST's STEPNC++
//! maps retract_plane to RTP instead; we follow the standard's meaning so
//! that every target makes the same moves. The security plane is read in
//! workpiece coordinates (NIST's interpreter does the same; ex1 shares one
//! plane across features of different heights).

use super::frame::Frame;
use super::PostError;
use crate::stepnc::model::*;

/// The clearance above the top used when an operation has no retract plane.
pub const DEFAULT_SDIS: f64 = 2.0;

/// One machining workingstep, resolved.
pub struct Step<'p> {
    /// 1-based position among the workingsteps.
    pub number: usize,
    pub ws: &'p MachiningWorkingstep,
    pub feature: &'p Feature,
    pub op: &'p Operation,
    pub tool: &'p Tool,
    /// The tool number the program uses (T1.. in order of first use).
    pub tool_no: u32,
    /// The feature's frame in workpiece coordinates (vertical axis).
    pub frame: Frame,
    /// Absolute z of the feature's top, its bottom (depth plane) and the
    /// clearance (security) plane.
    pub top: f64,
    pub bottom: f64,
    pub clear: f64,
    /// The R-plane distance above the top.
    pub sdis: f64,
    /// An earlier roughing operation on the same feature, if any.
    pub roughed_by: Option<&'p Operation>,
    /// The security plane below the retract plane (E0901), reported by
    /// the validator.
    pub plane_error: Option<PostError>,
}

/// Anything else in the workplan, in order.
pub enum Item<'p> {
    Step(Box<Step<'p>>),
    Stop {
        optional: bool,
    },
    Message(&'p str),
    /// A `RAPID_MOVEMENT` with its own toolpath, in workpiece coordinates.
    Rapid {
        id: &'p str,
        moves: Vec<super::toolpaths::PathMove>,
    },
}

/// Walks the main workplan (and nested workplans) into items.
pub fn plan(project: &Project) -> Result<Vec<Item<'_>>, Vec<PostError>> {
    let base = setup_frame(project);
    let mut out = Vec::new();
    let mut errors = Vec::new();
    let mut tools: Vec<ToolId> = Vec::new();
    let mut count = 0;
    walk(
        project,
        &project.main_workplan,
        &base,
        &mut tools,
        &mut count,
        &mut out,
        &mut errors,
    );
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// The setup chain (setup origin, then the first workpiece setup) as a
/// frame: workpiece coordinates to machine coordinates.
pub fn setup_frame(project: &Project) -> Frame {
    let mut f = Frame::identity();
    if let Some(setup) = &project.main_workplan.setup {
        if let Some(o) = &setup.origin {
            f = f.then(&Frame::from_placement(o));
        }
        if let Some(ws) = setup.workpiece_setups.first() {
            f = f.then(&Frame::from_placement(&ws.origin));
        }
    }
    f
}

#[allow(clippy::too_many_arguments)]
fn walk<'p>(
    project: &'p Project,
    wp: &'p Workplan,
    base: &Frame,
    tools: &mut Vec<ToolId>,
    count: &mut usize,
    out: &mut Vec<Item<'p>>,
    errors: &mut Vec<PostError>,
) {
    for e in &wp.elements {
        match e {
            Executable::Workingstep(ws) => {
                *count += 1;
                match resolve(project, ws, base, tools, *count, out) {
                    Ok(s) => out.push(Item::Step(Box::new(s))),
                    Err(e) => errors.push(e),
                }
            }
            Executable::Workplan(inner) => walk(project, inner, base, tools, count, out, errors),
            Executable::ProgramStop { .. } => out.push(Item::Stop { optional: false }),
            Executable::OptionalStop { .. } => out.push(Item::Stop { optional: true }),
            Executable::DisplayMessage { text, .. } => out.push(Item::Message(text)),
            Executable::Rapid(r) => match r.toolpath.as_deref() {
                Some(paths) => {
                    match super::toolpaths::moves(base, paths, None, (true, None), &r.id) {
                        Ok(moves) => out.push(Item::Rapid { id: &r.id, moves }),
                        Err(e) => errors.push(e),
                    }
                }
                // Without a toolpath it is the move via the security plane
                // that every posted workingstep already starts with.
                None => {}
            },
            Executable::Other(raw) => errors.push(other_executable(raw)),
        }
    }
}

/// E0900 for an executable kept as written: named by its its_id, with
/// why (a workingstep kept raw when read: the W0802 warning gives the
/// attribute).
fn other_executable(raw: &Raw) -> PostError {
    let id = match raw.params.first() {
        Some(RawValue::String(s)) if !s.is_empty() => s.clone(),
        _ => raw.entity.clone(),
    };
    let why = if raw.entity.eq_ignore_ascii_case("MACHINING_WORKINGSTEP") {
        "a workingstep cncc kept as written when reading (the kept-raw warning W0802 names the attribute that does not fit ISO 14649)"
            .to_string()
    } else {
        format!(
            "a {} (an NC function cncc carries but does not post)",
            raw.entity
        )
    };
    PostError::unsupported(&id, &why)
}

fn resolve<'p>(
    project: &'p Project,
    ws: &'p MachiningWorkingstep,
    base: &Frame,
    tools: &mut Vec<ToolId>,
    number: usize,
    earlier: &[Item<'p>],
) -> Result<Step<'p>, PostError> {
    let feature = project
        .features
        .get(ws.feature.index())
        .ok_or_else(|| PostError::broken(&ws.id, "its feature is missing"))?;
    let op = project
        .operations
        .get(ws.operation.index())
        .ok_or_else(|| PostError::broken(&ws.id, "its operation is missing"))?;
    let tool = project
        .tools
        .get(op.tool.index())
        .ok_or_else(|| PostError::broken(&op.id, "its tool is missing"))?;
    let frame = base.then(&Frame::from_placement(&feature.placement));
    if !frame.is_vertical() {
        return Err(PostError::unsupported(
            &feature.id,
            "a feature whose axis is not the machine's Z axis (3-axis posts only)",
        ));
    }
    let top = frame.origin[2];
    let bottom = match &feature.depth {
        Some(d) => frame.apply(d.position.location.xyz)[2],
        None => through_bottom(project, feature, base)?,
    };
    let clear = base.apply(ws.secplane.position.location.xyz)[2];
    let sdis = op.retract_plane.unwrap_or(DEFAULT_SDIS);
    // Reported by the validator, after the stock check (a feature placed
    // outside the stock is the likelier cause).
    let plane_error = (clear < top + sdis).then(|| {
        PostError::broken(
            &ws.id,
            &format!(
                "the security plane (z {clear}) is below the operation's retract plane (z {})",
                top + sdis
            ),
        )
    });
    let tool_no = match tools.iter().position(|t| *t == op.tool) {
        Some(i) => i as u32 + 1,
        None => {
            tools.push(op.tool);
            tools.len() as u32
        }
    };
    let roughed_by = earlier.iter().rev().find_map(|i| match i {
        Item::Step(s) if std::ptr::eq(s.feature, feature) && is_rough(s.op) => Some(s.op),
        _ => None,
    });
    Ok(Step {
        number,
        ws,
        feature,
        op,
        tool,
        tool_no,
        frame,
        top,
        bottom,
        clear,
        sdis,
        roughed_by,
        plane_error,
    })
}

/// The bottom of a through feature whose depth plane is `$`: the stock's
/// bottom (the feature ends where the material does).
fn through_bottom(project: &Project, f: &Feature, base: &Frame) -> Result<f64, PostError> {
    let stock = super::validate::stock(project, f.workpiece, base);
    match stock {
        Some(b) if super::validate::is_through(&f.kind) => Ok(b.min.z),
        _ => Err(PostError::broken(
            &f.id,
            "its depth plane is `$`, and it is not a through feature of a workpiece with a BLOCK, so its depth is unknown",
        )),
    }
}

/// True for roughing milling operations.
/// A milling operation (plane, side, bottom and side milling).
pub fn is_milling(op: &Operation) -> bool {
    matches!(
        op.kind,
        OperationKind::PlaneMilling { .. }
            | OperationKind::SideMilling { .. }
            | OperationKind::BottomAndSideMilling { .. }
    )
}

pub fn is_rough(op: &Operation) -> bool {
    match &op.kind {
        OperationKind::PlaneMilling { finish, .. }
        | OperationKind::SideMilling { finish, .. }
        | OperationKind::BottomAndSideMilling { finish, .. } => !finish,
        OperationKind::Freeform { .. }
        | OperationKind::Drilling(_)
        | OperationKind::CenterDrilling(_)
        | OperationKind::CounterSinking(_)
        | OperationKind::MultistepDrilling { .. }
        | OperationKind::Boring { .. }
        | OperationKind::Tapping { .. }
        | OperationKind::ThreadDrilling { .. }
        | OperationKind::Other(_) => false,
    }
}
