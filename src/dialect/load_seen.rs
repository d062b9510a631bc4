//! What reading one spec file keeps track of, in time linear in the
//! number of its entries: the keys already defined in this file (for
//! duplicate detection) and the code table being built, looked up by key,
//! with removals as holes until the file is read (a spec of 80k codes
//! took 27 s when each code was looked for in a list).

use super::load_items::Ctx;
use super::spec::CodeDef;
use crate::diag::{Code, Diagnostic};
use crate::ir::Decimal;
use crate::span::Span;
use std::collections::HashMap;

/// Keys of entries defined in this file, for duplicate detection.
#[derive(Default)]
pub(super) struct Seen {
    items: HashMap<String, Span>,
    /// How many `<variables>` this file defines.
    pub vars: usize,
}

impl Seen {
    pub fn check(&mut self, cx: &mut Ctx, key: String, what: &str, span: Span) {
        if key.starts_with("vars ") {
            self.vars += 1;
        }
        if let Some(first) = self.items.get(&key) {
            cx.diags.push(
                Diagnostic::new(Code::SpecDuplicate, format!("{what} is defined twice in this spec"))
                    .primary(span, "defined again here")
                    .secondary(*first, "first defined here")
                    .help("remove one; to change an inherited entry, define it once in the extending spec"),
            );
        } else {
            self.items.insert(key, span);
        }
    }
}

/// The key of a code: its letter and number as written without trailing
/// zeros (`G5.1`, `M3`).
pub(super) fn code_key(letter: char, code: Decimal) -> String {
    format!("{letter}{}", code.normalized().format(0, false))
}

/// The spec's codes while its file is read.
pub(super) struct Codes {
    list: Vec<Option<CodeDef>>,
    at: HashMap<String, usize>,
}

impl Codes {
    /// Takes the inherited codes (built by this loader: one per key).
    pub fn new(inherited: Vec<CodeDef>) -> Codes {
        let mut at = HashMap::new();
        for (i, c) in inherited.iter().enumerate() {
            at.entry(code_key(c.letter, c.code)).or_insert(i);
        }
        Codes {
            list: inherited.into_iter().map(Some).collect(),
            at,
        }
    }

    /// Adds a code, or replaces the one with its key in place.
    pub fn upsert(&mut self, c: CodeDef) {
        let key = code_key(c.letter, c.code);
        match self.at.get(&key) {
            Some(&i) => self.list[i] = Some(c),
            None => {
                self.at.insert(key, self.list.len());
                self.list.push(Some(c));
            }
        }
    }

    /// Removes the code with this key; whether there was one.
    pub fn remove(&mut self, letter: char, code: Decimal) -> bool {
        let Some(i) = self.at.remove(&code_key(letter, code)) else {
            return false;
        };
        self.list[i] = None;
        true
    }

    /// The codes in order, without the removed ones.
    pub fn finish(self) -> Vec<CodeDef> {
        self.list.into_iter().flatten().collect()
    }
}
