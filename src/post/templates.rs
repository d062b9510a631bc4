//! Where a target's post templates come from. The spec declares which
//! templates its post has (`<post-template name="drill"/>`); each is the
//! file `drill.j2`, taken from the user's `--post-dir` folder when it is
//! there, else from the built-in folder `posts/<id>/` of the spec or of
//! the nearest spec it extends that has the file (a user dialect
//! extending fanuc posts with fanuc's templates). The built-in folders are
//! compiled in (`build.rs` lists them), so the binary is self-contained.

use crate::diag::{Code, Diagnostic};
use crate::dialect::post_templates::{is_post_template, POST_TEMPLATES};
use crate::dialect::DialectSpec;
use std::borrow::Cow;
use std::path::{Path, PathBuf};

type Set = &'static [(&'static str, &'static str)];

/// Every folder of `posts/` with its files: (folder, [(file, text)]).
const BUILTIN: &[(&str, Set)] = include!(concat!(env!("OUT_DIR"), "/post_sets.rs"));

/// A folder of user templates (`--post-dir`): `NAME.j2` files that
/// override the built-in ones file by file.
#[derive(Clone, Debug)]
pub struct PostDir {
    pub path: PathBuf,
    /// (file name, text), sorted by name.
    pub files: Vec<(String, String)>,
}

/// The largest template file read.
const MAX_TEMPLATE: u64 = 1 << 20;

impl PostDir {
    /// Reads the `.j2` files of `path` (other files are left alone).
    pub fn read(path: &Path) -> Result<PostDir, String> {
        let entries = std::fs::read_dir(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let mut files = Vec::new();
        for e in entries {
            let p = e.map_err(|e| format!("{}: {e}", path.display()))?.path();
            let Some(name) = p.file_name().map(|n| n.to_string_lossy().into_owned()) else {
                continue;
            };
            if !name.ends_with(".j2") || !p.is_file() {
                continue;
            }
            let len = std::fs::metadata(&p).map(|m| m.len()).unwrap_or(0);
            if len > MAX_TEMPLATE {
                return Err(format!("{}: larger than {MAX_TEMPLATE} bytes", p.display()));
            }
            let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
            files.push((name, text));
        }
        files.sort();
        Ok(PostDir {
            path: path.to_path_buf(),
            files,
        })
    }

    fn get(&self, file: &str) -> Option<&str> {
        self.files
            .iter()
            .find(|(n, _)| n == file)
            .map(|(_, t)| t.as_str())
    }
}

/// One template of a target's post.
#[derive(Clone, Debug)]
pub struct Source {
    /// The file name, `drill.j2`.
    pub file: String,
    pub text: Cow<'static, str>,
    /// Where it was read from (`posts/fanuc/drill.j2`, or the user's path).
    pub origin: String,
}

/// The templates `spec` declares, each from the post folder or the
/// nearest built-in folder of its lineage; every declared template
/// without a file, and every file of the post folder the spec does not
/// declare, is an error (E0909).
pub fn resolve(spec: &DialectSpec, dir: Option<&PostDir>) -> Result<Vec<Source>, Vec<Diagnostic>> {
    if spec.post_templates.is_empty() {
        return Err(vec![Diagnostic::new(
            Code::PostNoTarget,
            format!("`{}` has no post: its spec declares no post templates", spec.id),
        )
        .help("extend a dialect that has a post (`cncc dialects` lists them), or declare `<post-template name=\"...\"/>` entries and give their files with --post-dir")]);
    }
    let lineage: Vec<&str> = std::iter::once(spec.id.as_str())
        .chain(spec.ancestors.iter().map(String::as_str))
        .collect();
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for decl in &spec.post_templates {
        let file = format!("{}.j2", decl.name);
        if let Some(text) = dir.and_then(|d| d.get(&file)) {
            let origin = dir.map(|d| d.path.join(&file).display().to_string());
            out.push(Source {
                file,
                text: Cow::Owned(text.to_string()),
                origin: origin.unwrap_or_default(),
            });
            continue;
        }
        match builtin_file(&lineage, &file) {
            Some((folder, text)) => out.push(Source {
                origin: format!("posts/{folder}/{file}"),
                file,
                text: Cow::Borrowed(text),
            }),
            None => errors.push(missing(spec, decl, &file, dir, &lineage)),
        }
    }
    if let Some(d) = dir {
        for (file, _) in &d.files {
            let name = file.trim_end_matches(".j2");
            if !spec.post_templates.iter().any(|t| t.name == name) {
                errors.push(undeclared(spec, d, file, name));
            }
        }
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        Err(errors)
    }
}

/// The first built-in folder along `lineage` that has `file`.
fn builtin_file(lineage: &[&str], file: &str) -> Option<(&'static str, &'static str)> {
    lineage.iter().find_map(|id| {
        let (folder, set) = BUILTIN.iter().find(|(f, _)| f == id)?;
        set.iter()
            .find(|(n, _)| *n == file)
            .map(|(_, text)| (*folder, *text))
    })
}

fn missing(
    spec: &DialectSpec,
    decl: &crate::dialect::PostTemplateDecl,
    file: &str,
    dir: Option<&PostDir>,
    lineage: &[&str],
) -> Diagnostic {
    let looked: Vec<String> = dir
        .map(|d| d.path.display().to_string())
        .into_iter()
        .chain(
            lineage
                .iter()
                .filter(|id| BUILTIN.iter().any(|(f, _)| f == *id))
                .map(|id| format!("the built-in posts/{id}")),
        )
        .collect();
    let looked = if looked.is_empty() {
        "no post folder was given and no dialect it extends has a built-in one".to_string()
    } else {
        format!("looked in {}", looked.join(", "))
    };
    Diagnostic::new(
        Code::PostTemplateFile,
        format!(
            "`{}` declares the post template `{}` but there is no `{file}` ({looked})",
            spec.id, decl.name
        ),
    )
    .primary(decl.span, "declared here")
    .help(format!(
        "put `{file}` in the folder given with --post-dir (copy one from `cncc dialects --templates ID`), or remove the declaration"
    ))
}

fn undeclared(spec: &DialectSpec, dir: &PostDir, file: &str, name: &str) -> Diagnostic {
    let path = dir.path.join(file).display().to_string();
    let help = if is_post_template(name) {
        format!(
            "declare it in the spec (`<post-template name=\"{name}\"/>` in a spec extending `{}`), or remove the file",
            spec.id
        )
    } else {
        format!(
            "post templates are named {}",
            POST_TEMPLATES
                .iter()
                .map(|(n, _)| format!("{n}.j2"))
                .collect::<Vec<_>>()
                .join(", ")
        )
    };
    let what = if is_post_template(name) {
        format!("`{}` does not declare the post template `{name}`", spec.id)
    } else {
        format!("`{name}` is not a post template")
    };
    Diagnostic::new(
        Code::PostTemplateFile,
        format!("{path}: {what}, so this file would never be used"),
    )
    .help(help)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every built-in spec declares exactly the templates its own folder
    /// holds, or its base's where it has no folder of its own.
    #[test]
    fn every_built_in_folder_is_declared_by_its_spec() {
        for (folder, set) in BUILTIN {
            let spec = crate::dialect::builtin(folder).unwrap();
            let mut declared: Vec<String> = spec
                .post_templates
                .iter()
                .map(|t| format!("{}.j2", t.name))
                .collect();
            declared.sort();
            let files: Vec<String> = set.iter().map(|(n, _)| n.to_string()).collect();
            assert_eq!(declared, files, "{folder}");
            let resolved = resolve(&spec, None).unwrap();
            assert!(resolved
                .iter()
                .all(|s| s.origin.starts_with(&format!("posts/{folder}/"))));
        }
    }

    #[test]
    fn a_user_dialect_inherits_its_bases_templates() {
        let mut spec = (*crate::dialect::builtin("fanuc").unwrap()).clone();
        spec.ancestors.insert(0, spec.id.clone());
        spec.id = "mazak".into();
        let got = resolve(&spec, None).unwrap();
        assert!(got.iter().any(|s| s.origin == "posts/fanuc/drill.j2"));
    }
}
