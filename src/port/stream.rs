//! The port of a large program without holding it (issue 13's "flat
//! memory"): a program is read once, block by block. Blocks that only move (literal coordinates, a literal feed, a
//! comment) come in runs; the middle of a long run is ported in chunks
//! while it is read, and only the rest of the program (the *skeleton*:
//! set-ups, tool changes, cycles, control flow, each run's first and
//! last block and a short summary of its middle) is held and ported
//! whole. Since session 13 programs with control flow stream too: jumps
//! to labels land on labelled blocks, which are never in a run, so a loop
//! or a call repeats whole runs; a program that goes to a block by its
//! sequence number (`GOTO 10`, `M97 P10`, `M99 P10`) goes whole, since
//! that block may stand in a run already ported.
//!
//! Every piece is ported by the same passes and written by the same
//! writer as the whole program would be, in the context of what precedes
//! it: a chunk is ported as the skeleton so far, a summary of the run's
//! earlier chunks, the chunk, and the block after it; only the chunk's
//! own blocks are kept from that port (by their spans). The summary of a
//! stretch of moves is the last block of each *shape* (motion code,
//! axes named, feed, comment) in their order, an implicit move carrying
//! the run's motion code in force; it leaves every modal value (motion,
//! feed, each axis's last position) and every "has it happened yet" (a
//! first move in Z) as the full stretch leaves them.
//! The skeleton is ported with each run's summary where its middle was,
//! and a placeholder comment where the chunks go; the summary's blocks
//! are dropped from what is written.
//!
//! Anything unusual sends the program down the whole path instead: a
//! placeholder the passes changed, an error in
//! any piece (the whole port reports it, and legalizes), or a skeleton so
//! large that porting it before every chunk would cost more than the
//! program. `tests/port_stream.rs` ports every test and real program
//! both ways, in chunks of two blocks, and requires the same text.

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Block, CallKind, CommentStyle, JumpTarget, MotionKind, Program, Stmt, StmtKind};
use crate::span::{FileId, Span};
use std::collections::HashSet;

/// How the streamed port cuts a program (tests use small chunks).
#[derive(Clone, Copy, Debug)]
pub struct Chunking {
    /// Middle blocks of a run ported together.
    pub chunk: usize,
}

impl Default for Chunking {
    fn default() -> Self {
        Chunking { chunk: 4096 }
    }
}

/// A streamed port: the text, the reader's warnings and the port's, or
/// `None` where the program must be ported whole (see the module doc).
pub type Streamed = Option<StreamedPort>;

/// What a streamed port made.
pub struct StreamedPort {
    pub text: String,
    /// The reader's diagnostics (warnings: an error sends the program the
    /// whole way).
    pub read: Vec<Diagnostic>,
    /// The passes' and the writer's warnings.
    pub port: Vec<Diagnostic>,
    /// How many blocks were ported in chunks (not held in the skeleton).
    pub chunked: usize,
    /// What `port --verify` learns from reading the source, learnt from
    /// this reading of it (not a second one).
    pub scan: super::verify_text::Scan,
}

/// Ports `text` (registered as `file`, read as `from`) to `to` as a
/// stream; `None` where it must go the whole way.
pub fn port_text(
    text: &str,
    file: FileId,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &super::PortOptions,
    chunking: Chunking,
) -> Streamed {
    let marker = marker_for(text)?;
    let mut st = State::new(file, from, to, opts, chunking, marker);
    let mut reader = crate::driver::Reader::new(from, file);
    let mut read_diags = Vec::new();
    let mut scanning = super::verify_text::Scanning::default();
    for (line, offset) in crate::driver::lines(text) {
        let before = st.skeleton.exprs.len();
        let Some(b) = reader.line(line, offset, &mut st.skeleton.exprs, &mut read_diags) else {
            continue;
        };
        if read_diags.iter().any(Diagnostic::is_error) {
            return None;
        }
        read_diags.truncate(crate::diag::MAX_KEPT);
        scanning.block(&b, from);
        if b.stmts.iter().any(|s| to_sequence_number(&s.kind)) {
            return None;
        }
        if crate::ir::plain::is_plain(&b) && st.skeleton.exprs.len() == before {
            st.plain(b)?;
        } else {
            st.other(b)?;
        }
    }
    st.close_run()?;
    read_diags.extend(reader.finish());
    if read_diags.iter().any(Diagnostic::is_error) {
        return None;
    }
    let chunked = st.chunked;
    let (text, port) = st.finish()?;
    Some(StreamedPort {
        text,
        scan: scanning.finish(read_diags.clone()),
        read: read_diags,
        port,
        chunked,
    })
}

/// Does the statement go to a block by its sequence number (`GOTO 10`,
/// Haas `M97 P10`, `M99 P10`)? Such a block may stand in a run, where a
/// chunk already ported did not see the jump: the program goes whole.
fn to_sequence_number(k: &StmtKind) -> bool {
    match k {
        StmtKind::Goto {
            target: JumpTarget::Sequence(_),
            ..
        } => true,
        StmtKind::Call {
            kind: CallKind::Local,
            ..
        } => true,
        StmtKind::SubReturn { to } => to.is_some(),
        StmtKind::IfThen { then, .. } => to_sequence_number(&then.kind),
        _ => false,
    }
}

/// A comment text the program does not contain, marking where a run's
/// chunks go in the skeleton's output.
fn marker_for(text: &str) -> Option<String> {
    (0..8u32)
        .map(|i| format!("CNCC STREAMED RUN {i:X}"))
        .find(|m| !text.contains(m.as_str()))
}

/// What distinguishes moves for the summary: the motion code (an
/// implicit move's taken as `implicit`, where given), the words named, a
/// feed, a comment; written into `out`.
fn shape_into(b: &Block, implicit: Option<&MotionKind>, out: &mut Vec<u32>) {
    out.clear();
    out.extend(b.stmts.iter().map(|s| match &s.kind {
        StmtKind::Motion(m) => {
            let t = &m.target;
            let axes = [&t.x, &t.y, &t.z, &t.a, &t.b, &t.c, &t.u, &t.v, &t.w];
            let mut bits = 0u32;
            for (i, c) in axes.into_iter().enumerate() {
                bits |= (c.is_some() as u32) << i;
            }
            let a = &m.arc;
            for (i, c) in [
                a.i.is_some(),
                a.j.is_some(),
                a.k.is_some(),
                a.radius.is_some(),
            ]
            .into_iter()
            .enumerate()
            {
                bits |= (c as u32) << (9 + i);
            }
            let kind = match (&m.kind, implicit) {
                (MotionKind::Implicit, Some(k)) => k,
                (k, _) => k,
            };
            let kind = match kind {
                MotionKind::Implicit => 1,
                MotionKind::Rapid => 2,
                MotionKind::Linear => 3,
                MotionKind::Arc(d) => 4 + *d as u32,
                _ => 15,
            };
            bits | kind << 13 | 1 << 20
        }
        StmtKind::Feed(_) => 1 << 21,
        StmtKind::Comment { .. } => 1 << 22,
        _ => 1 << 23,
    }));
}

/// The motion code a block writes (None: implicit, or no move).
fn explicit_kind(b: &Block) -> Option<MotionKind> {
    b.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Motion(m) if m.kind != MotionKind::Implicit => Some(m.kind.clone()),
        _ => None,
    })
}

/// `b` with its implicit move given the code in force (`G1` after `G1`
/// is the same move), so that it means the same wherever the summary
/// puts it.
fn with_kind(mut b: Block, kind: &MotionKind) -> Block {
    for s in &mut b.stmts {
        if let StmtKind::Motion(m) = &mut s.kind {
            if m.kind == MotionKind::Implicit {
                m.kind = kind.clone();
            }
        }
    }
    b
}
/// A run of plain blocks being read.
#[derive(Default)]
struct Run {
    /// Its middle blocks not yet ported (the last one read may still be
    /// the run's last block).
    pending: Vec<Block>,
    /// The summary of the middle ported so far.
    summary: Vec<Block>,
    /// The shape of each summary block (made once per block read).
    shapes: Vec<Vec<u32>>,
    /// The lines its chunks were written as, each ended by [`END`] (none:
    /// no chunk yet).
    lines: Option<String>,
    /// Whether its first block is in the skeleton.
    started: bool,
    /// The last motion code the run wrote so far (None: the one in force
    /// before it, perhaps a cycle's).
    kind: Option<MotionKind>,
}

impl Run {
    /// What `blocks` (the next ones of the run) add to the summary: the
    /// last block of each shape, in their order, cloned (the blocks
    /// themselves go to the port). An implicit move after a motion code
    /// of the run is kept with that code, so that a later block of the
    /// code's shape moving past it cannot change its meaning; one before
    /// any code of the run keeps its place before all of them.
    fn additions(&mut self, blocks: &[Block]) -> Vec<(Vec<u32>, Block)> {
        // (shape, index in `blocks`, the code an implicit move takes)
        let mut last: Vec<(Vec<u32>, usize, Option<MotionKind>)> = Vec::new();
        let mut buf = Vec::new();
        for (i, b) in blocks.iter().enumerate() {
            let implicit = match (explicit_kind(b), &self.kind) {
                (Some(k), _) => {
                    self.kind = Some(k);
                    None
                }
                (None, Some(k)) => Some(k.clone()),
                (None, None) => None,
            };
            shape_into(b, implicit.as_ref(), &mut buf);
            let shape = match last.iter().position(|(s, ..)| *s == buf) {
                Some(j) => last.remove(j).0,
                None => buf.clone(),
            };
            last.push((shape, i, implicit));
        }
        last.into_iter()
            .map(|(shape, i, implicit)| {
                let b = blocks[i].clone();
                let b = match &implicit {
                    Some(k) => with_kind(b, k),
                    None => b,
                };
                (shape, b)
            })
            .collect()
    }

    /// Puts what [`Run::additions`] found into the summary: each replaces
    /// the block of its shape there and goes last.
    fn merge(&mut self, additions: Vec<(Vec<u32>, Block)>) {
        for (s, b) in additions {
            if let Some(i) = self.shapes.iter().position(|k| *k == s) {
                self.shapes.remove(i);
                self.summary.remove(i);
            }
            self.shapes.push(s);
            self.summary.push(b);
        }
    }
}

struct State<'a> {
    skeleton: Program,
    from: &'a DialectSpec,
    to: &'a DialectSpec,
    opts: &'a super::PortOptions,
    chunking: Chunking,
    marker: String,
    run: Run,
    /// The chunks' lines of each closed run, by placeholder.
    runs: Vec<String>,
    /// The spans of the summary blocks in the skeleton (not written).
    summarized: HashSet<Span>,
    diags: Vec<Diagnostic>,
    /// Blocks ported so far for the chunks (skeleton copies included).
    work: usize,
    blocks: usize,
    chunked: usize,
}

impl<'a> State<'a> {
    fn new(
        file: FileId,
        from: &'a DialectSpec,
        to: &'a DialectSpec,
        opts: &'a super::PortOptions,
        chunking: Chunking,
        marker: String,
    ) -> Self {
        State {
            skeleton: Program::new(file, from.id.clone()),
            from,
            to,
            opts,
            chunking,
            marker,
            run: Run::default(),
            runs: Vec::new(),
            summarized: HashSet::new(),
            diags: Vec::new(),
            work: 0,
            blocks: 0,
            chunked: 0,
        }
    }

    fn plain(&mut self, b: Block) -> Option<()> {
        self.blocks += 1;
        if !self.run.started {
            self.run.started = true;
            self.run.kind = explicit_kind(&b);
            self.skeleton.blocks.push(b);
            return Some(());
        }
        self.run.pending.push(b);
        if self.run.pending.len() > self.chunking.chunk {
            // The block after the chunk starts the next one, in a vector
            // that will not grow again.
            let mut rest = Vec::with_capacity(self.chunking.chunk + 1);
            rest.extend(self.run.pending.drain(self.chunking.chunk..));
            let chunk = std::mem::replace(&mut self.run.pending, rest);
            self.port_chunk(chunk)?;
        }
        Some(())
    }

    fn other(&mut self, b: Block) -> Option<()> {
        self.blocks += 1;
        self.close_run()?;
        self.skeleton.blocks.push(b);
        Some(())
    }

    /// Ends the run being read: a short one goes into the skeleton as it
    /// is; a chunked one gets its last chunk, summary and placeholder.
    fn close_run(&mut self) -> Option<()> {
        let mut run = std::mem::take(&mut self.run);
        let Some(mut lines) = run.lines.take() else {
            self.skeleton.blocks.append(&mut run.pending);
            return Some(());
        };
        let last = run.pending.pop();
        if !run.pending.is_empty() {
            let chunk = std::mem::take(&mut run.pending);
            let suffix = last.clone();
            let added = run.additions(&chunk);
            push_lines(&mut lines, self.chunk_lines(chunk, &run.summary, suffix)?);
            run.merge(added);
        }
        for s in &run.summary {
            self.summarized.insert(s.span);
        }
        // An empty span where the middle began: no block has it.
        let mut at = run.summary.first().map(|b| b.span).unwrap_or_default();
        at.end = at.start;
        self.skeleton.blocks.append(&mut run.summary);
        let text = format!("{} {}", self.marker, self.runs.len());
        let style = super::comment_style(self.from);
        self.skeleton.blocks.push(placeholder(text, style, at));
        // Held until the skeleton is written: without the growth slack.
        lines.shrink_to_fit();
        self.runs.push(lines);
        self.skeleton.blocks.extend(last);
        Some(())
    }

    /// Ports the chunk of the run being read; the block after it is the
    /// next pending one.
    fn port_chunk(&mut self, chunk: Vec<Block>) -> Option<()> {
        let suffix = self.run.pending.first().cloned();
        let added = self.run.additions(&chunk);
        let summary = std::mem::take(&mut self.run.summary);
        let lines = self.chunk_lines(chunk, &summary, suffix);
        self.run.summary = summary;
        push_lines(self.run.lines.get_or_insert_with(String::new), lines?);
        self.run.merge(added);
        Some(())
    }

    /// The lines the chunk's own blocks are written as, ported after the
    /// skeleton and the run's summary, with `suffix` after it.
    fn chunk_lines(
        &mut self,
        chunk: Vec<Block>,
        summary: &[Block],
        suffix: Option<Block>,
    ) -> Option<Vec<String>> {
        let (first, last) = (chunk.first()?.span, chunk.last()?.span);
        self.chunked += chunk.len();
        self.work += self.skeleton.blocks.len() + summary.len() + chunk.len();
        // Porting the skeleton before each chunk must not cost more than
        // a few times the program; past that the whole port is cheaper.
        if self.work > 8 * self.blocks + 200_000 {
            return None;
        }
        let mut p = Program::new(self.skeleton.file, self.skeleton.dialect.clone());
        p.exprs = self.skeleton.exprs.clone();
        p.blocks
            .reserve(self.skeleton.blocks.len() + summary.len() + chunk.len() + 1);
        p.blocks.extend(self.skeleton.blocks.iter().cloned());
        p.blocks.extend(summary.iter().cloned());
        p.blocks.extend(chunk);
        p.blocks.extend(suffix);
        let inside = |sp: Span| sp.start >= first.start && sp.end <= last.end;
        let (ported, diags) = super::port_owned(p, self.from, self.to, self.opts);
        if diags.iter().any(Diagnostic::is_error) {
            return None;
        }
        let (lines, wdiags) =
            crate::emit::write_kept_lines(&ported, self.to, &|b| inside(b.span)).ok()?;
        self.keep_diags(diags.into_iter().chain(wdiags), &inside);
        Some(lines)
    }

    /// The diagnostics located in the piece (`inside`); unlocated ones once.
    fn keep_diags(
        &mut self,
        diags: impl Iterator<Item = Diagnostic>,
        inside: &dyn Fn(Span) -> bool,
    ) {
        for d in diags {
            let here = match d.labels.iter().find(|l| l.primary).or(d.labels.first()) {
                Some(l) => inside(l.span),
                None => !self.diags.contains(&d),
            };
            if here {
                self.diags.push(d);
            }
        }
    }

    /// Ports the skeleton and puts each run's lines where its placeholder
    /// was written.
    fn finish(mut self) -> Option<(String, Vec<Diagnostic>)> {
        let skeleton = std::mem::replace(&mut self.skeleton, Program::new(FileId::default(), ""));
        let (ported, diags) = super::port_owned(skeleton, self.from, self.to, self.opts);
        if diags.iter().any(Diagnostic::is_error) {
            return None;
        }
        let summarized = std::mem::take(&mut self.summarized);
        let keep = |b: &Block| !summarized.contains(&b.span);
        let (lines, wdiags) = crate::emit::write_framed_lines(&ported, self.to, &keep).ok()?;
        let mut all = Vec::new();
        for d in diags.into_iter().chain(wdiags) {
            let summary = d.labels.iter().any(|l| summarized.contains(&l.span));
            if !summary {
                all.push(d);
            }
        }
        all.append(&mut self.diags);
        let runs = std::mem::take(&mut self.runs);
        let text = assemble(lines, runs, &self.marker, self.to)?;
        Some((text, all))
    }
}

/// Ends each of a chunk's lines (a Klartext block may hold `~\n`).
const END: char = '\0';

fn push_lines(to: &mut String, lines: Vec<String>) {
    for l in lines {
        to.push_str(&l);
        to.push(END);
    }
}

/// The skeleton's lines with each placeholder replaced by its run's
/// lines, as the target's file (Klartext numbered); None where a
/// placeholder is missing or was changed.
fn assemble(
    skeleton: Vec<String>,
    runs: Vec<String>,
    marker: &str,
    to: &DialectSpec,
) -> Option<String> {
    let size = skeleton.iter().map(|l| l.len() + 8).sum::<usize>()
        + runs.iter().map(|r| r.len() * 9 / 8).sum::<usize>();
    let mut out = Output {
        text: String::with_capacity(size),
        to,
        next: 0,
    };
    let mut runs = runs.into_iter().enumerate();
    let mut next = runs.next();
    for line in skeleton {
        match &next {
            Some((i, _)) if is_placeholder(&line, &format!("{marker} {i}")) => {
                let (_, run) = next.take()?;
                run.split_terminator(END).for_each(|l| out.line(l));
                next = runs.next();
            }
            _ if line.contains(marker) => return None,
            _ => out.line(&line),
        }
    }
    next.is_none().then_some(out.text)
}

/// The text being assembled, line by line as the target's writer ends
/// and numbers them.
struct Output<'a> {
    text: String,
    to: &'a DialectSpec,
    next: usize,
}

impl Output<'_> {
    fn line(&mut self, l: &str) {
        crate::emit::push_written_line(self.to, &mut self.text, self.next, l);
        self.next += 1;
    }
}

/// A comment block at `span` that marks where a run's chunks go.
fn placeholder(text: String, style: CommentStyle, span: Span) -> Block {
    let stmt = Stmt::new(StmtKind::Comment { text, style }, span);
    Block {
        span,
        skip: None,
        number: None,
        label: None,
        stmts: vec![stmt],
    }
}

/// Whether `line` is the placeholder comment `text` and nothing else.
fn is_placeholder(line: &str, text: &str) -> bool {
    match line.find(text) {
        Some(at) => {
            let rest = format!("{}{}", &line[..at], &line[at + text.len()..]);
            rest.chars().all(|c| matches!(c, '(' | ')' | ';' | ' '))
                && !line[at + text.len()..].starts_with(|c: char| c.is_ascii_hexdigit())
        }
        None => false,
    }
}
