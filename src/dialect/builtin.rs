//! The built-in dialect specs (embedded from `dialects/*.xml`, parsed once)
//! and the [`Registry`] that adds user specs loaded at run time and
//! resolves ids and aliases.

use super::load::load_spec;
use super::spec::DialectSpec;
use crate::diag::{Code, Diagnostic};
use crate::span::FileId;
use std::sync::{Arc, OnceLock};

/// The built-in specs in load order (a base before what extends it):
/// (id, file name, text).
pub const BUILTIN_SOURCES: &[(&str, &str, &str)] = &[
    (
        "iso6983",
        "dialects/iso6983.xml",
        include_str!("../../dialects/iso6983.xml"),
    ),
    (
        "fanuc",
        "dialects/fanuc.xml",
        include_str!("../../dialects/fanuc.xml"),
    ),
    (
        "haas",
        "dialects/haas.xml",
        include_str!("../../dialects/haas.xml"),
    ),
    (
        "linuxcnc",
        "dialects/linuxcnc.xml",
        include_str!("../../dialects/linuxcnc.xml"),
    ),
    (
        "siemens840d",
        "dialects/siemens840d.xml",
        include_str!("../../dialects/siemens840d.xml"),
    ),
    (
        "heidenhain",
        "dialects/heidenhain.xml",
        include_str!("../../dialects/heidenhain.xml"),
    ),
];

/// Names of dialects cncc knows of but cannot read yet.
const PLANNED: &[(&str, &str)] = &[];

/// Known dialects: the built-ins and specs loaded with `--dialect-file`.
#[derive(Clone, Debug, Default)]
pub struct Registry {
    specs: Vec<Arc<DialectSpec>>,
}

impl Registry {
    /// An empty registry (no built-ins).
    pub fn empty() -> Self {
        Registry::default()
    }

    /// The built-in specs.
    pub fn with_builtins() -> Self {
        Registry {
            specs: builtins().to_vec(),
        }
    }

    pub fn specs(&self) -> &[Arc<DialectSpec>] {
        &self.specs
    }

    /// A spec by id or alias (case-insensitive).
    pub fn get(&self, name: &str) -> Option<Arc<DialectSpec>> {
        let n = name.trim().to_ascii_lowercase();
        let by_id = self.specs.iter().rev().find(|s| s.id == n);
        by_id
            .or_else(|| self.specs.iter().rev().find(|s| s.aliases.contains(&n)))
            .cloned()
    }

    /// A spec by id or alias, or a diagnostic saying why there is none.
    pub fn resolve(&self, name: &str) -> Result<Arc<DialectSpec>, Diagnostic> {
        if let Some(s) = self.get(name) {
            return Ok(s);
        }
        let n = name.trim().to_ascii_lowercase();
        if let Some((_, id)) = PLANNED.iter().find(|(alias, _)| *alias == n) {
            return Err(Diagnostic::new(
                Code::UnknownDialect,
                format!("the {id} dialect is not available yet"),
            )
            .note(format!(
                "`{name}` names the {id} dialect, which cncc cannot read or write in this version"
            ))
            .help(format!("available dialects: {}", self.ids().join(", "))));
        }
        Err(
            Diagnostic::new(Code::UnknownDialect, format!("unknown dialect `{name}`")).help(
                format!(
                    "available dialects: {} (`cncc dialects` lists their aliases)",
                    self.ids().join(", ")
                ),
            ),
        )
    }

    pub fn ids(&self) -> Vec<String> {
        self.specs.iter().map(|s| s.id.clone()).collect()
    }

    /// Loads a user spec (it may extend any spec already here) and adds it;
    /// a spec with an existing id replaces that one for lookups.
    pub fn load(&mut self, text: &str, file: FileId) -> Result<Arc<DialectSpec>, Vec<Diagnostic>> {
        let spec = load_spec(text, file, &|name| self.get(name))?;
        let spec = Arc::new(spec);
        self.specs.retain(|s| s.id != spec.id);
        self.specs.push(spec.clone());
        Ok(spec)
    }
}

/// Every built-in spec, loaded on first use.
///
/// A built-in that does not load is a bug caught by the tests; at run time
/// it is left out rather than stopping the program.
pub fn builtins() -> &'static [Arc<DialectSpec>] {
    static SPECS: OnceLock<Vec<Arc<DialectSpec>>> = OnceLock::new();
    SPECS.get_or_init(|| {
        let mut reg = Registry::empty();
        for (i, (_, _, text)) in BUILTIN_SOURCES.iter().enumerate() {
            let _ = reg.load(text, FileId(i as u32));
        }
        reg.specs
    })
}

/// The XML text a built-in spec is built from, by id or alias.
pub fn builtin_source(id: &str) -> Option<&'static str> {
    let id = builtin(id)?.id.clone();
    BUILTIN_SOURCES
        .iter()
        .find(|(i, _, _)| *i == id)
        .map(|(_, _, text)| *text)
}

/// A built-in spec by id or alias.
pub fn builtin(id: &str) -> Option<Arc<DialectSpec>> {
    let n = id.trim().to_ascii_lowercase();
    let specs = builtins();
    let by_id = specs.iter().find(|s| s.id == n);
    by_id
        .or_else(|| specs.iter().find(|s| s.aliases.contains(&n)))
        .cloned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::render::human;
    use crate::source::SourceMap;

    #[test]
    fn every_builtin_loads_clean() {
        let mut reg = Registry::empty();
        let mut files = SourceMap::new();
        for (id, name, text) in BUILTIN_SOURCES {
            let f = files.add(*name, *text);
            match reg.load(text, f) {
                Ok(s) => assert_eq!(s.id, *id),
                Err(d) => panic!("{name} does not load:\n{}", human(&d, &files, false)),
            }
        }
        assert_eq!(builtins().len(), BUILTIN_SOURCES.len());
    }

    #[test]
    fn aliases_resolve() {
        for (alias, id) in [
            ("sinumerik", "siemens840d"),
            ("840D", "siemens840d"),
            ("siemens", "siemens840d"),
            ("rs274ngc", "linuxcnc"),
            ("ngc", "linuxcnc"),
            ("emc", "linuxcnc"),
            ("fanuc", "fanuc"),
            ("HAAS", "haas"),
        ] {
            assert_eq!(
                builtin(alias).map(|s| s.id.clone()).as_deref(),
                Some(id),
                "{alias}"
            );
        }
        assert!(builtin("nonsense").is_none());
    }

    #[test]
    fn heidenhain_resolves() {
        let reg = Registry::with_builtins();
        for name in ["tnc", "klartext", "heidenhain"] {
            assert_eq!(
                reg.resolve(name).map(|s| s.id.clone()).ok().as_deref(),
                Some("heidenhain")
            );
        }
        assert!(reg
            .resolve("gibberish")
            .unwrap_err()
            .message
            .contains("unknown dialect"));
    }
}
