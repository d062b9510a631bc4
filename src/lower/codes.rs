//! The G and M words of a line: looked up in the dialect's code table
//! (E0203/E0204 when missing, E0213 when out of range) and checked against
//! each other (E0201 two motions, E0202 two codes of one modal group).

use crate::diag::{Code, Diagnostic, Severity};
use crate::dialect::{Capability, CodeDef, DialectSpec, Meaning};
use crate::ir::{Decimal, MotionKind};
use crate::span::Span;

/// A code word of a line, resolved against the spec.
#[derive(Clone, Debug)]
pub(super) struct CodeWord<'s> {
    pub letter: char,
    pub code: Decimal,
    pub span: Span,
    /// `None`: not in the table (kept as `Aux`).
    pub meaning: Option<Meaning>,
    pub def: Option<&'s CodeDef>,
}

impl CodeWord<'_> {
    /// `G1`, `M98`, `CIP` as written (without leading zeros).
    pub fn name(&self) -> String {
        if self.letter == '\0' {
            return pseudo_name(self.meaning);
        }
        format!("{}{}", self.letter, self.code)
    }

    /// Motion codes and fixed cycles: one of them per block.
    pub fn is_motion(&self) -> bool {
        matches!(
            self.meaning,
            Some(Meaning::Motion(_)) | Some(Meaning::Cycle(_))
        )
    }

    fn group(&self) -> Option<&str> {
        self.def.map(|d| d.group.as_str()).filter(|g| !g.is_empty())
    }
}

fn pseudo_name(m: Option<Meaning>) -> String {
    match m {
        Some(Meaning::Motion(MotionKind::ArcTangent)) => "CT".into(),
        _ => "CIP".into(),
    }
}

/// Siemens motion keywords that arrive as words without a value.
pub(super) fn pseudo_motion(address: &[u8]) -> Option<Meaning> {
    match address {
        b"CIP" => Some(Meaning::Motion(MotionKind::ArcThrough)),
        b"CT" => Some(Meaning::Motion(MotionKind::ArcTangent)),
        _ => None,
    }
}

/// The spec's answers for the G and M codes `0`..`99.9` a file has used:
/// the same lookup as [`DialectSpec::code`], asked once per code.
pub(super) struct Cache<'s> {
    /// Index `letter * 1000 + code × 10`; `None` until asked.
    slots: Vec<Option<Option<&'s CodeDef>>>,
}

impl Default for Cache<'_> {
    fn default() -> Self {
        Cache {
            slots: vec![None; 2000],
        }
    }
}

impl<'s> Cache<'s> {
    fn code(&mut self, letter: char, code: Decimal, spec: &'s DialectSpec) -> Option<&'s CodeDef> {
        let Some(i) = Self::slot(letter, code) else {
            return spec.code(letter, code);
        };
        *self.slots[i].get_or_insert_with(|| spec.code(letter, code))
    }

    fn slot(letter: char, code: Decimal) -> Option<usize> {
        let base = match letter {
            'G' => 0,
            'M' => 1000,
            _ => return None,
        };
        let tenths = match code.scale {
            0 => code.mantissa.checked_mul(10)?,
            1 => code.mantissa,
            _ => return None,
        };
        (0..1000).contains(&tenths).then(|| base + tenths as usize)
    }
}

/// Looks a numeric G/M word up, reporting unknown and out-of-range codes.
pub(super) fn resolve<'s>(
    letter: char,
    code: Decimal,
    span: Span,
    cache: &mut Cache<'s>,
    spec: &'s DialectSpec,
    diags: &mut Vec<Diagnostic>,
) -> CodeWord<'s> {
    let def = cache.code(letter, code, spec);
    let cw = CodeWord {
        letter,
        code,
        span,
        meaning: def.map(|d| d.meaning),
        def,
    };
    if code.is_negative() || (letter == 'M' && !code.is_integer()) {
        diags.push(
            Diagnostic::new(
                Code::InvalidValue,
                format!("`{letter}{code}` is not a valid {letter} code"),
            )
            .primary(
                span,
                "codes are whole numbers, G codes with at most one decimal",
            )
            .help("check the number"),
        );
        return cw;
    }
    if def.is_none() {
        diags.push(unknown(letter, code, span, spec));
    }
    cw
}

fn unknown(letter: char, code: Decimal, span: Span, spec: &DialectSpec) -> Diagnostic {
    let name = format!("{letter}{code}");
    if letter == 'G' {
        let help = known_elsewhere(letter, code, spec).unwrap_or_else(|| {
            format!(
                "check the number; if it is the machine builder's code (a tool-change or probing macro), describe the machine in a dialect file extending `{}`, with `<code letter=\"G\" number=\"{code}\" group=\"non-modal\" meaning=\"aux\" uses=\"...\"/>` for its words (and `run=\"pass\"` if the moves after it are as written), and load it with `--dialect-file`",
                spec.id
            )
        });
        return Diagnostic::new(
            Code::UnknownGCode,
            format!("`{name}` is not a G code of {}", spec.name),
        )
        .primary(span, "unknown G code")
        .help(help);
    }
    // M codes are the machine builder's: another dialect's is no hint.
    let d = Diagnostic::new(
        Code::UnknownMCode,
        format!("`{name}` is not an M code of {}", spec.name),
    )
    .help("machine builders add M codes: describe this one in a dialect spec loaded with `--dialect-file`");
    if spec.has(Capability::StrictMCodes) {
        d.primary(span, "unknown M code")
    } else {
        d.with_severity(Severity::Warning)
            .primary(span, "unknown M code, passed to the machine as written")
    }
}

/// Drops a code written again in its block where the control counts it
/// once ([`Capability::RepeatedCodeOnce`]), with a W0598 note.
pub(super) fn drop_repeats(
    codes: &mut Vec<CodeWord<'_>>,
    spec: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    if !spec.has(Capability::RepeatedCodeOnce) {
        return;
    }
    let mut i = 0;
    while i < codes.len() {
        let again = |c: &CodeWord<'_>| {
            c.letter != '\0' && c.letter == codes[i].letter && c.code == codes[i].code
        };
        let Some(first) = codes[..i].iter().find(|c| again(c)) else {
            i += 1;
            continue;
        };
        diags.push(
            Diagnostic::new(
                Code::RepeatedCode,
                format!("`{}` is written twice in this block", first.name()),
            )
            .primary(codes[i].span, "written again")
            .secondary(first.span, "first written here")
            .help("remove the second one: the control counts it once, but a control that refuses two codes of one group stops on it"),
        );
        codes.remove(i);
    }
}

/// Reports two motion codes, or two codes of one modal group, in a block.
pub(super) fn check_groups(
    codes: &[CodeWord<'_>],
    spec: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    for (i, later) in codes.iter().enumerate() {
        let Some(first) = codes[..i].iter().find(|c| conflicts(c, later, spec)) else {
            continue;
        };
        diags.push(conflict(first, later));
    }
}

fn conflicts(a: &CodeWord<'_>, b: &CodeWord<'_>, spec: &DialectSpec) -> bool {
    if a.is_motion() && b.is_motion() {
        return true;
    }
    if overridden_cancel(a, b) || overridden_cancel(b, a) {
        return false;
    }
    let exclusive = |g: &str| spec.group(g).map(|d| d.exclusive).unwrap_or(true);
    let together = |g: &str| {
        let allowed = spec.group(g).map(|d| d.together.as_slice()).unwrap_or(&[]);
        let ok = |m: Option<Meaning>| m.is_some_and(|m| allowed.contains(&m));
        ok(a.meaning) && ok(b.meaning) && a.meaning != b.meaning
    };
    a.letter == b.letter
        && a.group().is_some_and(|g| exclusive(g) && !together(g))
        && a.group() == b.group()
}

/// Is `cancel` a cycle cancel (G80) sharing its modal group with the
/// motion code `motion`? rs274 accepts `G80 G0 X1` and `G0 G80 X1`: the
/// motion code is the block's and the G80 counts for nothing (LinuxCNC's
/// reader skips a G80 when its group already has a code, and a later code
/// replaces a G80). A dialect with G80 in a group of its own (Fanuc's
/// group 09) never has the two in one group.
pub(super) fn overridden_cancel(cancel: &CodeWord<'_>, motion: &CodeWord<'_>) -> bool {
    cancel.meaning == Some(Meaning::CycleCancel)
        && motion.is_motion()
        && cancel.letter == motion.letter
        && cancel.group().is_some()
        && cancel.group() == motion.group()
}

/// Removes a G80 a motion code of its group overrides (see
/// [`overridden_cancel`]), with a W0581 note: the block's statements are
/// the motion code's, as rs274 runs it.
pub(super) fn drop_overridden_cancels(codes: &mut Vec<CodeWord<'_>>, diags: &mut Vec<Diagnostic>) {
    let overridden: Vec<usize> = (0..codes.len())
        .filter(|&i| codes.iter().any(|m| overridden_cancel(&codes[i], m)))
        .collect();
    for i in overridden.into_iter().rev() {
        let cancel = codes.remove(i);
        let motion = codes.iter().find(|m| overridden_cancel(&cancel, m));
        let mut d = Diagnostic::new(
            Code::CancelOverridden,
            format!(
                "`{}` has no effect beside the motion code `{}`",
                cancel.name(),
                motion.map(|m| m.name()).unwrap_or_default()
            ),
        )
        .primary(cancel.span, "overridden by the block's motion code")
        .help("remove it: the block's motion code sets the motion mode (as in rs274)");
        if let Some(m) = motion {
            d = d.secondary(m.span, "the block's motion code");
        }
        diags.push(d);
    }
}

fn conflict(first: &CodeWord<'_>, later: &CodeWord<'_>) -> Diagnostic {
    let (a, b) = (first.name(), later.name());
    if first.is_motion() && later.is_motion() {
        return Diagnostic::new(
            Code::TwoMotionCodes,
            format!("two motion codes in one block: `{a}` and `{b}`"),
        )
        .primary(later.span, "second motion code")
        .secondary(first.span, "first motion code")
        .help("a block asks for one motion: split it into two blocks or remove one code");
    }
    let group = first.group().unwrap_or_default();
    let d = Diagnostic::new(
        Code::ModalGroupConflict,
        format!("`{a}` and `{b}` are both in modal group `{group}`"),
    )
    .primary(later.span, "second code of the group")
    .secondary(first.span, "first code of the group");
    // Builders' posts pair one-shot codes their machine takes together
    // (`G91 G28 G53 Z0. W0.`): such a machine is described, not guessed.
    match (first.meaning, later.meaning) {
        (Some(m1), Some(m2)) if m1 != m2 && group == "non-modal" => d.help(format!(
            "codes of one modal group exclude each other: keep one per block; if this machine's builder takes them together, describe the machine in a dialect file extending this dialect, with `<group name=\"{group}\" together=\"{} {}\"/>`, and load it with `--dialect-file`",
            m1.name(),
            m2.name()
        )),
        _ => d.help("codes of one modal group exclude each other: keep one per block"),
    }
}

/// The built-in dialects that define the code, as advice: the program may
/// have been read as the wrong dialect (a Haas `.nc` read as Fanuc).
fn known_elsewhere(letter: char, code: Decimal, spec: &DialectSpec) -> Option<String> {
    let others: Vec<&str> = crate::dialect::builtin::builtins()
        .iter()
        .filter(|s| s.id != spec.id && s.family == spec.family && s.code(letter, code).is_some())
        .map(|s| s.id.as_str())
        .collect();
    let first = others.first()?;
    Some(format!(
        "{letter}{code} is a code of {}: if the program is for that control, read it with `--dialect {first}`",
        others.join(", ")
    ))
}
