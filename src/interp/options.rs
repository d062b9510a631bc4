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
}

impl Default for Options {
    fn default() -> Self {
        Options {
            tool_table: ToolTable::builtin(),
            machine_units: LengthUnit::Inch,
            limits: Limits::default(),
            block_delete: false,
        }
    }
}
