//! Rendering post templates with minijinja. Each target dialect has a set
//! of templates in `posts/<dialect>/` (compiled into the binary). A
//! template is filled with [`Vals`]; a name the template asks for that is
//! not given is an error (strict undefined), and so is a value the
//! template does not use, unless the template says so in its first line:
//! `{#- unused: top, sdis -#}` (a value whose information another value
//! already carries, such as the Fanuc R plane carrying top + clearance).

use super::templates::template_set;
use super::values::Vals;
use minijinja::value::{Object, Value};
use minijinja::{Environment, UndefinedBehavior};
use std::collections::BTreeSet;
use std::sync::{Arc, Mutex};

/// The templates of one target.
pub struct Post {
    env: Environment<'static>,
    names: Vec<&'static str>,
    sources: &'static [(&'static str, &'static str)],
    unused_ok: Vec<(&'static str, Vec<String>)>,
}

impl Post {
    /// The template set for `dialect`, or `None` when there is none.
    pub fn for_dialect(dialect: &str) -> Option<Result<Post, String>> {
        let set = template_set(dialect)?;
        let mut env = Environment::new();
        env.set_undefined_behavior(UndefinedBehavior::Strict);
        let mut names = Vec::new();
        let mut unused_ok = Vec::new();
        for (name, src) in set {
            if let Err(e) = env.add_template(name, src) {
                return Some(Err(format!("post template {dialect}/{name}: {e}")));
            }
            names.push(*name);
            unused_ok.push((*name, declared_unused(src)));
        }
        Some(Ok(Post {
            env,
            names,
            sources: set,
            unused_ok,
        }))
    }

    /// True when the set has a template of that name (`pocket_rect.j2`...).
    pub fn has(&self, name: &str) -> bool {
        self.names.contains(&name)
    }

    /// The text of template `name` (empty when there is none).
    pub fn source(&self, name: &str) -> &str {
        self.sources
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, s)| *s)
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
            .map_err(|e| format!("post template `{name}`: {e}"))?;
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
                "post template `{name}` does not use {}",
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
        let post = Post::for_dialect("fanuc").unwrap().unwrap();
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
