//! `TOOL CALL 1 Z S3000 DL+0.1 DR-0.05`: the tool's length and radius
//! from the tool table, with the call's oversizes added.
//!
//! The length offset becomes the table length plus DL (one
//! `USE_TOOL_LENGTH_OFFSET`, as LinuxCNC prints for G43 with a tool table
//! that holds that length), and the compensation radius the table radius
//! plus DR (what RL/RR offset by, as LinuxCNC does with that diameter).
//! A `TOOL CALL` without a tool number but with DL/DR changes the
//! oversizes of the tool in the spindle.

use super::super::{tools, Interp, Stop};
use crate::canon::Canon;
use crate::diag::Code;
use crate::interp::state::{State, MM_PER_INCH};
use crate::ir::{Arena, Block, CompSide, Decimal, Expr, LengthUnit, Stmt, StmtKind, Value};

/// The block's `DL`/`DR` in mm (0 when not given).
fn oversize_in(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<[f64; 2], Stop> {
    let mut out = [0.0; 2];
    for s in &block.stmts {
        if let StmtKind::ToolOversize { length, radius } = &s.kind {
            for (i, v) in [length, radius].into_iter().enumerate() {
                if let Some(v) = v {
                    let x = it.value(v, exprs)?;
                    out[i] = it.state.to_mm(x);
                }
            }
        }
    }
    Ok(out)
}

/// After the tool change of `TOOL CALL`: the new tool's length and radius
/// with the call's oversizes, and Q108.
pub fn tool_change(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.heidenhain.oversize = oversize_in(it, block, exprs)?;
    activate(it)?;
    super::tool_called(it);
    Ok(())
}

/// `DL`/`DR` in a `TOOL CALL` without a tool number (with one, the tool
/// change has already applied them).
pub fn oversize_alone(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if block
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::ToolChange))
    {
        return Ok(());
    }
    it.heidenhain.oversize = oversize_in(it, block, exprs)?;
    activate(it)?;
    super::tool_called(it);
    Ok(())
}

/// Makes the tool in the spindle active: length offset and radius from
/// the table plus the oversizes.
fn activate(it: &mut Interp<'_, '_>) -> Result<(), Stop> {
    let tool = it.state.tool_in_spindle;
    let [dl, dr] = it.heidenhain.oversize;
    let (mut offset, mut radius) = ([0.0; 9], 0.0);
    if tool != 0 {
        crate::interp::tools::known_tool(it, tool)?;
        let Some(t) = it.tool_table.get(tool) else {
            return Err(it.error_at(
                it.span,
                Code::ToolNotInTable,
                format!("Requested tool {tool} not found in the tool table"),
            ));
        };
        let k = match it.opts.machine_units {
            LengthUnit::Mm => 1.0,
            LengthUnit::Inch => MM_PER_INCH,
        };
        offset = t.offset;
        for (i, x) in offset.iter_mut().enumerate() {
            if State::is_linear(i) {
                *x *= k;
            }
        }
        radius = t.diameter * k / 2.0;
    }
    offset[2] += dl;
    it.state.tool_offset = offset;
    it.state.comp_radius = radius + dr;
    let printed = it.state.pose_to_prog(&offset);
    it.emit(Canon::UseToolLengthOffset(printed));
    Ok(())
}

/// `RL`/`RR`: compensation by the table radius plus the TOOL CALL's DR
/// (run as LinuxCNC's G41.1/G42.1 with that diameter, which offsets by
/// the same radius); without DR, as G41/G42.
pub fn radius_comp(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let dr = it.heidenhain.oversize[1];
    let tool = it.state.tool_in_spindle;
    match &s.kind {
        StmtKind::RadiusComp {
            side: side @ (CompSide::Left | CompSide::Right),
            register: None,
            diameter: false,
        } if dr != 0.0 && tool != 0 && it.tool_table.get(tool).is_some() => {
            let r = super::mapping::tool_radius(it) + it.state.to_prog(dr);
            let kind = StmtKind::RadiusComp {
                side: *side,
                register: Some(Value::Number(Decimal::from_f64(2.0 * r, 6))),
                diameter: true,
            };
            tools::exec(it, &Stmt::new(kind, s.span), block, exprs)
        }
        _ => tools::exec(it, s, block, exprs),
    }
}
