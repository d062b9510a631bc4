//! The program walker: runs blocks one after another and follows control
//! flow (jumps, IF/WHILE/FOR/REPEAT/LOOP, o-words, subprogram and macro
//! calls, Siemens section repeats), with every loop and call bounded.

use super::index::FlowIndex;
use super::{Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    Arena, CallArgs, CallKind, CallTarget, Expr, ExprId, FlowId, JumpDir, JumpTarget, Program,
    Stmt, StmtKind, Value, Var,
};
use std::collections::HashMap;

/// Finds programs that a call names but this file does not hold
/// (`o<name> call` → `name.ngc`, `M98 P1000` → `O1000.nc` beside it).
pub trait ProgramLoader {
    fn load(&mut self, target: &CallTarget) -> Option<std::rc::Rc<Program>>;
}

/// No other files.
pub struct NoLoader;

impl ProgramLoader for NoLoader {
    fn load(&mut self, _: &CallTarget) -> Option<std::rc::Rc<Program>> {
        None
    }
}

/// Numbered parameters a call sets, with their values (`None`: vacant).
type ArgValues = Vec<(u32, Option<f64>)>;

/// A place to return to.
struct Frame {
    prog: usize,
    ret: usize,
    /// Numbered locals saved at the call (restored on return).
    saved: Vec<(u32, Option<f64>)>,
    new_scope: bool,
    /// For a section repeat: its first and last block and the passes left.
    section: Option<(usize, usize, u64)>,
    /// A repeated call (`M98 P.. L3`): where it starts and the passes left.
    repeat: Option<((usize, usize), u64)>,
    /// The frame of a `G66` modal macro call.
    modal: bool,
    /// The statement that made the call (shown with errors inside it).
    call_span: crate::span::Span,
    /// The contour subroutine of a lathe profile cycle: its return makes
    /// the cycle's passes ([`super::lathe_cycles`]).
    profile: bool,
}

struct Loaded {
    program: std::rc::Rc<Program>,
    index: std::rc::Rc<FlowIndex>,
}

/// Walks programs; program 0 is the main one.
pub struct Walker<'l> {
    progs: Vec<Loaded>,
    loader: &'l mut dyn ProgramLoader,
    frames: Vec<Frame>,
    loop_counts: HashMap<(usize, usize), u64>,
    repeat_left: HashMap<(usize, usize), u64>,
    blocks_run: u64,
    started_with_percent: bool,
    /// The active `G66` modal macro: its target and argument values.
    modal: Option<(CallTarget, ArgValues)>,
    /// Where the main program starts (after a streamed beginning).
    start: usize,
    /// The file is a subprogram run alone: a return with no caller ends
    /// the run (it goes back to the caller cncc does not have).
    called: bool,
    /// Sub definitions rs274 has recorded (passed in sequence or found by
    /// a call), by program and block: see [`super::sub_styles`].
    known_defs: std::collections::HashSet<(usize, usize)>,
    /// The main program's plain moves held as text (see [`super::lazy`]).
    lazy: Option<super::lazy::LazyBlocks<'l>>,
}

/// What a block asks the walker to do next.
enum Next {
    Step,
    Jump(usize),
    /// Enter a branch (If/ElseIf/Else/EndIf) by a jump.
    Enter(usize),
    Call {
        prog: usize,
        at: usize,
        frame: Frame,
    },
    Return,
    End,
}

impl<'l> Walker<'l> {
    pub fn new(main: std::rc::Rc<Program>, loader: &'l mut dyn ProgramLoader) -> Self {
        let index = std::rc::Rc::new(FlowIndex::build(&main));
        Walker {
            progs: vec![Loaded {
                program: main,
                index,
            }],
            loader,
            frames: Vec::new(),
            loop_counts: HashMap::new(),
            repeat_left: HashMap::new(),
            blocks_run: 0,
            started_with_percent: false,
            modal: None,
            start: 0,
            called: false,
            known_defs: Default::default(),
            lazy: None,
        }
    }

    /// Walks a main program read by [`super::lazy::read_program_lazy`].
    pub fn with_lazy(mut self, lazy: super::lazy::LazyBlocks<'l>) -> Self {
        self.lazy = Some(lazy);
        self
    }

    /// The main program's first block with statements (a stub has them).
    fn first_content_block(&self) -> usize {
        let stub = |i: usize| self.lazy.as_ref().is_some_and(|l| l.is_stub(i));
        self.progs[0]
            .program
            .blocks
            .iter()
            .enumerate()
            .position(|(i, b)| !b.stmts.is_empty() || stub(i))
            .unwrap_or(0)
    }

    /// Block `pc` of the main program as the walker runs it, where it is
    /// a stub (see [`super::lazy`]).
    fn stub_block(
        &mut self,
        prog: usize,
        pc: usize,
        stub: &crate::ir::Block,
    ) -> Option<std::rc::Rc<crate::ir::Block>> {
        let lazy = self.lazy.as_mut().filter(|l| prog == 0 && l.is_stub(pc))?;
        lazy.fetch(pc, stub)
    }

    /// Runs the file as a subprogram checked alone (see `called`).
    pub fn run_as_called(&mut self) {
        self.called = true;
    }

    /// Starts at block `at` of the main program, after `blocks` blocks
    /// were run in sequence (see [`super::stream`]).

    pub fn resume(&mut self, at: usize, started_with_percent: bool, blocks: u64) {
        self.start = at;
        self.started_with_percent = started_with_percent;
        self.blocks_run = blocks;
    }

    /// Runs the main program to its end or first error; an error inside a
    /// subprogram also shows where it was called from.
    pub fn run(&mut self, it: &mut Interp<'_, '_>) -> Result<(), Stop> {
        match self.walk(it) {
            Err(Stop::Error(mut d)) => {
                let mut shown: Vec<crate::span::Span> = d.labels.iter().map(|l| l.span).collect();
                for f in self.frames.iter().rev().filter(|f| f.section.is_none()) {
                    if shown.len() < 8 && !shown.contains(&f.call_span) {
                        shown.push(f.call_span);
                        d = d.secondary(f.call_span, "called from here");
                    }
                }
                Err(Stop::Error(d))
            }
            r => r,
        }
    }

    fn walk(&mut self, it: &mut Interp<'_, '_>) -> Result<(), Stop> {
        let (mut prog, mut pc) = (0usize, self.start);
        let mut entered = false;
        loop {
            let program = self.progs[prog].program.clone();
            let Some(stored) = program.blocks.get(pc) else {
                if self.frames.is_empty() || prog == 0 {
                    return Ok(());
                }
                (prog, pc) = self.pop_frame(it);
                continue;
            };
            let unstubbed = self.stub_block(prog, pc, stored);
            let block = unstubbed.as_deref().unwrap_or(stored);
            self.count_block(it, block.span)?;
            if block.skip.is_some() && it.opts.block_delete {
                pc += 1;
                continue;
            }
            if let Some(at) = self.section_end(it, prog, pc)? {
                (prog, pc) = at;
                continue;
            }
            observe(it, prog, pc, self.frames.len());
            it.hold();
            let next = self.block(it, prog, pc, block, entered);
            let next = match it.settle_block(next, block, &program.exprs, self.frames.len()) {
                Err(stop) => {
                    it.recover(stop)?;
                    Next::Step
                }
                Ok(next) => next,
            };
            entered = false;
            match next {
                Next::Step => pc += 1,
                Next::Jump(to) => pc = to,
                Next::Enter(to) => {
                    pc = to;
                    entered = true;
                }
                Next::Call { prog: p, at, frame } => {
                    if self.frames.len() as u32 >= it.opts.limits.call_depth {
                        return Err(limit(it, "call nesting deeper than the limit", "a subprogram probably calls itself without end; raise --max-depth if the program is right"));
                    }
                    self.frames.push(frame);
                    (prog, pc) = (p, at);
                }
                Next::Return => {
                    if self.frames.is_empty() {
                        return Ok(());
                    }
                    if let Some(at) = self.repeat_again(it)? {
                        (prog, pc) = at;
                        continue;
                    }
                    let profile = self.frames.last().is_some_and(|f| f.profile);
                    (prog, pc) = self.pop_frame(it);
                    if profile {
                        super::lathe_cycles::finish(it)?;
                    }
                }
                Next::End => return Err(Stop::End),
            }
        }
    }

    fn count_block(&mut self, it: &Interp<'_, '_>, span: crate::span::Span) -> Result<(), Stop> {
        self.blocks_run += 1;
        if self.blocks_run > it.opts.limits.blocks {
            return Err(Stop::Error(
                Diagnostic::new(Code::LimitExceeded, "more blocks run than the limit")
                    .primary(span, "here"),
            ));
        }
        Ok(())
    }

    /// A repeated call that has passes left: its start again.
    fn repeat_again(&mut self, it: &Interp<'_, '_>) -> Result<Option<(usize, usize)>, Stop> {
        let Some(f) = self.frames.last_mut() else {
            return Ok(None);
        };
        let Some((at, left)) = f.repeat else {
            return Ok(None);
        };
        if left <= 1 {
            return Ok(None);
        }
        f.repeat = Some((at, left - 1));
        self.count_loop(it, at.0, at.1)?;
        Ok(Some(at))
    }

    fn pop_frame(&mut self, it: &mut Interp<'_, '_>) -> (usize, usize) {
        let f = self.frames.pop().expect("frame");
        for (n, v) in f.saved {
            it.params.set_numbered(n, v);
        }
        if f.new_scope {
            it.params.pop_scope();
        }
        (f.prog, f.ret)
    }

    /// Runs one block: machine statements first (in Table 8 order), then
    /// assignments, then control flow.
    fn block(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        block: &crate::ir::Block,
        entered: bool,
    ) -> Result<Next, Stop> {
        let program = self.progs[prog].program.clone();
        let exprs = &program.exprs;
        // A sub definition met in sequence is skipped, not run.
        if let Some(s) = block
            .stmts
            .iter()
            .find(|s| matches!(s.kind, StmtKind::SubStart { .. }))
        {
            it.span = s.span;
            let known = !self.known_defs.insert((prog, pc));
            super::sub_styles::check_reached(it, block, known)?;
            return Ok(match self.progs[prog].index.partner.get(&pc) {
                Some(&end) => Next::Jump(end + 1),
                None => Next::Step,
            });
        }
        it.line = pc as u32 + 1;
        let ends = |s: &Stmt| matches!(s.kind, StmtKind::ProgramEnd { .. });
        if !self.frames.is_empty() && block.stmts.iter().any(ends) {
            // Heidenhain `END PGM` of a program called by `CALL PGM`: back
            // to the caller.
            super::heidenhain::flush(it)?;
            return Ok(Next::Return);
        }
        if it.lathe.reading() {
            let mut run = it
                .lathe
                .running
                .take()
                .expect("a cycle reading its contour");
            let r = super::lathe_profile::record(it, &mut run.contour, block, exprs);
            it.lathe.running = Some(run);
            r?;
        } else {
            it.block(block, exprs)?;
            if let Some(q) = it.lathe.take_call() {
                return self.profile_call(it, prog, pc, q);
            }
        }
        self.assignments(it, &block.stmts, exprs)?;
        for s in &block.stmts {
            it.span = s.span;
            if let Some(n) = self.control(it, prog, pc, s, exprs, entered)? {
                return Ok(n);
            }
        }
        if it.ended {
            return Ok(Next::End);
        }
        self.modal_call(it, prog, pc, block)
    }

    /// A lathe profile cycle's block: its contour subroutine is called,
    /// and read instead of run.
    fn profile_call(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        q: u32,
    ) -> Result<Next, Stop> {
        let target = CallTarget::Number(q);
        let mut next = self.enter(it, prog, pc, CallKind::OWord, &target, Vec::new(), 1)?;
        match &mut next {
            Next::Call { frame, .. } => frame.profile = true,
            _ => {
                it.lathe.running = None;
            }
        }
        Ok(next)
    }

    /// The `G66` hook: after a block that moves (and not inside the modal
    /// macro itself), the modal macro is called with its arguments.
    fn modal_call(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        block: &crate::ir::Block,
    ) -> Result<Next, Stop> {
        let Some((target, values)) = self.modal.clone() else {
            return Ok(Next::Step);
        };
        let moves = block
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::Motion(_)));
        if !moves || self.frames.iter().any(|f| f.modal) {
            return Ok(Next::Step);
        }
        let mut next = self.enter(it, prog, pc, CallKind::Macro, &target, values, 1)?;
        if let Next::Call { frame, .. } = &mut next {
            frame.modal = true;
        }
        Ok(next)
    }

    /// Evaluates every assignment's value first, then sets them all.
    fn assignments(
        &mut self,
        it: &mut Interp<'_, '_>,
        stmts: &[Stmt],
        exprs: &Arena<Expr>,
    ) -> Result<(), Stop> {
        let mut sets = Vec::new();
        for s in stmts {
            if let StmtKind::Assign { var, value } = &s.kind {
                it.span = s.span;
                sets.push((var, it.eval(*value, exprs)?, s.span));
            }
        }
        for (var, v, span) in sets {
            it.span = span;
            assign(it, var, v, exprs)?;
        }
        Ok(())
    }

    /// A section repeat that reached the end of its section: the section
    /// again, or back after the `REPEAT` when no passes are left.
    fn section_end(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
    ) -> Result<Option<(usize, usize)>, Stop> {
        let Some(f) = self.frames.last_mut() else {
            return Ok(None);
        };
        let Some((start, end, left)) = f.section else {
            return Ok(None);
        };
        if f.prog != prog || pc != end + 1 {
            return Ok(None);
        }
        if left > 1 {
            f.section = Some((start, end, left - 1));
            self.count_loop(it, prog, start)?;
            return Ok(Some((prog, start)));
        }
        Ok(Some(self.pop_frame(it)))
    }

    /// Siemens `REPEAT start [end] P=n` / `REPEATB label P=n`: runs the
    /// section n times, then goes on after the `REPEAT`. Without an end
    /// label the section ends just before the `REPEAT`.
    fn section_repeat(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        s: &Stmt,
        exprs: &Arena<Expr>,
    ) -> Result<Next, Stop> {
        let StmtKind::SectionRepeat {
            start,
            end,
            count,
            single,
        } = &s.kind
        else {
            return Ok(Next::Step);
        };
        let ix = self.progs[prog].index.clone();
        let find = |l: &str| ix.labels.get(&l.to_ascii_uppercase()).copied();
        let Some(first) = find(start) else {
            return Err(it.error_at(
                s.span,
                Code::JumpTargetMissing,
                format!("REPEAT: label {start} not found"),
            ));
        };
        let last = match (end, single) {
            (_, true) => first,
            (Some(e), false) => match find(e) {
                Some(i) => i,
                None => {
                    return Err(it.error_at(
                        s.span,
                        Code::JumpTargetMissing,
                        format!("REPEAT: label {e} not found"),
                    ))
                }
            },
            (None, false) => pc.saturating_sub(1),
        };
        let n = match count {
            Some(c) => it.eval(*c, exprs)?.unwrap_or(0.0).round().max(0.0) as u64,
            None => 1,
        };
        if n == 0 || last < first || (first <= pc && pc <= last) {
            return Ok(Next::Step);
        }
        let frame = Frame {
            prog,
            ret: pc + 1,
            saved: Vec::new(),
            new_scope: false,
            section: Some((first, last, n)),
            repeat: None,
            modal: false,
            call_span: s.span,
            profile: false,
        };
        Ok(Next::Call {
            prog,
            at: first,
            frame,
        })
    }

    fn control(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        s: &Stmt,
        exprs: &Arena<Expr>,
        entered: bool,
    ) -> Result<Option<Next>, Stop> {
        use StmtKind::*;
        let ix = self.progs[prog].index.clone();
        let after = |i: Option<&usize>| i.map(|&e| Next::Jump(e + 1));
        Ok(match &s.kind {
            Goto { target, dir, cond } => {
                if let Some(c) = cond {
                    if !truth(it.eval(*c, exprs)?) {
                        return Ok(None);
                    }
                    it.last_jump = Some(s.span);
                }
                Some(self.jump(it, prog, pc, target, *dir, exprs)?)
            }
            IfThen { cond, then } => {
                if truth(it.eval(*cond, exprs)?) {
                    if let Assign { var, value } = &then.kind {
                        let v = it.eval(*value, exprs)?;
                        assign(it, var, v, exprs)?;
                    } else {
                        return Ok(Some(
                            self.control(it, prog, pc, then, exprs, false)?
                                .unwrap_or(Next::Step),
                        ));
                    }
                }
                None
            }
            If { cond, .. } => {
                if truth(it.eval(*cond, exprs)?) {
                    None
                } else {
                    ix.next_branch.get(&pc).map(|&b| Next::Enter(b))
                }
            }
            ElseIf { cond, .. } => {
                if !entered {
                    Some(Next::Jump(end_of_if(&ix, pc) + 1))
                } else if truth(it.eval(*cond, exprs)?) {
                    None
                } else {
                    ix.next_branch.get(&pc).map(|&b| Next::Enter(b))
                }
            }
            Else { .. } => (!entered).then(|| Next::Jump(end_of_if(&ix, pc) + 1)),
            EndIf { .. } | Do { .. } | RepeatUntil | Loop => None,
            While { cond, .. } => {
                if truth(it.eval(*cond, exprs)?) {
                    self.count_loop(it, prog, pc)?;
                    None
                } else {
                    self.loop_done(prog, pc);
                    after(ix.partner.get(&pc))
                }
            }
            EndWhile { .. } => ix.partner.get(&pc).map(|&o| Next::Jump(o)),
            DoWhile { cond, .. } => {
                if truth(it.eval(*cond, exprs)?) {
                    self.count_loop(it, prog, pc)?;
                    ix.partner.get(&pc).map(|&o| Next::Jump(o + 1))
                } else {
                    self.loop_done(prog, pc);
                    None
                }
            }
            Until { cond } => {
                if truth(it.eval(*cond, exprs)?) {
                    self.loop_done(prog, pc);
                    None
                } else {
                    self.count_loop(it, prog, pc)?;
                    ix.partner.get(&pc).map(|&o| Next::Jump(o + 1))
                }
            }
            EndLoop => {
                self.count_loop(it, prog, pc)?;
                ix.partner.get(&pc).map(|&o| Next::Jump(o + 1))
            }
            Repeat { count, .. } => {
                let n = it.eval(*count, exprs)?.unwrap_or(0.0).round().max(0.0) as u64;
                if n == 0 {
                    after(ix.partner.get(&pc))
                } else {
                    self.repeat_left.insert((prog, pc), n);
                    None
                }
            }
            EndRepeat { .. } => {
                let Some(&o) = ix.partner.get(&pc) else {
                    return Ok(None);
                };
                let left = self
                    .repeat_left
                    .get(&(prog, o))
                    .copied()
                    .unwrap_or(1)
                    .saturating_sub(1);
                self.repeat_left.insert((prog, o), left);
                if left > 0 {
                    self.count_loop(it, prog, o)?;
                    Some(Next::Jump(o + 1))
                } else {
                    self.loop_done(prog, o);
                    None
                }
            }
            For { var, from, to } => {
                let from = it.eval(*from, exprs)?.unwrap_or(0.0);
                let to_v = it.eval(*to, exprs)?.unwrap_or(0.0);
                assign(it, var, Some(from), exprs)?;
                if from > to_v {
                    after(ix.partner.get(&pc))
                } else {
                    None
                }
            }
            EndFor => {
                let Some(&o) = ix.partner.get(&pc) else {
                    return Ok(None);
                };
                let p = self.progs[prog].program.clone();
                let Some(StmtKind::For { var, to, .. }) = p.blocks[o]
                    .stmts
                    .iter()
                    .map(|s| &s.kind)
                    .find(|k| matches!(k, StmtKind::For { .. }))
                else {
                    return Ok(None);
                };
                let v = read_var(it, var, exprs)? + 1.0;
                assign(it, var, Some(v), exprs)?;
                if v <= it.eval(*to, exprs)?.unwrap_or(0.0) {
                    self.count_loop(it, prog, o)?;
                    Some(Next::Jump(o + 1))
                } else {
                    self.loop_done(prog, o);
                    None
                }
            }
            Break { .. } => {
                let o = ix.loop_of.get(&pc).copied();
                let e = o.and_then(|o| ix.partner.get(&o).copied());
                for k in [o, e].into_iter().flatten() {
                    self.loop_done(prog, k);
                }
                e.map(|e| Next::Jump(e + 1))
            }
            Continue { .. } => ix
                .loop_of
                .get(&pc)
                .and_then(|o| ix.partner.get(o))
                .map(|&e| Next::Jump(e)),
            Case {
                selector,
                arms,
                default,
            } => {
                let v = it.eval(*selector, exprs)?.unwrap_or(0.0);
                let mut chosen = None;
                for arm in arms {
                    if it.eval(arm.value, exprs)?.unwrap_or(0.0) == v {
                        chosen = Some((arm.target.clone(), arm.dir));
                        break;
                    }
                }
                match chosen.or_else(|| default.clone()) {
                    Some((label, dir)) => {
                        Some(self.jump(it, prog, pc, &JumpTarget::Label(label), dir, exprs)?)
                    }
                    None => None,
                }
            }
            SubEnd { value, .. } | Return { value, .. } => {
                // Without a value LinuxCNC sets `_value` to 0 (retval.ngc).
                let v = match value {
                    Some(v) => it.eval(*v, exprs)?.unwrap_or(0.0),
                    None => 0.0,
                };
                it.params.set_named("_value", v);
                it.params
                    .set_named("_value_returned", value.is_some() as i64 as f64);
                Some(Next::Return)
            }
            ModalMacroCancel => {
                self.modal = None;
                None
            }
            Declare { vars, .. } => {
                for v in vars {
                    machine_sized(it, v);
                    let val = match v.init {
                        Some(e) => it.eval(e, exprs)?.unwrap_or(0.0),
                        None => 0.0,
                    };
                    it.params.declare_user(&v.name, val);
                }
                None
            }
            SubReturn { to } => Some(self.sub_return(it, to.as_ref(), (prog, pc), exprs)?),
            Call {
                kind,
                target,
                args,
                repeat,
            } => Some(self.call(it, prog, pc, *kind, target, args, repeat.as_ref(), exprs)?),
            SectionRepeat { .. } => Some(self.section_repeat(it, prog, pc, s, exprs)?),
            Tape => {
                if prog == 0 && pc == self.first_content_block() {
                    self.started_with_percent = true;
                    None
                } else if self.started_with_percent && prog == 0 {
                    super::machine::finish_sequence(it);
                    Some(Next::End)
                } else {
                    None
                }
            }
            _ => None,
        })
    }

    /// A loop that ended: its next run counts from zero again.
    fn loop_done(&mut self, prog: usize, at: usize) {
        self.loop_counts.remove(&(prog, at));
    }

    fn count_loop(&mut self, it: &Interp<'_, '_>, prog: usize, at: usize) -> Result<(), Stop> {
        let c = self.loop_counts.entry((prog, at)).or_insert(0);
        *c += 1;
        if *c > it.opts.limits.loop_iterations {
            return Err(limit(
                it,
                "a loop ran more times than the limit",
                "the program probably loops forever; raise --max-loop if it is right",
            ));
        }
        Ok(())
    }

    fn jump(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        target: &JumpTarget,
        dir: JumpDir,
        exprs: &Arena<Expr>,
    ) -> Result<Next, Stop> {
        let ix = self.progs[prog].index.clone();
        let found = match target {
            JumpTarget::Sequence(v) => {
                let n = it.value(v, exprs)?.round() as u32;
                let list = ix.seq.get(&n).cloned().unwrap_or_default();
                pick(&list, pc, dir)
            }
            JumpTarget::Label(l) => {
                let key = l.to_ascii_uppercase();
                ix.labels.get(&key).copied().filter(|&i| match dir {
                    JumpDir::Forward => i > pc,
                    JumpDir::Backward => i <= pc,
                    _ => true,
                })
            }
        };
        match found {
            Some(i) => {
                if i <= pc {
                    self.count_loop(it, prog, pc)?;
                }
                Ok(Next::Jump(i))
            }
            None if dir == JumpDir::EitherNoAlarm => Ok(Next::Step),
            None => Err(it.error_at(it.span, Code::JumpTargetMissing, "jump target not found")),
        }
    }

    fn sub_return(
        &mut self,
        it: &mut Interp<'_, '_>,
        to: Option<&Value>,
        (prog, pc): (usize, usize),
        exprs: &Arena<Expr>,
    ) -> Result<Next, Stop> {
        if self.frames.is_empty()
            && it
                .spec
                .has(crate::dialect::Capability::SubEndInMainContinues)
        {
            // Heidenhain `LBL 0` met in the main program: it goes on.
            return Ok(Next::Step);
        }
        if self.frames.is_empty() && self.called {
            // The end of a subprogram checked alone: back to its caller.
            return Ok(Next::End);
        }
        if self.frames.is_empty() && it.spec.has(crate::dialect::Capability::MainReturnEnds) {
            // The standalone LinuxCNC interpreter ends here as at M2 (and
            // the line's comment, skipped on a return, is shown).
            let program = self.progs[prog].program.clone();
            super::modes::block_comments(it, &program.blocks[pc])?;
            super::machine::program_end(it, false)?;
            return Ok(Next::End);
        }
        if self.frames.is_empty() {
            // M99 in a main program: start again from the top (bounded).
            self.count_loop(it, 0, 0)?;
            return Ok(Next::Jump(0));
        }
        match to {
            None => Ok(Next::Return),
            Some(v) => {
                let n = it.value(v, exprs)?.round() as u32;
                let (prog, _) = {
                    let f = self.frames.last().expect("frame");
                    (f.prog, f.ret)
                };
                let (p, _) = self.pop_frame(it);
                let at = self.progs[p]
                    .index
                    .seq
                    .get(&n)
                    .and_then(|l| l.first().copied());
                let _ = prog;
                match at {
                    Some(i) => Ok(Next::Jump(i)),
                    None => Err(it.error_at(
                        it.span,
                        Code::JumpTargetMissing,
                        format!("M99 P{n}: no block N{n}"),
                    )),
                }
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        kind: CallKind,
        target: &CallTarget,
        args: &CallArgs,
        repeat: Option<&Value>,
        exprs: &Arena<Expr>,
    ) -> Result<Next, Stop> {
        let passes = match repeat {
            Some(r) => it.value(r, exprs)?.round().max(0.0) as u64,
            None => 1,
        };
        if passes == 0 {
            return Ok(Next::Step);
        }
        let target = match target {
            CallTarget::Computed(e) => {
                CallTarget::Number(it.eval(*e, exprs)?.unwrap_or(0.0).round() as u32)
            }
            t => t.clone(),
        };
        let values = self.arg_values(it, args, exprs)?;
        if kind == CallKind::ModalMacro {
            self.modal = Some((target, values));
            return Ok(Next::Step);
        }
        self.enter(it, prog, pc, kind, &target, values, passes)
    }

    /// Enters a subprogram: a frame to come back to, and fresh locals for
    /// the kinds of call that have them.
    #[allow(clippy::too_many_arguments)]
    fn enter(
        &mut self,
        it: &mut Interp<'_, '_>,
        prog: usize,
        pc: usize,
        kind: CallKind,
        target: &CallTarget,
        values: Vec<(u32, Option<f64>)>,
        passes: u64,
    ) -> Result<Next, Stop> {
        if kind == CallKind::Subprogram && it.opts.rs274.disable_fanuc_subs {
            return Err(it.read_error(
                it.span,
                Code::SubStyleDisabled,
                "DISABLE_FANUC_STYLE_SUB set in INI file, but found m98",
            ));
        }
        let target = target.clone();
        let (to_prog, at) = match self.find(prog, &target, kind) {
            Some(x) => x,
            None if it.opts.missing_calls_warn => {
                it.diags.push(missing_call(it.span, &target));
                // What the called program sets is not known from here on.
                it.from_outside = true;
                return Ok(Next::Step);
            }
            None => {
                return Err(it.error_at(
                    it.span,
                    Code::JumpTargetMissing,
                    format!(
                        "subprogram {} not found in this file or beside it",
                        target_name(&target)
                    ),
                ))
            }
        };
        let def = at.checked_sub(1);
        let def_block = def.and_then(|i| self.progs[to_prog].program.blocks.get(i));
        super::sub_styles::check_call(it, kind, def_block)?;
        if let Some(i) = def {
            self.known_defs.insert((to_prog, i));
        }
        let repeat = (passes > 1).then_some(((to_prog, at), passes));
        let call_span = it.span;
        let mut frame = Frame {
            prog,
            ret: pc + 1,
            saved: Vec::new(),
            new_scope: false,
            section: None,
            repeat,
            modal: false,
            call_span,
            profile: false,
        };
        if matches!(
            kind,
            CallKind::OWord | CallKind::Macro | CallKind::ModalMacro | CallKind::Named
        ) {
            frame.new_scope = true;
            for n in local_numbers(it.spec) {
                frame.saved.push((n, it.params.numbered(n)));
                it.params.set_numbered(n, None);
            }
            it.params.push_scope();
            let declared = self.declared_params(to_prog, at);
            if declared.is_empty() {
                for (n, v) in values {
                    it.params.set_numbered(n, v);
                }
            } else {
                // Siemens `PROC NAME(REAL A, ...)`: arguments by position.
                for (i, name) in declared.iter().enumerate() {
                    let v = values
                        .iter()
                        .find(|(n, _)| *n == i as u32 + 1)
                        .and_then(|(_, v)| *v);
                    it.params.declare_user(name, v.unwrap_or(0.0));
                }
            }
        }
        Ok(Next::Call {
            prog: to_prog,
            at,
            frame,
        })
    }

    /// The values a call passes: o-word `[a] [b]` → #1, #2; G65 letters by
    /// Fanuc's argument specification I.
    fn arg_values(
        &mut self,
        it: &mut Interp<'_, '_>,
        args: &CallArgs,
        exprs: &Arena<Expr>,
    ) -> Result<Vec<(u32, Option<f64>)>, Stop> {
        let mut out = Vec::new();
        match args {
            CallArgs::None => {}
            CallArgs::Positional(list) => {
                for (i, a) in list.iter().enumerate() {
                    let v = match a {
                        Some(e) => it.eval(*e, exprs)?,
                        None => None,
                    };
                    out.push((i as u32 + 1, v));
                }
            }
            CallArgs::Letters(list) => {
                for (letter, v) in list {
                    if let Some(n) = fanuc_argument(*letter) {
                        out.push((n, it.value_or_vacant(v, exprs)?));
                    }
                }
            }
        }
        Ok(out)
    }

    /// The program and the first block a call runs.
    /// The parameter names a subprogram declares (`PROC NAME(REAL A)`).
    fn declared_params(&self, prog: usize, at: usize) -> Vec<String> {
        let Some(b) = at
            .checked_sub(1)
            .and_then(|i| self.progs[prog].program.blocks.get(i))
        else {
            return Vec::new();
        };
        b.stmts
            .iter()
            .find_map(|s| match &s.kind {
                StmtKind::SubStart { params, .. } => {
                    Some(params.iter().map(|p| p.name.clone()).collect())
                }
                _ => None,
            })
            .unwrap_or_default()
    }

    fn find(&mut self, prog: usize, target: &CallTarget, kind: CallKind) -> Option<(usize, usize)> {
        if kind == CallKind::Local {
            // Haas M97 P: a sequence number in this program.
            let CallTarget::Number(n) = target else {
                return None;
            };
            return self.progs[prog]
                .index
                .seq
                .get(n)
                .and_then(|l| l.first())
                .map(|&i| (prog, i));
        }
        if kind == CallKind::Label {
            // Heidenhain `CALL LBL n`: from the label in this program to `LBL 0`.
            let name = match target {
                CallTarget::Number(n) => n.to_string(),
                CallTarget::Name(n) => n.clone(),
                CallTarget::Computed(_) => return None,
            };
            let ix = &self.progs[prog].index;
            return ix
                .labels
                .get(&name.to_ascii_uppercase())
                .map(|&i| (prog, i + 1));
        }
        for p in std::iter::once(prog).chain(0..self.progs.len()) {
            if let Some(i) = self.progs[p].index.call_target(target) {
                return Some((p, i + 1));
            }
        }
        let program = self.loader.load(target)?;
        let index = std::rc::Rc::new(FlowIndex::build(&program));
        // A file holding the sub's definition starts after it (also a
        // Siemens `L140.SPF` whose `PROC L140(..)` names it as a program,
        // not by the number called); a bare program file starts at its
        // first block.
        let start = index
            .call_target(target)
            .map(|i| i + 1)
            .or_else(|| proc_head(&program).map(|i| i + 1))
            .unwrap_or(0);
        self.progs.push(Loaded { program, index });
        Some((self.progs.len() - 1, start))
    }
}

/// The block of a file's own `PROC` header, when the file starts with one.
fn proc_head(p: &Program) -> Option<usize> {
    for (i, b) in p.blocks.iter().enumerate() {
        for s in &b.stmts {
            match s.kind {
                StmtKind::SubStart {
                    id: FlowId::Nested, ..
                } => return Some(i),
                StmtKind::Comment { .. } | StmtKind::Tape | StmtKind::ProgramStart { .. } => {}
                _ => return None,
            }
        }
    }
    None
}

fn target_name(t: &CallTarget) -> String {
    match t {
        CallTarget::Number(n) => n.to_string(),
        CallTarget::Name(s) => s.clone(),
        CallTarget::Computed(_) => "(computed)".into(),
    }
}

fn limit(it: &Interp<'_, '_>, msg: &str, help: &str) -> Stop {
    Stop::Error(
        Diagnostic::new(Code::LimitExceeded, msg)
            .primary(it.span, "here")
            .help(help.to_string()),
    )
}

fn truth(v: Option<f64>) -> bool {
    v.unwrap_or(0.0) != 0.0
}

fn end_of_if(ix: &FlowIndex, mut pc: usize) -> usize {
    // Follow the branch chain to the EndIf.
    let mut guard = 0;
    while let Some(&n) = ix.next_branch.get(&pc) {
        pc = n;
        guard += 1;
        if guard > 10_000 {
            break;
        }
    }
    pc
}

/// The block a sequence-number jump goes to: Fanuc searches forward from
/// the jump, then from the top.
fn pick(list: &[usize], pc: usize, dir: JumpDir) -> Option<usize> {
    let fwd = list.iter().copied().find(|&i| i > pc);
    let back = list.iter().copied().rev().find(|&i| i <= pc);
    match dir {
        JumpDir::Forward => fwd,
        JumpDir::Backward => back,
        JumpDir::Either | JumpDir::EitherNoAlarm => fwd.or_else(|| list.first().copied()),
    }
}

/// Fanuc G65 argument specification I: letter → local variable number.
pub fn fanuc_argument(letter: char) -> Option<u32> {
    Some(match letter.to_ascii_uppercase() {
        'A' => 1,
        'B' => 2,
        'C' => 3,
        'I' => 4,
        'J' => 5,
        'K' => 6,
        'D' => 7,
        'E' => 8,
        'F' => 9,
        'H' => 11,
        'M' => 13,
        'Q' => 17,
        'R' => 18,
        'S' => 19,
        'T' => 20,
        'U' => 21,
        'V' => 22,
        'W' => 23,
        'X' => 24,
        'Y' => 25,
        'Z' => 26,
        _ => return None,
    })
}

fn read_var(it: &mut Interp<'_, '_>, var: &Var, exprs: &Arena<Expr>) -> Result<f64, Stop> {
    let id_free = Expr {
        kind: crate::ir::ExprKind::Var(var.clone()),
        span: it.span,
    };
    let mut tmp = exprs.clone();
    let id: ExprId = tmp.alloc(id_free);
    Ok(it.eval(id, &tmp)?.unwrap_or(0.0))
}

/// Sets a variable.
pub fn assign(
    it: &mut Interp<'_, '_>,
    var: &Var,
    v: Option<f64>,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    match var {
        Var::Numbered(n) => {
            it.check_writable(*n, it.span)?;
            it.params.set_numbered(*n, v)
        }
        Var::Indirect(e) => {
            let n = it.eval(*e, exprs)?.unwrap_or(0.0).round().max(0.0) as u32;
            it.check_writable(n, it.span)?;
            it.params.set_numbered(n, v);
        }
        Var::Named(name) => {
            // LinuxCNC's predefined parameters (`#<_x>`, `#<_ini[..]..>`)
            // are read-only: rs274 refuses the block as it reads it.
            if super::predefined::named(it, name).is_some() {
                return Err(it.read_error(
                    it.span,
                    Code::UnsupportedHere,
                    format!("Cannot assign to read-only parameter #<{name}>"),
                ));
            }
            it.params.set_named(name, v.unwrap_or(0.0))
        }
        Var::R(n) => it.params.set_r(*n, v.unwrap_or(0.0)),
        Var::Q(bank, n) => it.params.set_q(*bank, *n, v.unwrap_or(0.0)),
        Var::RIndirect(e) => {
            let n = it.eval(*e, exprs)?.unwrap_or(0.0).round().max(0.0) as u32;
            it.params.set_r(n, v.unwrap_or(0.0));
        }
        Var::User(name, _) => it.params.set_user(name, v.unwrap_or(0.0)),
        Var::System(name, index) => {
            if let Some(r) = super::siemens::assign_tool_data(it, name, index, v, exprs) {
                return r;
            }
            return Err(it.error_at(
                it.span,
                Code::UnsupportedHere,
                format!("writing system variable {name} is not simulated"),
            ));
        }
    }
    Ok(())
}

/// The numbered parameters local to a call level (the spec's `local`
/// ranges: LinuxCNC #1-#30, Fanuc #1-#33), bounded.
fn local_numbers(spec: &crate::dialect::DialectSpec) -> Vec<u32> {
    spec.variables
        .iter()
        .filter(|r| r.prefix == '#' && r.class == crate::dialect::spec::VarClass::Local)
        .flat_map(|r| r.first..=r.last.min(r.first.saturating_add(999)))
        .collect()
}

#[cfg(test)]
#[path = "flow_tests.rs"]
mod tests;

/// W0591: the called program is not here; the run goes on after the call.
fn missing_call(span: crate::span::Span, target: &CallTarget) -> Diagnostic {
    Diagnostic::new(
        Code::CalledProgramMissing,
        format!(
            "subprogram {} is neither in this file nor beside it: what it does was not checked",
            target_name(target)
        ),
    )
    .primary(span, "called here")
    .help("the run goes on after the call as if it returned without moving; put the called program beside this file to check it too")
}

/// Tells the run's observer, if any, which block runs next.
fn observe(it: &mut Interp<'_, '_>, prog: usize, pc: usize, depth: usize) {
    if let Some(mut f) = it.observer.take() {
        let modal_call = it.modal_call_active();
        let held = it.heidenhain.held.is_some() || it.heidenhain.approach.is_some();
        f(
            &super::BlockEvent {
                prog,
                pc,
                depth,
                modal_call,
                held,
            },
            &it.state,
            &it.params,
        );
        it.observer = Some(f);
    }
}

/// `DEF REAL A[MaxFaza]`: an array size given by a name of the machine's
/// definition files (a DEFINE macro of _N_SMAC/_N_MMAC/_N_UMAC_DEF or a
/// GUD constant, active in every program of the control). cncc does not
/// have those files: the size is not known and not checked (W0517); the
/// run goes on, since it does not bound array indices.
fn machine_sized(it: &mut Interp<'_, '_>, v: &crate::ir::VarDecl) {
    if it
        .diags
        .iter()
        .any(|d| d.code == Code::UnknownAtCheckTime && d.labels.iter().any(|l| l.span == v.span))
    {
        return;
    }
    for (_, name) in &v.dim_names {
        it.diags.push(
            Diagnostic::new(
                Code::UnknownAtCheckTime,
                format!("the size of array {} is `{name}`, a name of the machine's definition files: not known at check time", v.name),
            )
            .primary(v.span, "size given by the machine")
            .help("DEFINE macros and GUD constants live in the control's _N_DEF_DIR (SMAC/MMAC/UMAC, SGUD/MGUD/UGUD); the array's size and its indices are not checked"),
        );
    }
}
