//! Which part of the program to replace by what it does: the smallest
//! run of main-program blocks around a construct the target cannot
//! express that the program enters once at its top, leaves once at its
//! bottom, and starts and ends in a plain modal state (no cutter
//! compensation, no modal cycle). A construct inside a subprogram is
//! replaced at each call; the subprogram's definition then goes.

use super::trace::Trace;
use crate::ir::{Program, StmtKind};

/// Blocks `a..=b` of the main program, run as steps `first..=last`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Range {
    pub a: usize,
    pub b: usize,
    pub first: usize,
    pub last: usize,
}

/// Where each structured construct (IF .. ENDIF, loops, subroutine
/// definitions) starts and ends, by block.
pub struct Structure {
    /// The innermost construct around or opened/closed by each block.
    around: Vec<Option<(usize, usize)>>,
}

fn opens(k: &StmtKind) -> bool {
    use StmtKind::*;
    matches!(
        k,
        If { .. }
            | While { .. }
            | Do { .. }
            | Repeat { .. }
            | For { .. }
            | Loop
            | RepeatUntil
            | SubStart { .. }
    )
}

fn closes(k: &StmtKind) -> bool {
    use StmtKind::*;
    matches!(
        k,
        EndIf { .. }
            | EndWhile { .. }
            | DoWhile { .. }
            | EndRepeat { .. }
            | EndFor
            | EndLoop
            | Until { .. }
            | SubEnd { .. }
    )
}

impl Structure {
    pub fn of(p: &Program) -> Structure {
        let n = p.blocks.len();
        let mut around = vec![None; n];
        let mut stack: Vec<usize> = Vec::new();
        for (i, b) in p.blocks.iter().enumerate() {
            let (o, c) = (
                b.stmts.iter().any(|s| opens(&s.kind)),
                b.stmts.iter().any(|s| closes(&s.kind)),
            );
            if c {
                if let Some(s) = stack.pop() {
                    for slot in &mut around[s..=i] {
                        if slot.is_none() {
                            *slot = Some((s, i));
                        }
                    }
                }
            }
            if o && !c {
                stack.push(i);
            }
        }
        Structure { around }
    }

    fn around(&self, i: usize) -> Option<(usize, usize)> {
        self.around.get(i).copied().flatten()
    }

    fn is_flow(&self, i: usize) -> bool {
        self.around(i).is_some_and(|(s, e)| s == i || e == i)
    }
}

/// Grows `a..=b` until it can be replaced, or says why it cannot.
pub fn grow(t: &Trace, st: &Structure, mut a: usize, mut b: usize) -> Result<Range, String> {
    for _ in 0..10_000 {
        let (na, nb) = widen(t, st, a, b)?;
        if (na, nb) == (a, b) {
            return finish(t, a, b);
        }
        (a, b) = (na, nb);
    }
    Err("the part around it does not settle into one run".into())
}

fn steps_in(t: &Trace, a: usize, b: usize) -> Option<(usize, usize)> {
    let inside = |k: &usize| (a..=b).contains(&t.steps[*k].pc);
    let ks = 0..t.steps.len();
    let first = ks.clone().find(|k| inside(k))?;
    let last = ks.rev().find(|k| inside(k))?;
    Some((first, last))
}

/// One round of widening.
fn widen(t: &Trace, st: &Structure, a: usize, b: usize) -> Result<(usize, usize), String> {
    let (mut na, mut nb) = (a, b);
    // A flow statement takes its whole construct with it.
    for i in a..=b {
        if st.is_flow(i) {
            let (s, e) = st.around(i).unwrap_or((i, i));
            (na, nb) = (na.min(s), nb.max(e));
        }
    }
    let Some((k0, k1)) = steps_in(t, a, b) else {
        // Never run at the top: take the construct around it.
        return match st.around(a) {
            Some((s, e)) if (s, e) != (a, b) => Ok((na.min(s), nb.max(e))),
            // Jumped over: take the block that jumped.
            _ => match t.steps.iter().map(|s| s.pc).filter(|&pc| pc < a).max() {
                Some(prev) => Ok((prev, nb)),
                None => Err("it never runs".into()),
            },
        };
    };
    // Everything run between the first and the last visit.
    for s in &t.steps[k0..=k1] {
        (na, nb) = (na.min(s.pc), nb.max(s.pc));
    }
    // Entered by falling into its first block.
    if k0 > 0 {
        let prev = t.steps[k0 - 1].pc;
        if prev + 1 != a && prev + 1 != na {
            (na, nb) = (na.min(prev), nb.max(prev));
        }
        if !t.steps[k0].before.is_plain() {
            na = na.min(prev);
        }
    }
    // Left by falling out of its last block.
    if let Some(next) = t.steps.get(k1 + 1).map(|s| s.pc) {
        if next < na {
            na = next;
        } else if next > nb + 1 {
            nb = next - 1;
        }
        let shift = t.steps[k0].before.g92;
        match t.after(k1) {
            Some(m) if m.is_plain() && m.g92 == shift => {}
            // It ends unshifted but began inside a shift: take the block
            // that made the shift too.
            Some(m) if m.is_plain() && m.g92 == [0.0; 9] && k0 > 0 => {
                na = na.min(t.steps[k0 - 1].pc)
            }
            _ => nb = nb.max(next),
        }
    } else if !t.after(k1).is_some_and(|m| m.is_plain()) {
        return Err("the program ends in cutter compensation or a modal cycle".into());
    }
    Ok((na, nb))
}

fn finish(t: &Trace, a: usize, b: usize) -> Result<Range, String> {
    let Some((first, last)) = steps_in(t, a, b) else {
        return Err("it never runs".into());
    };
    if let Some(k) = t.stopped {
        if k <= last {
            return Err(
                "the run stops before it is done (an error or a value known only at run time)"
                    .into(),
            );
        }
    }
    if !t.steps[first].before.is_plain() {
        return Err("it starts in cutter compensation or a modal cycle".into());
    }
    let comp = |k: usize| t.steps[k].before.comp != crate::ir::CompSide::Off;
    if (first..=last).any(comp) {
        return Err("cutter radius compensation is on in it: its path depends on the radius the machine's tool has, which moves cannot carry".into());
    }
    Ok(Range { a, b, first, last })
}

/// The definition a subprogram block `j` belongs to: its `PROC`/`sub`
/// .. end, or from its `O`/label start to the next program start.
pub fn definition(p: &Program, st: &Structure, t: &Trace, j: usize) -> Option<(usize, usize)> {
    if let Some((s, e)) = st.around(j) {
        if p.blocks[s]
            .stmts
            .iter()
            .any(|x| matches!(x.kind, StmtKind::SubStart { .. }))
        {
            return Some((s, e));
        }
    }
    let top: std::collections::HashSet<usize> = t.steps.iter().map(|s| s.pc).collect();
    let starts = |i: usize| {
        let b = &p.blocks[i];
        b.label.is_some()
            || b.stmts.iter().any(|x| {
                matches!(
                    x.kind,
                    StmtKind::ProgramStart { .. } | StmtKind::SubStart { .. }
                )
            })
    };
    let ends = |i: usize| {
        p.blocks[i]
            .stmts
            .iter()
            .any(|x| matches!(x.kind, StmtKind::ProgramEnd { .. }))
    };
    let mut s = j;
    while !starts(s) {
        if s == 0 || top.contains(&(s - 1)) {
            break;
        }
        s -= 1;
    }
    if top.contains(&s) {
        return None;
    }
    let mut e = j;
    while e + 1 < p.blocks.len() && !starts(e + 1) && !ends(e + 1) && !top.contains(&(e + 1)) {
        e += 1;
    }
    Some((s, e))
}
