//! Heidenhain Klartext semantics in the interpreter: the pole (`CC`), arcs
//! round it (`C`, `CP`), polar lines (`LP`), `RND`/`CHF` corners, cycle
//! definitions and calls, old-style cycles (1 pecking, 7 datum shift,
//! 8 mirror, 9 dwell, 10 rotation, 11 scaling), `END PGM`; `APPR`/`DEP`
//! (LT, LN, CT, LCT), paraxial `R+`/`R-`, `TOOL CALL` DL/DR, and the
//! function blocks FN 14..20, `PLANE`, FK ([`functions`]).
//!
//! Arcs, `CT` and the coordinate transformations go through the Siemens
//! machinery (capability `frame-arcs`): a `C` block becomes an arc with an
//! absolute centre at the pole, polar blocks become cartesian end points,
//! datum shift/rotation/mirror/scaling become the programmable frame.
//! Sources: `reference/dialects.md` §2; assumptions are marked `[?]`.

mod approach;
mod approach_arc;
mod corner;
mod corner_arc;
mod corner_arcs;
mod cycles;
mod cycles_bore;
mod cycles_geom;
mod cycles_helix;
mod cycles_old;
mod cycles_run;
mod cycles_slot;
mod depart;
mod functions;
mod held_arc;
mod mapping;
mod paraxial;
mod paths;
mod pattern;
mod tooldelta;

use super::{Interp, Stop};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, Stmt, StmtKind};

pub use corner::{flush, flush_before};
pub use functions::kinematics_not_run;
pub use paths::motion;
pub use tooldelta::{radius_comp, tool_change};

/// The Heidenhain part of the machine state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct HeidenhainState {
    /// The pole / circle centre (programmed system, mm, plane axes).
    pub pole: Option<[f64; 3]>,
    /// The last cycle definition (numbered cycles), values evaluated.
    pub cycle: Option<Defined>,
    /// Old-style cycle values by (cycle, sub-number): the first value.
    pub old: Vec<((u32, u32), f64)>,
    /// The old-style cycle defined last (1..5, 17) for M99 / CYCL CALL.
    pub old_cycle: Option<u32>,
    /// M89: call the cycle after every positioning block.
    pub modal_call: bool,
    /// The points of the last PATTERN DEF (programmed, program units).
    pub pattern: Vec<[Option<f64>; 3]>,
    /// Datum shift, rotation, mirror and scale (cycles 7, 10, 8, 11).
    pub shift: [f64; 3],
    pub rotation: f64,
    pub mirror: [bool; 3],
    pub scale: f64,
    /// A straight feed move held back until the next block says whether a
    /// corner (`RND`/`CHF`) follows it.
    pub held: Option<corner::Held>,
    /// An `APPR` waiting for its first contour element.
    pub approach: Option<approach::PendingApproach>,
    /// The compensation side of the last APPR (DEP leaves on that side
    /// even when its own R0 has already switched compensation off).
    pub side: Option<crate::ir::CompSide>,
    /// `DL`/`DR` of the last TOOL CALL (mm): added to the tool's length
    /// offset and compensation radius.
    pub oversize: [f64; 2],
    /// A `DEP CT`/`LCT` already run before its block's `R0` (see
    /// [`approach::depart_before_comp_off`]).
    pub departed: bool,
    /// The last path element was an arc (a rounding after it is not run).
    pub after_arc: bool,
}

/// `TOOL DEF 5 L+50 R+3`: the tool's radius (and length) in the run's
/// tool table, used by radius compensation, Q108 and the milling cycles
/// [?: the length is taken from the table given with --tool-table when
/// the tool is called].
fn tool_def(
    it: &mut Interp<'_, '_>,
    tool: &crate::ir::ToolRef,
    length: &Option<crate::ir::Value>,
    radius: &Option<crate::ir::Value>,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let crate::ir::ToolRef::Number(n) = tool else {
        return Ok(());
    };
    let n = it.value(n, exprs)?.round() as i64;
    let to_machine = |it: &Interp<'_, '_>, v: f64| {
        let mm = it.state.to_mm(v);
        match it.opts.machine_units {
            crate::ir::LengthUnit::Inch => mm / crate::interp::state::MM_PER_INCH,
            crate::ir::LengthUnit::Mm => mm,
        }
    };
    let l = match length {
        Some(v) => {
            let x = it.value(v, exprs)?;
            Some(to_machine(it, x))
        }
        None => None,
    };
    let r = match radius {
        Some(v) => {
            let x = it.value(v, exprs)?;
            Some(to_machine(it, x))
        }
        None => None,
    };
    if l.is_some() || r.is_some() {
        it.tool_table.from_program.insert(n);
    }
    let table = &mut it.tool_table.tools;
    let i = match table.iter().position(|t| t.number == n) {
        Some(i) => i,
        None => {
            table.push(crate::interp::tooltable::Tool {
                number: n,
                pocket: n,
                offset: [0.0; 9],
                diameter: 0.0,
                front_angle: 0.0,
                back_angle: 0.0,
                orientation: 0,
                comment: String::new(),
            });
            table.len() - 1
        }
    };
    if let Some(l) = l {
        table[i].offset[2] = l;
    }
    if let Some(r) = r {
        table[i].diameter = 2.0 * r.abs();
    }
    Ok(())
}

/// After `TOOL CALL`: Q108 holds the active tool radius with the DR of
/// the call [K: TNC system parameter], as programs such as corpus
/// `Plan.h` expect.
pub fn tool_called(it: &mut Interp<'_, '_>) {
    let r = mapping::tool_radius(it) + it.state.to_prog(it.heidenhain.oversize[1]);
    it.params.set_q(crate::ir::QBank::Q, 108, r);
}

/// A cycle definition with its parameter values.
#[derive(Clone, Debug, PartialEq)]
pub struct Defined {
    pub number: u32,
    pub params: Vec<(u32, f64)>,
}

/// Runs one Heidenhain-only statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    match &s.kind {
        StmtKind::Pole(axes) => paths::pole(it, axes, exprs),
        StmtKind::Corner { kind, size } => corner::corner(it, *kind, size, s.span, exprs),
        StmtKind::Approach(a) => approach::exec(it, a, s.span, exprs),
        StmtKind::CycleDef(c) => mapping::define(it, c, exprs),
        StmtKind::CycleLine(l) => cycles::line(it, l, s.span, exprs),
        StmtKind::CycleRun(kind) => cycles::run(it, kind, s.span, block, exprs),
        StmtKind::PatternDef(items) => cycles::pattern(it, items, exprs),
        StmtKind::ToolDef {
            tool,
            length,
            radius,
        } => tool_def(it, tool, length, radius, exprs),
        // The blank says nothing the run uses.
        StmtKind::Stock { .. } => Ok(()),
        StmtKind::ToolOversize { .. } => tooldelta::oversize_alone(it, block, exprs),
        StmtKind::TncFunction(f) => functions::exec(it, f, s.span, exprs),
        StmtKind::ProgramEnd { .. } => {
            corner::flush(it)?;
            super::machine::program_end(it, true)
        }
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the interpreter yet",
        )),
    }
}
