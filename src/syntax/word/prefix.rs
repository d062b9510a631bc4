//! What the front end does around the grammar: comments out of the token
//! stream, the block delete and `N` number at the line start, o-word
//! tagging, and `O1234 (NAME)` naming.

use super::lexer::{Kw, Spanned, Tok};
use crate::diag::{Code, Diagnostic};
use crate::dialect::Capability;
use crate::ir::{CommentStyle, Decimal, Stmt, StmtKind};
use crate::span::{Span, Spanned as At};
use crate::syntax::{Item, LineInput, LineSyntax};

fn span(input: &LineInput<'_>, l: usize, r: usize) -> Span {
    Span::new(
        input.file,
        l + input.offset as usize,
        r + input.offset as usize,
    )
}

/// Copies the grammar's tokens into `feed`; returns comments as items and
/// reports bad characters and unclosed comments.
pub fn split(
    input: &LineInput<'_>,
    toks: &[Spanned],
    feed: &mut Vec<Spanned>,
    diags: &mut Vec<Diagnostic>,
) -> Vec<Item> {
    feed.clear();
    let mut side = Vec::new();
    for &(l, t, r) in toks {
        let sp = span(input, l, r);
        match t {
            Tok::Comment { .. } if nested_comment(input, l, r, diags) => break,
            Tok::Comment { closed } => side.push(paren_comment(input, l, r, closed, diags)),
            Tok::Semi => side.extend(semicolon(input, l, r, diags)),
            Tok::Colon if input.spec.has(Capability::ColonProgramNumber) => {
                feed.push((l, Tok::O, r))
            }
            Tok::Bad | Tok::Colon => diags.push(bad_char(input.text.get(l..r).unwrap_or("?"), sp)),
            _ if join_blanked(input, feed, l, t, r) => {}
            Tok::Name if input.spec.has(Capability::MacroWordAbbreviations) => {
                let kw = input.text.get(l..r).and_then(Kw::abbreviated);
                feed.push((l, kw.map_or(t, Tok::Kw), r))
            }
            _ => feed.push((l, t, r)),
        }
    }
    side
}

/// Where the dialect has `blanks-inside-words` (LinuxCNC drops every blank
/// outside comments): a keyword or name right after another, with only
/// blanks between, joins it when the two spell one keyword (`end sub` is
/// `endsub`, `else if` is `elseif`). True when `t` was joined.
fn join_blanked(input: &LineInput<'_>, feed: &mut [Spanned], l: usize, t: Tok, r: usize) -> bool {
    let wordy = |t: Tok| matches!(t, Tok::Kw(_) | Tok::Name);
    if !wordy(t) || !input.spec.has(Capability::BlanksInsideWords) {
        return false;
    }
    let Some(last) = feed.last_mut() else {
        return false;
    };
    let (pl, pt, pr) = *last;
    let between = input.text.get(pr..l).unwrap_or("x");
    if !wordy(pt) || !between.chars().all(|c| c == ' ' || c == '\t') {
        return false;
    }
    let joined = format!("{}{}", &input.text[pl..pr], &input.text[l..r]);
    match Kw::lookup(&joined) {
        Some(kw) => {
            *last = (pl, Tok::Kw(kw), r);
            true
        }
        None => false,
    }
}

/// Where the dialect has `no-nested-comments` (LinuxCNC): a `(` inside a
/// comment is "Nested comment found", and the line is read no further (so
/// the comment's text after the inner `)` is not read as words).
fn nested_comment(input: &LineInput<'_>, l: usize, r: usize, diags: &mut Vec<Diagnostic>) -> bool {
    if !input.spec.has(Capability::NoNestedComments) {
        return false;
    }
    let Some(k) = input.text[l + 1..r].find('(') else {
        return false;
    };
    let at = l + 1 + k;
    diags.push(
        Diagnostic::new(Code::NestedComment, "nested comment found")
            .primary(span(input, at, at + 1), "a `(` inside a comment")
            .secondary(span(input, l, l + 1), "the comment opens here")
            .help("comments do not nest here: remove the inner parentheses or write them as [ ]"),
    );
    true
}

fn paren_comment(
    input: &LineInput<'_>,
    l: usize,
    r: usize,
    closed: bool,
    diags: &mut Vec<Diagnostic>,
) -> Item {
    let sp = span(input, l, r);
    if !closed {
        diags.push(
            Diagnostic::new(Code::UnclosedComment, "comment not closed on its line")
                .primary(span(input, l, l + 1), "this `(` has no `)`")
                .help("close the comment with `)` before the end of the line"),
        );
    }
    let inner = &input.text[l + 1..if closed { r - 1 } else { r }];
    Item::Stmt(Stmt::new(comment_kind(inner, CommentStyle::Paren), sp))
}

/// `(MSG,text)` is an operator message; anything else a comment.
pub fn comment_kind(inner: &str, style: CommentStyle) -> StmtKind {
    let t = inner.trim_start();
    if style == CommentStyle::Paren && t.get(..4).is_some_and(|p| p.eq_ignore_ascii_case("MSG,")) {
        return StmtKind::Message(Some(t[4..].to_string()));
    }
    StmtKind::Comment {
        text: inner.to_string(),
        style,
    }
}

fn semicolon(
    input: &LineInput<'_>,
    l: usize,
    r: usize,
    diags: &mut Vec<Diagnostic>,
) -> Option<Item> {
    let rest = &input.text[l + 1..r];
    if input.spec.has(Capability::SemicolonComments) {
        return Some(Item::Stmt(Stmt::new(
            comment_kind(rest, CommentStyle::Semicolon),
            span(input, l, r),
        )));
    }
    if !rest.trim().is_empty() {
        diags.push(
            Diagnostic::new(
                Code::BadCharacter,
                "`;` comments are not part of this dialect",
            )
            .primary(span(input, l, l + 1), "`;` starts no comment here")
            .help("write the comment in parentheses: `( ... )`"),
        );
    }
    // A bare `;` at the end is the end-of-block mark some files keep.
    None
}

fn bad_char(text: &str, sp: Span) -> Diagnostic {
    Diagnostic::new(
        Code::BadCharacter,
        format!("unexpected character `{}`", text.escape_debug()),
    )
    .primary(sp, "not part of any word")
    .help("remove it, or put it in a comment")
}

/// Reads the block delete `/` `/n` and the `N` number at the start of
/// `feed`; returns where the grammar's tokens begin.
pub fn line_start(
    input: &LineInput<'_>,
    line: &mut LineSyntax,
    feed: &[Spanned],
    diags: &mut Vec<Diagnostic>,
) -> usize {
    let mut i = 0;
    if let Some(&(l, Tok::Slash, r)) = feed.first() {
        let (level, end) = match feed.get(1) {
            Some(&(nl, Tok::Number, nr))
                if nl == r && nr == nl + 1 && input.text.as_bytes()[nl].is_ascii_digit() =>
            {
                i = 1;
                (input.text.as_bytes()[nl] - b'0', nr)
            }
            _ => (0, r),
        };
        line.skip = Some(At::new(level, span(input, l, end)));
        i += 1;
    }
    if let (Some(&(l, Tok::Letter(b'N'), _)), Some(&(nl, Tok::Number, nr))) =
        (feed.get(i), feed.get(i + 1))
    {
        let text = &input.text[nl..nr];
        let text = match text.split_once('.') {
            Some((whole, _)) if input.spec.has(Capability::FractionalSequenceNumbers) => whole,
            _ => text,
        };
        let n = seq_number(text, span(input, nl, nr), diags);
        line.number = Some(At::new(n, span(input, l, nr)));
        i += 2;
    }
    i
}

fn seq_number(text: &str, sp: Span, diags: &mut Vec<Diagnostic>) -> u32 {
    let v = Decimal::parse(text)
        .ok()
        .filter(|d| !d.point)
        .and_then(|d| d.as_int())
        .and_then(|v| u32::try_from(v).ok());
    v.unwrap_or_else(|| {
        diags.push(
            Diagnostic::new(
                Code::InvalidValue,
                "a sequence number must be a whole number",
            )
            .primary(sp, "not a sequence number")
            .help("write the N number as digits only, as in `N10`"),
        );
        0
    })
}

/// Marks `O` as an o-word where a number or `<name>` and an o-word keyword
/// follow (`o100 sub`), so the grammar tells it from `O1234`. Returns how
/// many tokens to keep: LinuxCNC ignores whatever follows `oN else` on its
/// line (`o100 else if [..]` is a plain `else`; checked with rs274).
pub fn retag_owords(feed: &mut [Spanned]) -> usize {
    for i in 0..feed.len().saturating_sub(2) {
        if feed[i].1 == Tok::O {
            if let Some(k) = computed_oword_end(feed, i + 1) {
                if feed.get(k).map(|t| t.1) == Some(Tok::Kw(Kw::Call)) {
                    feed[i].1 = Tok::OWord;
                    continue;
                }
            }
        }
        let named = matches!(feed[i + 1].1, Tok::Number | Tok::Named);
        if feed[i].1 == Tok::O && named && is_oword_keyword(feed[i + 2].1) {
            feed[i].1 = Tok::OWord;
            if feed[i + 2].1 == Tok::Kw(Kw::Else) {
                return i + 3;
            }
        }
    }
    feed.len()
}

/// Where a computed o-word number starting at `i` ends (`o#<sub> call`,
/// `o##1 call`, `O[#2*10] call`: rs274 reads a parameter or a bracketed
/// expression as the number): the index of the token after it.
fn computed_oword_end(feed: &[Spanned], mut i: usize) -> Option<usize> {
    let mut hashes = 0;
    while feed.get(i)?.1 == Tok::Hash {
        hashes += 1;
        i += 1;
    }
    match feed.get(i)?.1 {
        Tok::Number | Tok::Named if hashes > 0 => Some(i + 1),
        Tok::LBr => {
            let mut depth = 0;
            for (k, t) in feed.iter().enumerate().skip(i) {
                match t.1 {
                    Tok::LBr => depth += 1,
                    Tok::RBr => {
                        depth -= 1;
                        if depth == 0 {
                            return (k + 1 < feed.len()).then_some(k + 1);
                        }
                    }
                    _ => {}
                }
            }
            None
        }
        _ => None,
    }
}

fn is_oword_keyword(t: Tok) -> bool {
    use Kw::*;
    matches!(
        t,
        Tok::Kw(
            Sub | EndSub
                | Call
                | Return
                | If
                | ElseIf
                | Else
                | EndIf
                | While
                | EndWhile
                | Do
                | Repeat
                | EndRepeat
                | Break
                | Continue
        )
    )
}

/// `O1234 (NAME)`: the comment right after a program number names it.
pub fn name_program(items: &mut Vec<Item>) {
    let Some(i) = items.iter().position(|it| {
        matches!(
            it,
            Item::Stmt(Stmt {
                kind: StmtKind::ProgramStart { name: None, .. },
                ..
            })
        )
    }) else {
        return;
    };
    let Some(Item::Stmt(Stmt {
        kind:
            StmtKind::Comment {
                text,
                style: CommentStyle::Paren,
            },
        span: cspan,
    })) = items.get(i + 1)
    else {
        return;
    };
    let (text, cspan) = (text.trim().to_string(), *cspan);
    if let Item::Stmt(Stmt {
        kind: StmtKind::ProgramStart { name, .. },
        span,
    }) = &mut items[i]
    {
        *name = Some(text);
        *span = span.to(cspan);
    }
    items.remove(i + 1);
}
