//! `--tool-map`: tool numbers renumbered on the way to the target, given
//! as `OLD=NEW` pairs (`1=5,2=7`) or a file with one pair per line (`#`
//! starts a comment). The map applies to T words and to the length and
//! radius registers (H, D) that name the same numbers, as CAM posts write
//! H and D equal to the tool number.

use std::collections::BTreeMap;

#[derive(Clone, Debug, Default, PartialEq)]
pub struct ToolMap {
    pairs: BTreeMap<i64, i64>,
}

impl ToolMap {
    /// Reads `1=5,2=7` or, when `text` names a file, its lines.
    pub fn parse(text: &str) -> Result<ToolMap, String> {
        let mut pairs = BTreeMap::new();
        let items = text
            .split([',', '\n'])
            .map(|s| s.split('#').next().unwrap_or("").trim())
            .filter(|s| !s.is_empty());
        for item in items {
            let (a, b) = item
                .split_once('=')
                .ok_or_else(|| format!("`{item}` is not OLD=NEW"))?;
            let num = |s: &str| -> Result<i64, String> {
                s.trim()
                    .parse::<i64>()
                    .ok()
                    .filter(|n| *n >= 0)
                    .ok_or_else(|| format!("`{}` is not a tool number", s.trim()))
            };
            let (a, b) = (num(a)?, num(b)?);
            if pairs.insert(a, b).is_some() {
                return Err(format!("tool {a} is mapped twice"));
            }
        }
        Ok(ToolMap { pairs })
    }

    /// Reads the map from `arg`: a file if one exists by that name.
    pub fn from_arg(arg: &str) -> Result<ToolMap, String> {
        let p = std::path::Path::new(arg);
        if p.is_file() {
            let text =
                crate::cli::context::read_limited(p.as_ref(), crate::cli::context::MAX_SIDE_FILE)
                    .map(|b| String::from_utf8_lossy(&b).into_owned())
                    .map_err(|e| format!("{arg}: {e}"))?;
            return Self::parse(&text);
        }
        Self::parse(arg)
    }

    pub fn is_empty(&self) -> bool {
        self.pairs.is_empty()
    }

    /// The new number of tool `n` (itself when not mapped).
    pub fn map(&self, n: i64) -> i64 {
        self.pairs.get(&n).copied().unwrap_or(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_and_errors() {
        let m = ToolMap::parse("1=5, 2=7\n# comment\n3=3").unwrap();
        assert_eq!((m.map(1), m.map(2), m.map(4)), (5, 7, 4));
        assert!(ToolMap::parse("1=5,1=6").is_err());
        assert!(ToolMap::parse("1:5").is_err());
        assert!(ToolMap::parse("a=5").is_err());
        assert!(ToolMap::parse("1=-2").is_err());
    }
}
