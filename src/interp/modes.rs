//! Running the modes statements of a block (see [`super::exec`] for which):
//! comments and messages, feed mode and F, S and spindle, coolant,
//! overrides and other M functions, dwell, plane, units, path mode,
//! distance modes, retract mode and the program stops.

use super::state::PathControl;
use super::{aux, Interp, Stop};
use crate::canon::{Canon, CanonPlane, CanonUnits, MotionMode};
use crate::diag::{Code, Diagnostic};
use crate::interp::host::SpindleDir;
use crate::ir::{
    Arena, Block, CommentStyle, Coolant, DimMode, DwellUnit, Expr, FeedMode, LengthUnit, PathMode,
    Plane, SpindleState, Stmt, StmtKind, StopKind, Value, Word,
};

pub fn exec(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    use StmtKind::*;
    it.begin_block(block);
    match &s.kind {
        // rs274 ignores comments on o-word lines.
        Comment { .. } if block.stmts.iter().any(|s| is_oword(&s.kind)) => Ok(()),
        Comment { .. } | Message(_) if later_comment(it, s, block) => Ok(()),
        Comment { text, style } => comment(it, text, *style),
        Message(m) => {
            it.out(Canon::Message(m.clone().unwrap_or_default()));
            Ok(())
        }
        FeedMode(m) => feed_mode(it, *m),
        Feed(v) => feed(it, v, exprs),
        SpindleSpeed(v) => speed(it, v, exprs),
        SpindleCss { on, max_rpm } => {
            let max = match (on, max_rpm) {
                (true, Some(v)) => it.value(v, exprs)?,
                _ => 0.0,
            };
            it.state.css_max = max;
            it.out(Canon::SetSpindleMode(max));
            Ok(())
        }
        Spindle(st) => spindle(it, st, block, exprs),
        Coolant(c) => coolant(it, *c),
        Aux {
            letter,
            code,
            words,
        } => aux::exec(it, *letter, code.to_f64(), words, exprs),
        DynamicCode {
            letter,
            value,
            words,
        } => {
            let code = it.eval(*value, exprs)?.unwrap_or(0.0);
            aux::dynamic(it, *letter, code, words, block, exprs)
        }
        Dwell { value, unit } => dwell(it, value, *unit, exprs),
        Plane(p) => plane(it, *p),
        Units { unit, .. } => {
            it.state.units = *unit;
            it.out(Canon::UseLengthUnits(match unit {
                LengthUnit::Mm => CanonUnits::Mm,
                LengthUnit::Inch => CanonUnits::Inches,
            }));
            Ok(())
        }
        PathMode { mode, words } => path_mode(it, s, *mode, words, exprs),
        Distance(d) => {
            let abs = *d == DimMode::Absolute;
            if abs != it.state.absolute {
                let what = if abs { "absolute" } else { "incremental" };
                it.out(Canon::Comment(format!(
                    "interpreter: distance mode changed to {what}"
                )));
            }
            it.state.absolute = abs;
            Ok(())
        }
        ArcDistance(d) => {
            let abs = *d == DimMode::Absolute;
            if abs != it.state.arc_absolute {
                let what = if abs { "absolute" } else { "incremental" };
                it.out(Canon::Comment(format!(
                    "interpreter: IJK distance mode changed to {what}"
                )));
            }
            it.state.arc_absolute = abs;
            Ok(())
        }
        ReturnToInitial(b) => {
            let what = if *b { "old_z" } else { "r_plane" };
            it.out(Canon::Comment(format!(
                "interpreter: retract mode set to {what}"
            )));
            it.state.retract_initial = *b;
            Ok(())
        }
        Stop(k) => stop(it, *k),
        _ => Err(it.error_at(
            s.span,
            Code::UnsupportedHere,
            "this statement is not run by the interpreter yet",
        )),
    }
}

/// The comments and messages of `block` run as on a line without control
/// flow (a main-program M99 that ends the run shows them).
pub fn block_comments(it: &mut Interp<'_, '_>, block: &Block) -> Result<(), Stop> {
    for s in &block.stmts {
        match &s.kind {
            _ if later_comment(it, s, block) => {}
            StmtKind::Comment { text, style } => comment(it, text, *style)?,
            StmtKind::Message(m) => it.out(Canon::Message(m.clone().unwrap_or_default())),
            _ => {}
        }
    }
    Ok(())
}

/// Where the dialect has `last-comment-only` (rs274 keeps one comment per
/// block, the last): whether a later `( )` comment on the line replaces
/// this one.
fn later_comment(it: &Interp<'_, '_>, s: &Stmt, block: &Block) -> bool {
    let paren = |k: &StmtKind| {
        matches!(
            k,
            StmtKind::Message(_)
                | StmtKind::Comment {
                    style: CommentStyle::Paren,
                    ..
                }
        )
    };
    paren(&s.kind)
        && it.spec.has(crate::dialect::Capability::LastCommentOnly)
        && block
            .stmts
            .iter()
            .any(|o| paren(&o.kind) && o.span.start > s.span.start)
}

/// A control-flow statement (an o-word line in LinuxCNC).
fn is_oword(k: &StmtKind) -> bool {
    use StmtKind::*;
    super::exec::phase(k) == 0
        && !matches!(
            k,
            Tape | ProgramStart { .. }
                | Raw { .. }
                | Word(_)
                | Command { .. }
                | Assign { .. }
                | Declare { .. }
        )
}

/// `( ... )`: COMMENT, or MESSAGE for `MSG,` and `DEBUG,`; `;` comments
/// and `(PRINT,`/`(LOG` print nothing in the call stream.
fn comment(it: &mut Interp<'_, '_>, text: &str, style: CommentStyle) -> Result<(), Stop> {
    if style != CommentStyle::Paren {
        return Ok(());
    }
    let lower = text.trim_start().to_ascii_lowercase();
    if let Some(rest) = strip_prefix_ci(text, "debug,") {
        // #5599 = 0 turns DEBUG messages off.
        if it.read_numbered(5599) == Some(0.0) {
            return Ok(());
        }
        let msg = substitute(it, rest);
        it.out(Canon::Message(msg));
    } else if let Some(rest) = strip_prefix_ci(text, "msg,") {
        it.out(Canon::Message(rest.to_string()));
    } else if let Some(call) = log_call(it, text) {
        it.out(call);
    } else if lower.starts_with("print,") {
    } else if let Some(rest) = abort_text(it, text) {
        // `(ABORT, text)`: the run stops with the text, parameters
        // substituted as in DEBUG (rs274 2.9, its abort-hot-comment test).
        let msg = substitute(it, rest);
        return Err(it.error_at(it.span, crate::diag::Code::ProgramAborted, msg));
    } else {
        it.out(Canon::Comment(text.to_string()));
    }
    Ok(())
}

/// The text after `ABORT,` when the dialect's spec lists ABORT among its
/// active comments.
fn abort_text<'t>(it: &Interp<'_, '_>, text: &'t str) -> Option<&'t str> {
    let (word, _, comma) = it.spec.text.active_word(text)?;
    (word.word.eq_ignore_ascii_case("abort")).then_some(())?;
    text.get(comma? + 1..)
}

/// `(LOGOPEN,f)`, `(LOGAPPEND,f)`, `(LOGCLOSE)`, `(LOG,text)` (parameters
/// substituted as in DEBUG), as rs274 prints them.
fn log_call(it: &Interp<'_, '_>, text: &str) -> Option<Canon> {
    if let Some(f) = strip_prefix_ci(text, "logopen,") {
        return Some(Canon::LogOpen(f.trim().to_string()));
    }
    if let Some(f) = strip_prefix_ci(text, "logappend,") {
        return Some(Canon::LogAppend(f.trim().to_string()));
    }
    if strip_prefix_ci(text, "logclose").is_some() {
        return Some(Canon::LogClose);
    }
    strip_prefix_ci(text, "log,").map(|rest| Canon::Log(substitute(it, rest)))
}

fn strip_prefix_ci<'t>(text: &'t str, prefix: &str) -> Option<&'t str> {
    let t = text.trim_start();
    let head = t.get(..prefix.len())?;
    head.eq_ignore_ascii_case(prefix)
        .then(|| &t[prefix.len()..])
}

/// How a DEBUG text prints parameter values: rs274's `%.6f` until a
/// `%d`, `%f` (4 decimals) or `%.Nf` in the text sets another for the
/// values after it (the spec itself is not printed; rs274 2.9, its
/// param_format_printing test and probes).
#[derive(Clone, Copy)]
enum ValueFormat {
    Decimals(usize),
    /// `%d`: rounded half up [?] (rs274 prints 2.7 as 3 and -2.5 as -2).
    Integer,
}

impl ValueFormat {
    fn show(self, v: f64) -> String {
        match self {
            ValueFormat::Decimals(n) => format!("{v:.n$}"),
            ValueFormat::Integer => format!("{}", (v + 0.5).floor() as i64),
        }
    }

    /// A format spec at the start of `s`, and its length.
    fn spec(s: &str) -> Option<(ValueFormat, usize)> {
        let b = s.as_bytes();
        match b.get(1)? {
            b'd' => Some((ValueFormat::Integer, 2)),
            b'f' => Some((ValueFormat::Decimals(4), 2)),
            b'.' => {
                let digits = b[2..].iter().take_while(|c| c.is_ascii_digit()).count();
                (digits > 0 && b.get(2 + digits) == Some(&b'f')).then(|| {
                    let n = s[2..2 + digits].parse().unwrap_or(6);
                    (ValueFormat::Decimals(n), 3 + digits)
                })
            }
            _ => None,
        }
    }
}

/// `#<name>` and `#123` in a DEBUG text replaced by their values (`%f`).
fn substitute(it: &Interp<'_, '_>, text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    let mut fmt = ValueFormat::Decimals(6);
    while let Some(i) = rest.find(['#', '%']) {
        out.push_str(&rest[..i]);
        if rest[i..].starts_with('%') {
            match ValueFormat::spec(&rest[i..]) {
                Some((f, len)) => {
                    fmt = f;
                    rest = &rest[i + len..];
                }
                None => {
                    out.push('%');
                    rest = &rest[i + 1..];
                }
            }
            continue;
        }
        let after = &rest[i + 1..];
        if let Some(name) = after
            .strip_prefix('<')
            .and_then(|a| a.find('>').map(|j| &a[..j]))
        {
            // Spaces inside a parameter name are ignored, as everywhere in a line.
            let key: String = name
                .chars()
                .filter(|c| !c.is_whitespace())
                .collect::<String>()
                .to_ascii_lowercase();
            match it.read_named(&key) {
                Some(v) => out.push_str(&fmt.show(v)),
                None => out.push_str("######"),
            }
            rest = &after[name.len() + 2..];
        } else {
            let digits: String = after.chars().take_while(|c| c.is_ascii_digit()).collect();
            if digits.is_empty() {
                out.push('#');
            } else {
                let n: u32 = digits.parse().unwrap_or(0);
                out.push_str(&fmt.show(it.read_numbered(n).unwrap_or(0.0)));
            }
            rest = &after[digits.len()..];
        }
    }
    out.push_str(rest);
    out
}

fn feed_mode(it: &mut Interp<'_, '_>, m: FeedMode) -> Result<(), Stop> {
    let (what, code) = match m {
        FeedMode::PerMinute => ("units per minute", 0),
        FeedMode::InverseTime => ("inverse time", 0),
        FeedMode::PerRevolution => ("units per revolution", 1),
    };
    it.out(Canon::Comment(format!(
        "interpreter: feed mode set to {what}"
    )));
    it.out(Canon::SetFeedMode(code));
    if m != FeedMode::InverseTime {
        it.out(Canon::SetFeedRate(0.0));
    }
    it.state.feed_mode = m;
    it.state.feed = 0.0;
    Ok(())
}

fn feed(it: &mut Interp<'_, '_>, v: &Value, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let f = it.value(v, exprs)?;
    if f < 0.0 {
        return Err(it.error_at(it.span, Code::BadWordValue, "Negative f word used"));
    }
    it.state.feed = f;
    if it.state.feed_mode != FeedMode::InverseTime {
        it.out(Canon::SetFeedRate(f));
    }
    Ok(())
}

fn speed(it: &mut Interp<'_, '_>, v: &Value, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let s = it.value(v, exprs)?;
    if s < 0.0 {
        return Err(it.error_at(it.span, Code::BadWordValue, "Negative s word used"));
    }
    it.state.speed = s;
    it.out(Canon::SetSpindleSpeed(s));
    Ok(())
}

pub(super) fn spindle(
    it: &mut Interp<'_, '_>,
    st: &SpindleState,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    match st {
        SpindleState::Cw => {
            it.state.spindle = SpindleDir::Cw;
            it.out(Canon::SpindleCw);
        }
        SpindleState::Ccw => {
            it.state.spindle = SpindleDir::Ccw;
            it.out(Canon::SpindleCcw);
        }
        SpindleState::Stop => {
            it.state.spindle = SpindleDir::Stopped;
            it.out(Canon::StopSpindle);
        }
        SpindleState::Orient(angle) => {
            let given = angle.is_some();
            let angle = match angle {
                Some(v) => it.value(v, exprs)?,
                None => 0.0,
            };
            let mode = aux::block_word(it, block, 'P', exprs)?;
            let wait = aux::block_word(it, block, 'Q', exprs)?;
            it.state.spindle = SpindleDir::Stopped;
            // LinuxCNC (`orient-by-words`): orient only with R or P, wait
            // only with Q; elsewhere always both.
            let by_words = it.spec.has(crate::dialect::Capability::OrientByWords);
            if !by_words || given || mode.is_some() {
                let mode = mode.unwrap_or(0.0) as i64;
                // LinuxCNC's [RS274NGC]ORIENT_OFFSET (0 without an INI).
                let angle = angle + it.opts.rs274.orient_offset;
                it.out(Canon::OrientSpindle { angle, mode });
            }
            if !by_words || wait.is_some() {
                it.out(Canon::WaitOrientComplete(wait.unwrap_or(0.0)));
            }
        }
    }
    Ok(())
}

pub(super) fn coolant(it: &mut Interp<'_, '_>, c: Coolant) -> Result<(), Stop> {
    match c {
        Coolant::Mist => {
            it.state.mist = true;
            it.out(Canon::MistOn);
        }
        Coolant::Flood => {
            it.state.flood = true;
            it.out(Canon::FloodOn);
        }
        Coolant::Off => {
            it.state.mist = false;
            it.state.flood = false;
            it.out(Canon::MistOff);
            it.out(Canon::FloodOff);
        }
        // rs274 has no canonical call for it and nothing the run computes
        // depends on it: kept in the meta-model, passed to the machine.
        Coolant::ThroughTool => {}
    }
    Ok(())
}

fn dwell(
    it: &mut Interp<'_, '_>,
    v: &Value,
    unit: DwellUnit,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let t = it.value(v, exprs)?;
    let seconds = match unit {
        DwellUnit::Seconds => t,
        DwellUnit::Milliseconds => t / 1000.0,
        DwellUnit::Revolutions if it.state.speed > 0.0 => t * 60.0 / it.state.speed,
        DwellUnit::Revolutions => t,
    };
    if seconds < 0.0 {
        return Err(it.error_at(it.span, Code::BadWordValue, "Negative dwell time"));
    }
    it.out(Canon::Dwell(seconds));
    Ok(())
}

fn plane(it: &mut Interp<'_, '_>, p: Plane) -> Result<(), Stop> {
    let cp = match p {
        Plane::XY => CanonPlane::XY,
        Plane::ZX => CanonPlane::XZ,
        Plane::YZ => CanonPlane::YZ,
    };
    if cp != it.state.plane {
        if let Err(e) = it.comp.check_plane_change() {
            return Err(it.comp_error(e));
        }
    }
    it.state.plane = cp;
    it.out(Canon::SelectPlane(cp));
    Ok(())
}

fn path_mode(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    mode: PathMode,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let word = |c: char| words.iter().find(|w| w.letter.eq_ignore_ascii_case(&c));
    match mode {
        PathMode::ExactStop => {
            it.state.path = PathControl::ExactStop;
            it.out(Canon::SetMotionControlMode(MotionMode::ExactStop));
        }
        PathMode::ExactPath => {
            it.state.path = PathControl::ExactPath;
            it.out(Canon::SetMotionControlMode(MotionMode::ExactPath));
        }
        PathMode::Continuous => {
            let p = match word('P') {
                Some(w) => it.value(&w.value, exprs)?,
                None => 0.0,
            };
            let q = match word('Q') {
                Some(w) => it.value(&w.value, exprs)?,
                None => p,
            };
            it.state.path = PathControl::Continuous {
                tolerance: p,
                naive: q,
            };
            it.out(Canon::SetMotionControlMode(MotionMode::Continuous(p)));
            it.out(Canon::SetNaivecamTolerance(q));
        }
        PathMode::CornerOverride => {
            // A feed change at corners, not a path change: the run goes on.
            let note = Diagnostic::new(
                Code::CornerFeedNotSimulated,
                "the feed override at corners is not simulated; the path is unchanged",
            )
            .primary(s.span, "corner feed override");
            it.diags.push(note);
        }
        PathMode::ExactStopBlock | PathMode::Tapping => {
            return Err(it.error_at(
                s.span,
                Code::UnsupportedHere,
                "this path mode is not run by the interpreter yet",
            ))
        }
    }
    Ok(())
}

fn stop(it: &mut Interp<'_, '_>, k: StopKind) -> Result<(), Stop> {
    match k {
        StopKind::Program => it.out(Canon::ProgramStop),
        StopKind::Optional => it.out(Canon::OptionalProgramStop),
        StopKind::PalletStop => {
            it.out(Canon::PalletShuttle);
            it.out(Canon::ProgramStop);
        }
        StopKind::End | StopKind::EndRewind => {
            super::machine::program_end(it, k == StopKind::EndRewind)?;
            return Err(Stop::End);
        }
    }
    Ok(())
}
