//! `cncc port`: a program read in one dialect turned into the forms the
//! target dialect has, before the target's writer prints it.
//!
//! The passes work on a copy of the meta-model, each asking the target
//! spec (capabilities, code table, cycle signatures), never its name:
//!
//! * [`to_named`]: word-address cycles (G81..G89 with R, Z, Q, P, G98/G99,
//!   the position-only blocks that repeat them, G80) become named cycle
//!   calls `MCALL CYCLE8x(..)` + positions + `MCALL` where the target has
//!   named cycles and no G8x codes; [`to_word`] does the reverse.
//! * Heidenhain Klartext: [`pockets`] (POCKET1/2 ↔ `CYCL DEF 251/252`),
//!   [`from_tnc`] (`CYCL DEF 200/203` + calls → G81/G82/G83/G73, which
//!   [`to_named`] turns into CYCLE8x for Siemens), [`to_tnc`] (G8x, and
//!   CYCLE8x through [`to_word`], → `CYCL DEF 200/203` + `L X Y R0 FMAX
//!   M99`), [`frame`] (`BEGIN`/`END PGM`, block numbers, D1), [`poles`]
//!   (`CC` + `C` → G2/G3 with I J) and [`tool_call`] (`TOOL CALL n Z S`).
//! * Klartext variables and loops: [`to_tnc`] (`variables_and_flow`:
//!   `#n`/`Rn`/named → Q/QL parameters, loops and jumps → `LBL` + `FN
//!   9..12`) and `from_tnc_flow` (back: `#n`/`Rn`/named, `IF .. GOTO`,
//!   `GOTOB`/`GOTOF`, o-word `do`/`if`/`break`).
//! * [`forms`]: numbered variables (`#n` ↔ `Rn`), loop and conditional
//!   forms (Fanuc DO ids, Siemens nesting, LinuxCNC o-words), labels to
//!   sequence numbers, tool length (G43 H / G49 ↔ D / D0), and the tool map.
//! * [`decls`]: Siemens `DEF` variables as named or free numbered ones;
//!   [`loops`]: `FOR` as a WHILE loop where the target has no FOR.
//! * [`groups`]: a code moved to its own block where the target puts it in
//!   the modal group of another code in the block (`G80` with `G0`).
//! * [`arcs`]: Siemens `CIP` arcs as `G2`/`G3` with their centre.
//! * [`ref_return`]: `G91 G28 Z0` ↔ Siemens `G74 Z1=0`.
//! * [`osubs`]: LinuxCNC o-word subroutines as `O n` .. `M99` programs
//!   called with `G65 P n` and argument letters (Fanuc, Haas), inlined
//!   with their arguments in R parameters (Siemens).
//! * [`blank`]: `BLK FORM` as a comment (and the `--stock` it implies)
//!   where the target has no blank statement.
//! * [`old_cycles`]: Heidenhain `CYCL DEF 7` (datum shift) as `TRANS` or
//!   `G52`, `CYCL DEF 9` (dwell) as `G4`, where exact.
//! * [`case`]: Siemens `CASE` as a chain of conditional jumps where the
//!   target has no structured control; [`flow_jumps`]: structured IF and
//!   end-tested loops as Macro B jumps.
//! * [`named_params`]: LinuxCNC `#<name>` as free common variables;
//!   [`proc_file`], [`proc_calls`]: a Siemens PROC file as the target's
//!   called program, and its calls with their arguments.
//! * [`funcs`]: rounding and power functions the target lacks, written
//!   exactly with the ones it has (`POT(x)` → `x*x`, `FUP` → `INT` + `SGN`).
//! * [`dwell_block`]: a move that shares a block with a dwell gets a
//!   block of its own after it where the target wants that.
//! * [`preselect`]: the next tool of `T1 T2 M6` in a block of its own
//!   where the target names one tool per block.
//! * [`messages`]: operator messages as comments where the target shows
//!   none without stopping.
//! * [`expand`]: the documented fallback `--expand-cycles`, a cycle written
//!   as the moves the interpreter makes for it.
//!
//! A large program without control flow is ported as a stream
//! ([`stream`]): the same passes, run on pieces of it in their context.
//!
//! What the target cannot express is an error naming the construct and
//! where it is (E0601, E0610..E0614, E0621..E0623); the writer reports
//! the rest.

mod after_cycle;
mod arcs;
mod blank;
mod case;
mod change_tool;
mod commands;
mod comp_modal;
mod comp_register;
mod cycle_return;
mod decls;
mod dwell_block;
pub mod expand;
pub mod expand_range;
mod flow_ids;
mod flow_jumps;
pub mod forms;
mod frame;
mod free_vars;
mod from_tnc;
mod from_tnc_flow;
mod funcs;
mod groups;
mod haas_cycles;
mod length_register;
mod levels;
mod loops;
mod machine_functions;
mod messages;
mod named_params;
mod named_tools;
mod old_cycles;
mod oriented_boring;
pub(crate) mod osubs;
mod path_words;
mod per_value_dims;
mod pockets;
mod poles;
mod power_on_motion;
mod preselect;
mod proc_calls;
mod proc_file;
mod program_end;
mod program_name;
mod ref_return;
mod spf;
pub mod stream;
pub mod subload;
mod text;
mod tnc_labels;
pub mod to_named;
pub mod to_tnc;
pub mod to_word;
mod tolerance_cycle;
mod tool_call;
pub mod toolmap;
mod tools;
pub mod verify;
mod verify_digest;
pub mod verify_lockstep;
pub mod verify_text;
mod work_offsets;

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Block, Decimal, Expr, ExprId, ExprKind, Program, Value};
use crate::span::Span;
pub use toolmap::ToolMap;

/// What the user allowed and asked for.
#[derive(Clone, Debug, Default)]
pub struct PortOptions {
    pub tool_map: ToolMap,
    /// Write cycles the target cannot express as the moves they make.
    pub expand_cycles: bool,
    /// The tool table's tools by name (the comment of each row) and number.
    pub tool_names: Vec<(String, i64)>,
}

/// Turns `p` (read as `from`) into the target's forms. Diagnostics may be
/// errors (the program cannot be ported as asked) or warnings.
pub fn port_program(
    p: &Program,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &PortOptions,
) -> (Program, Vec<Diagnostic>) {
    port_owned(p.clone(), from, to, opts)
}

/// [`port_program`] on a program the caller no longer needs: the passes
/// work on it in place (a large program is not held twice).
pub fn port_owned(
    mut out: Program,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &PortOptions,
) -> (Program, Vec<Diagnostic>) {
    let mut diags = Vec::new();
    haas_cycles::run(&out, from, to, opts.expand_cycles, &mut diags);
    tolerance_cycle::run(&mut out, from, to);
    if opts.expand_cycles {
        expand::expand_unmappable(&mut out, from, to, &mut diags);
    }
    funcs::run(&mut out, to);
    length_register::run(&mut out, from, to);
    power_on_motion::run(&mut out, from, to);
    cycle_return::run(&mut out, from, to);
    blank::run(&mut out, to, &mut diags);
    old_cycles::run(&mut out, to);
    to_tnc::modes::presets_to_codes(&mut out, from, to);
    pockets::run(&mut out, from, to, &mut diags);
    from_tnc::run(&mut out, from, to, &mut diags);
    program_end::run(&mut out, to);
    frame::run(&mut out, from, to);
    program_name::run(&mut out, to);
    work_offsets::run(&mut out, from, to);
    named_tools::run(&mut out, to, &opts.tool_names, &mut diags);
    machine_functions::run(&mut out, from, to, &mut diags);
    commands::run(&mut out, from, to, &mut diags);
    after_cycle::run(&mut out, from, to);
    from_tnc::subprograms::run(&mut out, from, to, &mut diags);
    poles::run(&mut out, from, to, &mut diags);
    to_named::run(&mut out, from, to, &mut diags);
    to_tnc::named::run(&mut out, from, to, &mut diags);
    to_word::run(&mut out, from, to, &mut diags);
    oriented_boring::run(&out, from, to, &mut diags);
    to_tnc::run(&mut out, from, to, &mut diags);
    to_tnc::modes::run(&mut out, to, &mut diags);
    path_words::run(&mut out, to, &mut diags);
    to_tnc::variables_and_flow(&mut out, to, &mut diags);
    from_tnc_flow::run(&mut out, from, to, &mut diags);
    proc_file::run(&mut out, to, &mut diags);
    proc_calls::run(&mut out, from, to);
    decls::run(&mut out, to, &mut diags);
    named_params::run(&mut out, to, &mut diags);
    loops::run(&mut out, to, &mut diags);
    case::run(&mut out, to);
    flow_jumps::run(&mut out, to);
    arcs::run(&mut out, from, to);
    ref_return::run(&mut out, from, to, &mut diags);
    per_value_dims::run(&mut out, from, to);
    osubs::run(&mut out, from, to, &mut diags);
    forms::run(&mut out, from, to, opts, &mut diags);
    spf::run(&mut out, from, to);
    groups::run(&mut out, to);
    dwell_block::run(&mut out, to);
    preselect::run(&mut out, to);
    change_tool::run(&mut out, to);
    tool_call::run(&mut out, from, to);
    comp_register::run(&mut out, to);
    comp_modal::run(&mut out, from, to);
    to_tnc::subprograms::run(&mut out, from, to, &mut diags);
    messages::run(&mut out, to, &mut diags);
    text::run(&mut out, from, to, &mut diags);
    out.dialect = to.id.clone();
    (out, diags)
}

/// The start of the labels the port makes (jump targets of lowered
/// structures); a target that numbers them does not keep their names.
pub(crate) const MADE_LABEL: &str = "CNCC_";

/// The comment form a port writes its own notes in for `to`: `( )` where
/// the target has it, else `;`.
pub(crate) fn comment_style(to: &DialectSpec) -> crate::ir::CommentStyle {
    if to.has(crate::dialect::Capability::ParenComments) {
        crate::ir::CommentStyle::Paren
    } else {
        crate::ir::CommentStyle::Semicolon
    }
}

/// A number as an expression in `p`'s arena (for cycle arguments).
pub(crate) fn number_expr(p: &mut Program, d: Decimal, span: Span) -> ExprId {
    p.exprs.alloc(Expr {
        kind: ExprKind::Number(d),
        span,
    })
}

/// A value as an expression (numbers get a new node, expressions are shared).
pub(crate) fn value_expr(p: &mut Program, v: &Value, span: Span) -> ExprId {
    match v {
        Value::Number(d) => number_expr(p, *d, span),
        Value::Expr(e) => *e,
    }
}

/// A computed length written back exactly enough: six places, trimmed.
pub(crate) fn decimal(v: f64) -> Decimal {
    let mut d = Decimal::from_f64(v, 6).normalized();
    d.point = true;
    d
}

/// A block made by a pass from `like`: same skip level, no number or label.
pub(crate) fn follow_block(like: &Block, stmts: Vec<crate::ir::Stmt>) -> Block {
    Block {
        span: like.span,
        skip: like.skip.clone(),
        number: None,
        label: None,
        stmts,
    }
}
