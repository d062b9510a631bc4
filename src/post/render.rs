//! Rendering post templates with minijinja. A target's templates are the
//! ones its spec declares, read from `--post-dir` or the built-in folders
//! ([`super::templates`]). A
//! template is filled with [`Vals`]; a name the template asks for that is
//! not given is an error (strict undefined), and so is a value the
//! template does not use, unless the template says so in its first line:
//! `{#- unused: top, sdis -#}` (a value whose information another value
//! already carries, such as the Fanuc R plane carrying top + clearance).

use super::templates::{resolve, PostDir, Source};
use super::values::Vals;
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use minijinja::value::{Object, Value};
use minijinja::{Environment, UndefinedBehavior};
use std::collections::BTreeSet;
use std::sync::{Arc, Mutex};

/// The templates of one target.
pub struct Post {
    env: Environment<'static>,
    sources: Vec<Source>,
    unused_ok: Vec<(String, Vec<String>)>,
}

impl Post {
    /// The templates `spec` declares, from `dir` or the built-in folders;
    /// a missing or undeclared file, or one that does not compile, is an
    /// error.
    pub fn for_spec(spec: &DialectSpec, dir: Option<&PostDir>) -> Result<Post, Vec<Diagnostic>> {
        let sources = resolve(spec, dir)?;
        let mut env = Environment::new();
        env.set_undefined_behavior(UndefinedBehavior::Strict);
        let mut unused_ok = Vec::new();
        let mut errors = Vec::new();
        for s in &sources {
            if let Err(e) = env.add_template_owned(s.file.clone(), s.text.clone()) {
                errors.push(
                    Diagnostic::new(Code::PostTemplate, format!("post template {}: {e}", s.origin))
                        .help("fix the template (minijinja syntax: https://docs.rs/minijinja/latest/minijinja/syntax/)"),
                );
            }
            unused_ok.push((s.file.clone(), declared_unused(&s.text)));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(Post {
            env,
            sources,
            unused_ok,
        })
    }

    /// True when the set has a template of that name (`pocket_rect.j2`...).
    pub fn has(&self, name: &str) -> bool {
        self.sources.iter().any(|s| s.file == name)
    }

    /// Where template `name` was read from (for messages).
    pub fn origin<'a>(&'a self, name: &'a str) -> &'a str {
        self.sources
            .iter()
            .find(|s| s.file == name)
            .map(|s| s.origin.as_str())
            .unwrap_or(name)
    }

    /// The text of template `name` (empty when there is none).
    pub fn source(&self, name: &str) -> &str {
        self.sources
            .iter()
            .find(|s| s.file == name)
            .map(|s| &*s.text)
            .unwrap_or("")
    }

    /// True when template `name` declares `key` unused.
    pub fn ignores(&self, name: &str, key: &str) -> bool {
        self.unused_ok
            .iter()
            .any(|(n, u)| *n == name && u.iter().any(|k| k == key))
    }

    /// Renders `name` with `vals`; every value must be used.
    pub fn render(&self, name: &str, vals: &Vals) -> Result<String, String> {
        let tmpl = self
            .env
            .get_template(name)
            .map_err(|e| format!("no post template `{name}`: {e}"))?;
        let ctx = Arc::new(Tracked {
            vals: vals.clone(),
            used: Mutex::new(BTreeSet::new()),
        });
        let out = tmpl
            .render(Value::from_dyn_object(ctx.clone()))
            .map_err(|e| format!("post template {}: {e}", self.origin(name)))?;
        let used = ctx.used.lock().map(|u| u.clone()).unwrap_or_default();
        let allowed = self
            .unused_ok
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, u)| u.as_slice())
            .unwrap_or(&[]);
        let dropped: Vec<&str> = vals
            .entries
            .iter()
            .map(|(k, _)| *k)
            .filter(|k| !used.contains(*k) && !allowed.iter().any(|a| a == k))
            .filter(|k| !vals.derived.contains(k))
            .collect();
        if !dropped.is_empty() {
            return Err(format!(
                "post template {} does not use {}",
                self.origin(name),
                dropped.join(", ")
            ));
        }
        Ok(out)
    }
}

/// The names a template's first line declares unused.
fn declared_unused(src: &str) -> Vec<String> {
    let first = src.lines().next().unwrap_or("");
    let Some(rest) = first.split("unused:").nth(1) else {
        return Vec::new();
    };
    rest.trim_end_matches(|c: char| c == '}' || c == '#' || c == '-' || c.is_whitespace())
        .split(',')
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .collect()
}

/// The template context: records every name looked up.
#[derive(Debug)]
struct Tracked {
    vals: Vals,
    used: Mutex<BTreeSet<String>>,
}

impl Object for Tracked {
    fn get_value(self: &Arc<Self>, key: &Value) -> Option<Value> {
        self.lookup(key.as_str()?)
    }
    fn get_value_by_str(self: &Arc<Self>, key: &str) -> Option<Value> {
        self.lookup(key)
    }
}

impl Tracked {
    fn lookup(&self, key: &str) -> Option<Value> {
        let v = self.vals.get(key)?;
        if let Ok(mut u) = self.used.lock() {
            u.insert(key.to_string());
        }
        Some(Value::from(v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_value_must_be_used_and_every_name_given() {
        let post = Post::for_spec(&crate::dialect::builtin("fanuc").unwrap(), None).unwrap();
        let v = Vals::new().set("text", "HELLO");
        assert_eq!(post.render("comment.j2", &v).unwrap().trim_end(), "(HELLO)");
        let extra = v.clone().set("stray", "1");
        let err = post.render("comment.j2", &extra).unwrap_err();
        assert!(err.contains("does not use stray"), "{err}");
        assert!(post.render("comment.j2", &Vals::new()).is_err());
    }

    #[test]
    fn declared_unused_names_are_read_from_the_first_line() {
        assert_eq!(
            declared_unused("{#- unused: top, sdis -#}\nG81"),
            vec!["top".to_string(), "sdis".to_string()]
        );
        assert!(declared_unused("G81 X{{x}}").is_empty());
    }
}
