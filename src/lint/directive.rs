//! Inline directives in comments, in each dialect's comment syntax:
//! `(cncc: ignore[W0701])`, `; cncc: ignore[W0701, rapid-below-cut]`.
//! A directive silences the lint findings of its block; in a block of
//! comments alone, of the next block with statements. `cncc: ignore`
//! without a list silences every lint rule there, and
//! `cncc: ignore-file[...]` the whole file.

use crate::diag::{Code, Diagnostic};
use crate::ir::{Block, StmtKind};
use crate::span::Span;

/// Codes a directive names; None: every lint rule.
type Codes = Option<Vec<Code>>;

#[derive(Debug, Default)]
pub struct Directives {
    /// Block spans with the codes silenced there.
    blocks: Vec<(Span, Codes)>,
    /// Directives of a comment-only block, waiting for the next block.
    pending: Vec<Codes>,
    file: Vec<Codes>,
}

impl Directives {
    /// Reads the directives in the comments of one block.
    pub fn read(&mut self, b: &Block) {
        let mut here = Vec::new();
        let mut only_comments = true;
        for s in &b.stmts {
            match &s.kind {
                StmtKind::Comment { text, .. } | StmtKind::Message(Some(text)) => {
                    for (file, codes) in parse(text) {
                        if file {
                            self.file.push(codes);
                        } else {
                            here.push(codes);
                        }
                    }
                }
                _ => only_comments = false,
            }
        }
        if b.stmts.is_empty() {
            return;
        }
        if only_comments {
            self.pending.extend(here);
            return;
        }
        for c in std::mem::take(&mut self.pending).into_iter().chain(here) {
            self.blocks.push((b.span, c));
        }
    }

    /// Whether a finding is silenced by a directive.
    pub fn suppresses(&self, d: &Diagnostic) -> bool {
        let names = |c: &Codes| c.as_ref().is_none_or(|l| l.contains(&d.code));
        if self.file.iter().any(names) {
            return true;
        }
        let Some(at) = d.span() else { return false };
        self.blocks.iter().any(|(s, c)| {
            s.file == at.file
                && s.start <= at.start
                && at.start < s.end.max(s.start + 1)
                && names(c)
        })
    }
}

/// The directives in a comment's text: (whole file?, codes).
pub fn parse(text: &str) -> Vec<(bool, Codes)> {
    let mut out = Vec::new();
    let lower = text.to_ascii_lowercase();
    let mut from = 0;
    while let Some(i) = lower[from..].find("cncc:") {
        let rest = lower[from + i + 5..].trim_start();
        let offset = lower.len() - rest.len();
        from = offset;
        let (file, after) = if let Some(r) = rest.strip_prefix("ignore-file") {
            (true, r)
        } else if let Some(r) = rest.strip_prefix("ignore") {
            (false, r)
        } else {
            continue;
        };
        let codes = after
            .strip_prefix('[')
            .and_then(|r| r.find(']').map(|j| &r[..j]))
            .map(|list| {
                list.split([',', ' '])
                    .filter(|s| !s.is_empty())
                    .filter_map(Code::lookup)
                    .filter(|c| super::rules::rule(*c).is_some())
                    .collect::<Vec<_>>()
            });
        out.push((file, codes));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directives_in_comment_text() {
        assert_eq!(
            parse("cncc: ignore[W0701]"),
            vec![(false, Some(vec![Code::LintFeedSpindleStopped]))]
        );
        assert_eq!(
            parse("probe move  CNCC: ignore[w0701, rapid-below-cut]"),
            vec![(
                false,
                Some(vec![Code::LintFeedSpindleStopped, Code::LintRapidBelowCut])
            )]
        );
        assert_eq!(parse("cncc: ignore"), vec![(false, None)]);
        assert_eq!(
            parse("cncc: ignore-file[W0710]"),
            vec![(true, Some(vec![Code::LintNoUnits]))]
        );
        assert!(parse("cncc is great").is_empty());
    }
}
