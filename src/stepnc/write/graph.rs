//! The instance graph as the writer builds it, held compactly: each
//! instance is its own Part 21 text (`NAME(params)`) with provisional
//! numbers in its references, all in one buffer. Equal value instances are
//! found by a hash of that text (equal text is equal value: reals are
//! written in their shortest round-trip form). Numbering (depth-first from
//! the root, references in order) and writing then rewrite the numbers in
//! one pass over the text, straight into the output.

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};
use std::io::{self, Write};
use std::time::Instant;

/// Instance texts by provisional number (index + 1).
#[derive(Default)]
pub(super) struct Graph {
    /// Every instance's text, one after another, in chunks that are never
    /// reallocated (a growing single buffer would need up to twice the room).
    chunks: Vec<String>,
    /// Where instance n's text is, at index n - 1: chunk, start, length.
    nodes: Vec<(u32, u32, usize)>,
    /// The first shared instance whose text has that (32-bit) hash; both
    /// halves 32 bits to keep the table small (8 bytes an entry).
    shared: HashMap<u32, u32, BuildHasherDefault<KeyIsHash>>,
    /// Further shared instances whose text hashes the same.
    collided: HashMap<u32, Vec<u64>>,
    /// The instance being written.
    scratch: String,
}

impl Graph {
    /// The buffer to write the next instance's text into, emptied.
    pub fn scratch(&mut self) -> &mut String {
        self.scratch.clear();
        &mut self.scratch
    }

    /// The scratch text as a shared value instance: an equal one already
    /// there, or a new one.
    pub fn add_scratch_shared(&mut self) -> u64 {
        let hash = text_hash(&self.scratch);
        let Some(&first) = self.shared.get(&hash) else {
            let n = self.push_scratch();
            // Past 4 billion instances new values are no longer shared.
            if let Ok(n) = u32::try_from(n) {
                self.shared.insert(hash, n);
            }
            return n;
        };
        let first = u64::from(first);
        if self.node_text(first) == self.scratch {
            return first;
        }
        let others = self.collided.get(&hash).map_or(&[][..], |v| v.as_slice());
        if let Some(&n) = others.iter().find(|&&n| self.node_text(n) == self.scratch) {
            return n;
        }
        let n = self.push_scratch();
        self.collided.entry(hash).or_default().push(n);
        n
    }

    /// A number for an instance whose text comes later.
    pub fn reserve(&mut self) -> u64 {
        self.nodes.push((0, 0, 0));
        self.nodes.len() as u64
    }

    /// Gives a reserved instance the scratch text.
    pub fn fill_from_scratch(&mut self, n: u64) {
        const CHUNK: usize = 1 << 20;
        let len = self.scratch.len();
        let fits = self
            .chunks
            .last()
            .is_some_and(|c| c.capacity() - c.len() >= len);
        if !fits {
            self.chunks.push(String::with_capacity(CHUNK.max(len)));
        }
        let chunk = self.chunks.len() - 1;
        let text = &mut self.chunks[chunk];
        // A chunk holds at most CHUNK bytes before a longer instance,
        // which then starts a chunk of its own at 0: starts fit in u32.
        let span = (chunk as u32, text.len() as u32, len);
        text.push_str(&self.scratch);
        if let Some(slot) = self.nodes.get_mut((n as usize).wrapping_sub(1)) {
            *slot = span;
        }
    }

    fn push_scratch(&mut self) -> u64 {
        let n = self.reserve();
        self.fill_from_scratch(n);
        n
    }

    fn node_text(&self, n: u64) -> &str {
        match self.nodes.get((n as usize).wrapping_sub(1)) {
            Some(&(chunk, start, len)) => {
                let start = start as usize;
                self.chunks
                    .get(chunk as usize)
                    .and_then(|c| c.get(start..start + len))
                    .unwrap_or("")
            }
            None => "",
        }
    }

    /// Writes the instances reachable from `root`, numbered depth-first
    /// from it (`#1`) following references in order, one a line.
    pub fn write_numbered<O: Write + ?Sized>(mut self, root: u64, out: &mut O) -> io::Result<()> {
        self.shared = HashMap::default();
        self.collided = HashMap::new();
        let (order, new_id) = self.number(root);
        let mut buf = Vec::with_capacity(1 << 16);
        for &n in &order {
            buf.push(b'#');
            push_u64(&mut buf, new_id[n as usize]);
            buf.push(b'=');
            rewrite_refs(self.node_text(n), &new_id, &mut buf);
            buf.extend_from_slice(b";\n");
            if buf.len() >= 1 << 16 {
                out.write_all(&buf)?;
                buf.clear();
            }
        }
        out.write_all(&buf)
    }

    /// The reachable instances in their new order, and the new number of
    /// each provisional one (0: not reached).
    fn number(&self, root: u64) -> (Vec<u64>, Vec<u64>) {
        let mut new_id = vec![0u64; self.nodes.len() + 1];
        let mut order = Vec::new();
        let mut stack = vec![root];
        let mut refs = Vec::new();
        while let Some(n) = stack.pop() {
            match new_id.get(n as usize) {
                Some(0) => {}
                _ => continue,
            }
            order.push(n);
            new_id[n as usize] = order.len() as u64;
            refs.clear();
            for_each_ref(self.node_text(n), |r| refs.push(r));
            stack.extend(refs.iter().rev());
        }
        (order, new_id)
    }
}

/// Calls `f` with every `#n` outside strings, in order.
fn for_each_ref(text: &str, mut f: impl FnMut(u64)) {
    let b = text.as_bytes();
    let mut in_string = false;
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\'' => in_string = !in_string,
            b'#' if !in_string => {
                let (n, end) = number_at(b, i + 1);
                f(n);
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
}

/// Copies `text`, each `#n` outside strings renumbered as `#new_id[n]`.
fn rewrite_refs(text: &str, new_id: &[u64], out: &mut Vec<u8>) {
    let b = text.as_bytes();
    let mut in_string = false;
    let mut copied = 0;
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'\'' => in_string = !in_string,
            b'#' if !in_string => {
                let (n, end) = number_at(b, i + 1);
                out.extend_from_slice(&b[copied..=i]);
                match new_id.get(n as usize) {
                    Some(&id) if id > 0 => push_u64(out, id),
                    _ => out.extend_from_slice(&b[i + 1..end]),
                }
                copied = end;
                i = end;
                continue;
            }
            _ => {}
        }
        i += 1;
    }
    out.extend_from_slice(&b[copied..]);
}

/// The decimal number starting at `i` and where it ends.
fn number_at(b: &[u8], mut i: usize) -> (u64, usize) {
    let mut n = 0u64;
    while let Some(d) = b.get(i).filter(|d| d.is_ascii_digit()) {
        n = n.wrapping_mul(10).wrapping_add(u64::from(d - b'0'));
        i += 1;
    }
    (n, i)
}

fn push_u64(out: &mut Vec<u8>, mut n: u64) {
    let mut digits = [0u8; 20];
    let mut k = digits.len();
    loop {
        k -= 1;
        digits[k] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&digits[k..]);
}

fn text_hash(text: &str) -> u32 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    h.write(text.as_bytes());
    let h = h.finish();
    (h >> 32) as u32 ^ h as u32
}

/// The map key is already a hash: use it as it is.
#[derive(Default)]
struct KeyIsHash(u64);

impl Hasher for KeyIsHash {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(b);
        }
    }
    /// Spread over all 64 bits: the table uses the top ones too.
    fn write_u32(&mut self, n: u32) {
        self.0 = u64::from(n).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// Phase times on stderr when `CNCC_TIMING` is set.
pub(crate) struct PhaseTimer(Option<Instant>);

impl PhaseTimer {
    pub fn new() -> PhaseTimer {
        PhaseTimer(std::env::var_os("CNCC_TIMING").map(|_| Instant::now()))
    }

    pub fn phase(&self, name: &str) {
        if let Some(t) = self.0 {
            eprintln!(
                "[timing] stepnc write: {name}: {:.3} s",
                t.elapsed().as_secs_f64()
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refs_in_strings_are_not_renumbered() {
        let mut out = Vec::new();
        rewrite_refs("A('it''s #2',#2,(#1,#3))", &[0, 5, 7, 0], &mut out);
        assert_eq!(String::from_utf8(out).unwrap(), "A('it''s #2',#7,(#5,#3))");
    }

    #[test]
    fn texts_with_the_same_hash_stay_apart() {
        let mut seen = HashMap::new();
        let (a, b) = (0..1_000_000u32)
            .map(|i| format!("P('{i}')"))
            .find_map(|t| seen.insert(text_hash(&t), t.clone()).map(|o| (o, t)))
            .expect("a 32-bit collision among a million texts");
        let mut g = Graph::default();
        let mut add = |t: &str| {
            g.scratch().push_str(t);
            g.add_scratch_shared()
        };
        let (na, nb) = (add(&a), add(&b));
        assert_ne!(na, nb);
        assert_eq!((add(&a), add(&b)), (na, nb));
    }

    #[test]
    fn equal_text_is_one_instance() {
        let mut g = Graph::default();
        g.scratch().push_str("P((1.,2.))");
        let a = g.add_scratch_shared();
        g.scratch().push_str("P((1.,3.))");
        let b = g.add_scratch_shared();
        g.scratch().push_str("P((1.,2.))");
        assert_eq!(g.add_scratch_shared(), a);
        assert_ne!(a, b);
    }
}
