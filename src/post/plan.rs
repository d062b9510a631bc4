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
//! that every target makes the same moves.
//!
//! Both planes are in the feature's frame: ISO 14649-10 says of
//! `workingstep.its_secplane` that its "dimensions given are relative
//! coordinates as measured from the workpiece co-ordinate system or, if
//! this workingstep is associated with a manufacturing_feature, in the
//! local co-ordinate system of the feature", and that "all geometry and
//! parameters of the machining_operation are defined in the local
//! co-ordinate system of the feature" (NIST's ISO 14649 interpreter reads
//! the workingstep's plane in the feature's frame too). Generators that
//! write one absolute plane for the setup and every workingstep (ex1 at
//! z 30 over features at z 0 and 5; field files at z 75 over a 50 mm block)
//! then get a plane that much higher: safe, only longer rapids.
//!
//! A security plane below the retract plane (a file inconsistent even so)
//! is not refused: the tool cannot rapid below the retract plane, so the
//! post rapids at the retract plane and warns (W0904), which is what the
//! operation's own definition guarantees ("a change to rapid feed ... can
//! only occur above this plane").

use super::frame::Frame;
use super::PostError;
use crate::diag::{Code, Diagnostic};
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
    /// The feature's frame in the working plane's coordinates (vertical
    /// axis): the workpiece's, or the tilted plane's (then the identity).
    pub frame: Frame,
    /// A feature whose axis is not the machine's Z, on a target that can
    /// tilt its working plane (`tilted-working-plane`): the tilted plane
    /// in workpiece coordinates, which is the feature's own frame (origin
    /// at the feature, z along its axis). `frame`, `top`, `bottom` and
    /// `clear` are then in this plane.
    pub tilt: Option<Frame>,
    /// Absolute z of the feature's top, its bottom (depth plane) and the
    /// clearance (security) plane.
    pub top: f64,
    pub bottom: f64,
    pub clear: f64,
    /// The R-plane distance above the top.
    pub sdis: f64,
    /// An earlier roughing operation on the same feature, if any.
    pub roughed_by: Option<&'p Operation>,
    /// The security plane below the retract plane (W0904: `clear` is
    /// raised to the retract plane), reported by the validator.
    pub plane_warning: Option<Diagnostic>,
    /// A later workingstep cuts the same feature (this one need not
    /// finish it).
    pub later: bool,
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

/// Walks the main workplan (and nested workplans) into items, for a
/// 3-axis target.
pub fn plan(project: &Project) -> Result<Vec<Item<'_>>, Vec<PostError>> {
    plan_for(project, false)
}

/// [`plan`] for a target that can (`can_tilt`) or cannot tilt its working
/// plane: a feature whose axis is not the machine's Z is machined in a
/// tilted plane (3+2) or refused.
pub fn plan_for(project: &Project, can_tilt: bool) -> Result<Vec<Item<'_>>, Vec<PostError>> {
    let base = setup_frame(project);
    let mut out = Vec::new();
    let mut errors = Vec::new();
    let mut tools: Vec<ToolId> = Vec::new();
    let mut count = 0;
    let mut ctx = Walk {
        base: &base,
        can_tilt,
        tools: &mut tools,
        count: &mut count,
    };
    walk(
        project,
        &project.main_workplan,
        "/project/main_workplan",
        &mut ctx,
        &mut out,
        &mut errors,
    );
    mark_later(&mut out);
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// Marks each workingstep whose feature a later workingstep cuts too.
fn mark_later(items: &mut [Item<'_>]) {
    for i in 0..items.len() {
        let Item::Step(s) = &items[i] else { continue };
        let f = s.feature as *const Feature;
        let later = items[i + 1..]
            .iter()
            .any(|it| matches!(it, Item::Step(t) if std::ptr::eq(t.feature, f)));
        if let Item::Step(s) = &mut items[i] {
            s.later = later;
        }
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

/// What the walk carries: the setup frame, whether the target tilts, the
/// tools met so far and the workingsteps counted.
struct Walk<'a> {
    base: &'a Frame,
    can_tilt: bool,
    tools: &'a mut Vec<ToolId>,
    count: &'a mut usize,
}

fn walk<'p>(
    project: &'p Project,
    wp: &'p Workplan,
    path: &str,
    ctx: &mut Walk<'_>,
    out: &mut Vec<Item<'p>>,
    errors: &mut Vec<PostError>,
) {
    let base = ctx.base;
    for (k, e) in wp.elements.iter().enumerate() {
        let here = format!("{path}/its_elements[{k}]");
        match e {
            Executable::Workingstep(ws) => {
                *ctx.count += 1;
                match resolve(project, ws, ctx, out) {
                    Ok(s) => out.push(Item::Step(Box::new(s))),
                    Err(e) => errors.push(e),
                }
            }
            Executable::Workplan(inner) => walk(project, inner, &here, ctx, out, errors),
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
            Executable::Other(raw) => errors.push(other_executable(raw, &here)),
        }
    }
}

/// E0900 for an executable kept as written: named by its its_id, with
/// why (a workingstep kept raw when read: the W0802 warning gives the
/// attribute).
fn other_executable(raw: &Raw, path: &str) -> PostError {
    if raw.entity.eq_ignore_ascii_case("MACHINING_WORKINGSTEP") {
        return super::kept::refusal(raw, path);
    }
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
    ctx: &mut Walk<'_>,
    earlier: &[Item<'p>],
) -> Result<Step<'p>, PostError> {
    let (base, number) = (ctx.base, *ctx.count);
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
    let placed = base.then(&Frame::from_placement(&feature.placement));
    let (frame, tilt) = if placed.is_vertical() {
        (placed, None)
    } else if ctx.can_tilt {
        (Frame::identity(), Some(placed))
    } else {
        let r = |v: f64| (v * 1e6).round() / 1e6 + 0.0;
        return Err(PostError::unsupported(
            &feature.id,
            &format!(
                "a feature whose axis ({}, {}, {}) is not the machine's Z axis, on a target that cannot tilt its working plane (its spec declares no `tilted-working-plane`: a 3-axis machine, or the option not declared)",
                r(placed.z[0]),
                r(placed.z[1]),
                r(placed.z[2])
            ),
        ));
    };
    let top = frame.origin[2];
    let bottom = match &feature.depth {
        Some(d) => frame.apply(d.position.location.xyz)[2],
        None => through_bottom(project, feature, base, tilt.as_ref())?,
    };
    let sdis = op.retract_plane.unwrap_or(DEFAULT_SDIS);
    let (clear, plane_warning) = clearance(&ws.id, &frame, &ws.secplane, top, sdis);
    let tool_no = match ctx.tools.iter().position(|t| *t == op.tool) {
        Some(i) => i as u32 + 1,
        None => {
            ctx.tools.push(op.tool);
            ctx.tools.len() as u32
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
        tilt,
        top,
        bottom,
        clear,
        sdis,
        roughed_by,
        plane_warning,
        later: false,
    })
}

/// The clearance height (absolute z) of a workingstep: its security plane
/// read in the feature's `frame`, or the retract plane (`top + sdis`)
/// when the security plane lies below it, with a W0904 warning naming the
/// workingstep `ws`.
pub fn clearance(
    ws: &str,
    frame: &Frame,
    secplane: &Plane,
    top: f64,
    sdis: f64,
) -> (f64, Option<Diagnostic>) {
    let clear = frame.apply(secplane.position.location.xyz)[2];
    let retract = top + sdis;
    if clear >= retract - 1e-9 {
        return (clear, None);
    }
    let r = |v: f64| (v * 1000.0).round() / 1000.0;
    let d = Diagnostic::new(
        Code::SecplaneBelowRetract,
        format!(
            "`{ws}`: the security plane (z {}) is below the operation's retract plane (z {}): rapids are made at the retract plane",
            r(clear),
            r(retract)
        ),
    )
    .help("both planes are in the feature's frame (ISO 14649-10); raise the workingstep's security plane or lower the operation's retract_plane");
    (retract, Some(d))
}

/// The bottom of a through feature whose depth plane is `$`: the stock's
/// bottom (the feature ends where the material does), along the tilted
/// plane's axis when there is one.
fn through_bottom(
    project: &Project,
    f: &Feature,
    base: &Frame,
    tilt: Option<&Frame>,
) -> Result<f64, PostError> {
    let stock = super::validate::stock(project, f.workpiece, base);
    match stock {
        Some(b) if super::validate::is_through(&f.kind) => Ok(match tilt {
            None => b.min.z,
            Some(t) => b
                .corners()
                .iter()
                .filter_map(|c| t.transform().from_base((*c).into()))
                .map(|p| p[2])
                .fold(f64::INFINITY, f64::min),
        }),
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
