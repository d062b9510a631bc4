//! AP238 ed.1 AIM files (INTEGRATED_CNC_SCHEMA): their workplan, tools,
//! technology, machine functions and cutter-location toolpaths read into
//! the STEP-NC model (with the file's units), what is not read named in
//! W0807, and the plan listed, posted and run.

mod common;

use cncc::diag::Code;
use cncc::source::SourceMap;
use cncc::stepnc::{self, model::*};

fn slot() -> std::path::PathBuf {
    common::root().join("tests/programs/stepnc/ap238_slot.stpnc")
}

#[test]
fn a_composite_toolpath_its_security_plane_and_technology_read() {
    let mut files = SourceMap::new();
    let r = stepnc::read_file(&slot(), &mut files).unwrap();
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    let p = r.project.unwrap();
    let Executable::Workingstep(ws) = &p.main_workplan.elements[0] else {
        panic!("a workingstep");
    };
    assert_eq!(ws.secplane.position.location.xyz[2], 10.0);
    let op = p.operation(ws.operation);
    // -2000 rev/min in the file is clockwise: M3, +2000 in cncc's model.
    assert_eq!(op.technology.spindle, Some(2000.0));
    assert_eq!(op.technology.feed, Some(600.0));
    assert!(op.machine_functions.coolant);
    assert_eq!(p.tool(op.tool).body.dimension.diameter, 6.0);
    assert_eq!(p.tool(op.tool).body.kind, ToolBodyKind::Endmill);
    let Some(Toolpath::CutterLocation { basic_curve, .. }) =
        op.toolpath.as_ref().and_then(|t| t.first())
    else {
        panic!("a cutter location toolpath");
    };
    let Curve::Composite { segments, .. } = basic_curve else {
        panic!("{basic_curve:?}");
    };
    assert!(matches!(segments[0].curve, Curve::Line { .. }));
    let Curve::Arc {
        radius, sense, end, ..
    } = &segments[1].curve
    else {
        panic!("{:?}", segments[1].curve);
    };
    assert_eq!((*radius, *sense, end.xyz), (10.0, true, [40.0, 30.0, -2.0]));
}

#[test]
fn the_plan_is_listed_posted_and_run() {
    let s = common::cncc(&["stepnc", slot().to_str().unwrap(), "--summary"]);
    assert_eq!(s.status.code(), Some(0), "{}", common::stderr(&s));
    assert!(common::stdout(&s).contains("workingstep \"WS slot\""));
    let c = common::cncc(&["canon", slot().to_str().unwrap()]);
    assert_eq!(c.status.code(), Some(0), "{}", common::stderr(&c));
    let canon = common::stdout(&c);
    assert!(canon.contains("START_SPINDLE_CLOCKWISE"), "{canon}");
    assert!(canon.contains("FLOOD_ON()"));
    assert!(canon.contains("STRAIGHT_FEED(40.0000, 10.0000, -2.0000"));
    assert!(canon.contains("ARC_FEED(40.0000, 30.0000, 40.0000, 20.0000, 1, -2.0000"));
}

#[test]
fn what_is_not_read_is_named() {
    let Some(shared) = common::shared() else {
        return;
    };
    let mut files = SourceMap::new();
    let r = stepnc::read_file(
        &shared.join("stepnc-samples/test_program.stpnc"),
        &mut files,
    )
    .unwrap();
    let named: Vec<&str> = r
        .diagnostics
        .iter()
        .filter(|d| d.code == Code::Ap238NotRead)
        .map(|d| d.message.as_str())
        .collect();
    assert!(named.iter().any(|m| m.contains("taper angle")), "{named:?}");
    assert!(
        named.iter().any(|m| m.contains("security plane")),
        "{named:?}"
    );
    assert!(
        named.iter().any(|m| m.contains("MACHINING_FUNCTIONS ×1")),
        "{named:?}"
    );
    assert!(r.project.is_some());
}

#[test]
fn an_aim_file_without_a_project_is_a_model_error() {
    let mut files = SourceMap::new();
    let text = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\nFILE_SCHEMA(('INTEGRATED_CNC_SCHEMA'));\nENDSEC;\nDATA;\n#1=CARTESIAN_POINT('',(0.,0.,0.));\nENDSEC;\nEND-ISO-10303-21;\n";
    let id = files.add("mem.stpnc", text.to_string());
    let r = stepnc::read_text(files.text(id), id);
    assert!(r.project.is_none());
    assert_eq!(r.diagnostics[0].code, Code::StepncModel);
}

/// The workingstep's operation of an AP238 text.
fn first_operation(text: &str) -> (Operation, Tool, Vec<cncc::diag::Diagnostic>) {
    let mut files = SourceMap::new();
    let id = files.add("mem.stpnc", text.to_string());
    let r = stepnc::read_text(files.text(id), id);
    let p = r.project.expect("the plan reads");
    let ws = p
        .main_workplan
        .elements
        .iter()
        .find_map(|e| match e {
            Executable::Workingstep(w) => Some(w.operation),
            _ => None,
        })
        .unwrap();
    let op = p.operation(ws).clone();
    let tool = p.tool(op.tool).clone();
    (op, tool, r.diagnostics)
}

#[test]
fn each_value_is_read_in_its_own_declared_unit() {
    let Some(shared) = common::shared() else {
        return;
    };
    let text = std::fs::read_to_string(shared.join("stepnc-samples/test_program.stpnc")).unwrap();
    // As written: everything in inches (#58), the feed in inch/minute
    // (#104 = #58 over minutes): 2000 in/min, a 10 in tool, 3000 rpm.
    // Converted faithfully, the numbers are implausible for milling (a
    // 254 mm end mill at 2394 m/min, 50.8 m/min feed): W0808 says so
    // and names the millimetre reading, and the declared units are kept.
    let (op, tool, diags) = first_operation(&text);
    assert_eq!(op.technology.feed, Some(50_800.0));
    assert_eq!(tool.body.dimension.diameter, 254.0);
    let doubt: Vec<&cncc::diag::Diagnostic> = diags
        .iter()
        .filter(|d| d.code == Code::Ap238UnitsDoubtful)
        .collect();
    assert_eq!(doubt.len(), 1, "{diags:?}");
    assert!(
        doubt[0].message.contains("50800 mm/min"),
        "{}",
        doubt[0].message
    );
    let help = doubt[0].help.as_deref().unwrap_or_default();
    assert!(help.contains("2000 mm/min with a 10.00 mm tool"), "{help}");
    // The feed's unit made mm/minute (#105 -> #61, millimetre): the feed
    // is 2000 mm/min while the points and the tool stay in inches.
    let mm_feed = text.replace(
        "#105=DERIVED_UNIT_ELEMENT(#58,1.);",
        "#105=DERIVED_UNIT_ELEMENT(#61,1.);",
    );
    assert_ne!(mm_feed, text);
    let (op, tool, diags) = first_operation(&mm_feed);
    assert_eq!(op.technology.feed, Some(2000.0));
    assert_eq!(tool.body.dimension.diameter, 254.0);
    assert!(!diags.iter().any(|d| d.code == Code::Ap238UnitsDoubtful));
    // The diameter given in millimetres (#61) in the inch context: 10 mm.
    let mm_tool = text.replacen(
        "MEASURE_WITH_UNIT(LENGTH_MEASURE(10.),#58)",
        "MEASURE_WITH_UNIT(LENGTH_MEASURE(10.),#61)",
        1,
    );
    assert_ne!(mm_tool, text);
    let (_, tool, _) = first_operation(&mm_tool);
    assert_eq!(tool.body.dimension.diameter, 10.0);
}

#[test]
fn a_length_in_a_unit_not_resolved_is_named_not_taken_as_mm() {
    let Some(shared) = common::shared() else {
        return;
    };
    let text = std::fs::read_to_string(shared.join("stepnc-samples/test_program.stpnc")).unwrap();
    // The diameter in nanometres, a prefix cncc does not resolve: not
    // read as 10 mm, and named.
    let nano = text
        .replacen(
            "MEASURE_WITH_UNIT(LENGTH_MEASURE(10.),#58)",
            "MEASURE_WITH_UNIT(LENGTH_MEASURE(10.),#900)",
            1,
        )
        .replace(
            "ENDSEC;\nEND-ISO-10303-21;",
            "#900=(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.NANO.,.METRE.));\nENDSEC;\nEND-ISO-10303-21;",
        );
    assert!(nano.contains("#900=("));
    let (_, tool, diags) = first_operation(&nano);
    assert_eq!(tool.body.dimension.diameter, 0.0);
    assert!(
        diags
            .iter()
            .any(|d| d.code == Code::Ap238NotRead
                && d.message.contains("effective cutting diameter")),
        "{diags:?}"
    );
}
