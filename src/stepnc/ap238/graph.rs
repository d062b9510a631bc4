//! Reading an AIM instance graph: parameters by position, the instances
//! that refer to one (AIM relationships point from the relationship to
//! both ends), complex-instance parts, and units with their factors.

use crate::stepnc::part21::{Instance, P21File, Param, Value};
use std::cell::RefCell;
use std::collections::HashMap;

/// The graph with a reverse index: who refers to each instance, and which
/// instances the reader has used (the rest are named as not read).
pub struct Graph<'f> {
    pub f: &'f P21File,
    referrers: HashMap<u64, Vec<usize>>,
    used: RefCell<Vec<bool>>,
}

impl<'f> Graph<'f> {
    pub fn new(f: &'f P21File) -> Self {
        let mut referrers: HashMap<u64, Vec<usize>> = HashMap::new();
        for (pos, i) in f.instances.iter().enumerate() {
            let mut refs = Vec::new();
            collect_refs(&i.params, &mut refs);
            for r in &i.more_parts {
                collect_refs(&r.params, &mut refs);
            }
            refs.sort_unstable();
            refs.dedup();
            for r in refs {
                referrers.entry(r).or_default().push(pos);
            }
        }
        let used = RefCell::new(vec![false; f.instances.len()]);
        Graph { f, referrers, used }
    }

    /// Instance `#id`, marked used.
    pub fn get(&self, id: u64) -> Option<&'f Instance> {
        let pos = self.f.position(id)?;
        self.used.borrow_mut()[pos] = true;
        Some(&self.f.instances[pos])
    }

    /// Marks an instance used.
    pub fn touch(&self, i: &Instance) {
        if let Some(pos) = self.f.position(i.id) {
            self.used.borrow_mut()[pos] = true;
        }
    }

    /// The instances never used, in file order.
    pub fn unused(&self) -> Vec<&'f Instance> {
        let used = self.used.borrow();
        self.f
            .instances
            .iter()
            .zip(used.iter())
            .filter(|(_, u)| !**u)
            .map(|(i, _)| i)
            .collect()
    }

    /// Instances of `entity` whose parameter `k` refers to `id`.
    pub fn referring(&self, id: u64, entity: &str, k: usize) -> Vec<&'f Instance> {
        let f = self.f;
        self.referrers
            .get(&id)
            .map(|v| {
                v.iter()
                    .map(|&p| &f.instances[p])
                    .filter(|i| i.entity == entity && refers_at(i, k, id))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// The instances of an entity, in file order.
    pub fn all(&self, entity: &str) -> Vec<&'f Instance> {
        self.f
            .instances
            .iter()
            .filter(|i| i.entity == entity)
            .collect()
    }

    /// `parts[k]` of the instance's part named `part` (any part of a
    /// complex instance, or the simple instance itself).
    pub fn part<'a>(&self, i: &'a Instance, part: &str) -> Option<&'a [Param]> {
        if i.entity == part {
            return Some(&i.params);
        }
        i.more_parts
            .iter()
            .find(|r| r.entity == part)
            .map(|r| r.params.as_slice())
    }

    /// How many mm a length unit is (SI metre with its prefix, or a
    /// conversion-based unit such as the inch).
    pub fn length_mm(&self, unit: u64, depth: u32) -> Option<f64> {
        let i = self.get(unit)?;
        if let Some(p) = self.part(i, "SI_UNIT") {
            if enum_of(p.get(1)?)? != "METRE" {
                return None;
            }
            return Some(match p.first().and_then(enum_of).as_deref() {
                None => 1000.0,
                Some("MILLI") => 1.0,
                Some("CENTI") => 10.0,
                Some("DECI") => 100.0,
                Some("MICRO") => 0.001,
                Some("KILO") => 1e6,
                Some(_) => return None,
            });
        }
        let (v, base) = self.conversion(i, depth)?;
        Some(v * self.length_mm(base, depth + 1)?)
    }

    /// How many minutes a time unit is.
    pub fn time_min(&self, unit: u64, depth: u32) -> Option<f64> {
        let i = self.get(unit)?;
        if let Some(p) = self.part(i, "SI_UNIT") {
            return (enum_of(p.get(1)?)? == "SECOND" && p.first().and_then(enum_of).is_none())
                .then_some(1.0 / 60.0);
        }
        let (v, base) = self.conversion(i, depth)?;
        Some(v * self.time_min(base, depth + 1)?)
    }

    /// A conversion-based unit: its factor and the unit it is given in.
    fn conversion(&self, i: &Instance, depth: u32) -> Option<(f64, u64)> {
        if depth > 8 {
            return None;
        }
        let p = self.part(i, "CONVERSION_BASED_UNIT")?;
        let m = self.get(reference_of(p.get(1)?)?)?;
        self.measure(m)
    }

    /// Value and unit of a measure instance (`MEASURE_REPRESENTATION_ITEM`,
    /// `LENGTH_MEASURE_WITH_UNIT`..., or a complex instance with a
    /// `MEASURE_WITH_UNIT` part).
    pub fn measure(&self, i: &Instance) -> Option<(f64, u64)> {
        if let Some(p) = self.part(i, "MEASURE_WITH_UNIT") {
            return Some((number(p.first()?)?, reference_of(p.get(1)?)?));
        }
        if i.entity == "MEASURE_REPRESENTATION_ITEM" {
            return Some((number(i.params.get(1)?)?, reference_of(i.params.get(2)?)?));
        }
        if i.entity.ends_with("MEASURE_WITH_UNIT") {
            return Some((number(i.params.first()?)?, reference_of(i.params.get(1)?)?));
        }
        None
    }

    /// A rate unit (`DERIVED_UNIT` of a length or a revolution over a
    /// time) as the factor to per minute of mm (or revolutions), and the
    /// part of it its length unit gives (mm per unit of that length; 1
    /// for revolutions).
    pub fn per_minute(&self, unit: u64) -> Option<(f64, f64)> {
        let u = self.get(unit)?;
        let Value::List(elements) = &self.part(u, "DERIVED_UNIT")?.first()?.value else {
            return None;
        };
        let mut factor = 1.0;
        let mut length = 1.0;
        for e in elements {
            let e = self.get(reference_of(e)?)?;
            let (base, exp) = (reference_of(e.params.first()?)?, number(e.params.get(1)?)?);
            let b = self.get(base)?;
            let f = if self.part(b, "CONTEXT_DEPENDENT_UNIT").is_some() {
                1.0
            } else if let Some(mm) = self.length_mm(base, 0) {
                length *= mm.powf(exp);
                mm
            } else {
                self.time_min(base, 0)?
            };
            factor *= f.powf(exp);
        }
        Some((factor, length))
    }

    /// The length unit (mm per unit) of a representation context; mm when
    /// it assigns none.
    pub fn context_mm(&self, context: Option<u64>) -> f64 {
        let Some(c) = context.and_then(|c| self.get(c)) else {
            return 1.0;
        };
        let Some(Value::List(units)) = self
            .part(c, "GLOBAL_UNIT_ASSIGNED_CONTEXT")
            .and_then(|p| p.first())
            .map(|p| &p.value)
        else {
            return 1.0;
        };
        units
            .iter()
            .filter_map(reference_of)
            .find_map(|u| self.length_mm(u, 0))
            .unwrap_or(1.0)
    }
}

fn collect_refs(params: &[Param], out: &mut Vec<u64>) {
    for p in params {
        match &p.value {
            Value::Ref(r) => out.push(*r),
            Value::List(l) => collect_refs(l, out),
            Value::Typed(_, b) => collect_refs(std::slice::from_ref(b), out),
            _ => {}
        }
    }
}

/// Whether parameter `k` is `#id` or a list holding it.
fn refers_at(i: &Instance, k: usize, id: u64) -> bool {
    match i.params.get(k).map(|p| &p.value) {
        Some(Value::Ref(r)) => *r == id,
        Some(Value::List(l)) => l.iter().any(|p| reference_of(p) == Some(id)),
        _ => false,
    }
}

/// Parameter `k` as a reference.
pub fn reference(i: &Instance, k: usize) -> Option<u64> {
    reference_of(i.params.get(k)?)
}

pub fn reference_of(p: &Param) -> Option<u64> {
    match p.value {
        Value::Ref(r) => Some(r),
        _ => None,
    }
}

/// Parameter `k` as a string ("" when absent).
pub fn string(i: &Instance, k: usize) -> String {
    match i.params.get(k).map(|p| &p.value) {
        Some(Value::Str(s)) => s.clone(),
        _ => String::new(),
    }
}

/// A number, typed (`LENGTH_MEASURE(2.)`) or not.
pub fn number(p: &Param) -> Option<f64> {
    match &p.value {
        Value::Real(r) => Some(*r),
        Value::Int(n) => Some(*n as f64),
        Value::Typed(_, b) => number(b),
        _ => None,
    }
}

pub fn enum_of(p: &Param) -> Option<String> {
    match &p.value {
        Value::Enum(e) => Some(e.clone()),
        _ => None,
    }
}

/// The references in list parameter `k`.
pub fn refs(i: &Instance, k: usize) -> Vec<u64> {
    match i.params.get(k).map(|p| &p.value) {
        Some(Value::List(l)) => l.iter().filter_map(reference_of).collect(),
        _ => Vec::new(),
    }
}
