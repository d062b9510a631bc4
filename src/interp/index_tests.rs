//! The flow index against a plain reference (the innermost open opener
//! looked up by scanning the whole stack) on small programs with stray and
//! crossed closers, and on programs nested 100,000 deep.

use super::*;
use crate::dialect::builtin::builtin;
use crate::span::FileId;

fn read(dialect: &str, text: &str) -> Program {
    let spec = builtin(dialect).expect("dialect");
    crate::driver::read_program(text, FileId(0), &spec).0
}

/// The index as a scan of the open stack finds it (quadratic in depth; only
/// for small programs).
fn reference(p: &Program) -> FlowIndex {
    let mut ix = FlowIndex::default();
    let mut stack: Vec<(Kind, FlowId, usize)> = Vec::new();
    let mut last: HashMap<usize, usize> = HashMap::new();
    for (i, b) in p.blocks.iter().enumerate() {
        if let Some(&(_, _, top)) = stack.iter().rev().find(|e| e.0.is_loop()) {
            ix.loop_of.insert(i, top);
        }
        for s in &b.stmts {
            reference_stmt(&mut ix, i, &s.kind, &mut stack, &mut last);
        }
    }
    ix
}

fn reference_stmt(
    ix: &mut FlowIndex,
    i: usize,
    kind: &StmtKind,
    stack: &mut Vec<(Kind, FlowId, usize)>,
    last: &mut HashMap<usize, usize>,
) {
    use StmtKind::*;
    let nested = FlowId::Nested;
    let (k, id, opens) = match kind {
        If { id, .. } => (Kind::If, id, true),
        While { id, .. } => (Kind::While, id, true),
        Do { id } => (Kind::Do, id, true),
        Repeat { id, .. } => (Kind::Repeat, id, true),
        For { .. } => (Kind::For, &nested, true),
        Loop => (Kind::Loop, &nested, true),
        RepeatUntil => (Kind::RepeatUntil, &nested, true),
        SubStart { id, .. } => (Kind::Sub, id, true),
        ElseIf { id, .. } | Else { id } => {
            if let Some(&(_, _, o)) = stack.iter().rev().find(|e| e.0 == Kind::If && &e.1 == id) {
                let from = last.get(&o).copied().unwrap_or(o);
                ix.next_branch.insert(from, i);
                last.insert(o, i);
            }
            return;
        }
        EndIf { id } => (Kind::If, id, false),
        EndWhile { id } => (Kind::While, id, false),
        DoWhile { id, .. } => (Kind::Do, id, false),
        EndRepeat { id } => (Kind::Repeat, id, false),
        EndFor => (Kind::For, &nested, false),
        EndLoop => (Kind::Loop, &nested, false),
        Until { .. } => (Kind::RepeatUntil, &nested, false),
        SubEnd { id, .. } => (Kind::Sub, id, false),
        _ => return,
    };
    if opens {
        stack.push((k, id.clone(), i));
        return;
    }
    let Some(pos) = stack.iter().rposition(|e| e.0 == k && &e.1 == id) else {
        return;
    };
    let (_, _, o) = stack.remove(pos);
    ix.partner.insert(o, i);
    ix.partner.insert(i, o);
    if k == Kind::If {
        let from = last.remove(&o).unwrap_or(o);
        ix.next_branch.insert(from, i);
    }
}

fn same(a: &FlowIndex, b: &FlowIndex, what: &str) {
    assert_eq!(a.partner, b.partner, "partner: {what}");
    assert_eq!(a.next_branch, b.next_branch, "next_branch: {what}");
    assert_eq!(a.loop_of, b.loop_of, "loop_of: {what}");
}

/// A small deterministic generator (no dependency, same programs every run).
struct Lcg(u64);

impl Lcg {
    fn pick<'a>(&mut self, from: &[&'a str]) -> &'a str {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        from[(self.0 >> 33) as usize % from.len()]
    }
}

const SIEMENS: &[&str] = &[
    "IF R1==1",
    "ELSE",
    "ENDIF",
    "WHILE R1==1",
    "ENDWHILE",
    "LOOP",
    "ENDLOOP",
    "FOR R2=1 TO 2",
    "ENDFOR",
    "REPEAT",
    "UNTIL R1==1",
    "G1 X1 F100",
    "R1=1",
];

const LINUXCNC: &[&str] = &[
    "o1 if [1]",
    "o1 elseif [1]",
    "o1 else",
    "o1 endif",
    "o2 if [1]",
    "o2 endif",
    "o1 while [1]",
    "o1 endwhile",
    "o3 do",
    "o3 while [1]",
    "o4 repeat [2]",
    "o4 endrepeat",
    "o2 while [1]",
    "o2 endwhile",
    "G1 X1 F100",
];

const FANUC: &[&str] = &[
    "WHILE [#1 EQ 1] DO1",
    "END1",
    "WHILE [#1 EQ 1] DO2",
    "END2",
    "IF [#1 EQ 1] THEN #2=1",
    "G1 X1 F100",
    "#1=1",
];

#[test]
fn small_programs_with_stray_and_crossed_closers_match_the_reference() {
    let mut rng = Lcg(14);
    for (dialect, words) in [
        ("siemens840d", SIEMENS),
        ("linuxcnc", LINUXCNC),
        ("fanuc", FANUC),
    ] {
        let (mut pairs, mut in_loops) = (0, 0);
        for n in 0..300 {
            let lines: Vec<&str> = (0..1 + n % 25).map(|_| rng.pick(words)).collect();
            let text = lines.join("\n") + "\n";
            let p = read(dialect, &text);
            let ix = FlowIndex::build(&p);
            same(&ix, &reference(&p), &text);
            pairs += ix.partner.len();
            in_loops += ix.loop_of.len();
        }
        assert!(
            pairs > 300 && in_loops > 300,
            "{dialect}: {pairs} {in_loops}"
        );
    }
}

#[test]
fn a_small_nested_program_is_indexed() {
    let text = "WHILE R1==1\nIF R1==1\nG1 X1\nELSE\nLOOP\nG1 X2\nENDLOOP\nENDIF\nENDWHILE\nM30\n";
    let p = read("siemens840d", text);
    let ix = FlowIndex::build(&p);
    same(&ix, &reference(&p), text);
    let line = |s: &str| {
        p.blocks
            .iter()
            .position(|b| text[b.span.range()].starts_with(s))
    };
    let (w, i, e, l, el, ei, ew) = (0, 1, 3, 4, 6, 7, 8);
    assert_eq!(line("ENDLOOP"), Some(el));
    assert_eq!(ix.partner[&w], ew);
    assert_eq!(ix.partner[&ew], w);
    assert_eq!(ix.partner[&i], ei);
    assert_eq!(ix.partner[&l], el);
    assert_eq!(ix.next_branch[&i], e);
    assert_eq!(ix.next_branch[&e], ei);
    assert_eq!(ix.loop_of[&2], w);
    assert_eq!(ix.loop_of[&5], l);
    assert_eq!(
        ix.loop_of[&7], w,
        "after ENDLOOP the WHILE is innermost again"
    );
    assert_eq!(ix.loop_of.get(&w), None);
    assert_eq!(ix.loop_of.get(&9), None);
}

/// 100,000 openers deep, IF and WHILE alternating: every opener finds its
/// closer and every block its innermost loop (this took seconds when the
/// innermost loop was found by scanning the open stack).
#[test]
fn a_program_nested_100000_deep_is_indexed() {
    let depth = 100_000;
    let mut text = String::new();
    for k in 0..depth {
        text.push_str(if k % 2 == 0 {
            "IF R1==1\n"
        } else {
            "WHILE R1==1\n"
        });
    }
    text.push_str("G1 X1\n");
    for k in (0..depth).rev() {
        text.push_str(if k % 2 == 0 { "ENDIF\n" } else { "ENDWHILE\n" });
    }
    let p = read("siemens840d", &text);
    assert_eq!(p.blocks.len(), 2 * depth + 1);
    let ix = FlowIndex::build(&p);
    let closer = |k: usize| 2 * depth - k;
    for k in 0..depth {
        assert_eq!(ix.partner.get(&k), Some(&closer(k)), "opener {k}");
        assert_eq!(ix.partner.get(&closer(k)), Some(&k), "closer of {k}");
    }
    // Block b (an opener or closer at depth k) is inside openers 0..k;
    // the innermost loop is the last odd one.
    let innermost = |inside: usize| (0..inside).rev().find(|k| k % 2 == 1);
    for b in 0..p.blocks.len() {
        let inside = if b <= depth { b } else { closer(b) + 1 };
        assert_eq!(ix.loop_of.get(&b).copied(), innermost(inside), "block {b}");
    }
    assert_eq!(ix.next_branch.len(), depth / 2);
}
