//! Siemens tool data written by the program: `$TC_DPn[t,d]=value`
//! (`reference/dialects.md` §1.6) sets the data of edge `d` of tool `t`
//! in the run's tool table, so that a later `T.. D..` uses it.
//!
//! Carried: `$TC_DP1` (tool type: accepted, the table has no field for it),
//! `$TC_DP3` (length 1: the Z offset), `$TC_DP6` (radius: half the table
//! diameter). Other `$TC_DPn` stay unsimulated (W0511), as do edges other
//! than D1 (the LinuxCNC table holds one edge per tool).
//!
//! Units [?]: the 840D keeps tool data in its basic system (MD 10240);
//! here they are taken in the program's length unit at the time of the
//! assignment (what G710/G700 would give) and stored in machine units.

use crate::diag::Code;
use crate::interp::state::MM_PER_INCH;
use crate::interp::tooltable::Tool;
use crate::interp::{Interp, Stop};
use crate::ir::{Arena, Expr, ExprId, LengthUnit};

/// Which tool datum a `$TC_DPn` writes.
enum Datum {
    Kind,
    Length,
    Radius,
}

fn datum(name: &str) -> Option<Datum> {
    match name.to_ascii_uppercase().as_str() {
        "$TC_DP1" => Some(Datum::Kind),
        "$TC_DP3" => Some(Datum::Length),
        "$TC_DP6" => Some(Datum::Radius),
        _ => None,
    }
}

/// Writes `$TC_DPn[t,d]`: `None` when `name` is not a datum carried here
/// (the caller reports it as not simulated).
pub fn assign(
    it: &mut Interp<'_, '_>,
    name: &str,
    index: &[ExprId],
    v: Option<f64>,
    exprs: &Arena<Expr>,
) -> Option<Result<(), Stop>> {
    let datum = datum(name)?;
    Some(write(it, name, datum, index, v.unwrap_or(0.0), exprs))
}

fn write(
    it: &mut Interp<'_, '_>,
    name: &str,
    datum: Datum,
    index: &[ExprId],
    v: f64,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let [t, d] = index else {
        return Err(it.error_at(
            it.span,
            Code::DomainError,
            format!("{name} takes two indices: [tool, edge]"),
        ));
    };
    let t = it.eval(*t, exprs)?.unwrap_or(0.0);
    let d = it.eval(*d, exprs)?.unwrap_or(0.0);
    if t < 1.0 || t.fract() != 0.0 || t > 32000.0 || d < 1.0 || d.fract() != 0.0 {
        return Err(it.error_at(
            it.span,
            Code::DomainError,
            format!(
                "{name}[{t},{d}]: a tool is a whole number 1..32000, an edge a whole number from 1"
            ),
        ));
    }
    if d != 1.0 {
        return Err(it.error_at(
            it.span,
            Code::UnsupportedHere,
            format!("writing {name} of edge D{d} is not simulated: the tool table holds one edge (D1) per tool"),
        ));
    }
    let to_machine = match (it.state.units, it.opts.machine_units) {
        (LengthUnit::Mm, LengthUnit::Inch) => 1.0 / MM_PER_INCH,
        (LengthUnit::Inch, LengthUnit::Mm) => MM_PER_INCH,
        _ => 1.0,
    };
    it.tool_table.from_program.insert(t as i64);
    let tool = tool_mut(&mut it.tool_table.tools, t as i64);
    match datum {
        Datum::Kind => {}
        Datum::Length => tool.offset[2] = v * to_machine,
        Datum::Radius => tool.diameter = 2.0 * v * to_machine,
    }
    Ok(())
}

/// The table row of tool `number`, added (pocket = number) when new.
fn tool_mut(tools: &mut Vec<Tool>, number: i64) -> &mut Tool {
    let at = match tools.iter().position(|t| t.number == number) {
        Some(i) => i,
        None => {
            tools.push(Tool::blank(number, String::new()));
            tools.len() - 1
        }
    };
    &mut tools[at]
}
