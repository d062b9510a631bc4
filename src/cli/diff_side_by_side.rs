//! `cncc diff` of two programs run side by side: each on a thread of its
//! own with a branch of the source map (for the programs it calls), its
//! operations handed to the comparison in batches
//! ([`crate::compare::compare_windows`]), so the comparison holds a few
//! hundred operations of each, not both programs' (about 100 bytes a
//! move each). The branches' files are taken back afterwards and the
//! spans of the differences and diagnostics renumbered to them.

use crate::cli::context::{Context, Failure};
use crate::compare::window::{hand_over, QUEUED};
use crate::compare::{compare_windows, CompareOptions, Comparison, OpBuilder, OpWindow, Ops};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::Options;
use crate::source::SourceMap;
use crate::span::{FileId, Span};
use std::path::Path;
use std::sync::mpsc::{sync_channel, SyncSender};
use std::sync::Arc;

/// One program: its file, registered id (sparse) and dialect.
pub struct Program<'p> {
    pub path: &'p Path,
    pub id: FileId,
    pub spec: Arc<DialectSpec>,
}

/// The comparison and each run's diagnostics, their spans in `ctx`'s map.
pub struct Compared {
    pub comparison: Comparison,
    pub a: Vec<Diagnostic>,
    pub b: Vec<Diagnostic>,
}

pub fn compare(
    ctx: &mut Context,
    (a, b): (Program<'_>, Program<'_>),
    options: &Options,
    opts: &CompareOptions,
) -> Result<Compared, Failure> {
    let shared = ctx.files.len();
    let (fa, fb) = (ctx.files.branch(), ctx.files.branch());
    let (c, ra, rb) = std::thread::scope(|s| {
        let (ta, rxa) = sync_channel::<Ops>(QUEUED);
        let (tb, rxb) = sync_channel::<Ops>(QUEUED);
        let ha = s.spawn(move || run(&a, fa, options, opts, ta));
        let hb = s.spawn(move || run(&b, fb, options, opts, tb));
        let wa = OpWindow::pulled(Box::new(move || rxa.recv().ok()));
        let wb = OpWindow::pulled(Box::new(move || rxb.recv().ok()));
        let c = compare_windows(wa, wb, opts);
        let join = |h: std::thread::ScopedJoinHandle<'_, Ran>| {
            h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))
        };
        (c, join(ha), join(hb))
    });
    let (fa, mut da) = ra?;
    let (fb, mut db) = rb?;
    let ida = ctx.files.absorb(fa, shared);
    renumber(&mut da, &ida);
    let idb = ctx.files.absorb(fb, shared);
    renumber(&mut db, &idb);
    let mut comparison = c;
    for d in comparison
        .differences
        .iter_mut()
        .chain(comparison.rapid_differences.iter_mut())
    {
        d.a = d.a.map(|s| Span {
            file: ida(s.file),
            ..s
        });
        d.b = d.b.map(|s| Span {
            file: idb(s.file),
            ..s
        });
    }
    Ok(Compared {
        comparison,
        a: da,
        b: db,
    })
}

/// A run's files and diagnostics.
type Ran = Result<(SourceMap, Vec<Diagnostic>), Failure>;

fn renumber(diags: &mut [Diagnostic], id: &impl Fn(FileId) -> FileId) {
    for l in diags.iter_mut().flat_map(|d| d.labels.iter_mut()) {
        l.span.file = id(l.span.file);
    }
}

/// Runs one program, sending its operations as they are made.
fn run(
    p: &Program<'_>,
    mut files: SourceMap,
    options: &Options,
    opts: &CompareOptions,
    to: SyncSender<Ops>,
) -> Ran {
    let mut ops = match opts.compare_rapids {
        true => OpBuilder::new(opts.tolerance_mm),
        false => OpBuilder::without_rapids(opts.tolerance_mm),
    };
    let mut tracker = crate::toolpath::Tracker::new();
    let mut listening = true;
    let diags = {
        let mut sink = |call: crate::canon::Canon, span: Span| {
            tracker.push(&call, span, |e| ops.push(&e));
            listening = hand_over(&mut ops, &to, listening);
        };
        crate::interp::file::run_file(p.path, p.id, &p.spec, options, &mut files, &mut sink)
            .map_err(|e| Failure(format!("{}: {e}", p.path.display())))?
    };
    if listening {
        let _ = to.send(ops.finish());
    }
    Ok((files, diags))
}
