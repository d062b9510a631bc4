//! The non-code words of one line, gathered once: repeated addresses are
//! reported (E0205), lengths written without a decimal point are converted
//! to increments where the dialect says so (W0001), and each word is marked
//! when a statement takes it, so the words nobody takes can be reported.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, IntegerLengths};
use crate::ir::{Axes, Coord, Decimal, Value, Word, AXIS_LETTERS};
use crate::span::Span;
use crate::syntax::WordSyntax;

/// An address to look up: `"CR"` or `'X'` (no allocation either way).
pub(super) trait Addr: Copy {
    /// The address packed into an integer (see [`key`]).
    fn key(self) -> u64;
    /// `0..26` for a one-letter address `A`..`Z`.
    fn letter(self) -> Option<usize>;
}

impl Addr for &str {
    fn key(self) -> u64 {
        key(self.as_bytes())
    }
    fn letter(self) -> Option<usize> {
        match self.as_bytes() {
            [b] => letter_index(*b),
            _ => None,
        }
    }
}

impl Addr for char {
    fn key(self) -> u64 {
        if self.is_ascii() {
            self as u64
        } else {
            u64::MAX
        }
    }
    fn letter(self) -> Option<usize> {
        u8::try_from(self).ok().and_then(letter_index)
    }
}

fn letter_index(b: u8) -> Option<usize> {
    b.is_ascii_uppercase().then(|| usize::from(b - b'A'))
}

/// Addresses are short: up to 8 bytes packed into a `u64` compare in one
/// instruction (longer ones get a key no lookup uses).
fn key(b: &[u8]) -> u64 {
    if b.len() > 8 {
        return u64::MAX - 1;
    }
    b.iter()
        .enumerate()
        .fold(0u64, |k, (i, &c)| k | (c as u64) << (8 * i))
}

/// E0205: the address of `w` was already given in the block, at `first`.
pub(super) fn repeated(w: &WordSyntax, first: Span) -> Diagnostic {
    Diagnostic::new(
        Code::RepeatedWord,
        format!("`{}` is given twice in this block", w.address),
    )
    .primary(w.span, "repeated here")
    .secondary(first, "first given here")
    .help("keep one of the two words; a block holds each address once")
}

/// One word and whether a statement has taken it.
pub(super) struct Entry {
    pub w: WordSyntax,
    pub used: bool,
    key: u64,
}

/// The words of a line in source order.
#[derive(Default)]
pub(super) struct Words {
    list: Vec<Entry>,
    /// For each one-letter address `A`..`Z`: 1 + its index in `list`, or 0.
    letters: [u32; 26],
    /// Whether `list` holds any other address (looked up by scanning).
    others: bool,
    /// How many words of `list` no statement has taken yet.
    free: usize,
    /// The span of the words taken since the last [`Words::begin`].
    taken: Option<Span>,
    /// Whether a second `T` is kept aside as the next tool rather than
    /// reported (the spec's `second-tool-preselects`; set per file).
    pub second_tool: bool,
    /// The second `T` of the line, when `second_tool` allows one.
    preselect: Option<WordSyntax>,
}

impl Words {
    /// Empties the set, keeping its buffers for the next line.
    pub fn clear(&mut self) {
        self.list.clear();
        self.letters = [0; 26];
        self.others = false;
        self.free = 0;
        self.taken = None;
        self.preselect = None;
    }

    /// The line's second `T` word (`T1 T2 M6`), kept aside by [`Words::push`].
    pub fn take_preselect(&mut self) -> Option<WordSyntax> {
        self.preselect.take()
    }

    /// Adds a word, reporting a repeated address (the repeat is kept aside
    /// in `extra` so that nothing is lost).
    pub fn push(
        &mut self,
        w: &WordSyntax,
        diags: &mut Vec<Diagnostic>,
        extra: &mut Vec<WordSyntax>,
    ) {
        let letter = match w.address.as_bytes() {
            [b] => letter_index(*b),
            _ => None,
        };
        let first = match letter {
            Some(l) => self.letters[l].checked_sub(1).map(|i| i as usize),
            None if self.others => self.list.iter().position(|e| e.w.address == w.address),
            None => None,
        };
        if let Some(first) = first {
            if self.second_tool && w.address == "T" && self.preselect.is_none() {
                self.preselect = Some(w.clone());
                return;
            }
            diags.push(repeated(w, self.list[first].w.span));
            extra.push(w.clone());
            return;
        }
        match letter {
            Some(l) => self.letters[l] = self.list.len() as u32 + 1,
            None => self.others = true,
        }
        let key = key(w.address.as_bytes());
        self.list.push(Entry {
            w: w.clone(),
            used: false,
            key,
        });
        self.free += 1;
    }

    /// Whether any word is still free (when not, every lookup of a free
    /// word answers `None`, and callers may skip them).
    #[inline]
    pub fn any_free(&self) -> bool {
        self.free > 0
    }

    #[inline]
    fn find(&self, addr: impl Addr) -> Option<usize> {
        if let Some(l) = addr.letter() {
            return self.letters[l].checked_sub(1).map(|i| i as usize);
        }
        if !self.others {
            return None;
        }
        let k = addr.key();
        self.list.iter().position(|e| e.key == k)
    }

    /// Whether the line has a word with this address (taken or not).
    #[inline]
    pub fn has(&self, addr: impl Addr) -> bool {
        self.find(addr).is_some()
    }

    /// Whether the line has this word and nobody took it yet.
    #[inline]
    pub fn has_free(&self, addr: impl Addr) -> bool {
        self.find(addr).map(|i| !self.list[i].used).unwrap_or(false)
    }

    /// The word, if present (taken or not).
    #[inline]
    pub fn get(&self, addr: impl Addr) -> Option<&WordSyntax> {
        self.find(addr).map(|i| &self.list[i].w)
    }

    /// A word not yet taken by a statement.
    #[inline]
    pub fn get_free(&self, addr: impl Addr) -> Option<&WordSyntax> {
        self.find(addr)
            .filter(|&i| !self.list[i].used)
            .map(|i| &self.list[i].w)
    }

    /// Starts recording the spans of taken words for one statement.
    pub fn begin(&mut self) {
        self.taken = None;
    }

    /// The span of the words taken since [`Words::begin`] (`None`: none).
    pub fn taken_span(&self) -> Option<Span> {
        self.taken
    }

    fn mark_taken(&mut self, span: Span) {
        self.taken = Some(self.taken.map_or(span, |t| t.to(span)));
    }

    /// Takes a free word, giving a reference to it.
    #[inline]
    fn take_ref(&mut self, addr: impl Addr) -> Option<&WordSyntax> {
        let i = self.find(addr)?;
        if self.list[i].used {
            return None;
        }
        self.list[i].used = true;
        self.free -= 1;
        self.mark_taken(self.list[i].w.span);
        Some(&self.list[i].w)
    }

    /// Takes a free word.
    #[inline]
    pub fn take(&mut self, addr: impl Addr) -> Option<WordSyntax> {
        self.take_ref(addr).cloned()
    }

    #[inline]
    pub fn value(&mut self, addr: impl Addr) -> Option<Value> {
        self.take_ref(addr).map(|w| w.value.clone())
    }

    #[inline]
    pub fn coord(&mut self, addr: impl Addr) -> Option<Coord> {
        self.take_ref(addr).map(|w| Coord {
            value: w.value.clone(),
            dim: w.dim,
            span: w.span,
        })
    }

    /// Whether any free axis word is present.
    pub fn has_free_axes(&self) -> bool {
        AXIS_LETTERS.iter().any(|a| self.has_free(*a))
    }

    /// Takes every free axis word.
    pub fn take_axes(&mut self) -> Axes {
        let mut axes = Axes::default();
        self.take_axes_into(&mut axes);
        axes
    }

    /// Takes the machine-axis words `X1=`..`C1=` (Siemens `G74 Z1=0`) as
    /// the axes they name.
    pub fn take_machine_axes(&mut self) -> Axes {
        let mut axes = Axes::default();
        self.take_axis_words(&mut axes, |w, a| w.find(format!("{a}1").as_str()));
        axes
    }

    /// Takes the axis words into `axes` (which is left as it was for the others).
    pub fn take_axes_into(&mut self, axes: &mut Axes) {
        self.take_axis_words(axes, |w, a| w.find(a));
    }

    /// Takes, for each axis letter, the free word `find` gives for it.
    fn take_axis_words(&mut self, axes: &mut Axes, find: impl Fn(&Self, char) -> Option<usize>) {
        for a in AXIS_LETTERS {
            let Some(i) = find(self, a) else { continue };
            let e = &mut self.list[i];
            if e.used {
                continue;
            }
            e.used = true;
            self.free -= 1;
            if let Some(slot) = axes.slot_mut(a) {
                put_coord(slot, &e.w);
            }
            let span = e.w.span;
            self.mark_taken(span);
        }
    }

    /// Takes every free word, in source order.
    pub fn take_free(&mut self) -> Vec<WordSyntax> {
        if self.free == 0 {
            return Vec::new();
        }
        self.free = 0;
        self.list
            .iter_mut()
            .filter(|e| !e.used)
            .map(|e| {
                e.used = true;
                e.w.clone()
            })
            .collect()
    }

    /// Takes every free single-letter word in source order, but those in `except`.
    pub fn take_all_letters(&mut self, except: &[char]) -> Vec<Word> {
        let mut out = Vec::new();
        for i in 0..self.list.len() {
            let e = &self.list[i];
            let Some(letter) = single_letter(&e.w.address) else {
                continue;
            };
            if e.used || except.contains(&letter) {
                continue;
            }
            self.list[i].used = true;
            self.free -= 1;
            self.mark_taken(self.list[i].w.span);
            out.push(Word::new(
                letter,
                self.list[i].w.value.clone(),
                self.list[i].w.span,
            ));
        }
        out
    }
}

/// Writes a word's coordinate straight into its slot. Not inlined: inlined,
/// the coordinate is assembled on the stack and copied, which stalls.
#[inline(never)]
fn put_coord(slot: &mut Option<Coord>, w: &WordSyntax) {
    *slot = Some(Coord {
        value: w.value.clone(),
        dim: w.dim,
        span: w.span,
    });
}

/// The letter of a one-letter address, read without a UTF-8 check when ASCII.
pub(super) fn address_letter(a: &crate::syntax::Address) -> Option<char> {
    match a.as_bytes() {
        [b] => Some(char::from(*b)),
        b if b.len() <= 4 => single_letter(a),
        _ => None,
    }
}

/// The letter of a one-letter address.
pub(super) fn single_letter(addr: &str) -> Option<char> {
    let mut cs = addr.chars();
    match (cs.next(), cs.next()) {
        (Some(c), None) => Some(c),
        _ => None,
    }
}

/// `value × increment`, exactly; `None` on overflow.
fn times(value: Decimal, inc: Decimal) -> Option<Decimal> {
    let m = value.mantissa.checked_mul(inc.mantissa)?;
    let scale = value.scale.checked_add(inc.scale)?;
    Some(Decimal {
        mantissa: m,
        scale,
        point: true,
    })
}

/// Whether the dialect reads lengths without a decimal point in increments.
pub(super) fn converts_increments(spec: &DialectSpec) -> bool {
    spec.numbers.integer_lengths == IntegerLengths::Increments
}

/// Converts lengths written without a decimal point into increments when
/// the dialect reads them so; one warning per line labels every such word.
pub(super) fn convert_increments(
    words: &mut [WordSyntax],
    spec: &DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    if !converts_increments(spec) {
        return;
    }
    let mut warn: Option<Diagnostic> = None;
    let arc = has_arc_code(words, spec);
    for w in words.iter_mut() {
        let Some(letter) = address_letter(&w.address) else {
            continue;
        };
        let Value::Number(d) = w.value else { continue };
        if d.point || w.extended || !spec.is_length_address(letter) {
            continue;
        }
        // The repeat letter (Fanuc K) is a count unless an arc uses it as a centre.
        if letter == spec.repeat_letter && !arc {
            continue;
        }
        let (Some(mm), Some(inch)) = (
            times(d, spec.numbers.increment_mm),
            times(d, spec.numbers.increment_inch),
        ) else {
            diags.push(
                Diagnostic::new(
                    Code::InvalidValue,
                    format!("`{}{}` is too large to read in increments", w.address, d),
                )
                .primary(w.span, "too many digits")
                .help("write the length with a decimal point"),
            );
            continue;
        };
        w.value = Value::Number(mm);
        if d.mantissa == 0 {
            continue;
        }
        let label = format!("read as {mm} mm ({inch} in under G20)");
        let diag = warn.take().unwrap_or_else(|| {
            Diagnostic::new(
                Code::LengthWithoutPoint,
                "lengths without a decimal point are read in least input increments",
            )
            .help("write a decimal point (`X10.`) if whole millimetres or inches are meant")
        });
        warn = Some(diag.primary(w.span, label));
    }
    diags.extend(warn);
}

/// Does the block hold an arc code (whose K would be a centre word)?
fn has_arc_code(words: &[WordSyntax], spec: &DialectSpec) -> bool {
    use crate::dialect::Meaning;
    use crate::ir::MotionKind;
    words.iter().any(|w| {
        w.address.as_bytes() == b"G"
            && matches!(w.value, Value::Number(d) if matches!(
                spec.code('G', d).map(|c| c.meaning),
                Some(Meaning::Motion(MotionKind::Arc(_)))
            ))
    })
}
