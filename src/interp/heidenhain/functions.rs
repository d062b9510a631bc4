//! Running the Heidenhain function blocks ([`TncFunction`]): FN 14 stops
//! the run with the program's own error (E0519); FN 15/16 print a
//! `MESSAGE`; FN 18 reads the system data the run knows (the others are
//! unknown at check time: a note, W0517, and the parameter is NaN, which
//! formulas carry and no check reports); FN 17/19/20 are reported (W0513)
//! and skipped; `PLANE` runs when it tilts nothing, a tilt and `FUNCTION
//! TCPM` are kept and not made (W0518, once per run); `M140 MB` retracts
//! in the tool axis; FK blocks stop the run (not interpreted).
//!
//! FN 18 data numbers are those of the TNC system data table (technical
//! manuals TNC 426/430, iTNC 530); the values are metric as the TNC 7
//! manual says SYSREAD always gives them [?: older controls may give
//! program units].

use super::super::{siemens, Interp, Stop};
use crate::canon::Canon;
use crate::canon::CanonPlane;
use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, Expr, PrintItem, TiltPlane, TncFunction, TncFunctionKind, Var};
use crate::span::Span;

/// Runs one function block.
pub fn exec(
    it: &mut Interp<'_, '_>,
    f: &TncFunction,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    match &f.kind {
        TncFunctionKind::Error(v) => {
            let n = it.value(v, exprs)?;
            let mut d = Diagnostic::new(
                Code::KlartextProgramError,
                format!("the program stopped with its error {}", number(n)),
            )
            .primary(span, "FN 14 raises the program's own error here")
            .help("the program's own check failed; see the comments near this block for what the number means");
            if let Some(jump) = it.last_jump {
                d = d.secondary(jump, "the last test that jumped before it");
            }
            Err(Stop::Error(d))
        }
        TncFunctionKind::Print(items) => {
            let mut text = String::new();
            for i in items {
                match i {
                    PrintItem::Text(t) => text.push_str(t),
                    PrintItem::Value(v) => text.push_str(&number(it.value(v, exprs)?)),
                }
            }
            it.out(Canon::Message(text));
            Ok(())
        }
        TncFunctionKind::FormattedPrint { spec } => {
            it.diags.push(
                Diagnostic::new(
                    Code::FormattedPrintNotRead,
                    "FN 16: F-PRINT: the mask file is not read",
                )
                .primary(span, "shown as a MESSAGE naming the mask and the output")
                .help("the values the mask would format are not printed"),
            );
            it.out(Canon::Message(format!("F-PRINT {spec}")));
            Ok(())
        }
        TncFunctionKind::SysRead { var, id, nr, idx } => {
            let i = match idx {
                Some(v) => Some(it.value(v, exprs)?.round() as i64),
                None => None,
            };
            let value = match system_datum(it, *id, *nr, i) {
                Some(v) => v,
                None => {
                    unknown_datum(it, *id, *nr, i, span);
                    f64::NAN
                }
            };
            if let Var::Q(bank, n) = var {
                it.params.set_q(*bank, *n, value);
            }
            Ok(())
        }
        TncFunctionKind::MachineOnly(n) => {
            let what = match n {
                17 => "FN 17: SYSWRITE writes machine data",
                19 => "FN 19: PLC sends values to the PLC",
                _ => "FN 20: WAIT FOR waits for the PLC or a synchronisation",
            };
            it.diags.push(
                Diagnostic::new(Code::MachineFunctionNotRun, format!("{what}: not run"))
                    .primary(span, "skipped")
                    .help("the run has no machine data or PLC; check what the program expects of this block"),
            );
            Ok(())
        }
        TncFunctionKind::Plane(p) => plane(it, p, span, exprs),
        // Applied to the block's move (see `paraxial`).
        TncFunctionKind::Paraxial(_) => Ok(()),
        TncFunctionKind::Function(what) => {
            function(it, what, span);
            Ok(())
        }
        TncFunctionKind::Retract(d) => retract(it, d.as_ref(), span, exprs),
        TncFunctionKind::TouchProbe(n) => {
            it.diags.push(
                Diagnostic::new(
                    Code::MachineFunctionNotRun,
                    format!("TCH PROBE {n} measures with the touch probe: not run"),
                )
                .primary(span, "a probing cycle")
                .help("what it measures (Q150 and up) and the datum or tool data it may set are known only on the machine: a later block that reads them stops the run (W0590); the tool is taken to end where it started"),
            );
            Ok(())
        }
        TncFunctionKind::FreeContour(k) => Err(Stop::Error(
            Diagnostic::new(
                Code::UnsupportedHere,
                format!("FK free contour programming (`{k}`) is not interpreted"),
            )
            .primary(span, "an FK block")
            .help("the block is kept and written back to Heidenhain; to run or port the program, program the contour with L, C, CR and CT blocks"),
        )),
    }
}

/// A value as the TNC shows it: up to four decimals.
fn number(v: f64) -> String {
    crate::ir::num::short_text(v, 4)
}

/// The system data the run knows (mm, as FN 18 gives them).
fn system_datum(it: &Interp<'_, '_>, id: u32, nr: u32, idx: Option<i64>) -> Option<f64> {
    let tool = it.state.tool_in_spindle;
    let tool_axis = match it.state.plane {
        CanonPlane::YZ => 0.0,
        CanonPlane::XZ => 1.0,
        _ => 2.0,
    };
    let table = |t: i64| it.tool_table.get(t);
    let inch = matches!(it.opts.machine_units, crate::ir::LengthUnit::Inch);
    let machine_mm = |v: f64| if inch { v * 25.4 } else { v };
    Some(match (id, nr) {
        (10, 1) => match it.state.units {
            crate::ir::LengthUnit::Mm => 0.0,
            crate::ir::LengthUnit::Inch => 1.0,
        },
        (10, 3) => it
            .heidenhain
            .cycle
            .as_ref()
            .map_or(0.0, |c| c.number as f64),
        (20, 1) => tool as f64,
        (20, 3) => tool_axis,
        (20, 4) => it.state.speed,
        (20, 9) => it.state.to_mm(it.state.feed),
        (50, 1) => machine_mm(table(idx.unwrap_or(tool))?.offset[2]),
        (50, 2) => machine_mm(table(idx.unwrap_or(tool))?.diameter / 2.0),
        (60, 1) => tool as f64,
        (60, 4) => it.heidenhain.oversize[0],
        (60, 5) => it.heidenhain.oversize[1],
        (200, 1) => it.state.comp_radius,
        (200, 2) => it.state.tool_offset[tool_axis as usize],
        // Where the operator left the axes: known only on the machine.
        (270, 1) if it.sink.axes_left_by_operator => return None,
        (270, 1) => {
            let i = usize::try_from(idx?).ok().filter(|i| (1..=9).contains(i))?;
            let p = it.state.pos;
            if i <= 3 {
                siemens::from_base(it, [p[0], p[1], p[2]])[i - 1]
            } else {
                p[i - 1]
            }
        }
        _ => return None,
    })
}

/// An FN 18 datum the run cannot know: a note (once per datum), and the
/// parameter is unknown from here on.
fn unknown_datum(it: &mut Interp<'_, '_>, id: u32, nr: u32, idx: Option<i64>, span: Span) {
    let at = match idx {
        Some(i) => format!("ID{id} NR{nr} IDX{i}"),
        None => format!("ID{id} NR{nr}"),
    };
    let what = match id {
        240 => " (the nominal position in the machine's REF system: it depends on the preset)",
        270 => " (the position the axes stand at before any move, or after a program stop where the operator may have jogged them)",
        _ => "",
    };
    if !it.once(format!("sysread {at}")) {
        return;
    }
    it.diags.push(
        Diagnostic::new(
            Code::UnknownAtCheckTime,
            format!("FN 18: the system datum {at}{what} is unknown at check time"),
        )
        .primary(span, "read here; the parameter stays unknown")
        .help("cncc knows ID10 NR1/3, ID20 NR1/3/4/9, ID50 NR1/2, ID60 NR1/4/5, ID200 NR1/2 and ID270 NR1 IDX1..9 (once the program has moved since its start or last stop); the others belong to the machine (see `cncc explain W0517`)"),
    );
}

/// A 5-axis function the run does not make: one warning per run.
pub fn kinematics_not_run(it: &mut Interp<'_, '_>, what: &str, span: Span) {
    if !it.once("kinematics") {
        return;
    }
    it.diags.push(
        Diagnostic::new(
            Code::KinematicsNotRun,
            format!("{what}: the 3-axis run does not make it"),
        )
        .primary(span, "kept, not run")
        .help("the run goes on in the untilted plane with the coordinates as programmed (reported once; see `cncc explain W0518`)"),
    );
}

/// `FUNCTION ...`: `RESET TCPM` runs (nothing is on); `TCPM` is a 5-axis
/// function (W0518); the others are reported and skipped (W0513).
fn function(it: &mut Interp<'_, '_>, what: &str, span: Span) {
    if what.starts_with("RESET") {
        return;
    }
    if what.starts_with("TCPM") {
        kinematics_not_run(it, "FUNCTION TCPM keeps the tool tip on the path", span);
        return;
    }
    it.diags.push(
        Diagnostic::new(
            Code::MachineFunctionNotRun,
            format!("FUNCTION {what}: not run"),
        )
        .primary(span, "skipped")
        .help(
            "the run has no model of this machine function; check what the program expects of it",
        ),
    );
}

/// `M140 MB n`: a rapid by n along the tool axis; `MB MAX` goes to the end
/// of travel, which the run does not know (W0517): the tool stays.
fn retract(
    it: &mut Interp<'_, '_>,
    d: Option<&crate::ir::Value>,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let Some(d) = d else {
        if it.once("retract max") {
            it.diags.push(
                Diagnostic::new(
                    Code::UnknownAtCheckTime,
                    "M140 MB MAX retracts to the end of travel, which is unknown at check time",
                )
                .primary(span, "the run leaves the tool where it is")
                .help("the next moves are checked from the position before the retract (see `cncc explain W0517`)"),
            );
        }
        return Ok(());
    };
    let dist = it.value(d, exprs)?;
    let axis = match it.state.plane {
        CanonPlane::YZ => 0,
        CanonPlane::XZ => 1,
        _ => 2,
    };
    let mut to = crate::interp::host::MotionHost::position(it);
    to[axis] += dist;
    it.straight_move(crate::interp::comp::MoveKind::Rapid, to)
}

/// `PLANE`: RESET and a plane that tilts nothing run; a tilt is kept and
/// not made (W0518, once).
fn plane(
    it: &mut Interp<'_, '_>,
    p: &TiltPlane,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let mut vals = Vec::with_capacity(p.values.len());
    for (name, v) in &p.values {
        vals.push((name.as_str(), it.value(v, exprs)?));
    }
    let get = |n: &str| vals.iter().find(|(k, _)| *k == n).map_or(0.0, |(_, v)| *v);
    let flat = match p.how.as_str() {
        "RESET" => true,
        // The base vector along +X and the normal along +Z: no tilt.
        "VECTOR" => {
            get("NX").abs() < 1e-9
                && get("NY").abs() < 1e-9
                && get("NZ") > 0.0
                && get("BY").abs() < 1e-9
                && get("BX") > 0.0
        }
        // [?] the three points are not kept: any POINTS plane is a tilt.
        "POINTS" => false,
        _ => vals.iter().all(|(_, v)| v.abs() < 1e-9),
    };
    if !flat {
        let what = format!("PLANE {} tilts the working plane", p.how);
        kinematics_not_run(it, &what, span);
    }
    axis_angles(it, flat);
    Ok(())
}

/// The TNC leaves the rotary axis angles it computed for a `PLANE` in
/// Q120 (A), Q121 (B), Q122 (C), which programs with `STAY` then move to
/// (`L B+Q121 C+Q122`) [K: TNC 640 user's manual, "PLANE function:
/// positioning"]. Untilted, every rotary axis is at 0 [?: a kinematics
/// with a free axis may keep another C]; tilted, the angles depend on
/// the machine's kinematics and are unknown here.
fn axis_angles(it: &mut Interp<'_, '_>, flat: bool) {
    let v = if flat { 0.0 } else { f64::NAN };
    for n in 120..=122 {
        it.params.set_q(crate::ir::QBank::Q, n, v);
    }
}
