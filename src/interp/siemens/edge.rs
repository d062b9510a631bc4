//! Siemens cutting edges: `D1` activates the length and radius of the
//! tool in the spindle, `D0` cancels both.
//!
//! Sources: `reference/dialects.md` §0.4 and §1.6 [K]: on the 840D `T.. M6`
//! loads the tool and `D..` selects the cutting edge whose data (length,
//! radius) become active; no G43 is written. The LinuxCNC tool table holds
//! one edge per tool, so `D1` is that edge, printed as rs274 prints `G43`
//! for the tool in the spindle (`USE_TOOL_LENGTH_OFFSET`, program units);
//! the radius (half the table diameter) is kept for G41/G42.
//! `D2`.. (and, with flat D numbering, MD 18102, any D number such as
//! `D08`) have no data in such a table. The control takes them from its own
//! tool memory, which cncc cannot see: the run goes on with the tool's row
//! as that edge, with a W0530 note, rather than a false error.

use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::state::MM_PER_INCH;
use crate::interp::{Interp, Stop};
use crate::ir::{Arena, Expr, LengthUnit, Value};

pub fn exec(it: &mut Interp<'_, '_>, v: &Value, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let d = it.value(v, exprs)?;
    if d < 0.0 || d.fract() != 0.0 || d > 32000.0 {
        return Err(it.error_at(
            it.span,
            Code::DomainError,
            format!("D{d}: a cutting edge is a whole number 0..32000"),
        ));
    }
    activate_edge(it, d as i64)
}

/// Activates edge `d` of the tool in the spindle (0: none). The core may
/// call it after `M6` as well: the 840D activates D1 on a tool change by
/// default (MD 20270 CUTTING_EDGE_DEFAULT = 1) [K].
pub fn activate_edge(it: &mut Interp<'_, '_>, d: i64) -> Result<(), Stop> {
    let tool = it.state.tool_in_spindle;
    let (offset, radius) = if d == 0 || tool == 0 {
        ([0.0; 9], 0.0)
    } else {
        crate::interp::tools::known_tool(it, tool)?;
        let Some(t) = it.tool_table.get(tool).cloned() else {
            return Err(it.error_at(
                it.span,
                Code::ToolNotInTable,
                format!("Requested tool {tool} not found in the tool table"),
            ));
        };
        if d > 1 {
            edge_note(it, tool, d);
        }
        let k = match it.opts.machine_units {
            LengthUnit::Mm => 1.0,
            LengthUnit::Inch => MM_PER_INCH,
        };
        let mut off = t.offset;
        for (i, x) in off.iter_mut().enumerate() {
            if crate::interp::state::State::is_linear(i) {
                *x *= k;
            }
        }
        (off, t.diameter * k / 2.0)
    };
    it.state.tool_offset = offset;
    it.state.comp_radius = radius;
    let printed = it.state.pose_to_prog(&offset);
    it.emit(Canon::UseToolLengthOffset(printed));
    Ok(())
}

/// W0530: edge `d` of `tool` is not in the table; its row stands in.
fn edge_note(it: &mut Interp<'_, '_>, tool: i64, d: i64) {
    let msg = format!(
        "cutting edge D{d} of tool {tool} is not in the tool table: its length and radius are taken from the tool's row"
    );
    let note = Diagnostic::new(Code::EdgeNotInTable, msg)
        .primary(it.span, "edge selected here")
        .help("the control reads this edge from its tool memory (or, with flat D numbering, the D number alone); give it in the tool table's row for this tool if the values differ");
    it.diags.push(note);
}
