//! The Sinumerik front end (Siemens 840D): one line of text to a
//! [`LineSyntax`].
//!
//! Three steps: the logos [`lexer`] reads raw tokens; [`classify`] knows
//! the dialect spec and the names declared so far and turns them into
//! grammar tokens (keywords, variables, cycles, functions, commands, split
//! address words), taking off the block delete, block number, label,
//! archive header and trailing comment; the LALRPOP grammar
//! (`grammar/sinumerik.lalrpop`) reads the block's body, and [`finish`]
//! turns what it built into items.
//!
//! What is emitted: address words stay words (`G`, `M`, `F`, `S`, `T1`,
//! `D1`, axes, `CR=`, `I1=`, `CHF=`...) for the shared lowering; `CIP`
//! and `CT` are words with that address and the value 0; `L123` is a
//! `Call` (passes from `P`); `T="NAME"` a `ToolSelect`; everything else
//! the grammar builds as a statement; `SPOS=90` is a spindle positioning.
//! A call `NAME(args)` of a function the spec does not list (`ISAXIS(1)`)
//! is an [`ExprKind::Query`](crate::ir::ExprKind::Query): kept by name, its
//! value unknown until the program runs. A block the grammar cannot place
//! but that starts with an unknown name (`WHENEVER ...`), or that writes an
//! address with a computed extension (`G[8]=`, `M[n]=`, `AX[_Z]=`), is
//! kept as `Raw` with a W0005 warning. A main block `:10` is read as block
//! number 10. Several `IF cond GOTOF label` may share a block; `CASE expr
//! OF` needs no parentheses.

mod builder;
mod classify;
mod fast;
mod finish;
mod lexer;
mod split;
mod token;

#[cfg(test)]
mod field_tests;
#[cfg(test)]
mod tests;

use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, CommentStyle, Expr, Stmt, StmtKind};
use crate::span::Spanned;
use crate::syntax::word::fast as word_fast;
use crate::syntax::{FrontEnd, Item, LineInput, LineSyntax};
use builder::{Builder, Node};
use classify::{classify, Classified, Spanned3, Spanner};
use lalrpop_util::ParseError;
use std::collections::HashSet;
use token::Tok;

lalrpop_util::lalrpop_mod!(
    #[allow(clippy::all, unused)]
    pub grammar,
    "/sinumerik.rs"
);

/// The Sinumerik front end; one instance reads one file, remembering the
/// names declared by DEF and PROC.
#[derive(Debug, Default)]
pub struct SinumerikFrontEnd {
    /// Declared variable names, upper case.
    declared: HashSet<String>,
    /// Every line through the lexer and the grammar (tests of the fast path).
    no_fast_path: bool,
    /// Item memory handed back by [`FrontEnd::recycle`].
    spare: Vec<Item>,
    /// The fast path's table for the current spec and declared names.
    table: Option<fast::FastTable>,
}

impl SinumerikFrontEnd {
    pub fn new() -> Self {
        Self::default()
    }

    /// Every line through the lexer and the grammar (for tests of [`fast`]).
    pub fn without_fast_path() -> Self {
        SinumerikFrontEnd {
            no_fast_path: true,
            ..Self::default()
        }
    }
}

impl FrontEnd for SinumerikFrontEnd {
    fn parse_line(
        &mut self,
        input: &LineInput<'_>,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<LineSyntax> {
        if !self.no_fast_path {
            if !self.table.as_ref().is_some_and(|t| t.is_for(input.spec)) {
                self.table = Some(fast::FastTable::new(input.spec, &self.declared));
            }
            let plain = self
                .table
                .as_ref()
                .is_some_and(|t| t.plain_words(input.text));
            if plain {
                if let Some(line) = word_fast::fast_line_with(input, &mut self.spare) {
                    return Some(line);
                }
            }
        }
        let sp = Spanner {
            file: input.file,
            offset: input.offset,
        };
        let cl = classify(input.text, input.spec, &self.declared, sp, diags);
        let mut line = LineSyntax {
            span: sp.span(0, input.text.len()),
            skip: cl
                .skip
                .as_ref()
                .map(|(n, r)| Spanned::new(*n, sp.span(r.start, r.end))),
            number: cl
                .number
                .as_ref()
                .map(|(n, r)| Spanned::new(*n, sp.span(r.start, r.end))),
            label: cl
                .label
                .as_ref()
                .map(|(n, r)| Spanned::new(n.clone(), sp.span(r.start, r.end))),
            items: Vec::new(),
        };
        if let Some((name, r)) = &cl.header {
            let kind = StmtKind::ProgramStart {
                number: None,
                name: Some(name.clone()),
            };
            line.items
                .push(Item::Stmt(Stmt::new(kind, sp.span(r.start, r.end))));
        }
        if !cl.lex_error && !cl.toks.is_empty() {
            line.items.extend(self.body(input, &cl, sp, exprs, diags));
        }
        if let Some((text, r)) = &cl.comment {
            let kind = StmtKind::Comment {
                text: text.clone(),
                style: CommentStyle::Semicolon,
            };
            line.items
                .push(Item::Stmt(Stmt::new(kind, sp.span(r.start, r.end))));
        }
        self.declare(&line.items);
        Some(line)
    }

    fn recycle(&mut self, mut items: Vec<Item>) {
        if items.capacity() > self.spare.capacity() {
            items.clear();
            self.spare = items;
        }
    }
}

/// `ELSEIF`: the 840D's IF has only ELSE and ENDIF (Job Planning manual,
/// "Control structures"; no ELSEIF up to SINUMERIK ONE [K]). Dropping it
/// would run its branch as part of the IF branch, so it is an error; the
/// IF/ELSE/ENDIF round it stay as they are.
fn no_elseif(at: crate::span::Span) -> Diagnostic {
    Diagnostic::new(
        Code::NotInDialect,
        "`ELSEIF` is not a Sinumerik 840D statement",
        )
    .primary(at, "no ELSEIF in IF ... ELSE ... ENDIF")
    .note("the control refuses the block (a syntax alarm): its IF has only ELSE and ENDIF")
    .help("write ELSE, then a nested IF cond ... ENDIF inside it (and one more ENDIF), or use CASE for many values")
}

impl SinumerikFrontEnd {
    fn body(
        &mut self,
        input: &LineInput<'_>,
        cl: &Classified,
        sp: Spanner,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Vec<Item> {
        let mut b = Builder {
            exprs,
            sp,
            spec: input.spec,
            diags: Vec::new(),
            raw_reason: None,
        };
        let toks = cl.toks.iter().cloned().map(Ok::<Spanned3, String>);
        let parsed = grammar::BodyParser::new().parse(&mut b, toks);
        let (start, end) = (cl.toks[0].0, cl.toks[cl.toks.len() - 1].2);
        let raw = |why: String, at: crate::span::Span, diags: &mut Vec<Diagnostic>| {
            let text = input.text[start..end].to_string();
            let d = Diagnostic::new(Code::KeptAsText, format!("kept as text: {why}"))
                .primary(at, "not understood")
                .help("the block is written back unchanged into this dialect; it cannot be translated to another");
            diags.push(d);
            let kind = StmtKind::Raw {
                dialect: input.spec.id.clone(),
                text,
            };
            vec![Item::Stmt(Stmt::new(kind, sp.span(start, end)))]
        };
        match parsed {
            Ok(nodes) => {
                diags.append(&mut b.diags);
                if let Some((why, at)) = b.raw_reason.take() {
                    return raw(why, at, diags);
                }
                self.finish(input, nodes, b.exprs, diags)
            }
            Err(_) if matches!(cl.toks[0].1, Tok::Name(_)) => {
                let Tok::Name(n) = &cl.toks[0].1 else {
                    unreachable!()
                };
                let at = sp.span(cl.toks[0].0, cl.toks[0].2);
                if n.eq_ignore_ascii_case("ELSEIF") {
                    diags.push(no_elseif(at));
                    return Vec::new();
                }
                raw(
                    format!("`{n}` is not a statement this front end knows"),
                    sp.span(cl.toks[0].0, cl.toks[0].2),
                    diags,
                )
            }
            Err(e) => {
                diags.push(syntax_error(e, cl, sp));
                Vec::new()
            }
        }
    }

    fn finish(
        &mut self,
        input: &LineInput<'_>,
        nodes: Vec<Node>,
        exprs: &Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Vec<Item> {
        finish::Finish {
            spec: input.spec,
            exprs,
            diags,
        }
        .items(nodes)
    }

    /// Remembers the names a DEF or PROC line declares.
    fn declare(&mut self, items: &[Item]) {
        for item in items {
            let vars = match item {
                Item::Stmt(Stmt {
                    kind: StmtKind::Declare { vars, .. },
                    ..
                }) => vars,
                Item::Stmt(Stmt {
                    kind: StmtKind::SubStart { params, .. },
                    ..
                }) => params,
                _ => continue,
            };
            self.declared
                .extend(vars.iter().map(|v| v.name.to_ascii_uppercase()));
            self.table = None;
        }
    }
}

/// E0101 (or E0102 when the block ends too early) with what could come.
fn syntax_error(e: ParseError<usize, Tok, String>, cl: &Classified, sp: Spanner) -> Diagnostic {
    match e {
        ParseError::UnrecognizedToken {
            token: (l, t, r),
            expected,
        } => Diagnostic::new(Code::SyntaxError, format!("unexpected {}", t.describe()))
            .primary(sp.span(l, r), "not expected here")
            .help(expected_list(&expected)),
        ParseError::ExtraToken { token: (l, t, r) } => {
            Diagnostic::new(Code::SyntaxError, format!("unexpected {}", t.describe()))
                .primary(sp.span(l, r), "nothing more can follow here")
                .help("end the block before this, or start a new block")
        }
        ParseError::UnrecognizedEof { expected, .. } => {
            let (l, t, r) = cl.toks[cl.toks.len() - 1].clone();
            Diagnostic::new(
                Code::IncompleteExpression,
                format!(
                    "the block ends after {} before it is complete",
                    t.describe()
                ),
            )
            .primary(sp.span(l, r), "incomplete after this")
            .help(expected_list(&expected))
        }
        ParseError::InvalidToken { location } => {
            Diagnostic::new(Code::SyntaxError, "a token that cannot be read")
                .primary(sp.span(location, location), "here")
                .help("check the spelling")
        }
        ParseError::User { error } => Diagnostic::new(Code::SyntaxError, error),
    }
}

fn expected_list(expected: &[String]) -> String {
    let mut names: Vec<String> = expected
        .iter()
        .map(|s| s.trim_matches('"').replace("\\\"", "\""))
        .collect();
    names.dedup();
    let more = names.len() > 10;
    names.truncate(10);
    let list = names
        .iter()
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ");
    if more {
        format!("expected one of {list}, ...")
    } else {
        format!("expected one of {list}")
    }
}
