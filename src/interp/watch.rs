//! Watching a run block by block: after each block has run, a watcher
//! (the lint layer, [`crate::lint`]) is shown the block, the canonical
//! calls it made and the modal state the interpreter computed after it.
//! The watcher reads; it never changes the run.

use super::cycles::CycleMemory;
use super::state::State;
use super::tooltable::ToolTable;
use crate::canon::Canon;
use crate::ir::{Arena, Block, Expr};
use crate::span::Span;

/// One block that ran, as the interpreter left it.
pub struct Step<'x> {
    /// The block (None for calls made outside any block).
    pub block: &'x Block,
    pub exprs: &'x Arena<Expr>,
    /// How many subprogram calls deep the block ran (0: the main program).
    pub depth: usize,
    /// The calls the block made, each with the span of its statement.
    pub calls: &'x [(Canon, Span)],
    /// The modal state after the block.
    pub state: &'x State,
    /// Canned-cycle values after the block (R, Q, bottom as written).
    pub cycles: &'x CycleMemory,
    /// The tool table as the program left it.
    pub tools: &'x ToolTable,
    /// Tools whose sizes no table gave (invented or unknown).
    pub tools_without_data: &'x std::collections::BTreeMap<i64, (Span, bool)>,
}

/// Shown every block that ran.
pub type Watcher = dyn FnMut(&Step<'_>);

impl super::Interp<'_, '_> {
    /// [`super::Interp::settle`], showing the watcher (if any) the block
    /// that ran with its calls and the state after it.
    pub fn settle_block<T>(
        &mut self,
        result: Result<T, super::Stop>,
        block: &Block,
        exprs: &Arena<Expr>,
        depth: usize,
    ) -> Result<T, super::Stop> {
        if let Some(mut w) = self.watcher.take() {
            let unread = self.sink.unread
                || matches!(&result, Err(super::Stop::Error(d)) if super::read_time_error(d));
            let none: Vec<(Canon, Span)> = Vec::new();
            let calls = if unread { &none } else { &self.sink.held };
            w(&Step {
                block,
                exprs,
                depth,
                calls,
                state: &self.state,
                cycles: &self.cycles,
                tools: &self.tool_table,
                tools_without_data: &self.tools_without_data,
            });
            self.watcher = Some(w);
        }
        self.settle(result)
    }
}
