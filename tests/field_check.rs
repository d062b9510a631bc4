//! `cncc check` on every real program of `../shared/field/` and
//! `../shared/corpus/`, as a new user runs it: the dialect is the one the
//! folder names (`big/` files name it in their first word, and the generic
//! ISO program there is read as LinuxCNC, the control it was written for).
//!
//! A program that does not check clean must be listed in
//! `tests/field/<dialect>.expect` with the code of its first error and the
//! reason, which must be a real mistake in that file or a construct its own
//! controller refuses too. A listed file that now checks clean fails the
//! test as well, so the list never goes stale. No program may crash
//! (exit codes other than 0 and 1) or run away (the run is bounded).

mod common;
use common::field::*;
use common::*;

#[test]
fn field_programs_check_clean_or_fail_for_a_real_reason() {
    let Some(shared) = shared() else {
        return;
    };
    let expected = expectations();
    let mut failures = Vec::new();
    let (mut clean, mut field_clean, mut field_total) = (0, 0, 0);
    let all = programs(&shared);
    for (d, file) in &all {
        let path = shared.join(file);
        let o = cncc(&["check", "--dialect", d, path.to_str().unwrap()]);
        let code = o.status.code();
        let err = stderr(&o);
        let is_field = file.starts_with("field/");
        field_total += is_field as usize;
        match (code, expected.get(file)) {
            (Some(0), None) => {
                clean += 1;
                field_clean += is_field as usize;
            }
            (Some(0), Some(e)) => failures.push(format!(
                "{file}: listed as rejected ({}: {}) but checks clean: take it off the list",
                e.code, e.reason
            )),
            (Some(1), Some(e)) if first_error(&err).as_deref() == Some(&e.code) => {}
            (Some(1), Some(e)) => failures.push(format!(
                "{file}: listed for {} but the first error is {:?}:\n{}",
                e.code,
                first_error(&err),
                head(&err)
            )),
            (Some(1), None) => failures.push(format!(
                "{file} ({d}) does not check clean:\n{}",
                head(&err)
            )),
            (other, _) => failures.push(format!("{file}: crashed ({other:?}):\n{}", head(&err))),
        }
    }
    for file in expected.keys() {
        if !all.iter().any(|(_, f)| f == file) {
            failures.push(format!("{file} is listed but is not in ../shared"));
        }
    }
    eprintln!(
        "{clean}/{} programs check clean; field: {field_clean}/{field_total}",
        all.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

fn head(s: &str) -> String {
    s.lines().take(12).collect::<Vec<_>>().join("\n")
}

/// Programs that check clean but that cncc's own writer cannot yet write
/// back in their dialect: cncc's limits, not the programs' mistakes.
const NO_ROUND_TRIP: &[(&str, &str)] = &[
    (
        "field/fanuc/nick-burrill_SWCAM_CGIP09902-2.NC",
        "E0603: an inch feed with 4 places (F18.7734); the Fanuc spec writes feeds with 3 [?]",
    ),
    (
        "field/fanuc/nick-burrill_SWCAM_CGIP11719.NC",
        "E0603: an inch feed with 4 places; the Fanuc spec writes feeds with 3 [?]",
    ),
    (
        "field/haas/NX_Haas_VF3_testpart2.ptp",
        "E0603: a value of 0.5 where the writer wants a whole number",
    ),
    (
        "field/siemens840d/NX_Huron_KX20_Training.MPF",
        "E0603: a value of 0.5 where the writer wants a whole number",
    ),
];

/// Every program that checks clean ports to its own dialect and, ported
/// again, gives the same text (a fixpoint); comments keep their bytes
/// (`tests/encodings.rs` checks the bytes form by form).
#[test]
fn clean_field_programs_round_trip_to_a_fixpoint() {
    let Some(shared) = shared() else {
        return;
    };
    let expected = expectations();
    let dir = tempfile::tempdir().unwrap();
    let mut failures = Vec::new();
    for (i, (d, file)) in programs(&shared).iter().enumerate() {
        if expected.contains_key(file) {
            continue;
        }
        let listed = NO_ROUND_TRIP.iter().any(|(f, _)| f == file);
        let ext = file
            .rsplit('.')
            .next()
            .filter(|e| e.len() <= 4)
            .unwrap_or("txt");
        let (a, b) = (
            dir.path().join(format!("{i}a.{ext}")),
            dir.path().join(format!("{i}b.{ext}")),
        );
        let src = shared.join(file);
        let port = |from: &std::path::Path, to: &std::path::Path| {
            cncc(&[
                "port",
                "--from",
                d,
                "--to",
                d,
                from.to_str().unwrap(),
                "-o",
                to.to_str().unwrap(),
            ])
        };
        let first = port(&src, &a);
        let ok = first.status.code() == Some(0)
            && port(&a, &b).status.code() == Some(0)
            && std::fs::read(&a).ok() == std::fs::read(&b).ok();
        match (ok, listed) {
            (true, true) => {
                failures.push(format!("{file} round-trips now: take it off NO_ROUND_TRIP"))
            }
            (false, false) => failures.push(format!(
                "{file} ({d}) does not round-trip:\n{}",
                head(&stderr(&first))
            )),
            _ => {}
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
