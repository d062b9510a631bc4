//! The word-address front end (ISO 6983: Fanuc, Haas, LinuxCNC).
//!
//! A line goes one of two ways. Lines of plain `letter number` words (most
//! CAM output) are read by [`fast`] without lexer or parser. Every other
//! line is lexed ([`lexer`]); comments, the block delete `/n` and the `N`
//! number are taken out of the token stream here; the rest goes to the
//! LALRPOP grammar (`grammar/word.lalrpop`), whose actions build through
//! [`cx::Cx`]. Syntax errors are recovered per item, so a line still yields
//! what could be read, and the next line starts afresh.

pub mod cx;
mod errors;
pub mod fast;
pub mod flow;
pub mod lexer;
mod prefix;
#[cfg(test)]
mod tests;

lalrpop_util::lalrpop_mod!(
    #[allow(clippy::all, unused_parens, dead_code, unused_imports)]
    pub grammar,
    "/word.rs"
);

use crate::diag::Diagnostic;
use crate::ir::{Arena, Expr};
use crate::span::Span;
use crate::syntax::{FrontEnd, Item, LineInput, LineSyntax};
use cx::Cx;
use lexer::Spanned;
use std::cell::RefCell;

/// The word-address front end; one per file (it remembers open o-word
/// `do` loops, so that `oN while` can close them).
pub struct WordFrontEnd {
    toks: Vec<Spanned>,
    feed: Vec<Spanned>,
    open_do: Vec<String>,
    parser: grammar::LineParser,
    /// Off only in tests comparing the two ways.
    use_fast_path: bool,
    /// An emptied item vector handed back, for the next line.
    spare: Vec<Item>,
}

impl Default for WordFrontEnd {
    fn default() -> Self {
        Self::new()
    }
}

impl WordFrontEnd {
    pub fn new() -> Self {
        WordFrontEnd {
            toks: Vec::new(),
            feed: Vec::new(),
            open_do: Vec::new(),
            parser: grammar::LineParser::new(),
            use_fast_path: true,
            spare: Vec::new(),
        }
    }

    /// Every line through the grammar (for tests of the fast path).
    pub fn without_fast_path() -> Self {
        WordFrontEnd {
            use_fast_path: false,
            ..Self::new()
        }
    }

    fn slow_line(
        &mut self,
        input: &LineInput<'_>,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> LineSyntax {
        let span = Span::new(
            input.file,
            input.offset as usize,
            input.offset as usize + input.text.len(),
        );
        let mut line = LineSyntax {
            span,
            skip: None,
            number: None,
            label: None,
            items: Vec::new(),
        };
        lexer::lex_into(input.text, &mut self.toks);
        let side = prefix::split(input, &self.toks, &mut self.feed, diags);
        let start = prefix::line_start(input, &mut line, &self.feed, diags);
        let keep = prefix::retag_owords(&mut self.feed[start..]);
        self.feed.truncate(start + keep);
        let items = self.run_grammar(input, start, exprs, diags);
        line.items = merge(items, side);
        prefix::name_program(&mut line.items);
        line
    }

    fn run_grammar(
        &mut self,
        input: &LineInput<'_>,
        start: usize,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Vec<Item> {
        let feed = &self.feed[start..];
        if feed.is_empty() {
            return Vec::new();
        }
        let cx = Cx {
            text: input.text,
            file: input.file,
            offset: input.offset,
            spec: input.spec,
            exprs: RefCell::new(exprs),
            diags: RefCell::new(diags),
            items: RefCell::new(Vec::new()),
            errors: RefCell::new(Vec::new()),
            open_do: RefCell::new(&mut self.open_do),
            unknown_seen: std::cell::Cell::new(false),
        };
        let first = cx.diags.borrow().len();
        let result = self.parser.parse(&cx, feed.iter().map(|&t| Ok::<_, ()>(t)));
        let mut errs: Vec<_> = cx.errors.take().into_iter().map(|e| e.error).collect();
        if let Err(e) = result {
            errs.push(e);
        }
        for e in errs {
            let d = errors::to_diagnostic(&cx, feed, e);
            // An action may have said it already (an unknown name).
            let said = cx.diags.borrow()[first..]
                .iter()
                .any(|x| x.span() == d.span());
            if !said {
                cx.diag(d);
            }
        }
        cx.items.take()
    }
}

/// Grammar items and comments, in source order.
fn merge(items: Vec<Item>, side: Vec<Item>) -> Vec<Item> {
    if side.is_empty() {
        return items;
    }
    let mut out = Vec::with_capacity(items.len() + side.len());
    let mut side = side.into_iter().peekable();
    for it in items {
        while side.peek().is_some_and(|c| item_start(c) < item_start(&it)) {
            out.extend(side.next());
        }
        out.push(it);
    }
    out.extend(side);
    out
}

fn item_start(it: &Item) -> u32 {
    match it {
        Item::Word(w) => w.span.start,
        Item::Stmt(s) => s.span.start,
    }
}

impl FrontEnd for WordFrontEnd {
    fn parse_line(
        &mut self,
        input: &LineInput<'_>,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<LineSyntax> {
        if self.use_fast_path {
            if let Some(line) = fast::fast_line_with(input, &mut self.spare) {
                return Some(line);
            }
        }
        Some(self.slow_line(input, exprs, diags))
    }

    fn recycle(&mut self, mut items: Vec<Item>) {
        if items.capacity() > self.spare.capacity() {
            items.clear();
            self.spare = items;
        }
    }
}
