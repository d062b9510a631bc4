//! Posts as data: a user dialect posts with the templates it inherits,
//! `--post-dir` overrides them file by file, and what a target can post
//! is what its spec declares (`<post-template>`): the Makino profile
//! (`tests/dialects/makino.xml`) posts ISO 14649 Example 1 and a tapping
//! project with its own folder `tests/posts/makino/` (G05 P2 around the
//! program, G84.2 rigid tapping), with no Rust written for it.

mod common;
use common::*;
use std::path::PathBuf;

const SPEC: &str = "tests/dialects/makino.xml";
const POSTS: &str = "tests/posts/makino";
const TAPPED: &str = "tests/programs/stepnc/tapped_holes.stp";

/// ISO 14649 Example 1 from the shared samples, else the hand-built
/// fixture of the same project written as Part 21.
fn ex1() -> PathBuf {
    let shared = shared().map(|s| s.join("stepnc-samples/ex1.stp"));
    match shared {
        Some(p) if p.exists() => p,
        _ => {
            let p = tmp("ex1-fixture.stp");
            let text = cncc::stepnc::write_project(&cncc::post::fixture::ex1());
            std::fs::write(&p, text).unwrap();
            p
        }
    }
}

fn tmp(name: &str) -> PathBuf {
    let dir = root().join("target/tmp/post-dir-tests");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Posts `file` to the Makino with its post folder, into `out`.
fn post_makino(file: &str, out: &str) -> PathBuf {
    let path = tmp(out);
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "--post-dir",
        POSTS,
        "post",
        file,
        "--to",
        "makino",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    path
}

fn post_fanuc(file: &str, out: &str) -> PathBuf {
    let path = tmp(out);
    let o = cncc(&["post", file, "--to", "fanuc", "-o", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    path
}

fn canon(dialect: &str, file: &PathBuf) -> String {
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "canon",
        "--dialect",
        dialect,
        file.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{dialect}: {}", stderr(&o));
    stdout(&o)
}

fn check_clean(dialect: &str, file: &PathBuf) {
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "check",
        "--dialect",
        dialect,
        file.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("warning["), "{}", stderr(&o));
}

#[test]
fn a_user_dialect_posts_with_the_templates_it_inherits() {
    let ex1 = ex1();
    let ex1 = ex1.to_str().unwrap();
    let path = tmp("ex1-makino-inherited.nc");
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "post",
        ex1,
        "--to",
        "makino",
        "-o",
        path.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // Fanuc's templates, unchanged: the same text as the fanuc post.
    let fanuc = post_fanuc(ex1, "ex1-fanuc.nc");
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        std::fs::read_to_string(&fanuc).unwrap()
    );
}

#[test]
fn ex1_posts_to_the_makino_with_its_own_folder() {
    let ex1 = ex1();
    let ex1 = ex1.to_str().unwrap();
    let makino = post_makino(ex1, "ex1-makino.nc");
    let text = std::fs::read_to_string(&makino).unwrap();
    // begin.j2 and end.j2 from the folder, the rest inherited.
    assert!(text.contains("\nG05 P2\n"), "{text}");
    assert!(text.contains("\nG05 P0\nM30\n"), "{text}");
    assert!(text.contains("G98 G81 "), "{text}");
    check_clean("makino", &makino);
    // High-speed mode changes no move: the same machining as the fanuc post.
    let fanuc = post_fanuc(ex1, "ex1-fanuc.nc");
    assert_eq!(canon("makino", &makino), canon("fanuc", &fanuc));
}

#[test]
fn tapping_posts_as_g84_2_on_the_makino() {
    let makino = post_makino(TAPPED, "tapped-makino.nc");
    let text = std::fs::read_to_string(&makino).unwrap();
    assert!(text.contains("G98 G84.2 X"), "{text}");
    assert!(!text.contains("G84 "), "{text}");
    check_clean("makino", &makino);
    let fanuc = post_fanuc(TAPPED, "tapped-fanuc.nc");
    assert!(std::fs::read_to_string(&fanuc)
        .unwrap()
        .contains("G98 G84 X"));
    let (m, f) = (canon("makino", &makino), canon("fanuc", &fanuc));
    assert!(m.contains("START_SPINDLE_COUNTERCLOCKWISE"), "{m}");
    assert_eq!(m, f);
}

#[test]
fn a_file_the_spec_does_not_declare_is_refused() {
    let dir = tmp("stray-folder");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::copy(root().join(POSTS).join("tap.j2"), dir.join("tap.j2")).unwrap();
    std::fs::write(dir.join("pocket_rect.j2"), "G1\n").unwrap();
    std::fs::write(dir.join("tapp.j2"), "G1\n").unwrap();
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "--post-dir",
        dir.to_str().unwrap(),
        "post",
        TAPPED,
        "--to",
        "makino",
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).is_empty());
    let err = stderr(&o);
    assert!(
        err.contains("pocket_rect.j2: `makino` does not declare the post template `pocket_rect`"),
        "{err}"
    );
    assert!(
        err.contains("tapp.j2: `tapp` is not a post template"),
        "{err}"
    );
    assert_eq!(err.matches("E0909").count(), 2, "{err}");
}

/// A spec that declares a template nobody has a file for is pointed at;
/// one that removes a template makes the post refuse the feature, naming
/// the target and the template.
#[test]
fn declarations_decide_what_posts() {
    let spec = tmp("declares.xml");
    std::fs::write(
        &spec,
        "<dialect id=\"mill2\" name=\"Mill 2\" extends=\"fanuc\">\n  <post-template name=\"pocket_rect\"/>\n</dialect>\n",
    )
    .unwrap();
    let ex1 = ex1();
    let ex1 = ex1.to_str().unwrap();
    let o = cncc(&[
        "--dialect-file",
        spec.to_str().unwrap(),
        "post",
        ex1,
        "--to",
        "mill2",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("`mill2` declares the post template `pocket_rect` but there is no `pocket_rect.j2` (looked in the built-in posts/fanuc)"),
        "{err}"
    );
    assert!(err.contains("declares.xml:2:3"), "{err}");

    std::fs::write(
        &spec,
        "<dialect id=\"mill2\" name=\"Mill 2\" extends=\"fanuc\">\n  <remove post-template=\"drill\"/>\n</dialect>\n",
    )
    .unwrap();
    let o = cncc(&[
        "--dialect-file",
        spec.to_str().unwrap(),
        "post",
        ex1,
        "--to",
        "mill2",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("`WS DRILL HOLE1`: Mill 2 (mill2) cannot post the drilling cycle: its spec declares no `drill` post template"),
        "{err}"
    );
    assert!(err.contains("E0900"), "{err}");
}

#[test]
fn a_spec_without_templates_has_no_post() {
    let ex1 = ex1();
    let o = cncc(&["post", ex1.to_str().unwrap(), "--to", "iso6983"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("E0905") && stderr(&o).contains("declares no post templates"),
        "{}",
        stderr(&o)
    );
}

/// `cncc dialects --templates` writes a target's templates to start from;
/// posting with the copy unchanged gives the same program.
#[test]
fn copied_templates_post_the_same_program() {
    let dir = tmp("copied-fanuc");
    let _ = std::fs::remove_dir_all(&dir);
    let o = cncc(&[
        "dialects",
        "--templates",
        "fanuc",
        "-o",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(dir.join("drill.j2").exists());
    assert_eq!(
        std::fs::read_to_string(dir.join("tap.j2")).unwrap(),
        std::fs::read_to_string(root().join("posts/fanuc/tap.j2")).unwrap()
    );
    let ex1 = ex1();
    let ex1 = ex1.to_str().unwrap();
    let o = cncc(&[
        "--post-dir",
        dir.to_str().unwrap(),
        "post",
        ex1,
        "--to",
        "fanuc",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let fanuc = post_fanuc(ex1, "ex1-fanuc-copy.nc");
    assert_eq!(stdout(&o), std::fs::read_to_string(&fanuc).unwrap());
}

/// Running a STEP-NC plan posts it in memory with the same templates:
/// the canonical calls of `canon PLAN.stp --dialect makino` are those of
/// the posted Makino program, and a bad folder is refused there too.
#[test]
fn a_plan_runs_with_the_post_folder() {
    let makino = post_makino(TAPPED, "tapped-makino-run.nc");
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "--post-dir",
        POSTS,
        "canon",
        "--dialect",
        "makino",
        TAPPED,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o), canon("makino", &makino));
    let dir = tmp("stray-folder-run");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("pocket_rect.j2"), "G1\n").unwrap();
    let o = cncc(&[
        "--dialect-file",
        SPEC,
        "--post-dir",
        dir.to_str().unwrap(),
        "canon",
        "--dialect",
        "makino",
        TAPPED,
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("E0909"), "{}", stderr(&o));
}
