//! The program frame and what every workingstep has: the comments naming
//! feature and operation, tool data and tool change, tolerance, approach
//! over the security plane, spindle and coolant; the body comes from
//! [`super::holes`] or [`super::milling`].

use super::group::{self, Unit};
use super::names::{body_kind, feature_kind, operation_kind, siemens_tool_type};
use super::plan::{Item, Step};
use super::values::Vals;
use super::{holes, milling, PostError, Writer};
use crate::stepnc::model::*;

pub fn write_program(
    w: &mut Writer<'_>,
    project: &Project,
    items: &[Item<'_>],
) -> Result<(), Vec<PostError>> {
    let one = |r: Result<(), PostError>| r.map_err(|e| vec![e]);
    let begin = Vals::new()
        .set("number", "1000")
        .set("title", w.safe_text(&project.id, "begin.j2"));
    one(w.emit("begin.j2", blank(w, project, begin)))?;
    let mut errors = Vec::new();
    for unit in group::units(items) {
        let item = match unit {
            Unit::Holes(steps) | Unit::Slots(steps) => {
                if let Err(e) = write_step(w, project, &steps) {
                    errors.push(e);
                }
                continue;
            }
            Unit::Item(item) => item,
        };
        let r = match item {
            Item::Step(s) => write_step(w, project, &[&**s]),
            Item::Stop { optional } => w.emit(
                "stop.j2",
                Vals::new().set("m", if *optional { "1" } else { "0" }),
            ),
            Item::Message(text) => w.comment(&format!("MESSAGE: {text}")),
            Item::Rapid { id, moves } => rapid(w, id, moves),
        };
        if let Err(e) = r {
            errors.push(e);
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    one(w.emit("end.j2", Vals::new()))
}

/// A `RAPID_MOVEMENT` with its own toolpath: its moves as rapids from its
/// first point, where the path says the tool is.
fn rapid(
    w: &mut Writer<'_>,
    id: &str,
    moves: &[super::toolpaths::PathMove],
) -> Result<(), PostError> {
    w.comment(&format!("RAPID {id}"))?;
    let Some(first) = super::toolpaths::first_point(moves) else {
        return Ok(());
    };
    super::toolpaths::write(w, moves, first).map(|_| ())
}

/// The workpiece's block (`BLK FORM` on Heidenhain), when the project
/// gives one along the machine axes: `has_blk` ("1" or empty) and its
/// lowest and highest corners, for the templates that want them.
fn blank(w: &Writer<'_>, project: &Project, v: Vals) -> Vals {
    let block = project.workpieces.iter().find_map(|wp| match &wp.bounding {
        Some(Bounding::Block { position, size, .. })
            if super::frame::Frame::from_placement(position)
                .angle_deg()
                .abs()
                < 1e-9
                && super::frame::Frame::from_placement(position).is_vertical() =>
        {
            Some((position.location.xyz, *size))
        }
        _ => None,
    });
    let Some((at, size)) = block else {
        return v.set_derived("has_blk", "");
    };
    let (lo, hi) = (at, [at[0] + size[0], at[1] + size[1], at[2] + size[2]]);
    v.set_derived("has_blk", "1")
        .set_derived("blk_x0", w.fmt.len(lo[0]))
        .set_derived("blk_y0", w.fmt.len(lo[1]))
        .set_derived("blk_z0", w.fmt.len(lo[2]))
        .set_derived("blk_x1", w.fmt.len(hi[0]))
        .set_derived("blk_y1", w.fmt.len(hi[1]))
        .set_derived("blk_z1", w.fmt.len(hi[2]))
}

/// One workingstep, or several that make the same hole at different
/// places (one cycle, several positions).
fn write_step(w: &mut Writer<'_>, project: &Project, steps: &[&Step<'_>]) -> Result<(), PostError> {
    w.step = steps[0].ws.id.clone();
    w.summary.push(super::summary::PostedStep::new(steps));
    let r = write_step_body(w, project, steps);
    if let Some(s) = w.summary.last_mut() {
        s.open = false;
    }
    w.step.clear();
    r.map_err(|mut e| {
        // A feature or operation with an empty its_id: name the
        // workingstep instead, so that the message can be located.
        if let Some(rest) = e.message.strip_prefix("``") {
            e.message = format!("`{}`{rest}", steps[0].ws.id);
        }
        e
    })
}

fn write_step_body(
    w: &mut Writer<'_>,
    project: &Project,
    steps: &[&Step<'_>],
) -> Result<(), PostError> {
    let s = steps[0];
    for st in steps {
        let n = st.number;
        w.comment(&format!(
            "WS({n}) {} Feature={} {}",
            st.ws.id,
            feature_kind(&st.feature.kind),
            st.feature.id
        ))?;
        w.comment(&format!(
            "WS({n}) Operation={} {}",
            operation_kind(&st.op.kind),
            st.op.id
        ))?;
    }
    let tool_len = tool_length(s.tool);
    let d = s.tool.body.dimension.diameter;
    w.comment(&format!(
        "Tool={} {}, length {} mm, diameter {} mm",
        s.tool.id,
        body_kind(&s.tool.body.kind),
        w.fmt.plain(tool_len, 3),
        w.fmt.plain(d, 3)
    ))?;
    // The tool was called in this step (a Heidenhain TOOL CALL also sets
    // the spindle speed).
    let mut tool_called = false;
    if w.current_tool != Some(s.tool_no) {
        if w.post.has("tool_data.j2") && !w.defined_tools.contains(&s.tool_no) {
            w.defined_tools.push(s.tool_no);
            let code = match siemens_tool_type(&s.tool.body.kind) {
                Some(code) => code.to_string(),
                // A target whose tool data has no type code (Heidenhain
                // TOOL DEF) posts any tool.
                None if w.post.ignores("tool_data.j2", "type") => String::new(),
                None => {
                    return Err(PostError::unsupported(
                        &s.tool.id,
                        "a tool of this body type (no tool type code)",
                    ))
                }
            };
            w.emit(
                "tool_data.j2",
                Vals::new()
                    .set("t", s.tool_no.to_string())
                    .set("type", code)
                    .set("length", w.fmt.len(tool_len))
                    .set("radius", w.fmt.len(d / 2.0)),
            )?;
        }
        let sw = w.spindle(spindle_rpm(s)?)?;
        w.emit(
            "tool_change.j2",
            Vals::new()
                .set("t", s.tool_no.to_string())
                .set_derived("s", sw),
        )?;
        w.current_tool = Some(s.tool_no);
        tool_called = true;
    }
    if w.post.has("tolerance.j2") {
        if let Some(tol) = tolerance(project, s) {
            let mode = if super::plan::is_rough(s.op) {
                "102003"
            } else {
                "102001"
            };
            w.emit(
                "tolerance.j2",
                Vals::new()
                    .set("tol", w.fmt.plain(tol, 4))
                    .set("mode", mode),
            )?;
        }
    }
    // An operation with its own toolpath is posted as that path (CC1).
    let explicit = match s.op.toolpath.as_deref() {
        Some(paths) if !paths.is_empty() => Some(super::toolpaths::moves(
            &s.frame,
            paths,
            feed(s).ok(),
            (false, Some(s.top)),
            &s.op.id,
        )?),
        _ => None,
    };
    let at = explicit
        .as_deref()
        .and_then(super::toolpaths::first_point)
        .unwrap_or(s.frame.origin);
    if let Some(t) = &s.tilt {
        tilt(w, t)?;
    }
    w.emit(
        "approach.j2",
        Vals::new()
            .set("x", w.fmt.len(at[0]))
            .set("y", w.fmt.len(at[1]))
            .set("z", w.fmt.len(s.clear))
            .set("t", s.tool_no.to_string()),
    )?;
    let rpm = spindle_rpm(s)?;
    let sw = w.spindle(rpm)?;
    w.emit(
        "spindle.j2",
        Vals::new()
            .set("s", sw)
            .set("m", if rpm >= 0.0 { "3" } else { "4" })
            .set_derived("tool_called", if tool_called { "1" } else { "" }),
    )?;
    coolant(w, &s.op.machine_functions)?;
    if let Some(moves) = &explicit {
        super::toolpaths::write(w, moves, [at[0], at[1], s.clear])?;
        w.emit("retract.j2", Vals::new().set("z", w.fmt.len(s.clear)))?;
        return untilt(w, s);
    }
    match &s.feature.kind {
        FeatureKind::RoundHole { .. } if super::plan::is_milling(s.op) => {
            milling::write(w, project, steps)?
        }
        FeatureKind::RoundHole { .. } => holes::write(w, steps)?,
        FeatureKind::ClosedPocket { .. } | FeatureKind::PlanarFace { .. } => {
            milling::write(w, project, steps)?
        }
        FeatureKind::Slot { .. } | FeatureKind::Step { .. } => milling::write(w, project, steps)?,
        FeatureKind::OpenPocket { .. }
        | FeatureKind::GeneralOutsideProfile { .. }
        | FeatureKind::ToolpathFeature
        | FeatureKind::Other(_) => {
            return Err(PostError::unsupported(
                &s.feature.id,
                &format!("a {} feature", feature_kind(&s.feature.kind)),
            ))
        }
    }
    w.emit("retract.j2", Vals::new().set("z", w.fmt.len(s.clear)))?;
    untilt(w, s)
}

/// Tilts the working plane onto the feature's frame `t` (3+2): origin
/// `x0..z0` in workpiece coordinates and the rotation as the angles each
/// target's template wants: `xyz_*` about X, then Y', then Z''
/// (Siemens CYCLE800 axis by axis, mode 57), `zyx_*` about the fixed X,
/// then Y, then Z (Heidenhain PLANE SPATIAL SPA SPB SPC).
fn tilt(w: &mut Writer<'_>, t: &super::frame::Frame) -> Result<(), PostError> {
    let tr = t.transform();
    let (Some(xyz), Some(zyx)) = (tr.angles_xyz_intrinsic(), tr.angles_zyx()) else {
        return Err(PostError::template(
            "a tilted feature frame that is not a rotation".into(),
        ));
    };
    if !w.post.has("tilt.j2") || !w.post.has("untilt.j2") {
        return Err(PostError::template(format!(
            "{} declares `tilted-working-plane` but its post has no tilt.j2/untilt.j2",
            w.target.name
        )));
    }
    let a = |v: f64| w.fmt.angle(v);
    let vals = Vals::new()
        .set("x0", w.fmt.len(t.origin[0]))
        .set("y0", w.fmt.len(t.origin[1]))
        .set("z0", w.fmt.len(t.origin[2]))
        .set_derived("xyz_a", a(xyz[0]))
        .set_derived("xyz_b", a(xyz[1]))
        .set_derived("xyz_c", a(xyz[2]))
        .set_derived("zyx_a", a(zyx[0]))
        .set_derived("zyx_b", a(zyx[1]))
        .set_derived("zyx_c", a(zyx[2]));
    w.emit("tilt.j2", vals)
}

/// Back to the untilted working plane after a tilted workingstep.
fn untilt(w: &mut Writer<'_>, s: &Step<'_>) -> Result<(), PostError> {
    match s.tilt {
        Some(_) => w.emit("untilt.j2", Vals::new()),
        None => Ok(()),
    }
}

fn coolant(w: &mut Writer<'_>, mf: &MachineFunctions) -> Result<(), PostError> {
    let wanted = mf.coolant || mf.mist == Some(true);
    if w.coolant_on && !wanted {
        w.emit("coolant.j2", Vals::new().set("m", "9"))?;
    }
    w.coolant_on = wanted;
    if mf.coolant {
        w.emit("coolant.j2", Vals::new().set("m", "8"))?;
    }
    if mf.mist == Some(true) {
        w.emit("coolant.j2", Vals::new().set("m", "7"))?;
    }
    if mf.through_spindle_coolant {
        w.not_carried("through-spindle coolant (a machine-specific M code)")?;
    }
    if mf.oriented_spindle_stop.is_some() || !mf.axis_clamping.is_empty() {
        w.not_carried("oriented spindle stop / axis clamping of the machine functions")?;
    }
    Ok(())
}

/// Spindle rpm, positive clockwise: the technology's spindle, or its
/// cutting speed over the tool's circumference.
pub fn spindle_rpm(s: &Step<'_>) -> Result<f64, PostError> {
    let t = &s.op.technology;
    if let Some(rpm) = t.spindle {
        return Ok(rpm);
    }
    let d = s.tool.body.dimension.diameter;
    match t.cut_speed {
        Some(v) if d > 0.0 => Ok(v * 1000.0 / (std::f64::consts::PI * d)),
        _ => Err(PostError::broken(
            &s.op.id,
            "its technology gives no spindle speed",
        )),
    }
}

/// Feed mm/min: the technology's feed, or feed per tooth x teeth x rpm.
/// A feed of 0 is no feed (a tool that does not advance cuts nothing, and
/// LinuxCNC refuses `G1 ... F0`): the feed per tooth must give one.
pub fn feed(s: &Step<'_>) -> Result<f64, PostError> {
    let t = &s.op.technology;
    if let Some(f) = t.feed.filter(|f| *f > 0.0) {
        return Ok(f);
    }
    let per_tooth = t.feed_per_tooth.filter(|fz| *fz > 0.0);
    match (per_tooth, s.tool.body.number_of_teeth) {
        (Some(fz), Some(z)) if z > 0 => Ok(fz * z as f64 * spindle_rpm(s)?.abs()),
        _ => Err(PostError::broken(&s.op.id, &no_feed(t.feed))),
    }
}

/// Why a technology gives no feed.
fn no_feed(feed: Option<f64>) -> String {
    match feed {
        Some(f) => format!(
            "its technology's feedrate is {f}, and no feed per tooth (with the tool's number of teeth) gives another"
        ),
        None => "its technology gives no feed".into(),
    }
}

/// The contour tolerance: the tightest limit of the feature's toleranced
/// sizes, never coarser than the workpiece's global tolerance (which
/// holds where the feature says nothing).
pub(super) fn tolerance(project: &Project, s: &Step<'_>) -> Option<f64> {
    let mut sizes: Vec<&Toleranced> = Vec::new();
    match &s.feature.kind {
        FeatureKind::RoundHole { diameter, .. } => sizes.push(diameter),
        FeatureKind::ClosedPocket { pocket, boundary } => {
            sizes.extend(pocket.orthogonal_radius.iter());
            if let ClosedProfile::Rectangular { width, length, .. } = boundary {
                sizes.push(width);
                sizes.push(length);
            }
            if let ClosedProfile::Circular { diameter, .. } = boundary {
                sizes.push(diameter);
            }
        }
        FeatureKind::PlanarFace {
            course_of_travel: TravelPath::Linear { distance, .. },
            ..
        } => sizes.push(distance),
        FeatureKind::Slot { swept_shape, .. } => match swept_shape {
            OpenProfile::SquareU {
                width,
                first_radius,
                second_radius,
                ..
            } => {
                sizes.push(width);
                sizes.extend(first_radius.iter().chain(second_radius.iter()));
            }
            OpenProfile::RoundedU { width, .. } => sizes.push(width),
            OpenProfile::Vee { radius, .. } => sizes.push(radius),
            _ => {}
        },
        FeatureKind::Step {
            open_boundary: TravelPath::Linear { distance, .. },
            wall_boundary,
            ..
        } => {
            sizes.push(distance);
            if let Some(OpenProfile::Vee { radius, .. }) = wall_boundary {
                sizes.push(radius);
            }
        }
        _ => {}
    }
    let tightest = sizes
        .iter()
        .filter_map(|t| match t.tolerance {
            Tolerance::PlusMinus { upper, lower, .. } => Some(upper.abs().min(lower.abs())),
            Tolerance::LimitsAndFits { .. } | Tolerance::Other(_) | Tolerance::Unset => None,
        })
        .filter(|v| *v > 0.0)
        .fold(None, |a: Option<f64>, v| Some(a.map_or(v, |a| a.min(v))));
    let global = project
        .workpieces
        .get(s.feature.workpiece.index())
        .and_then(|wp| wp.global_tolerance)
        .filter(|v| *v > 0.0);
    match (tightest, global) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

pub(crate) fn tool_length(t: &Tool) -> f64 {
    t.overall_assembly_length
        .or_else(|| t.cutting_edges.first().and_then(|c| c.tool_offset_length))
        .unwrap_or(0.0)
}
