//! Running the tools statements of a block (see [`super::exec`] for which):
//! T, M6, cutter radius compensation G40/G41/G42 (.1), tool length
//! offsets G43/G43.1/G43.2/G44/G49. Tool-table numbers are in machine
//! units ([`crate::interp::Options::machine_units`]).

use super::comp::CompSide as Side;
use super::host::SpindleDir;
use super::state::MM_PER_INCH;
use super::{Interp, Stop};
use crate::canon::Canon;
use crate::diag::Code;
use crate::ir::{
    Arena, Axes, Block, CompSide, Expr, LengthComp, LengthUnit, Stmt, StmtKind, ToolRef, Value,
};

pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.begin_block(block);
    match &s.kind {
        StmtKind::ToolSelect(ToolRef::Number(v)) | StmtKind::ToolPreselect(ToolRef::Number(v)) => {
            let t = it.value(v, exprs)?.round() as i64;
            row_of(it, t)?;
            it.state.tool_selected = Some(t);
            it.out(Canon::SelectTool(t));
            Ok(())
        }
        StmtKind::ToolSelect(ToolRef::Name(name))
        | StmtKind::ToolPreselect(ToolRef::Name(name)) => {
            let t = tool_by_name(it, name)?;
            it.state.tool_selected = Some(t);
            it.out(Canon::SelectTool(t));
            Ok(())
        }
        StmtKind::ToolChange => tool_change(it),
        StmtKind::RadiusComp {
            side,
            register,
            diameter,
        } => radius_comp(it, *side, register.as_ref(), *diameter, block, exprs),
        StmtKind::LengthComp {
            mode,
            register,
            axes,
        } => length_comp(it, *mode, register.as_ref(), axes, exprs),
        StmtKind::OffsetRegister { letter, value } => {
            register_alone(it, (*letter, value), block, exprs)
        }
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the interpreter yet",
        )),
    }
}

/// Makes sure tool `t` has a row: on a control that holds its own tool
/// data, a tool the table lacks joins it with no sizes; elsewhere it is
/// E0501. Tools with no size from a real table are noted (W0592).
pub fn known_tool(it: &mut Interp<'_, '_>, t: i64) -> Result<(), Stop> {
    if t <= 0 {
        return Ok(());
    }
    let listed = it.tool_table.get(t).is_some();
    if !listed && !it.spec.has(crate::dialect::Capability::ControlHoldsTools) {
        return Err(it.error_at(
            it.span,
            Code::ToolNotInTable,
            format!("Requested tool {t} not found in the tool table"),
        ));
    }
    if !listed {
        let tool = crate::interp::tooltable::Tool::blank(t, String::new());
        it.tool_table.tools.push(tool);
    }
    let given = it.tool_table.from_program.contains(&t);
    // A tool the program names with no size ran with none, whatever the
    // table: the machine's own table must hold it.
    let named_only = it.tool_table.named_only.contains(&t);
    if named_only || (!given && (!listed || it.tool_table.invented)) {
        let span = it.span;
        it.tools_without_data
            .entry(t)
            .or_insert((span, listed && !named_only));
    }
    Ok(())
}

/// W0592, once per run: which tools ran with invented or no sizes.
pub fn tools_without_data(it: &mut Interp<'_, '_>) -> Option<crate::diag::Diagnostic> {
    let tools = std::mem::take(&mut it.tools_without_data);
    if !(it.opts.report_tool_sizes || it.comp_without_size) {
        return None;
    }
    let (&first, &(span, _)) = tools.iter().next()?;
    let list = |invented: bool| {
        tools
            .iter()
            .filter(|(_, (_, i))| *i == invented)
            .map(|(t, _)| format!("T{t}"))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let (made, none) = (list(true), list(false));
    let mut parts = Vec::new();
    if !made.is_empty() {
        parts.push(format!("{made} got sizes from cncc's built-in table"));
    }
    if !none.is_empty() {
        parts.push(format!("{none} ran with no length and no diameter"));
    }
    if it.comp_without_size {
        parts.push("radius compensation ran with no radius, so gouges were not checked".into());
    }
    Some(
        crate::diag::Diagnostic::new(
            Code::ToolSizesInvented,
            format!("no tool table gave these tools' sizes: {}", parts.join("; ")),
        )
        .primary(span, format!("T{first} first used here"))
        .help("give the shop's tool table with --tool-table to check lengths and radius compensation with real sizes"),
    )
}

/// The 1-based table row of tool `t` (tool 0: row 0, no tool).
pub fn row_of(it: &mut Interp<'_, '_>, t: i64) -> Result<i64, Stop> {
    if t == 0 {
        return Ok(0);
    }
    known_tool(it, t)?;
    match it.tool_table.row(t) {
        Some(r) => Ok(r as i64),
        None => Err(it.error_at(
            it.span,
            Code::ToolNotInTable,
            format!("Requested tool {t} not found in the tool table"),
        )),
    }
}

/// A tool called by name (Siemens `T="FACEMILL 63"`): the tool-table row
/// whose comment is that name (case and surrounding spaces aside), since
/// LinuxCNC tables have no name column.
fn tool_by_name(it: &mut Interp<'_, '_>, name: &str) -> Result<i64, Stop> {
    let wanted = name.trim();
    let found = it
        .tool_table
        .tools
        .iter()
        .any(|t| t.comment.trim().eq_ignore_ascii_case(wanted));
    if !found && it.opts.tool_table == crate::interp::tooltable::ToolTable::builtin() {
        return Ok(assumed_tool(it, wanted));
    }
    it.tool_table
        .tools
        .iter()
        .find(|t| t.comment.trim().eq_ignore_ascii_case(wanted))
        .map(|t| t.number)
        .ok_or_else(|| {
            match it.error_at(
                it.span,
                Code::ToolNotInTable,
                format!("no tool named \"{wanted}\" in the tool table"),
            ) {
                Stop::Error(d) => Stop::Error(d.help(format!(
                    "name a tool by its comment in the tool table: `T5 P5 Z2.0 D2.48 ;{wanted}`"
                ))),
                other => other,
            }
        })
}

/// No tool table was given: the named tool joins the run's table as a
/// tool of no size (numbers from 1001 up), with W0516.
fn assumed_tool(it: &mut Interp<'_, '_>, name: &str) -> i64 {
    let number = 1001
        + it.tool_table
            .tools
            .iter()
            .filter(|t| t.number > 1000)
            .count() as i64;
    it.tool_table
        .tools
        .push(crate::interp::tooltable::Tool::blank(
            number,
            name.to_string(),
        ));
    let d = crate::diag::Diagnostic::new(
        Code::NamedToolWithoutTable,
        format!("tool \"{name}\" is called by name and no tool table was given"),
    )
    .primary(it.span, "run as a tool of no length and no diameter")
    .help(format!(
        "give `--tool-table` with a row named by its comment: `T5 P5 Z2.0 D2.48 ;{name}`"
    ));
    it.diags.push(d);
    number
}

/// mm per machine unit.
fn machine_scale(it: &Interp<'_, '_>) -> f64 {
    match it.opts.machine_units {
        LengthUnit::Inch => MM_PER_INCH,
        LengthUnit::Mm => 1.0,
    }
}

fn tool_change(it: &mut Interp<'_, '_>) -> Result<(), Stop> {
    let t = it.state.tool_selected.unwrap_or(it.state.tool_in_spindle);
    let row = row_of(it, t)?;
    it.out(Canon::StartChange);
    it.state.spindle = SpindleDir::Stopped;
    it.out(Canon::StopSpindle);
    it.state.tool_in_spindle = t;
    it.state.spindle_row = row;
    it.state.resync = true;
    it.out(Canon::ChangeTool(row));
    set_tool_parameters(it, t);
    Ok(())
}

/// #5400 (tool number), #5401..#5409 (its table offsets, machine units, as
/// the table gives them) and #5410 (diameter): written by M6 only, as rs274
/// does (M61 and G43 leave them; `T0 M6` leaves them too, checked with rs274).
pub fn set_tool_parameters(it: &mut Interp<'_, '_>, t: i64) {
    let Some(tool) = it.tool_table.get(t).cloned() else {
        return;
    };
    it.params.set_numbered(5400, Some(t as f64));
    for (i, v) in tool.offset.iter().enumerate() {
        it.params.set_numbered(5401 + i as u32, Some(*v));
    }
    it.params.set_numbered(5410, Some(tool.diameter));
}

fn radius_comp(
    it: &mut Interp<'_, '_>,
    side: CompSide,
    register: Option<&Value>,
    diameter: bool,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.comp_block(block.span);
    let span = it.span;
    let side = match side {
        CompSide::Off => {
            if it.comp.is_on() {
                it.out(Canon::Comment(
                    "interpreter: cutter radius compensation off".into(),
                ));
            }
            let sink = &mut it.sink;
            let r = it.comp.stop(&mut |c| sink.call(c, span));
            it.state.comp_side = CompSide::Off;
            return r.map_err(|e| it.comp_error(e));
        }
        CompSide::Left => Side::Left,
        CompSide::Right => Side::Right,
    };
    let (radius, orientation) = comp_radius(it, register, diameter, exprs)?;
    let what = if side == Side::Left { "left" } else { "right" };
    it.out(Canon::Comment(format!(
        "interpreter: cutter radius compensation on {what}"
    )));
    let plane = it.state.plane;
    it.comp
        .start(side, radius, plane)
        .map_err(|e| it.comp_error(e))?;
    it.comp.set_tip(orientation);
    it.state.comp_side = if side == Side::Left {
        CompSide::Left
    } else {
        CompSide::Right
    };
    it.state.comp_radius = radius;
    Ok(())
}

/// G41/G42 [D]: half the table diameter of tool D (or of the tool in the
/// spindle), in program units, and that tool's orientation (lathe tools,
/// the table's Q); G41.1/G42.1 D: half of D itself [?: its L orientation
/// is not read].
fn comp_radius(
    it: &mut Interp<'_, '_>,
    register: Option<&Value>,
    dynamic: bool,
    exprs: &Arena<Expr>,
) -> Result<(f64, i64), Stop> {
    let d = match register {
        Some(v) => Some(it.value(v, exprs)?),
        None => None,
    };
    if dynamic {
        return Ok((d.unwrap_or(0.0) / 2.0, 0));
    }
    let modal = it.spec.has(crate::dialect::Capability::CompRegisterModal);
    if d.is_some() {
        it.state.comp_register = d;
    }
    // No D here and none before: D0, no radius.
    let d = match (d, modal) {
        (None, true) => Some(it.state.comp_register.unwrap_or(0.0)),
        _ => d,
    };
    let t = d
        .map(|v| v.round() as i64)
        .unwrap_or(it.state.tool_in_spindle);
    if t == 0 {
        return Ok((0.0, 0));
    }
    known_tool(it, t)?;
    let invented = it.tools_without_data.contains_key(&t);
    if invented && it.spec.has(crate::dialect::Capability::ControlHoldsTools) {
        // The built-in sizes are not this control's: compensating by them
        // would report gouges the real tool may not make (W0592 says so).
        it.comp_without_size = true;
        return Ok((0.0, 0));
    }
    let (dia, orientation) = match it.tool_table.get(t) {
        Some(tool) => (tool.diameter, tool.orientation),
        None => {
            return Err(it.error_at(
                it.span,
                Code::ToolNotInTable,
                format!("Requested tool {t} not found in the tool table"),
            ))
        }
    };
    Ok((it.state.to_prog(dia * machine_scale(it)) / 2.0, orientation))
}

/// A length register alone (`Z4. H2`) while G43/G44 is in force: where
/// the spec says so (`offset-register-alone`, Fanuc and Haas [K]: a new H
/// number in G43 mode replaces the offset), the new register's length is
/// active from this block's moves on, as `G43 H2` would make it.
/// Elsewhere it changes nothing here (LinuxCNC refuses it, see the lint).
fn register_alone(
    it: &mut Interp<'_, '_>,
    (letter, value): (char, &Value),
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let role = |r: &str| {
        it.spec
            .addresses
            .iter()
            .any(|a| a.letter == letter && a.role == r)
    };
    if role("radius-offset") {
        // D alone: the register a later G41/G42 without D uses [?: one
        // given while compensation is on changes the radius at once on a
        // Fanuc; here it waits for the next G41/G42].
        it.state.comp_register = Some(it.value(value, exprs)?);
        return Ok(());
    }
    // `G42 H19`: an H beside G41/G42 is the radius register on controls
    // set up so (Fanuc 0M posts write it) [?]: not a length change.
    let beside_comp = block
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::RadiusComp { .. }));
    let length = role("length-offset") && !beside_comp;
    if !length
        || it.state.length_tool.is_none()
        || !it.spec.has(crate::dialect::Capability::OffsetRegisterAlone)
    {
        return Ok(());
    }
    let mode = match it.state.length_negative {
        true => LengthComp::Negative,
        false => LengthComp::Positive,
    };
    length_comp(it, mode, Some(value), &Axes::default(), exprs)
}

fn length_comp(
    it: &mut Interp<'_, '_>,
    mode: LengthComp,
    register: Option<&Value>,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let scale = machine_scale(it);
    let table_offset = |it: &mut Interp<'_, '_>, t: i64| -> Result<[f64; 9], Stop> {
        if t == 0 {
            return Ok([0.0; 9]);
        }
        known_tool(it, t)?;
        match it.tool_table.get(t) {
            Some(tool) => {
                let mut o = tool.offset;
                for (i, v) in o.iter_mut().enumerate() {
                    if super::state::State::is_linear(i) {
                        *v *= scale;
                    }
                }
                Ok(o)
            }
            None => Err(it.error_at(
                it.span,
                Code::ToolNotInTable,
                format!("Requested tool {t} not found in the tool table"),
            )),
        }
    };
    let h = match register {
        Some(v) => Some(it.value(v, exprs)?.round() as i64),
        None => None,
    };
    let new = match mode {
        LengthComp::Positive | LengthComp::Negative => {
            // M61 in the same block counts; from the next block on rs274
            // reads the tool loaded by the last M6 again.
            let spindle = match it.state.m61_block {
                Some(b) if b == it.block_span => it.state.tool_number,
                _ => it.state.tool_in_spindle,
            };
            let t = h.unwrap_or(spindle);
            let mut o = table_offset(it, t)?;
            it.state.length_tool = (t != 0).then_some(t);
            it.state.length_negative = mode == LengthComp::Negative;
            if mode == LengthComp::Negative {
                o.iter_mut().for_each(|v| *v = -*v);
            }
            o
        }
        LengthComp::Cancel => {
            it.state.length_tool = None;
            [0.0; 9]
        }
        LengthComp::Dynamic => {
            it.state.length_tool = None;
            let mut o = [0.0; 9];
            for (i, letter) in crate::ir::AXIS_LETTERS.iter().enumerate() {
                if let Some(c) = axes.get(*letter) {
                    let v = it.value(&c.value, exprs)?;
                    o[i] = if super::state::State::is_linear(i) {
                        it.state.to_mm(v)
                    } else {
                        v
                    };
                }
            }
            o
        }
        LengthComp::Additive => {
            let t = h.unwrap_or(it.state.tool_in_spindle);
            let add = table_offset(it, t)?;
            let mut o = it.state.tool_offset;
            for i in 0..9 {
                o[i] += add[i];
            }
            o
        }
    };
    // The tool tip stays where it is: its program coordinates change
    // (until a tool change makes rs274 re-read the position, see
    // `State::resync`).
    let old = it.state.placement();
    it.state.tool_offset = new;
    it.state.reframe_keep_canon(old);
    let p = it.state.pose_to_prog(&new);
    it.out(Canon::UseToolLengthOffset(p));
    Ok(())
}
