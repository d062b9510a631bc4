//! `cncc post --summary`: what each workingstep of a plan was posted as.
//! The writer notes every template it renders while a workingstep is
//! being written; the templates that make the program's frame (comments,
//! tool change, spindle, coolant, approach) are left out, the moves of an
//! explicit toolpath are counted, and what remains is the target's cycle
//! (`drill`, `pocket_rect`, ...), named as the template files are
//! (docs/posts.md lists them).

use super::names::{feature_kind, operation_kind};
use super::plan::Step;

/// One workingstep (or several that share a cycle) as posted.
#[derive(Clone, Debug, Default)]
pub struct PostedStep {
    /// The workingsteps' numbers and ids.
    pub steps: Vec<(usize, String)>,
    pub feature: String,
    pub operation: String,
    pub tool: u32,
    /// Templates rendered, in order, each once, with how often.
    pub templates: Vec<(String, usize)>,
    /// Still being written (what is rendered is its).
    pub open: bool,
}

/// Templates that every workingstep renders around its body.
const FRAME: &[&str] = &[
    "comment",
    "coolant",
    "spindle",
    "tool_change",
    "tool_data",
    "approach",
    "retract",
    "tolerance",
    "cycle_end",
    "begin",
    "end",
    "stop",
];
/// Templates that write an explicit toolpath's moves.
const MOVES: &[&str] = &["rapid", "line", "arc", "helix"];
/// The template that calls a modal cycle at one more position.
const POSITION: &str = "hole_at";

impl PostedStep {
    pub fn new(steps: &[&Step<'_>]) -> Self {
        let s = steps[0];
        PostedStep {
            steps: steps.iter().map(|s| (s.number, s.ws.id.clone())).collect(),
            feature: format!("{} {}", feature_kind(&s.feature.kind), s.feature.id),
            operation: operation_kind(&s.op.kind),
            tool: s.tool_no,
            templates: Vec::new(),
            open: true,
        }
    }

    /// Notes that template `name` (`drill.j2`) was rendered.
    pub fn rendered(&mut self, name: &str) {
        let name = name.trim_end_matches(".j2");
        match self.templates.iter_mut().find(|(n, _)| n == name) {
            Some((_, k)) => *k += 1,
            None => self.templates.push((name.to_string(), 1)),
        }
    }

    /// What the workingstep became: the cycles, then the explicit moves.
    pub fn posted_as(&self) -> String {
        let is = |set: &[&str], n: &str| set.contains(&n);
        let mut parts: Vec<String> = self
            .templates
            .iter()
            .filter(|(n, _)| !is(FRAME, n) && !is(MOVES, n) && n != POSITION)
            .map(|(n, k)| match k {
                1 => format!("cycle `{n}`"),
                _ => format!("cycle `{n}` x{k}"),
            })
            .collect();
        if let Some((_, k)) = self.templates.iter().find(|(n, _)| n == POSITION) {
            parts.push(format!("at {k} position{}", if *k == 1 { "" } else { "s" }));
        }
        let moves: usize = self
            .templates
            .iter()
            .filter(|(n, _)| is(MOVES, n))
            .map(|(_, k)| k)
            .sum();
        if moves > 0 {
            parts.push(format!("explicit toolpath, {moves} moves"));
        }
        match parts.is_empty() {
            true => "nothing but its frame".into(),
            false => parts.join(" + "),
        }
    }

    /// One line of the summary.
    pub fn line(&self) -> String {
        let ids: Vec<String> = self
            .steps
            .iter()
            .map(|(n, id)| format!("WS({n}) {id}"))
            .collect();
        format!(
            "{}: {}, {}, T{} -> {}",
            ids.join(", "),
            self.feature.trim_end(),
            self.operation,
            self.tool,
            self.posted_as()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cycles_are_named_and_moves_counted() {
        let mut p = PostedStep {
            steps: vec![(3, "DRILL".into())],
            feature: "round_hole H1".into(),
            operation: "drilling".into(),
            tool: 2,
            templates: Vec::new(),
            open: true,
        };
        for t in [
            "comment.j2",
            "tool_change.j2",
            "drill.j2",
            "hole_at.j2",
            "hole_at.j2",
        ] {
            p.rendered(t);
        }
        assert_eq!(p.posted_as(), "cycle `drill` + at 2 positions");
        for t in ["rapid.j2", "line.j2", "line.j2", "arc.j2"] {
            p.rendered(t);
        }
        assert_eq!(
            p.line(),
            "WS(3) DRILL: round_hole H1, drilling, T2 -> cycle `drill` + at 2 positions + explicit toolpath, 4 moves"
        );
    }
}
