//! The walker's program with its plain moves held as text (issue 14: a
//! program with control flow must not cost a kilobyte a line). When a run
//! hands over to the walker ([`super::stream`]), the program is read
//! whole; each plain move ([`crate::ir::plain`]) is kept as a *stub*, the
//! block without its statements (its span, number and block-delete mark
//! stay, so labels, jumps and line numbers are as before), and read again
//! from the text when the walker reaches it, as rs274 reads its file again
//! on a loop.
//!
//! A block becomes a stub only when reading its text again, with the
//! reader that later reads it, gives the same block: a line whose reading
//! depends on the lines before it is held whole.
//!
//! A stub the walker reaches a second time (a loop, a called section) is
//! kept read, up to [`CACHED`] blocks, so a loop of moves is read once
//! more, not on every pass.

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::driver::Reader;
use crate::ir::{Arena, Block, Expr, Program};
use crate::span::FileId;
use std::borrow::Cow;
use std::collections::HashMap;
use std::rc::Rc;

/// At most this many stubs are kept read (a kilobyte or so each).
pub const CACHED: usize = 16_384;

/// The text behind a program's stubs, and the reader that reads them.
pub struct LazyBlocks<'s> {
    text: Cow<'s, str>,
    /// One bit per block: set for a stub.
    stubs: Vec<u64>,
    /// One bit per block: set once the walker has read the stub again.
    seen: Vec<u64>,
    /// Stubs read again more than once, kept read.
    cache: HashMap<usize, Rc<Block>>,
    reader: Reader<'s>,
    /// Plain moves make no expressions; the reader wants somewhere to
    /// put them all the same.
    scratch: Arena<Expr>,
}

impl<'s> LazyBlocks<'s> {
    fn new(text: Cow<'s, str>, file: FileId, spec: &'s DialectSpec) -> Self {
        LazyBlocks {
            text,
            stubs: Vec::new(),
            seen: Vec::new(),
            cache: HashMap::new(),
            reader: Reader::new(spec, file),
            scratch: Arena::new(),
        }
    }

    /// Is block `i` a stub (its statements are in the text)?
    pub fn is_stub(&self, i: usize) -> bool {
        bit(&self.stubs, i)
    }

    fn mark(&mut self, i: usize) {
        set_bit(&mut self.stubs, i);
    }

    /// Stub `i` as the walker runs it: read again, or kept read when it
    /// is reached again (see the module doc).
    pub fn fetch(&mut self, i: usize, stub: &Block) -> Option<Rc<Block>> {
        if let Some(b) = self.cache.get(&i) {
            return Some(b.clone());
        }
        let b = Rc::new(self.reread(stub)?);
        if !bit(&self.seen, i) {
            set_bit(&mut self.seen, i);
        } else if self.cache.len() < CACHED {
            self.cache.insert(i, b.clone());
        }
        Some(b)
    }

    /// The block `stub` stands for, read again from its text.
    pub fn reread(&mut self, stub: &Block) -> Option<Block> {
        reread_in(&self.text, &mut self.reader, &mut self.scratch, stub)
    }

    /// `b` (block `i` of `text`, read with no new expressions) as a stub,
    /// where reading its text again gives it back.
    fn stub(&mut self, text: &str, i: usize, b: Block) -> Block {
        if !crate::ir::plain::is_plain(&b)
            || reread_in(text, &mut self.reader, &mut self.scratch, &b).as_ref() != Some(&b)
        {
            return b;
        }
        self.mark(i);
        Block {
            stmts: Vec::new(),
            ..b
        }
    }
}

fn bit(bits: &[u64], i: usize) -> bool {
    bits.get(i / 64).is_some_and(|w| w & (1 << (i % 64)) != 0)
}

fn set_bit(bits: &mut Vec<u64>, i: usize) {
    if bits.len() <= i / 64 {
        bits.resize(i / 64 + 1, 0);
    }
    bits[i / 64] |= 1 << (i % 64);
}

/// The block whose span in `text` is `stub`'s, read again by `reader`.
fn reread_in(
    text: &str,
    reader: &mut Reader<'_>,
    scratch: &mut Arena<Expr>,
    stub: &Block,
) -> Option<Block> {
    let line = text.get(stub.span.start as usize..stub.span.end as usize)?;
    scratch.clear();
    let mut diags = Vec::new();
    reader.line(line, stub.span.start, scratch, &mut diags)
}

/// Reads `text` whole for the walker, its plain moves as stubs (the text
/// is held, or borrowed, for them).
pub fn read_program_lazy<'s>(
    text: impl Into<Cow<'s, str>>,
    file: FileId,
    spec: &'s DialectSpec,
) -> (Program, LazyBlocks<'s>, Vec<Diagnostic>) {
    let text = text.into();
    let mut lazy = LazyBlocks::new(Cow::Borrowed(""), file, spec);
    let mut program = Program::new(file, spec.id.clone());
    let mut blocks = Vec::new();
    let mut made = 0;
    let diags = crate::driver::read_each(&text, file, spec, &mut program.exprs, |b, exprs| {
        let fresh = exprs.len() == made;
        made = exprs.len();
        let i = blocks.len();
        blocks.push(if fresh { lazy.stub(&text, i, b) } else { b });
    });
    blocks.shrink_to_fit();
    program.blocks = blocks;
    lazy.text = text;
    (program, lazy, diags)
}
