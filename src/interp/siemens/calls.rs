//! Named cycle calls: direct (`CYCLE81(...)`), modal (`MCALL CYCLE81(...)`,
//! run after each positioning block), hole patterns running the modal
//! cycle at each position, `CYCLE832`, the milling cycles expanded in
//! [`super::milling`], and known cycles that are not expanded (W0510).

use super::host::FramedHost;
use super::{milling, ModalCall};
use crate::canon::{Canon, MotionMode};
use crate::diag::{Code, Diagnostic};
use crate::interp::cycles::{pattern_positions, run_named_drill_cycle};
use crate::interp::host::{plane_axes, MotionHost};
use crate::interp::state::PathControl;
use crate::interp::{Interp, Stop};
use crate::ir::{Arena, CycleCall, Expr};
use crate::span::Span;

/// What the interpreter does with a cycle name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// CYCLE81..CYCLE89: expanded in `interp::cycles`.
    Drill,
    /// HOLES1, HOLES2, CYCLE801: run the modal cycle at each position.
    Pattern,
    /// CYCLE832: path control.
    Tolerance,
    /// Expanded in [`milling`].
    Milling,
    /// Known to the dialect spec but not expanded: W0510.
    Known,
    /// A call that describes the program rather than machining it (the
    /// blank for the simulation, the editor's program structure): the
    /// spec's kinds `blank` and `structure`. Nothing to run.
    Describes,
    Unknown,
}

fn kind(it: &Interp<'_, '_>, name: &str) -> Kind {
    match name {
        "CYCLE81" | "CYCLE82" | "CYCLE83" | "CYCLE84" | "CYCLE85" | "CYCLE86" | "CYCLE87"
        | "CYCLE88" | "CYCLE89" | "CYCLE840" => Kind::Drill,
        "HOLES1" | "HOLES2" | "CYCLE801" => Kind::Pattern,
        "CYCLE832" => Kind::Tolerance,
        _ if milling::expands(name) => Kind::Milling,
        _ => match it.spec.cycle(name).map(|c| c.kind.as_str()) {
            Some("blank" | "structure") => Kind::Describes,
            Some(_) => Kind::Known,
            None => Kind::Unknown,
        },
    }
}

fn eval_args(
    it: &mut Interp<'_, '_>,
    c: &CycleCall,
    exprs: &Arena<Expr>,
) -> Result<Vec<Option<f64>>, Stop> {
    let mut out = Vec::with_capacity(c.args.len());
    for a in &c.args {
        out.push(match a.value {
            Some(e) => it.eval(e, exprs)?,
            None => None,
        });
    }
    Ok(out)
}

fn at(d: Diagnostic, span: Span) -> Diagnostic {
    if d.span().is_some() {
        d
    } else {
        d.primary(span, "in this cycle call")
    }
}

fn not_expanded(it: &mut Interp<'_, '_>, name: &str, span: Span) {
    it.diags.push(not_expanded_diag(name, span));
}

fn not_expanded_diag(name: &str, span: Span) -> Diagnostic {
    Diagnostic::new(
        Code::CannotExpandCycle,
        format!("{name} is not expanded into moves: its calls are left out"),
    )
    .primary(span, "not expanded")
    .help("the run goes on after the call as if the cycle did nothing")
}

/// Runs a `CycleCall` statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    c: &CycleCall,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let name = c.name.to_ascii_uppercase();
    let k = kind(it, &name);
    if k == Kind::Unknown {
        return Err(it.error_at(
            span,
            Code::UnsupportedHere,
            format!("{name} is not a cycle this dialect knows"),
        ));
    }
    let runs = matches!(
        k,
        Kind::Drill | Kind::Milling | Kind::Pattern | Kind::Tolerance
    );
    let args = if runs {
        eval_args(it, c, exprs)?
    } else {
        Vec::new()
    };
    if c.modal {
        if matches!(k, Kind::Pattern | Kind::Tolerance) {
            return Err(it.error_at(
                span,
                Code::UnsupportedHere,
                format!("{name} cannot be called modally (MCALL)"),
            ));
        }
        it.siemens.modal = Some(ModalCall {
            name,
            args,
            warned: false,
        });
        return Ok(());
    }
    run(it, k, &name, &args, span)
}

fn run(
    it: &mut Interp<'_, '_>,
    k: Kind,
    name: &str,
    args: &[Option<f64>],
    span: Span,
) -> Result<(), Stop> {
    let frame = it.siemens.frame;
    let scale = it.state.scale();
    let result = match k {
        Kind::Drill => run_named_drill_cycle(&mut FramedHost::new(it, frame, scale), name, args),
        Kind::Milling => {
            let radius = it.state.to_prog(it.state.comp_radius);
            let host = &mut FramedHost::new(it, frame, scale);
            match milling::run(host, name, args, radius) {
                Ok(milling::Outcome::NotExpanded(why)) => {
                    it.diags.push(not_expanded_diag(name, span).note(why));
                    Ok(())
                }
                r => r.map(|_| ()),
            }
        }
        Kind::Pattern => return run_pattern(it, name, args, span),
        Kind::Tolerance => {
            tolerance(it, args);
            Ok(())
        }
        Kind::Describes => Ok(()),
        Kind::Known | Kind::Unknown => {
            not_expanded(it, name, span);
            Ok(())
        }
    };
    result.map_err(|d| Stop::Error(at(d, span)))
}

/// Runs the modal call in force (if any) at the current position.
pub fn run_modal(it: &mut Interp<'_, '_>, span: Span) -> Result<(), Stop> {
    let Some(m) = it.siemens.modal.clone() else {
        return Ok(());
    };
    let k = kind(it, &m.name);
    if matches!(k, Kind::Known | Kind::Unknown) {
        if !m.warned {
            not_expanded(it, &m.name, span);
            if let Some(mm) = it.siemens.modal.as_mut() {
                mm.warned = true;
            }
        }
        return Ok(());
    }
    run(it, k, &m.name, &m.args, span)
}

/// HOLES1 / HOLES2 / CYCLE801: rapid to each position in the plane (at the
/// current height along the tool axis) and run the modal cycle there [?:
/// without MCALL the tool only visits the positions].
fn run_pattern(
    it: &mut Interp<'_, '_>,
    name: &str,
    args: &[Option<f64>],
    span: Span,
) -> Result<(), Stop> {
    let holes = pattern_positions(name, args).map_err(|m| {
        Stop::Error(
            Diagnostic::new(Code::CycleBadArgument, format!("{name}: {m}")).primary(span, "here"),
        )
    })?;
    let (a, b, _) = plane_axes(it.state.plane);
    for (pa, pb) in holes {
        let frame = it.siemens.frame;
        let scale = it.state.scale();
        {
            let mut h = FramedHost::new(it, frame, scale);
            let mut p = h.position();
            p[a] = pa;
            p[b] = pb;
            h.rapid(p);
        }
        run_modal(it, span)?;
    }
    Ok(())
}

/// CYCLE832(_TOL, _TOLM, ...): only the units digit of _TOLM is decoded
/// (0 deselect; 1..4 finishing .. roughing). Mapped to LinuxCNC's
/// `G64 P<_TOL>`, which rs274 prints as `SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS,
/// tol)` then `SET_NAIVECAM_TOLERANCE(tol)` (probed: Q defaults to P).
/// Deselection (or no tolerance: `CYCLE832()`) gives plain `G64` [?: the
/// 840D returns to its configured path mode, usually G64].
fn tolerance(it: &mut Interp<'_, '_>, args: &[Option<f64>]) {
    let tol = args.first().copied().flatten().unwrap_or(0.0).abs();
    // [?] A tolerance without a mode word selects finishing.
    let default_mode = if tol > 0.0 { 1.0 } else { 0.0 };
    let mode = args.get(1).copied().flatten().unwrap_or(default_mode).abs() as i64 % 10;
    let tol = if mode == 0 { 0.0 } else { tol };
    it.emit(Canon::SetMotionControlMode(MotionMode::Continuous(tol)));
    it.emit(Canon::SetNaivecamTolerance(tol));
    let mm = it.state.to_mm(tol);
    it.state.path = PathControl::Continuous {
        tolerance: mm,
        naive: mm,
    };
}
