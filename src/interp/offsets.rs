//! Running the offsets statements of a block (see [`super::exec`] for which):
//! work offsets G54..G59.3 (and G54.1 P), G10 L1/L2/L10/L11/L20, G92..G92.3,
//! G52, G28/G30 (and .1). G53 is read by the motion of its block.

use super::machine::{g5x_pose, pose6};
use super::state::{State, MM_PER_INCH};
use super::target::written;
use super::{Interp, Stop};
use crate::canon::Canon;
use crate::diag::Code;
use crate::ir::{Arena, Axes, Block, CoordShift, Expr, LengthUnit, Stmt, StmtKind, Word};

pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.begin_block(block);
    let _ = block;
    match &s.kind {
        StmtKind::WorkOffset {
            index,
            extended: None,
        } if (1..=9).contains(index) => {
            work_offset(it, *index);
            Ok(())
        }
        StmtKind::WorkOffset {
            index,
            extended: None,
        } if (10..=99).contains(index) => {
            numbered_offset(it, *index);
            Ok(())
        }
        StmtKind::WorkOffset {
            extended: Some(p), ..
        } => {
            let p = it.value(p, exprs)?;
            extended_offset(it, p)
        }
        StmtKind::MachineCoords => Ok(()),
        StmtKind::CoordShift { kind, axes } => coord_shift(it, *kind, axes, exprs),
        StmtKind::SetData { l, words } => {
            let l = it.value(l, exprs)?;
            set_data(it, l, words, exprs)
        }
        StmtKind::RefReturn {
            index,
            axes,
            store,
            direct,
        } => ref_return(it, *index, axes, (*store, *direct), block, exprs),
        StmtKind::Transform(t) => super::fanuc_xform::exec(it, t, exprs),
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the interpreter yet",
        )),
    }
}

/// mm per machine unit.
fn machine_scale(it: &Interp<'_, '_>) -> f64 {
    match it.opts.machine_units {
        LengthUnit::Inch => MM_PER_INCH,
        LengthUnit::Mm => 1.0,
    }
}

pub(crate) fn work_offset(it: &mut Interp<'_, '_>, index: u32) {
    if index == it.state.g5x_index {
        it.out(Canon::Comment(
            "interpreter: continuing to use same coordinate system".into(),
        ));
        return;
    }
    let old = it.state.placement();
    it.state.g5x_index = index;
    it.state.reframe(old);
    emit_g5x(it, index);
    emit_g92(it);
    it.out(Canon::SetXyRotation(it.state.g5x_rotation[index as usize]));
}

/// Fanuc G54.1 P / Haas G154 P: an extended work offset (LinuxCNC has
/// none). Its values are Fanuc's parameters #7001.. (P1 X at #7001, stride
/// 20 per P: axis `i` of P`n` is #7001 + 20(n-1) + i, program units), read
/// when selected into the spare work-offset slot 0 and printed as
/// `SET_G5X_OFFSET(100 + n, ...)` (no LinuxCNC index exists).
fn extended_offset(it: &mut Interp<'_, '_>, p: f64) -> Result<(), Stop> {
    if p.fract() != 0.0 || !(1.0..=300.0).contains(&p) {
        return Err(it.error_at(
            it.span,
            Code::BadWordValue,
            format!("extended work offset P{p} is not 1..300"),
        ));
    }
    let n = p as u32;
    let old = it.state.placement();
    for i in 0..9 {
        let v = it
            .params
            .numbered(7001 + 20 * (n - 1) + i as u32)
            .unwrap_or(0.0);
        it.state.g5x[0][i] = if State::is_linear(i) {
            it.state.to_mm(v)
        } else {
            v
        };
    }
    it.state.g5x_rotation[0] = 0.0;
    it.state.g5x_index = 0;
    it.state.reframe(old);
    let offset = g5x_pose(&it.state, 0);
    it.out(Canon::SetG5xOffset {
        index: 100 + n,
        offset,
    });
    emit_g92(it);
    it.out(Canon::SetXyRotation(0.0));
    Ok(())
}

/// Siemens G510..G599: a settable work offset past the nine slots
/// LinuxCNC numbers. Its values are the machine's (`$P_UIFR[n]`, set by
/// the operator), not known to the run: it runs as zero in the spare slot
/// 0, as an extended offset runs with parameters never written, and is
/// printed as `SET_G5X_OFFSET(n, ...)`.
fn numbered_offset(it: &mut Interp<'_, '_>, index: u32) {
    let old = it.state.placement();
    it.state.g5x[0] = [0.0; 9];
    it.state.g5x_rotation[0] = 0.0;
    it.state.g5x_index = 0;
    it.state.reframe(old);
    let offset = g5x_pose(&it.state, 0);
    it.out(Canon::SetG5xOffset { index, offset });
    emit_g92(it);
    it.out(Canon::SetXyRotation(0.0));
}

fn emit_g5x(it: &mut Interp<'_, '_>, index: u32) {
    let offset = g5x_pose(&it.state, index);
    it.out(Canon::SetG5xOffset { index, offset });
}

fn emit_g92(it: &mut Interp<'_, '_>) {
    let g = if it.state.g92_applied {
        it.state.g92
    } else {
        [0.0; 9]
    };
    let p = pose6(&it.state, &g);
    it.out(Canon::SetG92Offset(p));
}

fn coord_shift(
    it: &mut Interp<'_, '_>,
    kind: CoordShift,
    axes: &Axes,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let old = it.state.placement();
    let w = written(it, axes, exprs)?;
    match kind {
        CoordShift::Set => {
            let cur = if it.state.g92_applied {
                it.state.g92
            } else {
                [0.0; 9]
            };
            for i in 0..9 {
                if let Some(v) = w[i] {
                    let v = if State::is_linear(i) {
                        it.state.to_mm(v)
                    } else {
                        v
                    };
                    it.state.g92[i] = it.state.pos[i] + cur[i] - v;
                } else {
                    it.state.g92[i] = cur[i];
                }
            }
            it.state.g92_applied = true;
        }
        CoordShift::Local => {
            for i in 0..9 {
                if let Some(v) = w[i] {
                    it.state.g92[i] = if State::is_linear(i) {
                        it.state.to_mm(v)
                    } else {
                        v
                    };
                }
            }
            it.state.g92_applied = true;
        }
        CoordShift::Reset => {
            it.state.g92 = [0.0; 9];
            it.state.g92_applied = false;
        }
        CoordShift::Suspend => it.state.g92_applied = false,
        CoordShift::Restore => it.state.g92_applied = true,
    }
    it.state.g92_flag = if it.state.g92_applied { 1.0 } else { 0.0 };
    it.state.reframe(old);
    emit_g92(it);
    Ok(())
}

/// The value of a G10 word.
fn word(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match words
        .iter()
        .find(|w| w.letter.eq_ignore_ascii_case(&letter))
    {
        Some(w) => Ok(Some(it.value(&w.value, exprs)?)),
        None => Ok(None),
    }
}

/// G10 axis words, by index (program units as written).
fn axis_words(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<[Option<f64>; 9], Stop> {
    let mut out = [None; 9];
    for (i, letter) in crate::ir::AXIS_LETTERS.iter().enumerate() {
        out[i] = word(it, words, *letter, exprs)?;
    }
    Ok(out)
}

fn set_data(
    it: &mut Interp<'_, '_>,
    l: f64,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let p = word(it, words, 'P', exprs)?;
    let l = l.round() as i64;
    match l {
        2 | 20 => {
            let p = match p {
                Some(p) if (0.0..=9.0).contains(&p) && p.fract() == 0.0 => p as u32,
                _ => {
                    return Err(it.read_error(
                        it.span,
                        Code::BadWordValue,
                        format!("P value out of range (0-9) with G10 L{l}"),
                    ))
                }
            };
            set_work_offset(it, l == 20, p, words, exprs)
        }
        1 | 10 | 11 => set_tool(it, l, p, words, exprs),
        _ => Err(it.error_at(
            it.span,
            Code::UnsupportedHere,
            format!("G10 L{l} is not run by the interpreter"),
        )),
    }
}

fn set_work_offset(
    it: &mut Interp<'_, '_>,
    l20: bool,
    p: u32,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let index = if p == 0 { it.state.g5x_index } else { p };
    let w = axis_words(it, words, exprs)?;
    let r = word(it, words, 'R', exprs)?;
    let old = it.state.placement();
    let w: [Option<f64>; 9] = std::array::from_fn(|i| {
        w[i].map(|v| {
            if State::is_linear(i) {
                it.state.to_mm(v)
            } else {
                v
            }
        })
    });
    if l20 {
        l20_offset(&mut it.state, index, &w);
    } else {
        for (i, v) in w.iter().enumerate() {
            if let Some(v) = v {
                it.state.g5x[index as usize][i] = *v;
            }
        }
    }
    if let Some(r) = r {
        it.state.g5x_rotation[index as usize] = r;
    }
    if index != it.state.g5x_index {
        it.out(Canon::Comment(
            "interpreter: setting coordinate system origin".into(),
        ));
    } else {
        it.state.reframe(old);
        emit_g5x(it, index);
        it.out(Canon::SetXyRotation(it.state.g5x_rotation[index as usize]));
    }
    Ok(())
}

/// G10 L20: the work offset `index` moves so that the current position
/// reads `w` (mm) on the axes given. Under a rotation of that system a
/// given X or Y moves both X and Y of the offset (rs274: the current point
/// is read in that system, the words replace its coordinates, and the
/// offset is what maps the result back onto the machine position).
fn l20_offset(state: &mut State, index: u32, w: &[Option<f64>; 9]) {
    let ix = index as usize;
    let place = state.placement_in(index);
    let m = state.machine_pos();
    let mut c = place.from_machine(&m);
    for (i, v) in w.iter().enumerate() {
        if let Some(v) = v {
            c[i] = *v;
        }
    }
    let unshifted = super::state::Placement {
        g5x: [0.0; 9],
        ..place
    };
    let q = unshifted.to_machine(&c);
    let xy = place.rotation != 0.0 && (w[0].is_some() || w[1].is_some());
    for i in 0..9 {
        if w[i].is_some() || (xy && i < 2) {
            state.g5x[ix][i] = m[i] - q[i];
        }
    }
}

/// G10 L11: the current point (tool offset included) read in the G59.3
/// system, turned by its rotation; G92 left out, as rs274 does [?] (its
/// g10-l11 test: "g92 shouldn't affect the tool touchoff fixture").
fn fixture_reading(state: &State) -> [f64; 9] {
    let m = state.machine_pos();
    let mut c: [f64; 9] = std::array::from_fn(|i| m[i] - state.g5x[9][i]);
    if state.g5x_rotation[9] != 0.0 {
        let (x, y) = super::state::rotate_xy(c[0], c[1], -state.g5x_rotation[9]);
        c[0] = x;
        c[1] = y;
    }
    c
}

/// G10 L10: the tool offsets (mm) that make the current point read `w` on
/// the axes given, the others kept. Under a rotation a given X or Y sets
/// both (the tool offset is added after the rotation, in machine space).
/// rs274 reads the current point with the table's offsets of the tool
/// (`table`, mm), not the applied ones (its g10-l1-l10 test with rotation);
/// unrotated, both readings give the same offsets.
fn l10_offset(state: &State, table: &[f64; 9], w: &[Option<f64>; 9]) -> [Option<f64>; 9] {
    let place = state.placement();
    let xy = place.rotation != 0.0 && (w[0].is_some() || w[1].is_some());
    if !xy {
        return std::array::from_fn(|i| w[i].map(|v| state.pos[i] + state.tool_offset[i] - v));
    }
    let m = state.machine_pos();
    let mut c = super::state::Placement {
        tool: *table,
        ..place
    }
    .from_machine(&m);
    for (i, v) in w.iter().enumerate() {
        if let Some(v) = v {
            c[i] = *v;
        }
    }
    let bare = super::state::Placement {
        tool: [0.0; 9],
        ..place
    };
    let q = bare.to_machine(&c);
    std::array::from_fn(|i| {
        if w[i].is_some() || i < 2 {
            Some(m[i] - q[i])
        } else {
            None
        }
    })
}

/// G10 L1 (values), L10/L11 (so that the current position reads as given).
fn set_tool(
    it: &mut Interp<'_, '_>,
    l: i64,
    p: Option<f64>,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let t = p.unwrap_or(0.0).round() as i64;
    let row = super::tools::row_of(it, t)?;
    let w = axis_words(it, words, exprs)?;
    let scale = machine_scale(it);
    let r = word(it, words, 'R', exprs)?;
    let (i_w, j_w, q_w) = (
        word(it, words, 'I', exprs)?,
        word(it, words, 'J', exprs)?,
        word(it, words, 'Q', exprs)?,
    );
    let Some(tool) = it.tool_table.get(t).cloned() else {
        return Ok(());
    };
    let mut offset = tool.offset;
    let fixture = fixture_reading(&it.state);
    let w_mm: [Option<f64>; 9] = std::array::from_fn(|i| {
        w[i].map(|v| {
            if State::is_linear(i) {
                it.state.to_mm(v)
            } else {
                v
            }
        })
    });
    let table_mm: [f64; 9] = std::array::from_fn(|i| {
        if State::is_linear(i) {
            tool.offset[i] * scale
        } else {
            tool.offset[i]
        }
    });
    let touched = l10_offset(&it.state, &table_mm, &w_mm);
    for i in 0..9 {
        let mm = match (l, w_mm[i]) {
            (1, Some(v)) => v,
            (1, None) => continue,
            (10, _) => match touched[i] {
                Some(v) => v,
                None => continue,
            },
            (_, Some(v)) => fixture[i] - v,
            (_, None) => continue,
        };
        offset[i] = if State::is_linear(i) { mm / scale } else { mm };
    }
    let diameter = r
        .map(|r| it.state.to_mm(r) * 2.0 / scale)
        .unwrap_or(tool.diameter);
    let front = i_w.unwrap_or(tool.front_angle);
    let back = j_w.unwrap_or(tool.back_angle);
    let orientation = q_w.map(|q| q as i64).unwrap_or(tool.orientation);
    if let Some(slot) = it.tool_table.tools.iter_mut().find(|x| x.number == t) {
        slot.offset = offset;
        slot.diameter = diameter;
        slot.front_angle = front;
        slot.back_angle = back;
        slot.orientation = orientation;
    }
    it.out(Canon::SetToolTableEntry {
        row,
        tool: t,
        offset,
        diameter,
        front,
        back,
        orientation,
    });
    // The tool in the spindle also has row 0, which rs274 updates too,
    // with the M6 parameters.
    if row == it.state.spindle_row && row != 0 {
        super::tools::set_tool_parameters(it, t);
        it.out(Canon::SetToolTableEntry {
            row: 0,
            tool: t,
            offset,
            diameter,
            front,
            back,
            orientation,
        });
    }
    Ok(())
}

/// G28/G30: rapid through the given point, then to the stored position
/// (#5161.. / #5181.., machine units) of those axes (all when none given);
/// G28.1/G30.1 store the current position.
fn ref_return(
    it: &mut Interp<'_, '_>,
    index: u8,
    axes: &Axes,
    (store, direct): (bool, bool),
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let base = if index == 1 { 5161 } else { 5181 };
    let scale = machine_scale(it);
    let place = it.state.placement();
    if store {
        let machine = it.state.machine_pos();
        for i in 0..6 {
            let m = machine[i];
            let v = if State::is_linear(i) { m / scale } else { m };
            it.params.set_numbered(base + i as u32, Some(v));
        }
        return Ok(());
    }
    let machine = block
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::MachineCoords));
    let frame = if machine {
        super::target::Frame::Machine
    } else {
        super::target::Frame::Program
    };
    let given = written(it, axes, exprs)?;
    let via = if direct {
        // Siemens G74: no intermediate point; the words only name axes.
        it.comp_block(block.span);
        it.state.pos
    } else {
        let via = super::target::target(it, axes, exprs, frame)?;
        it.comp_block(block.span);
        let via_pose = pose6(&it.state, &via);
        it.straight_move(super::comp::MoveKind::Rapid, via_pose)?;
        via
    };
    let all = given.iter().all(|g| g.is_none());
    let mut stored = [0.0; 9];
    for (i, m) in stored.iter_mut().enumerate().take(6) {
        let v = it.read_numbered(base + i as u32).unwrap_or(0.0);
        *m = if State::is_linear(i) { v * scale } else { v };
    }
    // rs274 reads the whole stored point in the program frame (rotated),
    // then keeps the axes named (all when none is).
    let stored = place.from_machine(&stored);
    let mut home = via;
    for i in 0..6 {
        if all || given[i].is_some() {
            home[i] = stored[i];
        }
    }
    let home_pose = pose6(&it.state, &home);
    it.straight_move(super::comp::MoveKind::Rapid, home_pose)
}
