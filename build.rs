//! Runs LALRPOP over `grammar/`, one generated parser per syntax family,
//! and lists the built-in post templates (`posts/<dialect>/*.j2`) for
//! `src/post/templates.rs` to compile in, so no Rust names a folder.
use std::fmt::Write as _;

fn main() {
    println!("cargo:rerun-if-changed=grammar");
    lalrpop::Configuration::new()
        .set_in_dir("grammar")
        .set_out_dir(std::env::var("OUT_DIR").expect("OUT_DIR"))
        .emit_rerun_directives(true)
        .process()
        .expect("LALRPOP grammar generation failed");
    post_sets();
}

/// Writes `$OUT_DIR/post_sets.rs`: `(folder, [(file, text)])` for every
/// folder of `posts/`, sorted.
fn post_sets() {
    let root =
        std::path::Path::new(&std::env::var("CARGO_MANIFEST_DIR").expect("dir")).join("posts");
    println!("cargo:rerun-if-changed=posts");
    let mut dirs: Vec<_> = std::fs::read_dir(&root)
        .expect("posts/")
        .map(|e| e.expect("posts/ entry").path())
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    let mut out = String::from("&[\n");
    for dir in dirs {
        println!("cargo:rerun-if-changed={}", dir.display());
        let mut files: Vec<_> = std::fs::read_dir(&dir)
            .expect("posts/<dialect>/")
            .map(|e| e.expect("template entry").path())
            .filter(|p| p.extension().is_some_and(|x| x == "j2"))
            .collect();
        files.sort();
        let name = dir.file_name().expect("folder name").to_string_lossy();
        let _ = writeln!(out, "    ({name:?}, &[");
        for f in files {
            println!("cargo:rerun-if-changed={}", f.display());
            let file = f.file_name().expect("file name").to_string_lossy();
            let _ = writeln!(
                out,
                "        ({file:?}, include_str!({:?})),",
                f.display().to_string()
            );
        }
        out.push_str("    ]),\n");
    }
    out.push_str("]\n");
    let dest =
        std::path::Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR")).join("post_sets.rs");
    std::fs::write(dest, out).expect("write post_sets.rs");
}
