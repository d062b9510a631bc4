//! How a run is set up: tool table, machine units, limits.

use super::tooltable::ToolTable;
use crate::ir::LengthUnit;

/// Bounds that end a run with a diagnostic instead of a hang.
#[derive(Clone, Debug)]
pub struct Limits {
    /// Iterations of any one loop (WHILE, o-word loops, backward jumps).
    pub loop_iterations: u64,
    /// Nested subprogram and macro calls.
    pub call_depth: u32,
    /// Blocks executed in all.
    pub blocks: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            loop_iterations: 1_000_000,
            call_depth: 64,
            blocks: 100_000_000,
        }
    }
}

#[derive(Clone, Debug)]
pub struct Options {
    pub tool_table: ToolTable,
    /// The unit of tool-table numbers and stored G28/G30 positions.
    /// LinuxCNC's standalone interpreter uses inches; so does cncc by default.
    pub machine_units: LengthUnit,
    pub limits: Limits,
    /// Block delete switch: when on, blocks starting with `/` are skipped.
    pub block_delete: bool,
    /// A call to a program that is neither in the file nor beside it is a
    /// warning (W0591) and the run goes on after it, as `check` wants for a
    /// program whose controller may hold the called one; `canon` keeps it
    /// an error, as rs274 does.
    pub missing_calls_warn: bool,
    /// The machine: reference point and work offsets (`None`: rs274's
    /// standalone state, everything at 0).
    pub machine: Option<super::machine_desc::Machine>,
    /// Say which tools ran with invented or no sizes (W0592) even when
    /// radius compensation did not need them (`stats`, `plot`, `stepnc`,
    /// where the sizes shape the result).
    pub report_tool_sizes: bool,
    /// After a run-time mistake that leaves the program's state sound (a
    /// bad arc, a missing feed, a compensation error), report it and go on
    /// with the next block, as `check` does; `canon` stops at the first,
    /// as rs274 does.
    pub keep_going: bool,
    /// A LinuxCNC configuration's parameter file and `[RS274NGC]`
    /// settings (`--var-file`, `--ini`).
    pub rs274: super::config::Rs274Config,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tool_table: ToolTable::builtin(),
            machine_units: LengthUnit::Inch,
            limits: Limits::default(),
            block_delete: false,
            missing_calls_warn: false,
            machine: None,
            report_tool_sizes: false,
            keep_going: false,
            rs274: Default::default(),
        }
    }
}
