//! Where control flow can go in one program: sequence numbers, labels,
//! subroutines, and which closer belongs to which opener. Built once per
//! program before it runs.

use crate::ir::{Block, CallTarget, FlowId, Program, StmtKind};
use std::collections::{HashMap, HashSet};

use crate::ir::FlowKind as Kind;

#[derive(Clone, Debug, Default)]
pub struct FlowIndex {
    /// Sequence number → first block with it.
    pub seq: HashMap<u32, Vec<usize>>,
    /// Label (upper case) → block.
    pub labels: HashMap<String, usize>,
    /// Subroutine name (o-word `100`, `<name>`, Siemens PROC) → its SubStart block.
    pub subs: HashMap<String, usize>,
    /// Program number (Fanuc `O1234`) → its ProgramStart block.
    pub programs: HashMap<u32, usize>,
    /// Opener → its closer (If → EndIf, While → EndWhile, ...), and each
    /// closer → its opener.
    pub partner: HashMap<usize, usize>,
    /// If (or ElseIf/Else) → the next branch of the same if (ElseIf, Else or EndIf).
    pub next_branch: HashMap<usize, usize>,
    /// Any block inside a loop → the innermost loop's opener (for break/continue).
    pub loop_of: HashMap<usize, usize>,
}

fn flow_key(kind: Kind, id: &FlowId) -> (Kind, FlowId) {
    (kind, id.clone())
}

impl FlowIndex {
    /// One pass over the blocks, linear in their number whatever the
    /// nesting depth: openers are found by key, the innermost loop is the
    /// top of a stack of loops.
    pub fn build(p: &Program) -> FlowIndex {
        let mut ix = FlowIndex::default();
        let mut open = OpenStack::default();
        let mut last_branch: HashMap<usize, usize> = HashMap::new();
        for (i, b) in p.blocks.iter().enumerate() {
            ix.note_targets(i, b);
            if let Some(top) = open.innermost_loop() {
                ix.loop_of.insert(i, top);
            }
            for s in &b.stmts {
                ix.structure(i, &s.kind, &mut open, &mut last_branch);
            }
        }
        ix
    }

    fn note_targets(&mut self, i: usize, b: &Block) {
        if let Some(n) = &b.number {
            self.seq.entry(n.node).or_default().push(i);
        }
        if let Some(l) = &b.label {
            self.labels.entry(l.node.to_ascii_uppercase()).or_insert(i);
        }
        for s in &b.stmts {
            match &s.kind {
                StmtKind::SubStart { name, .. } => {
                    self.subs.entry(name.to_ascii_lowercase()).or_insert(i);
                }
                StmtKind::ProgramStart {
                    number: Some(n), ..
                } => {
                    self.programs.entry(*n).or_insert(i);
                }
                _ => {}
            }
        }
    }

    fn structure(
        &mut self,
        i: usize,
        kind: &StmtKind,
        stack: &mut OpenStack,
        last_branch: &mut HashMap<usize, usize>,
    ) {
        use StmtKind::*;
        let open = |k: Kind, id: &FlowId, stack: &mut OpenStack| stack.push(k, id, i);
        match kind {
            If { id, .. } => open(Kind::If, id, stack),
            While { id, .. } => open(Kind::While, id, stack),
            Do { id } => open(Kind::Do, id, stack),
            Repeat { id, .. } => open(Kind::Repeat, id, stack),
            For { .. } => open(Kind::For, &FlowId::Nested, stack),
            Loop => open(Kind::Loop, &FlowId::Nested, stack),
            RepeatUntil => open(Kind::RepeatUntil, &FlowId::Nested, stack),
            SubStart { id, .. } => open(Kind::Sub, id, stack),
            ElseIf { id, .. } | Else { id } => {
                if let Some(o) = stack.find(Kind::If, id) {
                    let from = last_branch.get(&o).copied().unwrap_or(o);
                    self.next_branch.insert(from, i);
                    last_branch.insert(o, i);
                }
            }
            EndIf { id } => self.close(i, Kind::If, id, stack, Some(last_branch)),
            EndWhile { id } => self.close(i, Kind::While, id, stack, None),
            DoWhile { id, .. } => self.close(i, Kind::Do, id, stack, None),
            EndRepeat { id } => self.close(i, Kind::Repeat, id, stack, None),
            EndFor => self.close(i, Kind::For, &FlowId::Nested, stack, None),
            EndLoop => self.close(i, Kind::Loop, &FlowId::Nested, stack, None),
            Until { .. } => self.close(i, Kind::RepeatUntil, &FlowId::Nested, stack, None),
            SubEnd { id, .. } => self.close(i, Kind::Sub, id, stack, None),
            _ => {}
        }
    }

    fn close(
        &mut self,
        i: usize,
        kind: Kind,
        id: &FlowId,
        stack: &mut OpenStack,
        last_branch: Option<&mut HashMap<usize, usize>>,
    ) {
        let Some(o) = stack.close(kind, id) else {
            return;
        };
        self.partner.insert(o, i);
        self.partner.insert(i, o);
        if let Some(lb) = last_branch {
            let from = lb.remove(&o).unwrap_or(o);
            self.next_branch.insert(from, i);
        }
    }

    /// The block a subprogram call goes to, if it is in this program.
    pub fn call_target(&self, t: &CallTarget) -> Option<usize> {
        match t {
            CallTarget::Number(n) => self
                .programs
                .get(n)
                .or_else(|| self.subs.get(&n.to_string()))
                .copied(),
            CallTarget::Name(s) => self.subs.get(&s.to_ascii_lowercase()).copied(),
            CallTarget::Computed(_) => None,
        }
    }
}

/// The openers not yet closed. A closer closes the innermost open opener
/// of its kind and id, which need not be the innermost of all (a stray
/// closer skips over others), so openers are kept per key; the loops are
/// kept in opening order with closed ones dropped when they reach the top.
#[derive(Default)]
struct OpenStack {
    /// (kind, id) → its open openers (serial, block), innermost last.
    by_key: HashMap<(Kind, FlowId), Vec<(usize, usize)>>,
    /// Loop openers (serial, block) in opening order, some perhaps closed.
    loops: Vec<(usize, usize)>,
    /// Serials of loop openers closed but still in `loops`.
    closed_loops: HashSet<usize>,
    /// Openers pushed so far (a block may open more than one).
    serial: usize,
}

impl OpenStack {
    fn push(&mut self, kind: Kind, id: &FlowId, block: usize) {
        self.serial += 1;
        let entry = (self.serial, block);
        self.by_key
            .entry(flow_key(kind, id))
            .or_default()
            .push(entry);
        if kind.is_loop() {
            self.loops.push(entry);
        }
    }

    /// The innermost open opener of this kind and id.
    fn find(&self, kind: Kind, id: &FlowId) -> Option<usize> {
        self.by_key.get(&flow_key(kind, id))?.last().map(|e| e.1)
    }

    /// Closes the innermost open opener of this kind and id.
    fn close(&mut self, kind: Kind, id: &FlowId) -> Option<usize> {
        let (serial, o) = self.by_key.get_mut(&flow_key(kind, id))?.pop()?;
        if kind.is_loop() {
            self.closed_loops.insert(serial);
        }
        Some(o)
    }

    /// The innermost loop still open (amortised constant time).
    fn innermost_loop(&mut self) -> Option<usize> {
        while let Some(&(serial, top)) = self.loops.last() {
            if !self.closed_loops.remove(&serial) {
                return Some(top);
            }
            self.loops.pop();
        }
        None
    }
}

#[cfg(test)]
#[path = "index_tests.rs"]
mod tests;
