//! The Klartext front end (Heidenhain TNC conversational programs): one
//! block of text to a [`LineSyntax`].
//!
//! A block may continue over several physical lines with a trailing `~`
//! (cycle definitions, long comments): the front end keeps such lines and
//! reads the block when its last line comes, from a text in which every
//! byte sits at its file offset (line endings blanked), so spans stay
//! exact. Each physical line's `;` comment is taken off first (in a
//! `CYCL DEF` it is the label of the parameter on that line); the block
//! number in front is taken off; a `*` block is a structure heading. The
//! [`lexer`] makes grammar tokens, the LALRPOP grammar
//! (`grammar/klartext.lalrpop`) reads the block, and [`path`]/[`cycles`]
//! build the statements. M words are left to the shared lowering (the
//! spec's code table), except `M99`/`M89` (cycle calls).
//!
//! How Heidenhain constructs are represented (for writers and for `port`):
//! * `CYCL DEF 200 DRILLING ~ Q200=2 ;SET-UP CLEARANCE ~ ...` is one
//!   [`StmtKind::CycleDef`]: the cycle number, its name as written, and every
//!   Q parameter by number with its value as written and its label, in the
//!   order written (unknown trailing parameters kept). The dialect spec lists
//!   each cycle's parameters (`dialects/heidenhain.xml`, cycle `200` ...).
//!   The definition is modal; the call is its own statement
//!   [`StmtKind::CycleRun`]: `CYCL CALL` (Call), `CYCL CALL POS X Y Z`
//!   (Pos), `CYCL CALL PAT` (Pattern), `M99` in a positioning block (Block,
//!   in the same block as the move), `M89` (Modal).
//!   Mapping for port: 200 ↔ G81/CYCLE81 (Q202 < depth ↔ G83/CYCLE83),
//!   203 ↔ G83/CYCLE83, 251 ↔ POCKET3, 252 ↔ POCKET4; Q200 = R − surface,
//!   Q201 = bottom − Q203 (signed), Q203 = surface, Q204 = 2nd clearance.
//! * Old cycles (`CYCL DEF 7.0 DATUM SHIFT`, `7.1 X+10`, `1.2 DEPTH-20`)
//!   are one [`StmtKind::CycleLine`] per block, by cycle and sub-number,
//!   with the words as written (their keywords vary by version/language).
//! * `CC` is [`StmtKind::Pole`]; `C` an arc with no centre words (the pole
//!   is the centre); `RND`/`CHF` a [`StmtKind::Corner`] block; `APPR`/`DEP`
//!   an [`StmtKind::Approach`]; `LBL n` the block's label (`LBL 0` a
//!   `SubReturn`); `CALL LBL n` a `Call` of kind `Label`; `CALL LBL n REP m`
//!   a `SectionRepeat` from the label to the call; `FN 9..12` a `Goto`
//!   with a condition; Q parameters are [`Var::Q`](crate::ir::Var::Q).
//! * `FN 14` ERROR, `FN 15/16` PRINT/F-PRINT, `FN 18` SYSREAD, `FN 17/19/20`
//!   (SYSWRITE, PLC, WAIT FOR), `PLANE ...`, `FUNCTION ...` (TCPM, RESET
//!   TCPM ...), `M140 MB MAX|n [F..]`, the FK blocks (`FL`, `FC`,
//!   `FPOL` ...) and the paraxial `R+`/`R-` of an `L` block are
//!   [`StmtKind::TncFunction`]: what they ask and their text as written,
//!   which the Klartext writer writes back ([`functions`]).
//!
//! What CAM posts write and the TNC reads: `F MAX` with a space (`FMAX`),
//! the block skip `/` before or after the block number, `X + 0` with
//! spaces, letters with an apostrophe in cycle texts (`PLAN D'USINAGE`),
//! `CYCL DEF9 .0`. Block numbers are not checked for order or repeats:
//! the TNC numbers blocks itself and the writer renumbers from 0 [?: how a
//! TNC loading a file with repeated numbers reacts is not documented to
//! us]. Post mistakes get located errors: `Xnan`, `BEGIN PGM .. IN`, a
//! CYCL DEF whose lines lack `~`, a TNC DIN/ISO program (`% name G71`).

mod approach;
mod build;
mod cycles;
mod fast;
mod flow;
mod functions;
mod lexer;
mod nodes;
mod paraxial;
mod path;
mod program;
mod token;

#[cfg(test)]
mod tests;

use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, CommentStyle, Expr, Stmt, StmtKind};
use crate::span::{Span, Spanned};
use crate::syntax::{FrontEnd, Item, LineInput, LineSyntax};
use build::{Ctx, LineComment};
use token::Tok;

lalrpop_util::lalrpop_mod!(
    #[allow(clippy::all, unused)]
    pub grammar,
    "/klartext.rs"
);

/// Longest block (all its continuation lines) read; longer is an error.
const MAX_BLOCK: usize = 1 << 20;

/// The Klartext front end; one instance reads one file.
#[derive(Debug, Default)]
pub struct KlartextFrontEnd {
    /// Lines of a block continued with `~`: text and file offset.
    pending: Vec<(String, u32)>,
    pending_len: usize,
    /// The name `BEGIN PGM` gave (for the `END PGM` check).
    begin: Option<String>,
}

impl KlartextFrontEnd {
    pub fn new() -> Self {
        Self::default()
    }
}

impl KlartextFrontEnd {
    /// E0191: the block with this line is longer than [`MAX_BLOCK`]. The
    /// whole block is reported and not read (never a part of it); when the
    /// line continues, the lines after it up to the block's end are skipped
    /// as part of the same block.
    fn too_long(
        &mut self,
        input: &LineInput<'_>,
        continued: bool,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<LineSyntax> {
        let start = self.pending.first().map_or(input.offset, |l| l.1) as usize;
        let end = input.offset as usize + input.text.len();
        let skipping = self.pending_len == usize::MAX;
        if !skipping {
            diags.push(
                Diagnostic::new(
                    Code::BlockTooLong,
                    format!("a block longer than {} bytes", MAX_BLOCK),
                )
                .primary(
                    Span::new(input.file, start, end.min(start + 80)),
                    "this block is not read",
                )
                .help("split it into several blocks"),
            );
        }
        self.pending.clear();
        // Skip the rest of the block: its lines are not a block of their own.
        self.pending_len = if continued { usize::MAX } else { 0 };
        None
    }
}

impl FrontEnd for KlartextFrontEnd {
    fn parse_line(
        &mut self,
        input: &LineInput<'_>,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<LineSyntax> {
        let continued = input.text.trim_end().ends_with('~');
        if self.pending_len == 0 && !continued {
            if let Some(line) = fast::line(input.text, input.offset as usize, input.file) {
                return Some(line);
            }
        }
        if self.pending_len.saturating_add(input.text.len()) > MAX_BLOCK {
            return self.too_long(input, continued, diags);
        }
        self.pending.push((input.text.to_string(), input.offset));
        self.pending_len += input.text.len();
        if continued {
            return None;
        }
        let lines = std::mem::take(&mut self.pending);
        self.pending_len = 0;
        let line = read_block(&lines, input, exprs, diags);
        if let Some(l) = &line {
            self.program_names(l, diags);
        }
        line
    }

    fn finish(&mut self, file: crate::span::FileId, diags: &mut Vec<Diagnostic>) {
        if let (Some(first), Some(last)) = (self.pending.first(), self.pending.last()) {
            let span = Span::new(file, first.1 as usize, last.1 as usize + last.0.len());
            diags.push(
                Diagnostic::new(
                    Code::KlartextContinuationAtEnd,
                    "the last block is continued with `~` but the file ends",
                )
                .primary(span, "this block is not complete")
                .help("complete the block or remove the trailing `~`"),
            );
        }
    }
}

impl KlartextFrontEnd {
    /// Remembers the `BEGIN PGM` name; an `END PGM` naming another program
    /// is a warning (the TNC writes the same name in both [K]; the run
    /// ends there all the same).
    fn program_names(&mut self, line: &LineSyntax, diags: &mut Vec<Diagnostic>) {
        for item in &line.items {
            let Item::Stmt(s) = item else { continue };
            match &s.kind {
                StmtKind::ProgramStart { name, .. } => self.begin = name.clone(),
                StmtKind::ProgramEnd { name: Some(end) } => {
                    let Some(begin) = &self.begin else { continue };
                    if !begin.eq_ignore_ascii_case(end) {
                        diags.push(
                            Diagnostic::new(
                                Code::KlartextEndNameMismatch,
                                format!("END PGM names `{end}`, but the program is `{begin}`"),
                            )
                            .primary(s.span, "this END PGM")
                            .help(format!(
                                "write `END PGM {begin}` with the name of BEGIN PGM"
                            )),
                        );
                    }
                }
                _ => {}
            }
        }
    }
}

/// The block's text with every byte at its file offset (from `base`):
/// line endings and comments blanked; and the comments of each line.
fn join(lines: &[(String, u32)]) -> (String, usize, Vec<LineComment>) {
    let base = lines[0].1 as usize;
    let mut text = String::new();
    let mut comments = Vec::new();
    // A block that is a comment alone continues its comment on every line.
    let head = lines[0]
        .0
        .trim_start()
        .trim_start_matches(|c: char| c.is_ascii_digit());
    let comment_block = head.trim_start().starts_with(';');
    for (k, (line, off)) in lines.iter().enumerate() {
        let at = (*off as usize).saturating_sub(base);
        while text.len() < at {
            text.push(' ');
        }
        // A comment keeps its trailing blanks (byte for byte); before a
        // continuation `~` they are only layout.
        let trimmed = line.trim_end();
        let line = match trimmed.strip_suffix('~') {
            Some(l) => l.trim_end(),
            None => line.trim_end_matches(['\r', '\n']),
        };
        let start = if comment_block && k > 0 {
            Some(usize::MAX)
        } else {
            comment_start(line)
        };
        match start {
            Some(usize::MAX) => {
                comments.push(LineComment {
                    text: line.to_string(),
                    start: base + text.len(),
                    end: base + text.len() + line.len(),
                });
                text.extend(std::iter::repeat_n(' ', line.len()));
            }
            Some(c) => {
                text.push_str(&line[..c]);
                let body = &line[c + 1..];
                comments.push(LineComment {
                    text: body.to_string(),
                    start: base + text.len(),
                    end: base + text.len() + line.len() - c,
                });
                text.extend(std::iter::repeat_n(' ', line.len() - c));
            }
            None => text.push_str(line),
        }
    }
    (text, base, comments)
}

/// Where a `;` comment starts (outside quotes).
fn comment_start(line: &str) -> Option<usize> {
    let mut quoted = false;
    for (i, c) in line.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ';' if !quoted => return Some(i),
            _ => {}
        }
    }
    None
}

fn read_block(
    lines: &[(String, u32)],
    input: &LineInput<'_>,
    exprs: &mut Arena<Expr>,
    diags: &mut Vec<Diagnostic>,
) -> Option<LineSyntax> {
    let file = input.file;
    let (mut text, base, comments) = join(lines);
    let full = Span::new(
        file,
        base,
        base + lines
            .last()
            .map(|l| l.1 as usize + l.0.len() - base)
            .unwrap_or(0),
    );
    let mut lead = text.len() - text.trim_start().len();
    // `/` before the block number (or after it, `12 /L ..`): the block is
    // skipped when block skip is on.
    let mut skip = slash_at(&mut text, lead, base, file);
    if skip.is_some() {
        lead = text.len() - text.trim_start().len();
    }
    let digits = text[lead..].bytes().take_while(u8::is_ascii_digit).count();
    let after = text[lead + digits..].chars().next();
    let mut number = None;
    if digits > 0 && after.is_none_or(|c| c.is_whitespace()) {
        let n = text[lead..lead + digits].parse::<u32>().ok();
        match n {
            Some(n) => {
                number = Some(Spanned::new(
                    n,
                    Span::new(file, base + lead, base + lead + digits),
                ))
            }
            None => diags.push(
                Diagnostic::new(Code::NumberTooLong, "block number too large")
                    .primary(Span::new(file, base + lead, base + lead + digits), "here")
                    .help("block numbers go up to 4294967295"),
            ),
        }
        text.replace_range(lead..lead + digits, &" ".repeat(digits));
        if skip.is_none() {
            let after = text.len() - text.trim_start().len();
            skip = slash_at(&mut text, after, base, file);
        }
    }
    let mut line = LineSyntax {
        span: full,
        skip,
        number,
        label: None,
        items: Vec::new(),
    };
    let code = text.trim();
    if code.is_empty() && comments.is_empty() {
        return line.number.is_some().then_some(line);
    }
    if let Some(rest) = code.strip_prefix('*') {
        let body = rest.strip_prefix(' ').unwrap_or(rest).to_string();
        let start = base + text.find('*').unwrap_or(0);
        let kind = StmtKind::Comment {
            text: body,
            style: CommentStyle::Heading,
        };
        line.items.push(Item::Stmt(Stmt::new(
            kind,
            Span::new(file, start, full.range().end),
        )));
        return Some(line);
    }
    let mut used = Vec::new();
    if !code.is_empty() {
        used = body(&text, base, input, &comments, exprs, diags, &mut line);
    }
    let rest: Vec<&LineComment> = comments
        .iter()
        .enumerate()
        .filter(|(i, _)| !used.contains(i))
        .map(|(_, c)| c)
        .collect();
    if let (Some(first), Some(last)) = (rest.first(), rest.last()) {
        let text: String = rest.iter().map(|c| c.text.as_str()).collect();
        let kind = StmtKind::Comment {
            text,
            style: CommentStyle::Semicolon,
        };
        let span = Span::new(file, first.start, last.end);
        line.items.push(Item::Stmt(Stmt::new(kind, span)));
    }
    Some(line)
}

/// `% name G71`: the first block of a TNC DIN/ISO program (a `%` line
/// ending in a G word, the units), which this front end does not read;
/// said so at once.
fn iso_start(text: &str, base: usize, file: crate::span::FileId) -> Option<Diagnostic> {
    let code = text.trim_start();
    let rest = code.strip_prefix('%')?;
    let words: Vec<&str> = rest.split_whitespace().collect();
    let last = words.iter().rev().find(|w| **w != "*")?;
    let g = last.strip_prefix(['G', 'g'])?;
    (!g.is_empty() && g.chars().all(|c| c.is_ascii_digit())).then_some(())?;
    let at = base + text.len() - code.len();
    Some(
        Diagnostic::new(
            Code::KlartextUnknownBlock,
            format!("`{}` starts a TNC DIN/ISO program, not a Klartext one", code.trim_end()),
        )
        .primary(Span::new(file, at, at + code.trim_end().len()), "DIN/ISO program start")
        .help("this is the TNC's ISO (G-code) programming: cncc has no TNC DIN/ISO dialect yet, and Klartext reads only conversational blocks (BEGIN PGM ... END PGM)"),
    )
}

/// A block-skip `/` at `at` (blanked in `text`): skip level 0.
fn slash_at(
    text: &mut String,
    at: usize,
    base: usize,
    file: crate::span::FileId,
) -> Option<Spanned<u8>> {
    if !text[at..].starts_with('/') {
        return None;
    }
    text.replace_range(at..at + 1, " ");
    Some(Spanned::new(0, Span::new(file, base + at, base + at + 1)))
}

/// Lexes and parses the block's code; returns the comments used as labels.
fn body(
    text: &str,
    base: usize,
    input: &LineInput<'_>,
    comments: &[LineComment],
    exprs: &mut Arena<Expr>,
    diags: &mut Vec<Diagnostic>,
    line: &mut LineSyntax,
) -> Vec<usize> {
    let file = input.file;
    if let Some(d) = iso_start(text, base, file) {
        diags.push(d);
        return Vec::new();
    }
    let mut raw = Vec::new();
    if let Err(e) = lexer::lex(text, base, &mut raw) {
        let code = match e.what {
            w if w.starts_with("a string") => Code::UnterminatedString,
            w if w.starts_with("a number") => Code::NumberTooLong,
            _ => Code::BadCharacter,
        };
        diags.push(
            Diagnostic::new(code, format!("{} here", e.what))
                .primary(Span::new(file, e.start, e.end), "not read")
                .help("remove it or put it in a `;` comment"),
        );
        return Vec::new();
    }
    let toks = lexer::classify(raw);
    let (l, r) = (
        toks.first().map(|t| t.0).unwrap_or(base),
        toks.last().map(|t| t.2).unwrap_or(base),
    );
    let mut ctx = Ctx {
        spec: input.spec,
        file,
        exprs,
        toks: &toks,
        text,
        base,
        comments,
        diags: Vec::new(),
        label: None,
        used_comments: Vec::new(),
    };
    if let Some((a, Tok::Name(n), b)) = toks.first() {
        if n != "M" && !functions::starts_block(n) {
            let mut w = vec![build::WordNode::new(n.clone(), None, None, *a, *b)];
            // The next name too: `CYCLE DEF` gets its own message.
            if let Some((a, Tok::Name(n), b)) = toks.get(1) {
                w.push(build::WordNode::new(n.clone(), None, None, *a, *b));
            }
            program::bare(&mut ctx, &w);
            diags.append(&mut ctx.diags);
            return Vec::new();
        }
    }
    let parsed = grammar::BlockParser::new().parse(&mut ctx, toks.iter().cloned());
    match parsed {
        Ok(node) => line.items = nodes::items(&mut ctx, node, l, r),
        Err(e) => ctx.diags.push(nodes::syntax_error(e, file, r)),
    }
    if let Some((name, span)) = ctx.label.take() {
        line.label = Some(Spanned::new(name, span));
    }
    diags.append(&mut ctx.diags);
    ctx.used_comments
}
