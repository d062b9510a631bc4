//! Variables while a program runs: numbered parameters (`#n`), named
//! parameters (`#<name>`, local per call level, global with `_`), Siemens
//! R parameters and DEF variables. A numbered parameter never set reads as
//! vacant (Fanuc `#0`), which arithmetic treats as zero.

use std::collections::HashMap;

#[derive(Clone, Debug, Default)]
pub struct Params {
    numbered: HashMap<u32, f64>,
    r: HashMap<u32, f64>,
    /// Heidenhain Q / QL / QR parameters (unset ones read 0).
    q: HashMap<(crate::ir::QBank, u32), f64>,
    global_named: HashMap<String, f64>,
    /// One scope per call level; the last is the current one.
    local_named: Vec<HashMap<String, f64>>,
    user: Vec<HashMap<String, f64>>,
    /// Numbered parameters made vacant by the program (`#1=#0`, a call's
    /// fresh locals): known to be vacant, unlike ones never touched.
    vacated: std::collections::HashSet<u32>,
}

impl Params {
    pub fn new() -> Params {
        Params {
            local_named: vec![HashMap::new()],
            user: vec![HashMap::new()],
            ..Default::default()
        }
    }

    /// `#n`: `None` when vacant.
    pub fn numbered(&self, n: u32) -> Option<f64> {
        self.numbered.get(&n).copied()
    }

    pub fn set_numbered(&mut self, n: u32, v: Option<f64>) {
        match v {
            Some(v) => {
                self.numbered.insert(n, v);
            }
            None => {
                self.numbered.remove(&n);
                self.vacated.insert(n);
            }
        }
    }

    /// Whether the run has given `#n` a value (vacant included).
    pub fn numbered_known(&self, n: u32) -> bool {
        self.numbered.contains_key(&n) || self.vacated.contains(&n)
    }

    /// Whether the run has set `Rn`.
    pub fn r_known(&self, n: u32) -> bool {
        self.r.contains_key(&n)
    }

    /// Whether the run has set `Qn` (`QLn`, `QRn`).
    pub fn q_known(&self, bank: crate::ir::QBank, n: u32) -> bool {
        self.q.contains_key(&(bank, n))
    }

    pub fn r(&self, n: u32) -> f64 {
        self.r.get(&n).copied().unwrap_or(0.0)
    }

    pub fn set_r(&mut self, n: u32, v: f64) {
        self.r.insert(n, v);
    }

    /// Heidenhain `Qn`, `QLn`, `QRn` (0 when never set).
    pub fn q(&self, bank: crate::ir::QBank, n: u32) -> f64 {
        self.q.get(&(bank, n)).copied().unwrap_or(0.0)
    }

    pub fn set_q(&mut self, bank: crate::ir::QBank, n: u32, v: f64) {
        self.q.insert((bank, n), v);
    }

    /// `#<name>` (names are case-insensitive; `_` prefix: global).
    pub fn named(&self, name: &str) -> Option<f64> {
        let key = name.to_ascii_lowercase();
        if key.starts_with('_') {
            self.global_named.get(&key).copied()
        } else {
            self.local_named.last().and_then(|s| s.get(&key)).copied()
        }
    }

    pub fn set_named(&mut self, name: &str, v: f64) {
        let key = name.to_ascii_lowercase();
        if key.starts_with('_') {
            self.global_named.insert(key, v);
        } else if let Some(s) = self.local_named.last_mut() {
            s.insert(key, v);
        }
    }

    pub fn user(&self, name: &str) -> Option<f64> {
        let key = name.to_ascii_uppercase();
        self.user.iter().rev().find_map(|s| s.get(&key)).copied()
    }

    pub fn set_user(&mut self, name: &str, v: f64) {
        let key = name.to_ascii_uppercase();
        if let Some(s) = self.user.iter_mut().rev().find(|s| s.contains_key(&key)) {
            s.insert(key, v);
        } else if let Some(s) = self.user.last_mut() {
            s.insert(key, v);
        }
    }

    /// `DEF`: a new variable in the current call level.
    pub fn declare_user(&mut self, name: &str, v: f64) {
        if let Some(s) = self.user.last_mut() {
            s.insert(name.to_ascii_uppercase(), v);
        }
    }

    /// Enters a call level (subroutine, macro): fresh local names.
    pub fn push_scope(&mut self) {
        self.local_named.push(HashMap::new());
        self.user.push(HashMap::new());
    }

    pub fn pop_scope(&mut self) {
        if self.local_named.len() > 1 {
            self.local_named.pop();
            self.user.pop();
        }
    }

    /// Every variable of the outermost level with its value: what a
    /// caller can read after a call (the port's expansion writes back the
    /// ones a replaced part of the program changed).
    pub fn outer_values(&self) -> HashMap<OuterVar, f64> {
        let mut m = HashMap::new();
        m.extend(
            self.numbered
                .iter()
                .map(|(&n, &v)| (OuterVar::Numbered(n), v)),
        );
        m.extend(self.r.iter().map(|(&n, &v)| (OuterVar::R(n), v)));
        m.extend(self.q.iter().map(|(&(b, n), &v)| (OuterVar::Q(b, n), v)));
        m.extend(
            self.global_named
                .iter()
                .map(|(k, &v)| (OuterVar::Named(k.clone()), v)),
        );
        if let Some(top) = self.local_named.first() {
            m.extend(top.iter().map(|(k, &v)| (OuterVar::Named(k.clone()), v)));
        }
        if let Some(top) = self.user.first() {
            m.extend(top.iter().map(|(k, &v)| (OuterVar::User(k.clone()), v)));
        }
        m
    }

    pub fn depth(&self) -> usize {
        self.local_named.len()
    }
}

/// A variable of the outermost call level, by kind and name.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum OuterVar {
    Numbered(u32),
    R(u32),
    Q(crate::ir::QBank, u32),
    /// `#<name>` (global or the main program's local), as stored.
    Named(String),
    /// A Siemens `DEF` variable of the main program (upper case).
    User(String),
}
