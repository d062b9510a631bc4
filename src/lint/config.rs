//! The shop's lint configuration: `[lint]` in a `cncc.toml` found beside
//! the program or in a folder above it, then `--select`/`--ignore` on the
//! command line, as ruff does it.
//!
//! ```toml
//! [lint]
//! select = ["W07"]            # replaces the default set: codes, prefixes, names
//! extend-select = ["W0711"]   # adds to it
//! ignore = ["W0703"]          # takes away (the more specific selector wins)
//! error = ["W0701"]           # reported as errors (check exits 1)
//!
//! [lint.peck-too-deep]
//! max-diameters = 4.0
//! ```

use super::rules::{Rule, RULES};
use crate::diag::{Code, Severity};
use serde::Deserialize;
use std::path::{Path, PathBuf};

/// The file name looked for beside the program and upward.
pub const FILE_NAME: &str = "cncc.toml";

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    lint: Option<LintTable>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct LintTable {
    select: Option<Vec<String>>,
    #[serde(default)]
    extend_select: Vec<String>,
    #[serde(default)]
    ignore: Vec<String>,
    #[serde(default)]
    error: Vec<String>,
    #[serde(rename = "peck-too-deep")]
    peck_too_deep: Option<PeckTable>,
    #[serde(rename = "rapid-below-cut")]
    rapid_below_cut: Option<ToleranceTable>,
    #[serde(rename = "speed-absurd-for-tool")]
    speed_for_tool: Option<SpeedTable>,
    #[serde(rename = "feed-absurd-for-tool")]
    feed_for_tool: Option<FeedTable>,
    #[serde(rename = "values-look-like-other-unit")]
    other_unit: Option<UnitTable>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct SpeedTable {
    max_surface_speed: Option<f64>,
    min_surface_speed: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct FeedTable {
    max_feed_per_rev: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct UnitTable {
    inch_max_z: Option<f64>,
    inch_max_xy: Option<f64>,
    metric_max_feed: Option<f64>,
    metric_max_size: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct PeckTable {
    max_diameters: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct ToleranceTable {
    tolerance_mm: f64,
}

/// Selectors given on the command line (they come after the file's).
#[derive(Clone, Debug, Default)]
pub struct CliSelect {
    pub select: Option<Vec<String>>,
    pub extend_select: Vec<String>,
    pub ignore: Vec<String>,
}

/// Which rules run, at which severity, with which limits.
#[derive(Clone, Debug)]
pub struct LintConfig {
    enabled: Vec<Code>,
    errors: Vec<Code>,
    /// Peck depth limit, in tool diameters (W0713).
    pub peck_max_diameters: f64,
    /// How far below the lowest cut a rapid may go, mm (W0709, W0712).
    pub below_tolerance_mm: f64,
    /// Surface speed limits, m/min (W0717).
    pub max_surface_speed: f64,
    pub min_surface_speed: f64,
    /// Feed per spindle revolution limit, in tool diameters (W0718).
    pub max_feed_per_rev: f64,
    /// W0719: an inch program's cuts beyond these (inch) look metric.
    pub inch_max_z: f64,
    pub inch_max_xy: f64,
    /// W0719: a metric program whose every cutting feed (mm/min) and
    /// whose cut size (mm) stay within these looks inch.
    pub metric_max_feed: f64,
    pub metric_max_size: f64,
    /// The file the settings came from, if any.
    pub source: Option<PathBuf>,
}

impl Default for LintConfig {
    fn default() -> Self {
        LintConfig {
            enabled: RULES.iter().filter(|r| r.default).map(|r| r.code).collect(),
            errors: Vec::new(),
            peck_max_diameters: 3.0,
            below_tolerance_mm: 0.01,
            max_surface_speed: 2500.0,
            min_surface_speed: 1.0,
            max_feed_per_rev: 0.5,
            inch_max_z: 20.0,
            inch_max_xy: 120.0,
            metric_max_feed: 50.0,
            metric_max_size: 25.0,
            source: None,
        }
    }
}

impl LintConfig {
    pub fn is_enabled(&self, code: Code) -> bool {
        self.enabled.contains(&code)
    }

    /// The severity a finding of `code` is reported with.
    pub fn severity(&self, code: Code) -> Severity {
        if self.errors.contains(&code) {
            Severity::Error
        } else {
            code.severity()
        }
    }

    /// The settings for a program at `program`: its `cncc.toml` (beside it
    /// or above), then the command line's selectors.
    pub fn for_program(program: &Path, cli: &CliSelect) -> Result<LintConfig, String> {
        let found = find_file(program);
        let (table, source) = match &found {
            Some(p) => (read_file(p)?, Some(p.clone())),
            None => (LintTable::default(), None),
        };
        let mut cfg = build(&table, cli).map_err(|e| match &found {
            Some(p) => format!("{}: {e}", p.display()),
            None => e,
        })?;
        cfg.source = source;
        Ok(cfg)
    }

    /// Settings from the text of a `cncc.toml` (for tests).
    pub fn from_toml(text: &str, cli: &CliSelect) -> Result<LintConfig, String> {
        let f: File = toml::from_str(text).map_err(|e| e.to_string())?;
        build(&f.lint.unwrap_or_default(), cli)
    }
}

/// `cncc.toml` in the program's folder or the nearest folder above it.
pub fn find_file(program: &Path) -> Option<PathBuf> {
    let abs = std::fs::canonicalize(program).ok()?;
    let mut dir = abs.parent();
    while let Some(d) = dir {
        let p = d.join(FILE_NAME);
        if p.is_file() {
            return Some(p);
        }
        dir = d.parent();
    }
    None
}

fn read_file(path: &Path) -> Result<LintTable, String> {
    let text = crate::cli::context::read_text_limited(path, crate::cli::context::MAX_SIDE_FILE)
        .map_err(|e| e.0)?;
    let f: File = toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(f.lint.unwrap_or_default())
}

fn build(t: &LintTable, cli: &CliSelect) -> Result<LintConfig, String> {
    for s in t
        .select
        .iter()
        .flatten()
        .chain(&t.extend_select)
        .chain(&t.ignore)
        .chain(&t.error)
        .chain(cli.select.iter().flatten())
        .chain(&cli.extend_select)
        .chain(&cli.ignore)
    {
        if !RULES.iter().any(|r| specificity(s, r).is_some()) {
            return Err(format!(
                "`{s}` is not a lint rule, a prefix of one or a rule name (`cncc explain W07` lists them)"
            ));
        }
    }
    let mut cfg = LintConfig::default();
    // Two layers, as ruff has them: the file's, then the command line's;
    // in each the more specific selector wins.
    let file: Vec<Code> = layer(&cfg.enabled, t.select.as_ref(), &t.extend_select, &t.ignore);
    cfg.enabled = layer(&file, cli.select.as_ref(), &cli.extend_select, &cli.ignore);
    cfg.errors = RULES
        .iter()
        .filter(|r| best(t.error.iter(), r).is_some())
        .map(|r| r.code)
        .collect();
    if let Some(p) = &t.peck_too_deep {
        if !(p.max_diameters > 0.0) {
            return Err("[lint.peck-too-deep] max-diameters must be above 0".into());
        }
        cfg.peck_max_diameters = p.max_diameters;
    }
    if let Some(r) = &t.rapid_below_cut {
        if !(r.tolerance_mm >= 0.0) {
            return Err("[lint.rapid-below-cut] tolerance-mm must be 0 or more".into());
        }
        cfg.below_tolerance_mm = r.tolerance_mm;
    }
    limits(t, &mut cfg)?;
    Ok(cfg)
}

/// The per-rule limits of W0717..W0719: each must be a positive number.
fn limits(t: &LintTable, cfg: &mut LintConfig) -> Result<(), String> {
    let set = |v: Option<f64>, to: &mut f64, what: &str| match v {
        Some(x) if !(x > 0.0 && x.is_finite()) => Err(format!("{what} must be above 0")),
        Some(x) => {
            *to = x;
            Ok(())
        }
        None => Ok(()),
    };
    if let Some(s) = &t.speed_for_tool {
        let w = "[lint.speed-absurd-for-tool]";
        set(
            s.max_surface_speed,
            &mut cfg.max_surface_speed,
            &format!("{w} max-surface-speed"),
        )?;
        set(
            s.min_surface_speed,
            &mut cfg.min_surface_speed,
            &format!("{w} min-surface-speed"),
        )?;
    }
    if let Some(f) = &t.feed_for_tool {
        let w = "[lint.feed-absurd-for-tool] max-feed-per-rev";
        set(Some(f.max_feed_per_rev), &mut cfg.max_feed_per_rev, w)?;
    }
    if let Some(u) = &t.other_unit {
        let w = "[lint.values-look-like-other-unit]";
        set(
            u.inch_max_z,
            &mut cfg.inch_max_z,
            &format!("{w} inch-max-z"),
        )?;
        set(
            u.inch_max_xy,
            &mut cfg.inch_max_xy,
            &format!("{w} inch-max-xy"),
        )?;
        set(
            u.metric_max_feed,
            &mut cfg.metric_max_feed,
            &format!("{w} metric-max-feed"),
        )?;
        set(
            u.metric_max_size,
            &mut cfg.metric_max_size,
            &format!("{w} metric-max-size"),
        )?;
    }
    Ok(())
}

/// One layer of selection over the rules `before` it enabled.
fn layer(
    before: &[Code],
    select: Option<&Vec<String>>,
    extend: &[String],
    ignore: &[String],
) -> Vec<Code> {
    RULES
        .iter()
        .filter(|r| {
            let chosen = match select {
                Some(list) => best(list.iter(), r),
                None => before.contains(&r.code).then_some(0),
            };
            let chosen = chosen.max(best(extend.iter(), r));
            match (chosen, best(ignore.iter(), r)) {
                (Some(c), Some(d)) => c > d,
                (c, _) => c.is_some(),
            }
        })
        .map(|r| r.code)
        .collect()
}

/// The most specific selector of `list` that picks `rule`.
fn best<'a>(list: impl Iterator<Item = &'a String>, rule: &Rule) -> Option<usize> {
    list.filter_map(|s| specificity(s, rule)).max()
}

/// How specifically `sel` names `rule`: the prefix length (`W07` 3,
/// `W0701` 5), a name counts as the whole code, `ALL` as 0; None when it
/// does not pick it.
fn specificity(sel: &str, rule: &Rule) -> Option<usize> {
    let s = sel.trim();
    let code = rule.code.code();
    if s.eq_ignore_ascii_case("ALL") {
        return Some(0);
    }
    if s.eq_ignore_ascii_case(rule.code.name()) {
        return Some(code.len());
    }
    let up = s.to_ascii_uppercase();
    (!up.is_empty() && code.starts_with(&up)).then_some(up.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg(toml: &str) -> LintConfig {
        LintConfig::from_toml(toml, &CliSelect::default()).unwrap()
    }

    #[test]
    fn defaults_are_the_rules_almost_always_right() {
        let c = LintConfig::default();
        assert!(c.is_enabled(Code::LintFeedSpindleStopped));
        assert!(!c.is_enabled(Code::LintNoWorkOffset));
        assert!(!c.is_enabled(Code::LintNoUnits));
    }

    #[test]
    fn select_replaces_extend_adds_ignore_removes() {
        let c = cfg("[lint]\nselect = [\"W0701\"]\n");
        assert!(c.is_enabled(Code::LintFeedSpindleStopped));
        assert!(!c.is_enabled(Code::LintNoUnits));
        let c = cfg("[lint]\nextend-select = [\"no-work-offset\"]\nignore = [\"W0701\"]\n");
        assert!(c.is_enabled(Code::LintNoWorkOffset));
        assert!(!c.is_enabled(Code::LintFeedSpindleStopped));
        assert!(c.is_enabled(Code::LintMoveAfterEnd));
        assert!(!c.is_enabled(Code::LintNoUnits));
    }

    #[test]
    fn the_more_specific_selector_wins() {
        let c = cfg("[lint]\nselect = [\"W07\", \"W0701\"]\nignore = [\"W070\"]\n");
        assert!(c.is_enabled(Code::LintFeedSpindleStopped));
        assert!(!c.is_enabled(Code::LintNoLengthOffset));
        assert!(c.is_enabled(Code::LintNoUnits));
    }

    #[test]
    fn cli_select_overrides_the_file_and_errors_are_kept() {
        let cli = CliSelect {
            select: Some(vec!["W0710".into()]),
            ..Default::default()
        };
        let c =
            LintConfig::from_toml("[lint]\nselect=[\"W0701\"]\nerror=[\"W0710\"]\n", &cli).unwrap();
        assert!(!c.is_enabled(Code::LintFeedSpindleStopped));
        assert!(c.is_enabled(Code::LintNoUnits));
        assert_eq!(c.severity(Code::LintNoUnits), Severity::Error);
    }

    #[test]
    fn unknown_selectors_and_keys_are_refused() {
        assert!(
            LintConfig::from_toml("[lint]\nselect=[\"E0201\"]\n", &CliSelect::default()).is_err()
        );
        assert!(
            LintConfig::from_toml("[lint]\nselekt=[\"W07\"]\n", &CliSelect::default()).is_err()
        );
        let c = cfg("[lint.peck-too-deep]\nmax-diameters = 5\n");
        assert_eq!(c.peck_max_diameters, 5.0);
    }

    #[test]
    fn the_shops_limits_for_speeds_feeds_and_units() {
        let c = cfg("[lint.speed-absurd-for-tool]\nmax-surface-speed = 1200\n\
             [lint.feed-absurd-for-tool]\nmax-feed-per-rev = 0.2\n\
             [lint.values-look-like-other-unit]\ninch-max-z = 30\n");
        assert_eq!(c.max_surface_speed, 1200.0);
        assert_eq!(c.min_surface_speed, 1.0);
        assert_eq!(c.max_feed_per_rev, 0.2);
        assert_eq!(c.inch_max_z, 30.0);
        assert_eq!(c.metric_max_feed, 50.0);
        for bad in [
            "[lint.feed-absurd-for-tool]\nmax-feed-per-rev = 0\n",
            "[lint.speed-absurd-for-tool]\nmax-surface-speed = -3\n",
            "[lint.values-look-like-other-unit]\ninch-max-q = 3\n",
        ] {
            assert!(
                LintConfig::from_toml(bad, &CliSelect::default()).is_err(),
                "{bad}"
            );
        }
    }
}
