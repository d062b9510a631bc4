//! What a comment or an operator message may hold on a target, and how a
//! writer makes any text safe for it (`<text>` in a dialect spec): the
//! characters its reader treats as something else (`%` ends a tape, a
//! trailing `~` continues a Klartext block, `)` closes a comment, `"` ends a
//! string), the words that make a comment a command (LinuxCNC's
//! `(LOGOPEN,..)`, `(PY,..)`, `(MSG,..)`...), and whether the target reads
//! only 7-bit text. Control characters (but tabs) never reach a program.

/// Where the text is written: the form decides which delimiter it must
/// not hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextForm {
    /// `( text )`.
    Paren,
    /// `; text` to the end of the line.
    Semicolon,
    /// A quoted string: `MSG("text")`.
    Quoted,
    /// A name (program names, `* heading` lines): one line, no delimiter.
    Plain,
}

impl TextForm {
    pub fn parse(s: &str) -> Option<TextForm> {
        match s {
            "paren" => Some(TextForm::Paren),
            "semicolon" => Some(TextForm::Semicolon),
            "quoted" => Some(TextForm::Quoted),
            "plain" => Some(TextForm::Plain),
            _ => None,
        }
    }
}

/// One character a comment may not hold, and what is written instead.
#[derive(Clone, Debug, PartialEq)]
pub struct Replace {
    pub ch: char,
    pub with: String,
    /// Only in this form (all forms when `None`).
    pub form: Option<TextForm>,
}

/// A word that makes a comment a command when it opens it (after spaces,
/// any case), followed by a comma (after spaces) when `comma`.
#[derive(Clone, Debug, PartialEq)]
pub struct ActiveWord {
    pub word: String,
    pub comma: bool,
}

#[derive(Clone, Debug, PartialEq, Default)]
pub struct TextRules {
    /// The target reads 7-bit text only.
    pub ascii: bool,
    pub replace: Vec<Replace>,
    pub active: Vec<ActiveWord>,
    /// Written instead of an active word's comma.
    pub comma_with: String,
    /// Written before an active word that takes no comma.
    pub prefix_with: String,
}

/// What [`TextRules::escape`] changed, for the writer's warnings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Escaped {
    pub text: String,
    /// The active word neutralised, if any.
    pub neutralised: Option<String>,
    /// Characters replaced because the reader would take them as syntax.
    pub replaced: Vec<char>,
    /// Non-ASCII characters written as ASCII.
    pub transliterated: bool,
}

impl Escaped {
    pub fn changed(&self) -> bool {
        self.neutralised.is_some() || !self.replaced.is_empty() || self.transliterated
    }
}

impl TextRules {
    /// `text` made safe to write in `form`. With `keep_active`, an active
    /// word is left as it is (the text came from this same dialect, where
    /// it was already a command).
    pub fn escape(&self, text: &str, form: TextForm, keep_active: bool) -> Escaped {
        self.escape_as(text, form, keep_active, false)
    }

    /// [`Self::escape`]; with `keep_chars`, the text came from this same
    /// dialect, whose control read its characters: they are not
    /// transliterated, so a round trip keeps a comment's bytes.
    pub fn escape_as(
        &self,
        text: &str,
        form: TextForm,
        keep_active: bool,
        keep_chars: bool,
    ) -> Escaped {
        let mut out = Escaped::default();
        let mut s = String::with_capacity(text.len());
        for c in text.chars() {
            if c.is_control() && c != '\t' {
                s.push(' ');
                note(&mut out.replaced, c);
            } else if let Some(r) = self.rule_for(c, form) {
                s.push_str(&r.with);
                note(&mut out.replaced, c);
            } else if let Some(r) = delimiter(c, form) {
                s.push(r);
                note(&mut out.replaced, c);
            } else if self.ascii && !c.is_ascii() && !keep_chars {
                out.transliterated = true;
                s.push_str(transliterate(c));
            } else {
                s.push(c);
            }
        }
        if !keep_active {
            out.neutralised = self.neutralise(&mut s);
        }
        out.text = s;
        out
    }

    /// `text` in the target's characters: for a 7-bit target, letters
    /// without their accents and other characters as `?`; `None` when
    /// nothing changes.
    pub fn to_charset(&self, text: &str) -> Option<String> {
        if !self.ascii || text.is_ascii() {
            return None;
        }
        Some(
            text.chars()
                .map(|c| {
                    if c.is_ascii() {
                        c.to_string()
                    } else {
                        transliterate(c).to_string()
                    }
                })
                .collect(),
        )
    }

    fn rule_for(&self, c: char, form: TextForm) -> Option<&Replace> {
        self.replace
            .iter()
            .find(|r| r.ch == c && r.form.is_none_or(|f| f == form))
    }

    /// The active word `text` opens with, if any: its byte range and the
    /// range of its comma.
    pub fn active_word(&self, text: &str) -> Option<(&ActiveWord, usize, Option<usize>)> {
        let lead = text.len() - text.trim_start().len();
        let rest = &text[lead..];
        self.active.iter().find_map(|a| {
            let n = a.word.len();
            let head = rest.get(..n)?;
            if !head.eq_ignore_ascii_case(&a.word) {
                return None;
            }
            if !a.comma {
                return Some((a, lead, None));
            }
            let after = &rest[n..];
            let sp = after.len() - after.trim_start().len();
            after[sp..]
                .starts_with(',')
                .then_some((a, lead, Some(lead + n + sp)))
        })
    }

    /// Changes the active word `s` opens with so that it stays text.
    /// Repeats, since a change could uncover another word.
    pub fn neutralise(&self, s: &mut String) -> Option<String> {
        let mut found = None;
        for _ in 0..4 {
            let Some((a, at, comma)) = self.active_word(s) else {
                break;
            };
            found = Some(a.word.clone());
            match comma {
                Some(c) => s.replace_range(c..c + 1, &self.comma_with),
                None => s.insert_str(at, &self.prefix_with),
            }
        }
        found
    }
}

/// What no table can allow: the form's own delimiters (`( )` nest in no
/// reader cncc knows, `"` ends a string).
fn delimiter(c: char, form: TextForm) -> Option<char> {
    match (form, c) {
        (TextForm::Paren, '(') => Some('['),
        (TextForm::Paren, ')') => Some(']'),
        (TextForm::Quoted, '"') => Some('\''),
        _ => None,
    }
}

fn note(list: &mut Vec<char>, c: char) {
    if !list.contains(&c) {
        list.push(c);
    }
}

/// The nearest ASCII for a character (`é` → `e`, `ß` → `ss`), or `?`.
pub fn transliterate(c: char) -> &'static str {
    const TABLE: &[(&str, &str)] = &[
        ("ÀÁÂÃÅĀĂĄ", "A"),
        ("àáâãåāăą", "a"),
        ("ÇĆĈĊČ", "C"),
        ("çćĉċč", "c"),
        ("ĎĐ", "D"),
        ("ďđ", "d"),
        ("ÈÉÊËĒĔĖĘĚ", "E"),
        ("èéêëēĕėęě", "e"),
        ("ĜĞĠĢ", "G"),
        ("ĝğġģ", "g"),
        ("ÌÍÎÏĨĪĬĮİ", "I"),
        ("ìíîïĩīĭįı", "i"),
        ("ŁĹĻĽ", "L"),
        ("łĺļľ", "l"),
        ("ÑŃŅŇ", "N"),
        ("ñńņň", "n"),
        ("ÒÓÔÕŌŎŐ", "O"),
        ("òóôõōŏő", "o"),
        ("ŔŖŘ", "R"),
        ("ŕŗř", "r"),
        ("ŚŜŞŠ", "S"),
        ("śŝşš", "s"),
        ("ŢŤ", "T"),
        ("ţť", "t"),
        ("ÙÚÛŨŪŬŮŰŲ", "U"),
        ("ùúûũūŭůűų", "u"),
        ("ÝŸ", "Y"),
        ("ýÿ", "y"),
        ("ŹŻŽ", "Z"),
        ("źżž", "z"),
        ("Ä", "AE"),
        ("ä", "ae"),
        ("Ö", "OE"),
        ("ö", "oe"),
        ("Ü", "UE"),
        ("ü", "ue"),
        ("ß", "ss"),
        ("Æ", "AE"),
        ("æ", "ae"),
        ("°", "DEG"),
        ("ø⌀Ø", "D"),
        ("±", "+-"),
        ("×", "x"),
        ("µμ", "u"),
        ("‘’′", "'"),
        ("“”″", "'"),
        ("–—", "-"),
    ];
    TABLE
        .iter()
        .find(|(from, _)| from.contains(c))
        .map_or("?", |(_, to)| to)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn linuxcnc() -> TextRules {
        crate::dialect::builtin("linuxcnc").unwrap().text.clone()
    }

    #[test]
    fn linuxcnc_active_comments_are_neutralised_in_any_case_and_spacing() {
        let r = linuxcnc();
        for t in [
            "LOGOPEN,/home/cnc/x",
            "  py,__import__('os')",
            "msg ,hello",
            "Abort,",
            "LOGCLOSE",
            "probeopen f.txt",
        ] {
            let e = r.escape(t, TextForm::Paren, false);
            assert!(e.neutralised.is_some(), "{t}");
            assert!(r.active_word(&e.text).is_none(), "{t} -> {}", e.text);
        }
        let e = r.escape("PRINTED PART, 2 OFF", TextForm::Paren, false);
        assert_eq!(e.text, "PRINTED PART, 2 OFF");
        assert!(!e.changed());
    }

    #[test]
    fn same_dialect_keeps_its_active_comments() {
        let e = linuxcnc().escape("DEBUG,#1", TextForm::Paren, true);
        assert_eq!(e.text, "DEBUG,#1");
    }

    #[test]
    fn percent_tilde_parens_and_controls() {
        let fanuc = crate::dialect::builtin("fanuc").unwrap().text.clone();
        let e = fanuc.escape("50% (A)\nB", TextForm::Paren, false);
        assert!(!e.text.contains(['%', '(', ')', '\n']), "{}", e.text);
        let tnc = crate::dialect::builtin("heidenhain").unwrap().text.clone();
        let e = tnc.escape("RETRACT ~", TextForm::Semicolon, false);
        assert!(!e.text.trim_end().ends_with('~'), "{}", e.text);
    }

    #[test]
    fn seven_bit_targets_get_ascii() {
        let fanuc = crate::dialect::builtin("fanuc").unwrap().text.clone();
        let e = fanuc.escape("Bohrung Ø12 für Möbel", TextForm::Paren, false);
        assert!(e.text.is_ascii() && e.transliterated, "{}", e.text);
        assert_eq!(e.text, "Bohrung D12 fuer Moebel");
    }
}
