//! Moves the recognisers do not explain: kept as a TOOLPATH_FEATURE with
//! a FREEFORM_OPERATION carrying them as explicit toolpaths (feed lines
//! as polylines, XY arcs as trimmed circles, helices and arcs in other
//! planes as polylines within 1 µm, rapids as polylines at rapid speed),
//! in workpiece coordinates. Reported with W0870.

use super::build::{machine_functions, placement, plane, point, r6, technology};
use super::Raiser;
use crate::diag::{Code, Diagnostic};
use crate::stepnc::model::*;
use crate::toolpath::{Move, MoveKind};

pub fn raise(r: &mut Raiser, t: i64, moves: &[Move], what: &str) {
    let name = r.name("TOOLPATH");
    let low = moves
        .iter()
        .map(|m| m.to[2].min(m.from[2]))
        .fold(f64::INFINITY, f64::min);
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [0.0, 0.0, 0.0], [1.0, 0.0]),
        depth: Some(plane(
            &format!("{name} DEPTH"),
            [0.0, 0.0, r6(low.min(0.0))],
        )),
        kind: FeatureKind::ToolpathFeature,
    };
    let feature = r.add_feature(f);
    let cuts: Vec<&Move> = moves.iter().filter(|m| m.is_feed()).collect();
    let op = Operation {
        id: format!("FREEFORM {name}"),
        toolpath: Some(toolpaths(moves)),
        tool_direction: None,
        retract_plane: None,
        start_point: None,
        tool: (r.tool)(t),
        technology: technology(&cuts),
        machine_functions: machine_functions(&cuts),
        overcut_length: None,
        kind: OperationKind::Freeform {
            approach: None,
            retract: None,
            strategy: None,
        },
    };
    r.add_operation(feature, op);
    if let Some(first) = moves.first() {
        r.diags.push(
            Diagnostic::new(
                Code::KeptAsToolpathFeature,
                format!("{what} kept as toolpath feature {name}"),
            )
            .primary(first.span, "these moves form no recognised feature")
            .help("the moves are carried as an explicit toolpath (FREEFORM_OPERATION); give the stock or the tool diameters, or program the feature as a drilling cycle, face, pocket, slot or profile to get a machining feature"),
        );
    }
}

/// The moves as toolpaths: runs of straight moves of one kind become one
/// polyline; each XY arc its own trimmed circle.
pub fn toolpaths(moves: &[Move]) -> Vec<Toolpath> {
    let mut out = Vec::new();
    let mut run: Vec<Point> = Vec::new();
    let mut rapid = false;
    for m in moves {
        let is_rapid = matches!(m.kind, MoveKind::Rapid);
        let plane_arc = match &m.kind {
            MoveKind::Arc(a) if a.axes == [0, 1, 2] && (m.to[2] - m.from[2]).abs() < 1e-9 => {
                Some(a)
            }
            _ => None,
        };
        if !run.is_empty() && (is_rapid != rapid || plane_arc.is_some()) {
            out.push(polyline(std::mem::take(&mut run), rapid));
        }
        if let Some(a) = plane_arc {
            out.push(arc(m, a));
            continue;
        }
        rapid = is_rapid;
        if run.is_empty() {
            run.push(point("", m.from));
        }
        match &m.kind {
            MoveKind::Arc(a) => run.extend(
                a.points(m.from, m.to, 1e-3)
                    .into_iter()
                    .map(|p| point("", p)),
            ),
            MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => run.push(point("", m.to)),
        }
    }
    if !run.is_empty() {
        out.push(polyline(run, rapid));
    }
    out
}

fn base(rapid: bool) -> ToolpathBase {
    ToolpathBase {
        priority: true,
        kind: if rapid {
            ToolpathType::Connect
        } else {
            ToolpathType::TrajectoryPath
        },
        speed: rapid.then(|| ToolpathSpeed::Named("RAPID".into())),
        technology: None,
        machine_functions: None,
    }
}

fn polyline(points: Vec<Point>, rapid: bool) -> Toolpath {
    Toolpath::CutterLocation {
        base: base(rapid),
        direction: None,
        basic_curve: Curve::Polyline {
            name: String::new(),
            points,
        },
        tool_axis: None,
        surface_normal: None,
    }
}

fn arc(m: &Move, a: &crate::toolpath::ArcGeom) -> Toolpath {
    let circle = placement("", a.centre, [1.0, 0.0]);
    Toolpath::CutterLocation {
        base: base(false),
        direction: None,
        basic_curve: Curve::Arc {
            name: String::new(),
            circle,
            circle_name: String::new(),
            radius: r6(a.radius(m.from)),
            start: point("", m.from),
            end: point("", m.to),
            sense: a.ccw(),
        },
        tool_axis: None,
        surface_normal: None,
    }
}
