//! Unit tests of the comparison engine, on hand-made event lists and on
//! the four-dialect same part (`tests/programs/samepart/`).

use super::*;
use crate::toolpath::{CoolantState, FeedMode, Move, MoveKind};

/// Builds event lists: moves from the current point, span start = line.
struct Prog {
    pos: P3,
    feed: f64,
    tool: i64,
    events: Vec<Event>,
}

fn sp(line: u32) -> Span {
    Span {
        file: crate::span::FileId(0),
        start: line,
        end: line + 1,
    }
}

impl Prog {
    fn new() -> Prog {
        Prog {
            pos: [0.0; 3],
            feed: 100.0,
            tool: 0,
            events: Vec::new(),
        }
    }
    fn mv(&mut self, kind: MoveKind, to: P3, line: u32) -> &mut Self {
        let m = Move {
            kind,
            from: self.pos,
            to,
            feed: self.feed,
            feed_mode: FeedMode::PerMinute,
            tool: self.tool,
            spindle: 1000.0,
            coolant: CoolantState::default(),
            span: sp(line),
        };
        self.pos = to;
        self.events.push(Event::Move(m));
        self
    }
    fn rapid(&mut self, to: P3, line: u32) -> &mut Self {
        self.mv(MoveKind::Rapid, to, line)
    }
    fn feed(&mut self, to: P3, line: u32) -> &mut Self {
        self.mv(MoveKind::Line, to, line)
    }
    fn tool(&mut self, t: i64, line: u32) -> &mut Self {
        self.tool = t;
        self.events.push(Event::ToolChange {
            tool: t,
            span: sp(line),
        });
        self
    }
    /// A hole at x y from z 2 to `depth`, in `pecks` pecks.
    fn hole(&mut self, x: f64, y: f64, depth: f64, pecks: usize, line: u32) -> &mut Self {
        self.rapid([x, y, 2.0], line);
        for k in 1..=pecks {
            let z = depth * k as f64 / pecks as f64;
            self.feed([x, y, z], line).rapid([x, y, 2.0], line);
        }
        self
    }
}

fn part(hole2: (f64, f64), pecks: usize, feed2: f64) -> Vec<Event> {
    let mut p = Prog::new();
    p.tool(1, 1)
        .rapid([0.0, 0.0, 5.0], 2)
        .feed([0.0, 0.0, -1.0], 3);
    p.feed([50.0, 0.0, -1.0], 4).feed([50.0, 20.0, -1.0], 5);
    p.feed = feed2;
    p.feed([0.0, 20.0, -1.0], 6).feed([0.0, 0.0, -1.0], 7);
    p.feed = 100.0;
    p.rapid([0.0, 0.0, 25.0], 8).tool(2, 9);
    p.hole(10.0, 10.0, -10.0, pecks, 10)
        .hole(hole2.0, hole2.1, -10.0, pecks, 11)
        .hole(50.0, 10.0, -10.0, pecks, 12);
    p.events.clone()
}

#[test]
fn the_same_program_is_the_same() {
    let a = part((30.0, 10.0), 1, 100.0);
    let c = compare(&a, &a, &CompareOptions::default());
    assert!(c.same, "{c:#?}");
    assert!(c.rapid_differences.is_empty());
    // 2 tools, plunge + 4 lines, 3 holes.
    assert_eq!(c.ops_a, 2 + 5 + 3);
}

#[test]
fn pecks_compare_as_one_hole() {
    let a = part((30.0, 10.0), 1, 100.0);
    let b = part((30.0, 10.0), 4, 100.0);
    let c = compare(&a, &b, &CompareOptions::default());
    assert!(c.same, "{c:#?}");
}

#[test]
fn a_moved_hole_is_one_difference_at_its_block() {
    let a = part((30.0, 10.0), 1, 100.0);
    let b = part((30.0, 12.0), 3, 100.0);
    let c = compare(&a, &b, &CompareOptions::default());
    assert!(!c.same);
    assert_eq!(c.differences.len(), 1, "{c:#?}");
    let d = &c.differences[0];
    assert_eq!(d.kind, DiffKind::Cuts);
    assert_eq!((d.a, d.b), (Some(sp(11)), Some(sp(11))));
    assert_eq!(d.group_a, 2);
    assert!(
        d.what.contains("X30 Y10") && d.what.contains("X30 Y12"),
        "{}",
        d.what
    );
}

#[test]
fn a_changed_feed_is_one_difference_where_it_starts() {
    let a = part((30.0, 10.0), 1, 100.0);
    let b = part((30.0, 10.0), 1, 120.0);
    let c = compare(&a, &b, &CompareOptions::default());
    assert_eq!(c.differences.len(), 1, "{c:#?}");
    let d = &c.differences[0];
    assert_eq!(d.kind, DiffKind::Feed);
    assert_eq!((d.a, d.b), (Some(sp(6)), Some(sp(6))));
    assert_eq!(d.a_ops.len(), 2, "the feed stays changed for two moves");
    let off = CompareOptions {
        compare_feeds: false,
        ..CompareOptions::default()
    };
    assert!(compare(&a, &b, &off).same);
}

#[test]
fn an_inserted_cut_does_not_cascade() {
    let a = part((30.0, 10.0), 1, 100.0);
    let mut b = a.clone();
    // One more line in B after the first side of the contour (then back).
    let mut extra = Prog::new();
    extra.pos = [50.0, 0.0, -1.0];
    extra
        .feed([60.0, 0.0, -1.0], 40)
        .feed([50.0, 0.0, -1.0], 41);
    let at = 1 + 4; // after the tool change, the rapid, plunge and first line
    b.splice(at..at, extra.events);
    let c = compare(&a, &b, &CompareOptions::default());
    assert_eq!(c.differences.len(), 1, "{c:#?}");
    let d = &c.differences[0];
    assert!(d.a.is_none() && d.b == Some(sp(40)), "{d:#?}");
    assert!(d.what.starts_with("only in B"), "{}", d.what);
}

#[test]
fn a_different_tool_is_named() {
    let a = part((30.0, 10.0), 1, 100.0);
    let mut b = a.clone();
    for e in b.iter_mut() {
        if let Event::ToolChange { tool, .. } = e {
            if *tool == 2 {
                *tool = 5;
            }
        }
    }
    let c = compare(&a, &b, &CompareOptions::default());
    let tools: Vec<_> = c
        .differences
        .iter()
        .filter(|d| d.kind == DiffKind::Tool)
        .collect();
    assert_eq!(tools.len(), 1, "{c:#?}");
    assert!(tools[0].what.contains("T2") && tools[0].what.contains("T5"));
}

#[test]
fn other_rapids_are_listed_not_fatal() {
    let a = part((30.0, 10.0), 1, 100.0);
    let mut b = a.clone();
    if let Event::Move(m) = &mut b[1] {
        m.to = [0.0, 0.0, 10.0]; // rapid to Z10 instead of Z5
    }
    if let Event::Move(m) = &mut b[2] {
        m.from = [0.0, 0.0, 10.0];
    }
    let c = compare(&a, &b, &CompareOptions::default());
    assert!(c.same, "{c:#?}");
    assert_eq!(c.rapid_differences.len(), 1);
    assert_eq!(c.rapid_differences[0].a, Some(sp(2)));
}

mod samepart {
    use super::super::*;
    use crate::dialect::Registry;
    use crate::source::SourceMap;
    use std::path::{Path, PathBuf};

    fn dir() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs/samepart")
    }

    /// Runs a program text (written to a temporary file) in a dialect.
    fn events(text: &str, name: &str, dialect: &str, files: &mut SourceMap) -> Vec<Event> {
        let tmp = tempfile::tempdir().unwrap();
        let path = tmp.path().join(name);
        std::fs::write(&path, text).unwrap();
        let spec = Registry::with_builtins().resolve(dialect).unwrap();
        let id = files.add(name, text);
        let opts = crate::interp::Options::default();
        let (ev, diags) = crate::toolpath::events_of_file(&path, id, &spec, &opts, files).unwrap();
        assert!(!diags.iter().any(|d| d.is_error()), "{name}: {diags:#?}");
        ev
    }

    fn read(name: &str) -> String {
        std::fs::read_to_string(dir().join(name)).unwrap()
    }

    fn line_of(files: &SourceMap, s: Span) -> usize {
        files.line_col(s.file, s.start as usize).0
    }

    #[test]
    fn four_dialects_cut_the_same_and_a_moved_hole_is_found() {
        let mut files = SourceMap::new();
        let fanuc = events(&read("part.nc"), "part.nc", "fanuc", &mut files);
        for (name, dialect) in [
            ("part-haas.nc", "haas"),
            ("part.ngc", "linuxcnc"),
            ("part.mpf", "siemens840d"),
        ] {
            let other = events(&read(name), name, dialect, &mut files);
            let c = compare(&fanuc, &other, &CompareOptions::default());
            assert!(c.same, "{name}: {:#?}", c.differences);
        }
        // Move the second hole by 2 mm in Y in the Siemens copy.
        let moved = read("part.mpf").replace("N180 X30", "N180 X30 Y12");
        let moved = moved.replace("N190 X50", "N190 X50 Y10");
        let siemens = events(&moved, "moved.mpf", "siemens840d", &mut files);
        let c = compare(&fanuc, &siemens, &CompareOptions::default());
        assert_eq!(c.differences.len(), 1, "{:#?}", c.differences);
        let d = &c.differences[0];
        let fanuc_line = read("part.nc").lines().position(|l| l == "X30.").unwrap() + 1;
        let siemens_line = moved.lines().position(|l| l.starts_with("N180")).unwrap() + 1;
        assert_eq!(line_of(&files, d.a.unwrap()), fanuc_line, "{d:#?}");
        assert_eq!(line_of(&files, d.b.unwrap()), siemens_line, "{d:#?}");
    }

    #[test]
    fn a_changed_pocket_depth_names_the_plunge_on_both_sides() {
        let mut files = SourceMap::new();
        let fanuc_text = read("part.nc").replacen("G1 Z-4. F150.", "G1 Z-4.5 F150.", 1);
        let fanuc = events(&fanuc_text, "deeper.nc", "fanuc", &mut files);
        let ngc = events(&read("part.ngc"), "part.ngc", "linuxcnc", &mut files);
        let c = compare(&fanuc, &ngc, &CompareOptions::default());
        assert_eq!(c.differences.len(), 1, "{:#?}", c.differences);
        let d = &c.differences[0];
        let want = fanuc_text
            .lines()
            .position(|l| l == "G1 Z-4.5 F150.")
            .unwrap()
            + 1;
        assert_eq!(line_of(&files, d.a.unwrap()), want, "{d:#?}");
        assert!(d.what.contains("Z-4.5"), "{}", d.what);
    }
}
