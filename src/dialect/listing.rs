//! The text `cncc dialects` prints: every known dialect with its id, name,
//! family, aliases, extensions, base and capabilities, in a stable order.

use super::builtin::Registry;
use super::spec::DialectSpec;
use std::fmt::Write;

/// Describes every dialect of the registry, in registry order.
pub fn describe_all(reg: &Registry) -> String {
    let mut out = String::new();
    for (i, s) in reg.specs().iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        describe(&mut out, s);
    }
    out
}

fn list(items: &[String], prefix: &str) -> String {
    if items.is_empty() {
        return "-".to_string();
    }
    items
        .iter()
        .map(|s| format!("{prefix}{s}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn describe(out: &mut String, s: &DialectSpec) {
    let caps: Vec<String> = s
        .capabilities
        .iter()
        .map(|c| c.name().to_string())
        .collect();
    let _ = writeln!(out, "{}: {}", s.id, s.name);
    let _ = writeln!(out, "  family:       {}", s.family.name());
    let _ = writeln!(
        out,
        "  extends:      {}",
        s.extends.as_deref().unwrap_or("-")
    );
    let _ = writeln!(out, "  aliases:      {}", list(&s.aliases, ""));
    let _ = writeln!(out, "  extensions:   {}", list(&s.extensions, "."));
    let _ = writeln!(out, "  capabilities: {}", list(&caps, ""));
    let _ = writeln!(
        out,
        "  table:        {} codes, {} cycles, {} functions, {} commands",
        s.codes.len(),
        s.cycles.len(),
        s.functions.len(),
        s.commands.len()
    );
    let posts: Vec<String> = s.post_templates.iter().map(|t| t.name.clone()).collect();
    let _ = writeln!(out, "  post:         {}", list(&posts, ""));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn listing_of_builtins() {
        insta::assert_snapshot!(describe_all(&Registry::with_builtins()));
    }
}
