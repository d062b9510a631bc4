//! Running STEP-NC plans: `cncc canon|stats|plot|diff FILE.stp` post the
//! plan in memory (LinuxCNC by default) and run the posted program. The
//! canon of a plan is the canon of `cncc post FILE.stp --to linuxcnc`, and
//! (where LinuxCNC's rs274 is installed) equals rs274's run of that post.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh scratch folder under target/tmp.
fn scratch(name: &str) -> PathBuf {
    let dir = common::root().join("target/tmp/stepnc-exec").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The plans that run: the project's own and the ARM samples of
/// ../shared that post to LinuxCNC.
fn plans() -> Vec<PathBuf> {
    let mut v = vec![
        common::root().join("tests/programs/stepnc/tapped_holes.stp"),
        common::root().join("tests/programs/stepnc/ap238_slot.stpnc"),
        common::root().join("tests/stepnc/milled_holes.stp"),
        common::root().join("tests/stepnc/general_pockets.stp"),
        common::root().join("tests/stepnc/v_slot.stp"),
        common::root().join("tests/stepnc/sloped_u.stp"),
        common::root().join("tests/stepnc/step.stp"),
    ];
    if let Some(shared) = common::shared() {
        let s = shared.join("stepnc-samples");
        for name in [
            "ex1.stp",
            "ex1E.stp",
            "furo.p21",
            "test_program.stpnc",
            "field/sanssouci__RanhuraPerfilRoundedU.p21",
            "field/sanssouci__STEP-NC_pocket1_File.p21",
            "field/sanssouci__Hole",
            "field/sanssouci__testePrecedencias.p21",
            "field/sanssouci__RanhuraPerfilVee.p21",
            "field/sanssouci__RanhuraPerfilUQuadrado.p21",
            "field/sanssouci__oneHoleOneSlotOneStepOnePoket.p21",
        ] {
            v.push(s.join(name));
        }
    }
    v
}

fn posted(plan: &Path, dir: &Path) -> PathBuf {
    let stem = plan.file_name().unwrap().to_string_lossy().into_owned();
    let out = dir.join(format!("{stem}.ngc"));
    let o = common::cncc(&[
        "post",
        plan.to_str().unwrap(),
        "--to",
        "linuxcnc",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", common::stderr(&o));
    out
}

#[test]
fn the_canon_of_a_plan_is_the_canon_of_its_linuxcnc_post() {
    let dir = scratch("same");
    for plan in plans() {
        let ngc = posted(&plan, &dir);
        let direct = common::cncc(&["canon", plan.to_str().unwrap()]);
        let via = common::cncc(&["canon", ngc.to_str().unwrap()]);
        assert_eq!(
            direct.status.code(),
            Some(0),
            "{}: {}",
            plan.display(),
            common::stderr(&direct)
        );
        let text = common::stdout(&direct);
        assert!(text.contains("PROGRAM_END()"), "{}", plan.display());
        assert_eq!(text, common::stdout(&via), "{}", plan.display());
    }
}

#[test]
fn the_canon_of_a_plan_equals_rs274_of_its_linuxcnc_post() {
    if !common::rs274_present() {
        common::skip_oracle("the STEP-NC oracle test", "rs274 is not installed");
        return;
    }
    let tools = common::root().join("../shared/tools");
    if !tools.join("rs274-canon").exists() {
        common::skip_oracle("the STEP-NC oracle test", "../shared/tools is absent");
        return;
    }
    let dir = scratch("oracle");
    for plan in plans() {
        let ngc = posted(&plan, &dir);
        let expected = ngc.with_extension("rs274");
        let o = Command::new(tools.join("rs274-canon"))
            .arg(&ngc)
            .output()
            .unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&o.stderr)
        );
        std::fs::write(&expected, &o.stdout).unwrap();
        let actual = ngc.with_extension("cncc");
        let c = common::cncc(&["canon", plan.to_str().unwrap()]);
        std::fs::write(&actual, &c.stdout).unwrap();
        let d = Command::new(tools.join("canon-diff"))
            .args([&expected, &actual])
            .output()
            .unwrap();
        assert_eq!(
            d.status.code(),
            Some(0),
            "{}: {}",
            plan.display(),
            String::from_utf8_lossy(&d.stdout)
        );
    }
}

#[test]
fn a_plan_is_known_by_its_first_word_whatever_its_name() {
    let dir = scratch("named");
    let plan = common::root().join("tests/programs/stepnc/tapped_holes.stp");
    let odd = dir.join("tapped_holes.txt");
    std::fs::copy(&plan, &odd).unwrap();
    let a = common::cncc(&["canon", plan.to_str().unwrap()]);
    let b = common::cncc(&["canon", odd.to_str().unwrap()]);
    assert_eq!(b.status.code(), Some(0), "{}", common::stderr(&b));
    assert_eq!(common::stdout(&a), common::stdout(&b));
}

#[test]
fn a_plan_that_cannot_be_read_gives_the_readers_diagnostics() {
    let aim = common::root().join("tests/stepnc/bad/aim.stp");
    let o = common::cncc(&["canon", aim.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    let err = common::stderr(&o);
    assert!(err.contains("E0806"), "{err}");
    assert!(!err.contains("E01") && !err.contains("E02"), "{err}");
    assert!(common::stdout(&o).is_empty());
}

#[test]
fn a_plan_the_post_refuses_gives_the_posts_located_diagnostics() {
    let dir = scratch("refused");
    // The M6 hole moved off the 60 x 40 plate.
    let text =
        std::fs::read_to_string(common::root().join("tests/programs/stepnc/tapped_holes.stp"))
            .unwrap()
            .replace(
                "#61=CARTESIAN_POINT('',(40.,20.,0.));",
                "#61=CARTESIAN_POINT('',(140.,20.,0.));",
            );
    let plan = dir.join("off-the-plate.stp");
    std::fs::write(&plan, text).unwrap();
    let post = common::cncc(&["post", plan.to_str().unwrap(), "--to", "linuxcnc"]);
    let o = common::cncc(&["canon", plan.to_str().unwrap()]);
    assert_eq!(post.status.code(), Some(1), "{}", common::stderr(&post));
    assert_eq!(o.status.code(), Some(1));
    let (err, post_err) = (common::stderr(&o), common::stderr(&post));
    assert!(err.contains("error[E09"), "{err}");
    assert!(
        err.contains("off-the-plate.stp:"),
        "located in the plan: {err}"
    );
    assert_eq!(err, post_err, "the post's own diagnostics");
    assert!(common::stdout(&o).is_empty());
}

#[test]
fn stats_plot_and_diff_take_a_plan() {
    let dir = scratch("others");
    let plan = common::root().join("tests/programs/stepnc/tapped_holes.stp");
    let s = common::cncc(&["stats", plan.to_str().unwrap()]);
    assert_eq!(s.status.code(), Some(0), "{}", common::stderr(&s));
    let stats = common::stdout(&s);
    // The plan's tool sizes (T1 a 6.8 mm drill), not the built-in table's.
    assert!(
        stats
            .lines()
            .any(|l| l.starts_with("T1") && l.contains(" 6.8 ")),
        "{stats}"
    );
    assert!(
        !common::stderr(&s).contains("W0592"),
        "{}",
        common::stderr(&s)
    );
    let svg = dir.join("plan.svg");
    let p = common::cncc(&["plot", plan.to_str().unwrap(), "-o", svg.to_str().unwrap()]);
    assert_eq!(p.status.code(), Some(0), "{}", common::stderr(&p));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
    let ngc = posted(&plan, &dir);
    let d = common::cncc(&["diff", plan.to_str().unwrap(), ngc.to_str().unwrap()]);
    assert_eq!(d.status.code(), Some(0), "{}", common::stdout(&d));
}
