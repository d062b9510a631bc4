//! A compact readable listing of a project (`cncc stepnc --summary`):
//! workpiece, setup, tools, then the workplan one element per line with
//! its feature, operation, technology and toolpaths (curve kinds and point
//! counts). Meant for people and for snapshot tests; numbers in mm,
//! mm/min, rpm (+ clockwise).

use super::curves::point_count;
use super::ops::operation_name;
use crate::stepnc::model::*;
use std::fmt::Write;

fn n(v: f64) -> String {
    crate::ir::num::short_text(v, 4)
}

fn p3(p: P3) -> String {
    format!("({}, {}, {})", n(p[0]), n(p[1]), n(p[2]))
}

/// The listing.
pub fn summary(p: &Project) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "project {:?}", p.id);
    for w in &p.workpieces {
        let _ = write!(out, "workpiece {:?}", w.id);
        match &w.bounding {
            Some(Bounding::Block { position, size, .. }) => {
                let _ = writeln!(
                    out,
                    " block {} x {} x {} from {}",
                    n(size[0]),
                    n(size[1]),
                    n(size[2]),
                    p3(position.location.xyz)
                );
            }
            Some(Bounding::Other(r)) => {
                let _ = writeln!(out, " bounding {}", r.entity);
            }
            None => out.push_str(" (no stock given)\n"),
        }
    }
    if let Some(s) = &p.main_workplan.setup {
        let _ = writeln!(
            out,
            "setup {:?} security plane z {}",
            s.id,
            n(s.secplane.position.location.xyz[2])
        );
    }
    for (i, t) in p.tools.iter().enumerate() {
        let len = t
            .cutting_edges
            .first()
            .and_then(|c| c.tool_offset_length)
            .unwrap_or(0.0);
        let _ = writeln!(
            out,
            "tool {i} {:?} {:?} diameter {} length {}",
            t.id,
            t.body.kind,
            n(t.body.dimension.diameter),
            n(len)
        );
    }
    let (steps, rapids, points) = totals(p);
    let _ = writeln!(
        out,
        "workplan: {} elements, {steps} workingsteps, {rapids} rapid movements, {} features, {points} toolpath points",
        p.main_workplan.elements.len(),
        p.features.len()
    );
    for (i, e) in p.main_workplan.elements.iter().enumerate() {
        element(&mut out, p, i + 1, e);
    }
    out
}

fn totals(p: &Project) -> (usize, usize, usize) {
    let mut steps = 0;
    let mut rapids = 0;
    let mut points = 0;
    for e in &p.main_workplan.elements {
        match e {
            Executable::Workingstep(w) => {
                steps += 1;
                points += paths_points(p.operation(w.operation).toolpath.as_deref());
            }
            Executable::Rapid(r) => {
                rapids += 1;
                points += paths_points(r.toolpath.as_deref());
            }
            Executable::Workplan(_)
            | Executable::ProgramStop { .. }
            | Executable::OptionalStop { .. }
            | Executable::DisplayMessage { .. }
            | Executable::Other(_) => {}
        }
    }
    (steps, rapids, points)
}

fn paths_points(t: Option<&[Toolpath]>) -> usize {
    t.unwrap_or(&[])
        .iter()
        .map(|t| match t {
            Toolpath::CutterLocation { basic_curve, .. } => point_count(basic_curve),
            Toolpath::Feedstop { .. } | Toolpath::Other(_) => 0,
        })
        .sum()
}

fn element(out: &mut String, p: &Project, i: usize, e: &Executable) {
    match e {
        Executable::Workingstep(w) => {
            let op = p.operation(w.operation);
            let f = p.feature(w.feature);
            let _ = writeln!(out, "{i:>3} workingstep {:?}", w.id);
            let _ = writeln!(out, "      feature {}", feature(f));
            let _ = writeln!(
                out,
                "      operation {} tool {:?} {}",
                operation(op),
                p.tool(op.tool).id,
                technology(&op.technology, &op.machine_functions)
            );
            toolpaths(out, op.toolpath.as_deref());
        }
        Executable::Rapid(r) => {
            let _ = writeln!(out, "{i:>3} rapid {:?}", r.id);
            toolpaths(out, r.toolpath.as_deref());
        }
        Executable::ProgramStop { id } => {
            let _ = writeln!(out, "{i:>3} program stop {id:?}");
        }
        Executable::OptionalStop { id } => {
            let _ = writeln!(out, "{i:>3} optional stop {id:?}");
        }
        Executable::DisplayMessage { id, text } => {
            let _ = writeln!(out, "{i:>3} message {id:?} {text:?}");
        }
        Executable::Workplan(w) => {
            let _ = writeln!(
                out,
                "{i:>3} workplan {:?} ({} elements)",
                w.id,
                w.elements.len()
            );
        }
        Executable::Other(r) => {
            let _ = writeln!(out, "{i:>3} {}", r.entity);
        }
    }
}

fn feature(f: &Feature) -> String {
    let at = p3(f.placement.location.xyz);
    let depth = n(-f.depth_z());
    match &f.kind {
        FeatureKind::RoundHole {
            diameter, bottom, ..
        } => {
            format!(
                "ROUND_HOLE {:?} at {at} diameter {} depth {depth} bottom {}",
                f.id,
                n(diameter.nominal),
                super::cc2::listing::hole_bottom(bottom)
            )
        }
        FeatureKind::ToolpathFeature => {
            format!("TOOLPATH_FEATURE {:?} lowest z {}", f.id, n(f.depth_z()))
        }
        other => format!(
            "{:?} {} at {at} depth {depth}",
            f.id,
            super::cc2::listing::kind(other)
        ),
    }
}

fn operation(op: &Operation) -> String {
    let mut s = operation_name(&op.kind).to_string();
    let d = |v: Option<f64>| v.map(n).unwrap_or_else(|| "-".into());
    match &op.kind {
        OperationKind::Drilling(c) | OperationKind::Boring { drill: c, .. } => {
            let _ = write!(
                s,
                " depth {} dwell {} feed out {}",
                d(c.cutting_depth),
                d(c.dwell_time_bottom),
                d(c.feed_on_retract)
            );
        }
        OperationKind::MultistepDrilling {
            drill,
            retract_distance,
            first_depth,
            depth_of_step,
            ..
        } => {
            let _ = write!(
                s,
                " depth {} first {} step {} retract {}",
                d(drill.cutting_depth),
                n(*first_depth),
                n(*depth_of_step),
                n(*retract_distance)
            );
        }
        OperationKind::Tapping {
            drill,
            compensation_chuck,
        } => {
            let _ = write!(
                s,
                " depth {} pitch {}{}",
                d(drill.cutting_depth),
                d(op.thread_pitch()),
                if *compensation_chuck {
                    " compensation chuck"
                } else {
                    ""
                }
            );
        }
        _ => {}
    }
    if let OperationKind::Boring {
        spindle_stop_at_bottom: true,
        ..
    } = op.kind
    {
        s.push_str(" spindle stop at bottom");
    }
    if let Some(r) = op.retract_plane {
        let _ = write!(s, " retract plane {}", n(r));
    }
    s
}

fn technology(t: &Technology, m: &MachineFunctions) -> String {
    let mut s = format!(
        "F {} S {}",
        t.feed.map(n).unwrap_or_else(|| "-".into()),
        t.spindle.map(n).unwrap_or_else(|| "-".into())
    );
    if m.coolant {
        s.push_str(" coolant");
    }
    if m.mist == Some(true) {
        s.push_str(" mist");
    }
    s
}

fn curve(c: &Curve) -> String {
    match c {
        Curve::Polyline { points, .. } => match (points.first(), points.last()) {
            (Some(a), Some(b)) => format!(
                "polyline {} points {} .. {}",
                points.len(),
                p3(a.xyz),
                p3(b.xyz)
            ),
            _ => "polyline (empty)".into(),
        },
        Curve::Arc {
            radius,
            sense,
            start,
            end,
            circle,
            ..
        } => format!(
            "arc r {} {} centre {} {} -> {}",
            n(*radius),
            if *sense { "ccw" } else { "cw" },
            p3(circle.location.xyz),
            p3(start.xyz),
            p3(end.xyz)
        ),
        Curve::Line { start, end, .. } => format!("line {} -> {}", p3(start.xyz), p3(end.xyz)),
        Curve::Composite { segments, .. } => {
            let parts: Vec<String> = segments.iter().map(|s| short(&s.curve)).collect();
            format!("composite [{}]", parts.join(", "))
        }
        Curve::Other(r) => r.entity.clone(),
    }
}

fn short(c: &Curve) -> String {
    match c {
        Curve::Polyline { points, .. } => format!("polyline {}", points.len()),
        Curve::Arc { radius, sense, .. } => {
            format!("arc r {} {}", n(*radius), if *sense { "ccw" } else { "cw" })
        }
        Curve::Line { .. } => "line".into(),
        Curve::Composite { segments, .. } => format!("composite {}", segments.len()),
        Curve::Other(r) => r.entity.clone(),
    }
}

fn toolpaths(out: &mut String, t: Option<&[Toolpath]>) {
    let Some(t) = t else {
        out.push_str("      (no toolpath: via the security plane)\n");
        return;
    };
    for tp in t {
        match tp {
            Toolpath::CutterLocation {
                base, basic_curve, ..
            } => {
                let _ = write!(out, "      {:?} {}", base.kind, curve(basic_curve));
                if let Some(ToolpathSpeed::Named(s)) = &base.speed {
                    let _ = write!(out, " at {s}");
                }
                if let Some(tech) = &base.technology {
                    let _ = write!(
                        out,
                        " with F {} S {}",
                        tech.feed.map(n).unwrap_or_default(),
                        tech.spindle.map(n).unwrap_or_default()
                    );
                }
                out.push('\n');
            }
            Toolpath::Feedstop { dwell, .. } => {
                let _ = writeln!(out, "      feedstop {} s", n(*dwell));
            }
            Toolpath::Other(r) => {
                let _ = writeln!(out, "      {}", r.entity);
            }
        }
    }
}
