//! CI's brief run of every fuzz target (issue 14, point 5) with neither
//! nightly nor cargo-fuzz: the entry points the targets in `fuzz/` call
//! (`cncc::fuzzing`, `cncc::stepnc::fuzz_read_write`) on the test
//! programs and on random mutations of them made with the fuzz dictionary
//! (`fuzz/dict/cncc.dict`): byte flips, dictionary words inserted, ranges
//! deleted, repeated or spliced from another seed. The mutations are the
//! same on every run; each target runs for `CNCC_FUZZ_SECONDS` seconds
//! (default 2) or 2000 inputs, at least 100. A panic prints the input that
//! caused it.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

type Target = fn(&[u8]);

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The test programs of these folders under `tests/programs/`.
fn seeds(folders: &[&str]) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    for f in folders {
        let mut paths: Vec<PathBuf> = walk(&root().join("tests/programs").join(f));
        paths.sort();
        for p in paths {
            let b = std::fs::read(&p).unwrap();
            if b.len() <= 16 * 1024 {
                out.push(b);
            }
        }
    }
    assert!(!out.is_empty(), "no seeds in {folders:?}");
    out
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for e in rd.flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}

/// The dictionary's words (`"..."` lines; `\"`, `\\` and `\xNN` escapes).
fn dictionary() -> Vec<Vec<u8>> {
    let text = std::fs::read_to_string(root().join("fuzz/dict/cncc.dict")).unwrap();
    let mut words = Vec::new();
    for line in text.lines() {
        let Some(q) = line.find('"') else { continue };
        let Some(body) = line[q + 1..].strip_suffix('"') else {
            continue;
        };
        let (mut w, b) = (Vec::new(), body.as_bytes());
        let mut i = 0;
        while i < b.len() {
            match (b[i], b.get(i + 1)) {
                (b'\\', Some(b'x')) if i + 4 <= b.len() => {
                    let hex = std::str::from_utf8(&b[i + 2..i + 4]).unwrap_or("");
                    w.push(u8::from_str_radix(hex, 16).unwrap_or(b'?'));
                    i += 4;
                }
                (b'\\', Some(&c)) => {
                    w.push(c);
                    i += 2;
                }
                (c, _) => {
                    w.push(c);
                    i += 1;
                }
            }
        }
        words.push(w);
    }
    assert!(words.len() > 100, "dictionary: {} words", words.len());
    words
}

/// A small deterministic generator.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) as usize) % n.max(1)
    }
}

/// One to four random edits of `input`.
fn mutate(rng: &mut Rng, input: &[u8], seeds: &[Vec<u8>], dict: &[Vec<u8>]) -> Vec<u8> {
    let mut v = input.to_vec();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(v.len() + 1);
        match rng.below(6) {
            0 if !v.is_empty() => {
                let i = at.min(v.len() - 1);
                v[i] ^= 1 << rng.below(8);
            }
            1 | 2 => {
                let w = &dict[rng.below(dict.len())];
                v.splice(at..at, w.iter().copied());
            }
            3 => {
                let end = (at + rng.below(64)).min(v.len());
                v.drain(at..end);
            }
            4 => {
                let end = (at + 1 + rng.below(32)).min(v.len());
                let piece = v[at.min(end)..end].to_vec();
                for _ in 0..1 + rng.below(8) {
                    v.splice(at..at, piece.iter().copied());
                }
            }
            _ => {
                let other = &seeds[rng.below(seeds.len())];
                let from = rng.below(other.len() + 1);
                let end = (from + rng.below(256)).min(other.len());
                v.splice(at..at, other[from..end].iter().copied());
            }
        }
    }
    v
}

fn budget() -> Duration {
    let s = std::env::var("CNCC_FUZZ_SECONDS")
        .ok()
        .and_then(|s| s.parse::<f64>().ok())
        .unwrap_or(2.0);
    Duration::from_secs_f64(s)
}

/// Runs `target` on every seed, then on mutations until the budget is spent.
fn run(name: &str, target: Target, seeds: Vec<Vec<u8>>) {
    let dict = dictionary();
    let start = Instant::now();
    let try_one = |input: &[u8], what: &str| {
        let r = std::panic::catch_unwind(|| target(input));
        if r.is_err() {
            panic!(
                "fuzz target {name} panicked on {what}: {:?}",
                String::from_utf8_lossy(input)
            );
        }
    };
    for (i, s) in seeds.iter().enumerate() {
        try_one(s, &format!("seed {i}"));
    }
    let mut rng = Rng(0x14);
    let mut n = 0;
    // At least 100 mutations, however long the seeds took.
    while n < 2000 && (n < 100 || start.elapsed() < budget()) {
        let base = &seeds[rng.below(seeds.len())];
        let input = mutate(&mut rng, base, &seeds, &dict);
        try_one(&input, &format!("mutation {n}"));
        n += 1;
    }
    eprintln!(
        "{name}: {} seeds, {n} mutations in {:.1?}",
        seeds.len(),
        start.elapsed()
    );
}

fn word_address(data: &[u8]) {
    for d in ["fanuc", "haas", "linuxcnc"] {
        cncc::fuzzing::read_and_write(d, data);
    }
}

fn interp(data: &[u8]) {
    for d in cncc::fuzzing::DIALECTS {
        cncc::fuzzing::interpret(d, data);
    }
}

/// As `fuzz/fuzz_targets/port.rs`: the first byte chooses the source.
fn port(data: &[u8]) {
    let Some((&k, rest)) = data.split_first() else {
        return;
    };
    let ds = cncc::fuzzing::DIALECTS;
    cncc::fuzzing::port(ds[k as usize % ds.len()], rest);
}

/// Seeds for the port target: a program with the byte choosing its dialect.
fn port_seeds() -> Vec<Vec<u8>> {
    let ds = cncc::fuzzing::DIALECTS;
    let mut out = Vec::new();
    for (k, d) in ds.iter().enumerate() {
        for s in seeds(&[d]).into_iter().take(6) {
            let mut v = vec![k as u8];
            v.extend(s);
            out.push(v);
        }
    }
    out
}

const PROGRAMS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// The Part 21 test files, good (`tests/programs/stepnc`) and bad (`tests/stepnc`).
const STEPNC: &[&str] = &["stepnc", "../stepnc"];

#[test]
fn fuzz_word_address_briefly() {
    run(
        "word_address",
        word_address,
        seeds(&["fanuc", "haas", "linuxcnc"]),
    );
}

#[test]
fn fuzz_sinumerik_briefly() {
    run(
        "sinumerik",
        |d| cncc::fuzzing::read_and_write("siemens840d", d),
        seeds(&["siemens840d"]),
    );
}

#[test]
fn fuzz_klartext_briefly() {
    run(
        "klartext",
        |d| cncc::fuzzing::read_and_write("heidenhain", d),
        seeds(&["heidenhain"]),
    );
}

#[test]
fn fuzz_part21_briefly() {
    run("part21", cncc::stepnc::fuzz_read_write, seeds(STEPNC));
}

#[test]
fn fuzz_interp_briefly() {
    let some: Vec<Vec<u8>> = PROGRAMS
        .iter()
        .flat_map(|d| seeds(&[d]).into_iter().take(8))
        .collect();
    run("interp", interp, some);
}

#[test]
fn fuzz_port_briefly() {
    run("port", port, port_seeds());
}

#[test]
fn fuzz_post_briefly() {
    run("post", cncc::fuzzing::post, seeds(STEPNC));
}
