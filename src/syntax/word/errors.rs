//! Parse errors into diagnostics: E0101 syntax-error with a readable list
//! of what could come instead, E0102 incomplete-expression, E0103
//! word-without-value.

use super::cx::Cx;
use super::lexer::{describe, Spanned, Tok};
use crate::diag::{Code, Diagnostic};
use lalrpop_util::ParseError;

pub fn to_diagnostic(cx: &Cx<'_>, feed: &[Spanned], e: ParseError<usize, Tok, ()>) -> Diagnostic {
    match e {
        ParseError::UnrecognizedToken {
            token: (l, t, r),
            expected,
        } => unexpected(cx, feed, l, t, r, &expected),
        ParseError::ExtraToken { token: (l, t, r) } => unexpected(cx, feed, l, t, r, &[]),
        ParseError::UnrecognizedEof { location, expected } => {
            early_end(cx, feed, location, &expected)
        }
        ParseError::InvalidToken { location } => {
            Diagnostic::new(Code::BadCharacter, "unexpected character")
                .primary(cx.span(location, location + 1), "not part of any word")
                .help("remove it, or put it in a comment")
        }
        ParseError::User { .. } => {
            Diagnostic::new(Code::SyntaxError, "syntax error").help("check the block")
        }
    }
}

/// The token before byte `l`, if it is an address letter.
fn letter_before(feed: &[Spanned], l: usize) -> Option<(usize, usize)> {
    let prev = feed.iter().rev().find(|t| t.2 <= l)?;
    matches!(prev.1, Tok::Letter(_) | Tok::O).then_some((prev.0, prev.2))
}

fn no_value(cx: &Cx<'_>, l: usize, r: usize) -> Diagnostic {
    let a = &cx.text[l..r];
    Diagnostic::new(
        Code::WordWithoutValue,
        format!("address `{a}` has no value"),
    )
    .primary(cx.span(l, r), "a value must follow")
    .help(format!(
        "write a number or an expression after it, as in `{}10.`",
        a.to_ascii_uppercase()
    ))
}

fn unexpected(
    cx: &Cx<'_>,
    feed: &[Spanned],
    l: usize,
    t: Tok,
    r: usize,
    expected: &[String],
) -> Diagnostic {
    if t == Tok::Named && feed.iter().any(|p| p.1 == Tok::O && p.2 <= l) {
        return Diagnostic::new(Code::SyntaxError, format!("o-word `o{}` without a statement", &cx.text[l..r]))
            .primary(cx.span(l, r), "expected `sub`, `call`, `endsub`, `return`, `if`, `while`, `do` or another o-word keyword after this")
            .help(format!("write for example `o{} call`", &cx.text[l..r]));
    }
    if let Some((pl, pr)) = letter_before(feed, l).filter(|_| wants_value(expected)) {
        return no_value(cx, pl, pr);
    }
    let found = describe(t, &cx.text[l..r]);
    // A closing bracket where an operand must come: the expression stops short.
    if matches!(t, Tok::RBr) && wants_value(expected) && after_operator(feed, l) {
        return Diagnostic::new(
            Code::IncompleteExpression,
            "the expression ends before it is complete",
        )
        .primary(
            cx.span(l, r),
            format!("expected {} before this", readable(expected)),
        )
        .help("an operand is missing before the closing `]`");
    }
    Diagnostic::new(Code::SyntaxError, format!("unexpected {found}"))
        .primary(cx.span(l, r), format!("expected {}", readable(expected)))
        .help(format!("expected {} here", readable(expected)))
}

fn early_end(cx: &Cx<'_>, feed: &[Spanned], at: usize, expected: &[String]) -> Diagnostic {
    let last = feed.last().map(|t| (t.0, t.2)).unwrap_or((at, at));
    if let Some((pl, pr)) = letter_before(feed, at).filter(|_| wants_value(expected)) {
        return no_value(cx, pl, pr);
    }
    if wants_value(expected) || expected.iter().any(|e| e == "\"]\"") {
        return Diagnostic::new(
            Code::IncompleteExpression,
            "the line ends inside an expression",
        )
        .primary(
            cx.span(last.0, last.1),
            format!("expected {} after this", readable(expected)),
        )
        .help("complete the expression: an operand or a closing `]` is missing");
    }
    Diagnostic::new(
        Code::SyntaxError,
        "the line ends before the statement is complete",
    )
    .primary(
        cx.span(last.0, last.1),
        format!("expected {} after this", readable(expected)),
    )
    .help(format!("add {}", readable(expected)))
}

/// Is the token before byte `l` an operator or an opening bracket?
fn after_operator(feed: &[Spanned], l: usize) -> bool {
    let Some(prev) = feed.iter().rev().find(|t| t.2 <= l) else {
        return false;
    };
    matches!(
        prev.1,
        Tok::Plus
            | Tok::Minus
            | Tok::Star
            | Tok::Pow
            | Tok::Slash
            | Tok::LBr
            | Tok::Comma
            | Tok::Kw(_)
    )
}

/// True when a value or operand could come next.
fn wants_value(expected: &[String]) -> bool {
    expected
        .iter()
        .any(|e| e == "\"number\"" || e == "\"[\"" || e == "\"#\"")
}

/// `"number"`, `"GOTO"` ... as words a reader understands.
pub fn readable(expected: &[String]) -> String {
    let mut out: Vec<String> = Vec::new();
    for e in expected {
        let name = match e.trim_matches('"') {
            "letter" => "an address letter".to_string(),
            "number" => "a number".to_string(),
            "name" => "a function name".to_string(),
            "o-word" | "O" => "an `O` word".to_string(),
            "<name>" => "a `<name>`".to_string(),
            other => format!("`{other}`"),
        };
        if !out.contains(&name) {
            out.push(name);
        }
    }
    match out.len() {
        0 => "nothing more".to_string(),
        1 => out.remove(0),
        n if n > 8 => format!("one of {}, ...", out[..8].join(", ")),
        _ => format!("one of {}", out.join(", ")),
    }
}
