//! One statement to words: the single exhaustive match over
//! [`StmtKind`]. What all families write alike (codes from the spec's
//! table, feeds, axes) is written here; the rest goes to [`super::word`]
//! (Fanuc, Haas, LinuxCNC) or [`super::sinumerik`] (Siemens 840D).

use super::flow;
use super::motion;
use super::number::NumKind;
use super::sinumerik as sin;
use super::word as wa;
use super::writer::{Style, Writer};
use crate::dialect::Meaning;
use crate::ir::{Stmt, StmtKind as K, Value};

/// Appends the words of `s` to `words`; `last` is true for a block's last
/// statement (a `;` comment can only go there).
pub fn write_stmt(w: &mut Writer<'_>, s: &Stmt, last: bool, words: &mut Vec<String>) {
    let span = s.span;
    let bracket = w.style == Style::Bracket;
    match &s.kind {
        K::Comment { text, style } => comment(w, text, *style, span, last, words),
        K::Message(text) if bracket => wa::message(w, text.as_deref(), span, words),
        K::Message(text) => sin::message(w, text.as_deref(), span, words),
        K::Tape => words.push("%".into()),
        K::ProgramStart { number, name } if bracket => {
            wa::program_start(w, *number, name.as_deref(), span, words)
        }
        K::ProgramStart { number, name } => {
            sin::program_start(w, *number, name.as_deref(), span, words)
        }
        K::Raw { dialect, text } => raw(w, dialect, text, span, words),
        K::ProgramEnd { .. }
        | K::Stock { .. }
        | K::ToolDef { .. }
        | K::ToolOversize { .. }
        | K::Pole(_)
        | K::Corner { .. }
        | K::Approach(_)
        | K::CycleDef(_)
        | K::CycleLine(_)
        | K::CycleRun(_)
        | K::PatternDef(_)
        | K::TncFunction(_) => super::klartext::foreign(w, s, words),
        K::Word(word) => w.push_words(words, std::slice::from_ref(word)),
        K::Units { unit, with_feeds } => {
            w.push_code(
                words,
                Meaning::Units {
                    unit: *unit,
                    with_feeds: *with_feeds,
                },
                span,
            );
            w.units = Some(*unit);
        }
        K::Plane(p) => w.push_code(words, Meaning::Plane(*p), span),
        K::Distance(d) => w.push_code(words, Meaning::Distance(*d), span),
        K::ArcDistance(d) => w.push_code(words, Meaning::ArcDistance(*d), span),
        K::FeedMode(m) => w.push_code(words, Meaning::FeedMode(*m), span),
        K::Feed(v) => w.push_word(words, "F", v, NumKind::Feed, span),
        K::SpindleSpeed(v) => w.push_word(words, "S", v, NumKind::Feed, span),
        K::SpindleCss { on, max_rpm } => {
            w.push_code(words, Meaning::Css(*on), span);
            if let Some(v) = max_rpm {
                let addr = if bracket { "D" } else { "LIMS" };
                w.push_word(words, addr, v, NumKind::Feed, span);
            }
        }
        K::Spindle(state) => motion::spindle(w, state, span, words),
        K::Coolant(c) => w.push_code(words, Meaning::Coolant(*c), span),
        K::ToolSelect(t) => motion::tool_select(w, t, span, words),
        K::ToolChange => w.push_code(words, Meaning::ToolChange, span),
        // A port gives it a block of its own where the target lacks the form.
        K::ToolPreselect(t) => motion::tool_select(w, t, span, words),
        K::CuttingEdge(v) if bracket => {
            w.cannot(
                span,
                "a Siemens cutting edge `D` (length and radius together)",
                "use G43 H and G41/G42 D",
            );
            let _ = v;
        }
        K::CuttingEdge(v) => w.push_word(words, "D", v, NumKind::Int, span),
        K::RadiusComp {
            side,
            register,
            diameter: false,
        } => {
            w.push_code(words, Meaning::RadiusComp(*side), span);
            opt_word(w, words, "D", register.as_ref(), NumKind::Int, span);
        }
        K::RadiusComp {
            side,
            register,
            diameter: true,
        } => {
            w.push_code(words, Meaning::RadiusCompDiameter(*side), span);
            opt_word(w, words, "D", register.as_ref(), NumKind::Length, span);
        }
        K::LengthComp {
            mode,
            register,
            axes,
        } => {
            w.push_code(words, Meaning::LengthComp(*mode), span);
            w.push_axes(words, axes);
            opt_word(w, words, "H", register.as_ref(), NumKind::Int, span);
        }
        K::OffsetRegister { letter, value } => {
            w.push_word(words, &letter.to_string(), value, NumKind::Int, span)
        }
        K::WorkOffset {
            index,
            extended: None,
        } => w.push_code(words, Meaning::WorkOffset(*index), span),
        K::WorkOffset {
            index: _,
            extended: Some(p),
        } => {
            w.push_code(words, Meaning::WorkOffsetExtended, span);
            w.push_word(words, "P", p, NumKind::Int, span);
        }
        K::MachineCoords => w.push_code(words, Meaning::MachineCoords, span),
        K::CoordShift { kind, axes } => {
            w.push_code(words, Meaning::CoordShift(*kind), span);
            w.push_axes(words, axes);
        }
        K::SetData { l, words: list } => {
            w.push_code(words, Meaning::SetData, span);
            w.push_word(words, "L", l, NumKind::Int, span);
            w.push_words(words, list);
        }
        K::RefReturn {
            index,
            axes,
            store,
            direct,
        } => {
            w.push_code(
                words,
                Meaning::RefReturn {
                    index: *index,
                    store: *store,
                    direct: *direct,
                },
                span,
            );
            if *direct {
                w.push_machine_axes(words, axes);
            } else {
                w.push_axes(words, axes);
            }
        }
        K::PathMode { mode, words: list } => {
            w.push_code(words, Meaning::PathMode(*mode), span);
            w.push_words(words, list);
        }
        K::ReturnToInitial(b) => w.push_code(words, Meaning::ReturnMode(*b), span),
        K::Transform(t) => motion::transform(w, t, span, words),
        K::Dwell { value, unit } => motion::dwell(w, value, *unit, span, words),
        K::Stop(k) => w.push_code(words, Meaning::Stop(*k), span),
        K::Aux {
            letter,
            code,
            words: list,
        } => {
            words.push(format!("{letter}{}", code.format(0, false)));
            // A high-speed code's words are switches and levels, written
            // as read (`G5.1 Q1`, not `Q1.`).
            let smoothing =
                w.spec.code(*letter, *code).map(|c| c.meaning) == Some(Meaning::PathSmoothing);
            if smoothing {
                for x in list {
                    w.push_word(words, &x.address(), &x.value, NumKind::Plain, x.span);
                }
            } else {
                w.push_words(words, list);
            }
        }
        K::DynamicCode {
            letter,
            value,
            words: list,
        } => {
            w.push_word(
                words,
                &letter.to_string(),
                &crate::ir::Value::Expr(*value),
                NumKind::Int,
                span,
            );
            w.push_words(words, list);
        }
        K::Command { name, args } if bracket => {
            let _ = args;
            w.cannot(
                span,
                &format!("the Siemens command `{name}`"),
                "remove it or find the target's equivalent",
            );
        }
        K::Command { name, args } => sin::command(w, name, args.as_deref(), words),
        K::Motion(m) => motion::motion(w, m, span, words),
        K::Cycle(c) => wa::cycle(w, c, span, words),
        K::CycleCancel => w.push_code(words, Meaning::CycleCancel, span),
        K::CycleCall(c) if bracket => {
            let _ = c;
            w.cannot(
                span,
                &format!("the named cycle call `{}`", c.name),
                "use the target's canned cycles (G81..G89), or `cncc port --expand-cycles` to write it as the moves it makes",
            );
        }
        K::CycleCall(c) => sin::cycle_call(w, c, words),
        K::ModalCallCancel if bracket => {
            w.cannot(span, "a modal cycle call cancel (`MCALL`)", "use G80")
        }
        K::ModalCallCancel => words.push("MCALL".into()),
        K::Assign { var, value } => assign(w, var, *value, span, words),
        K::Declare { ty, vars } if bracket => {
            let _ = (ty, vars);
            w.cannot(
                span,
                "a variable declaration (DEF)",
                "use numbered parameters",
            );
        }
        K::Declare { ty, vars } => sin::declare(w, *ty, vars, words),
        K::Goto { target, dir, cond } if bracket => wa::goto(w, target, *dir, *cond, span, words),
        K::Goto { target, dir, cond } => sin::goto(w, target, *dir, *cond, span, words),
        K::IfThen { cond, then } if bracket => wa::if_then(w, *cond, then, span, words),
        K::IfThen { cond, then } => {
            let _ = (cond, then);
            w.cannot(
                span,
                "a one-line IF ... THEN",
                "use IF ... ENDIF over several blocks",
            );
        }
        K::Call {
            kind,
            target,
            args,
            repeat,
        } if bracket => wa::call(w, *kind, target, args, repeat.as_ref(), span, words),
        K::Call {
            kind,
            target,
            args,
            repeat,
        } => sin::call(w, *kind, target, args, repeat.as_ref(), span, words),
        K::SubReturn { to } => {
            w.push_code(words, Meaning::SubReturn, span);
            opt_word(w, words, "P", to.as_ref(), NumKind::Int, span);
        }
        K::ModalMacroCancel => w.push_code(words, Meaning::ModalMacroCancel, span),
        K::If { cond, id } => flow::keyword(w, id, Some("IF"), "if", Some(*cond), span, words),
        K::ElseIf { cond, id } => flow::keyword(w, id, None, "elseif", Some(*cond), span, words),
        K::Else { id } => flow::keyword(w, id, Some("ELSE"), "else", None, span, words),
        K::EndIf { id } => flow::keyword(w, id, Some("ENDIF"), "endif", None, span, words),
        K::While { cond, id } => flow::while_(w, *cond, id, span, words),
        K::EndWhile { id } => flow::end_while(w, id, span, words),
        K::Do { id } => flow::keyword(w, id, None, "do", None, span, words),
        K::DoWhile { cond, id } => flow::keyword(w, id, None, "while", Some(*cond), span, words),
        K::Repeat { count, id } => flow::keyword(w, id, None, "repeat", Some(*count), span, words),
        K::EndRepeat { id } => flow::keyword(w, id, None, "endrepeat", None, span, words),
        K::For { var, from, to } => flow::for_(w, var, *from, *to, span, words),
        K::EndFor => flow::bare(w, "ENDFOR", span, words),
        K::Loop => flow::bare(w, "LOOP", span, words),
        K::EndLoop => flow::bare(w, "ENDLOOP", span, words),
        K::RepeatUntil => flow::bare(w, "REPEAT", span, words),
        K::Until { cond } => flow::until(w, *cond, span, words),
        K::Case {
            selector,
            arms,
            default,
        } => flow::case(w, *selector, arms, default.as_ref(), span, words),
        K::SectionRepeat {
            start,
            end,
            count,
            single,
        } => flow::section_repeat(w, start, end.as_deref(), *count, *single, span, words),
        K::Break { id } => flow::keyword(w, id, None, "break", None, span, words),
        K::Continue { id } => flow::keyword(w, id, None, "continue", None, span, words),
        K::SubStart { name, params, id } => flow::sub_start(w, name, params, id, span, words),
        K::SubEnd { id, value } => flow::sub_exit(w, id, *value, "endsub", span, words),
        K::Return { id, value } => flow::sub_exit(w, id, *value, "return", span, words),
    }
}

fn opt_word(
    w: &mut Writer<'_>,
    words: &mut Vec<String>,
    addr: &str,
    v: Option<&Value>,
    kind: NumKind,
    span: crate::span::Span,
) {
    if let Some(v) = v {
        w.push_word(words, addr, v, kind, span);
    }
}

/// A comment in place as `( )` where the target has those (and the text
/// allows), else as `;` text, which [`super::block`] moves to the block's end.
fn comment(
    w: &mut Writer<'_>,
    text: &str,
    style: crate::ir::CommentStyle,
    span: crate::span::Span,
    last: bool,
    words: &mut Vec<String>,
) {
    use crate::dialect::text::TextForm;
    use crate::dialect::Capability::{ParenComments, SemicolonComments, SemicolonEndOfBlock};
    use crate::ir::CommentStyle;
    // A `(` inside a comment read as `( )` reads back the same way; a `)`
    // would close it: such text goes to a `;` comment where there is one,
    // else the target's `<text>` table replaces the parentheses.
    let paren = w.spec.has(ParenComments);
    let semi = w.spec.has(SemicolonComments) && !w.spec.has(SemicolonEndOfBlock);
    let clean = !text.contains(')') && (style == CommentStyle::Paren || !text.contains('('));
    if paren && (clean || !semi) && (style == CommentStyle::Paren || !semi || !last) {
        let t = w.safe_text(text, TextForm::Paren, span);
        words.push(format!("({t})"));
    } else if semi {
        let t = w.safe_text(text, TextForm::Semicolon, span);
        w.trailing.push(t);
    } else {
        w.cannot(
            span,
            "a comment",
            "the target has no comment syntax cncc knows",
        );
    }
}

fn raw(
    w: &mut Writer<'_>,
    dialect: &str,
    text: &str,
    span: crate::span::Span,
    words: &mut Vec<String>,
) {
    let spec = w.spec;
    if spec.answers_to(dialect) {
        words.push(text.to_string());
        return;
    }
    let d = crate::diag::Diagnostic::new(
        crate::diag::Code::RawInForeignDialect,
        format!(
            "text kept verbatim from {dialect} cannot be written as {}",
            spec.name
        ),
    )
    .primary(span, format!("`{text}` was not understood, only kept"))
    .help("rewrite this part of the program by hand for the target");
    w.diags.push(d);
}

fn assign(
    w: &mut Writer<'_>,
    var: &crate::ir::Var,
    value: crate::ir::ExprId,
    span: crate::span::Span,
    words: &mut Vec<String>,
) {
    let lhs = super::expr::write_var(w, var, span);
    let rhs = w.expr(value);
    let (Some(lhs), Some(rhs)) = (lhs, rhs) else {
        return;
    };
    let simple = matches!(
        w.prog.exprs[value].kind,
        crate::ir::ExprKind::Number(_) | crate::ir::ExprKind::Var(_)
    );
    if w.style == Style::Bracket && !simple {
        words.push(format!("{lhs}=[{rhs}]"));
    } else {
        words.push(format!("{lhs}={rhs}"));
    }
}
