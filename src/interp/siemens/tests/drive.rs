//! Runs a small Siemens program through [`Interp`] with a stand-in for the
//! core's block statements (the core is written elsewhere): G0/G1 with
//! absolute X Y Z through [`super::super::to_base`], F, planes, T/M6.
//! Everything Siemens-specific goes through the real `siemens::exec` and
//! `siemens::after_motion`.

use crate::canon::{format_call, Canon, CanonPlane};
use crate::dialect::builtin::builtin;
use crate::driver::read_program;
use crate::interp::exec::phase;
use crate::interp::host::MotionHost;
use crate::interp::siemens::{after_motion, exec, from_base, to_base};
use crate::interp::{Interp, Options, Stop};
use crate::ir::{Arena, Expr, MotionKind, Plane, Stmt, StmtKind, ToolRef};
use crate::span::{FileId, Span};

/// The calls (rs274 text) and diagnostics of running `src`.
pub fn run(src: &str) -> String {
    run_checked(src, true)
}

/// As [`run`], also for programs the reader reports errors in.
pub fn run_lenient(src: &str) -> String {
    run_checked(src, false)
}

fn run_checked(src: &str, strict: bool) -> String {
    let spec = builtin("siemens840d").expect("siemens spec");
    let (program, diags) = read_program(src, FileId(0), &spec);
    assert!(
        !strict || diags.iter().all(|d| !d.is_error()),
        "{src}: {diags:?}"
    );
    let opts = Options::default();
    let mut out: Vec<String> = Vec::new();
    let mut sink = |c: Canon, _s: Span| out.push(format_call(&c));
    let mut it = Interp::new(&spec, &opts, &mut sink);
    let mut motion = MotionKind::Rapid;
    let mut end = String::new();
    'blocks: for b in &program.blocks {
        let mut order: Vec<&Stmt> = b.stmts.iter().filter(|s| phase(&s.kind) > 0).collect();
        order.sort_by_key(|s| phase(&s.kind));
        for s in order {
            it.span = s.span;
            if let Err(e) = stmt(&mut it, s, b, &program.exprs, &mut motion) {
                if let Stop::Error(d) = e {
                    end = format!("\nerror {}: {}", d.code.code(), d.message);
                }
                break 'blocks;
            }
        }
    }
    let diags: Vec<String> = it
        .diags
        .iter()
        .map(|d| format!("{} {}", d.code.code(), d.message))
        .collect();
    drop(it);
    let mut text = out.join("\n");
    text.push_str(&end);
    for d in diags {
        text.push_str(&format!("\n{d}"));
    }
    text
}

fn stmt(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    b: &crate::ir::Block,
    ex: &Arena<Expr>,
    mk: &mut MotionKind,
) -> Result<(), Stop> {
    match &s.kind {
        StmtKind::Transform(_)
        | StmtKind::CuttingEdge(_)
        | StmtKind::CycleCall(_)
        | StmtKind::ModalCallCancel => exec(it, s, b, ex),
        StmtKind::Feed(v) => {
            it.state.feed = it.value(v, ex)?;
            it.emit(Canon::SetFeedRate(it.state.feed));
            Ok(())
        }
        StmtKind::Plane(p) => {
            it.state.plane = match p {
                Plane::XY => CanonPlane::XY,
                Plane::ZX => CanonPlane::XZ,
                Plane::YZ => CanonPlane::YZ,
            };
            it.emit(Canon::SelectPlane(it.state.plane));
            Ok(())
        }
        StmtKind::Units { unit, .. } => {
            it.state.units = *unit;
            Ok(())
        }
        StmtKind::ToolSelect(ToolRef::Number(v)) => {
            it.state.tool_selected = Some(it.value(v, ex)? as i64);
            Ok(())
        }
        StmtKind::ToolChange => {
            it.state.tool_in_spindle = it.state.tool_selected.unwrap_or(0);
            Ok(())
        }
        StmtKind::Motion(m) => {
            if m.kind != MotionKind::Implicit {
                *mk = m.kind;
            }
            let cur = [it.state.pos[0], it.state.pos[1], it.state.pos[2]];
            let mut p = from_base(it, cur);
            for (i, l) in ['X', 'Y', 'Z'].into_iter().enumerate() {
                if let Some(c) = m.target.get(l) {
                    let v = it.value(&c.value, ex)?;
                    p[i] = it.state.to_mm(v);
                }
            }
            let q = to_base(it, p);
            let pose = [
                it.state.to_prog(q[0]),
                it.state.to_prog(q[1]),
                it.state.to_prog(q[2]),
                0.0,
                0.0,
                0.0,
            ];
            if *mk == MotionKind::Rapid {
                MotionHost::rapid(it, pose);
            } else {
                MotionHost::feed(it, pose);
            }
            after_motion(it, s, b, ex)
        }
        _ => Ok(()),
    }
}
