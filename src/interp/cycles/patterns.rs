//! Siemens hole patterns: the positions at which the modal (MCALL) drilling
//! cycle runs. Positions are in the active plane: (abscissa, ordinate),
//! i.e. X/Y in G17, Z/X in G18, Y/Z in G19. Angles in degrees from the
//! abscissa. Source: the parameter meanings of the classic SINUMERIK cycle
//! documentation as summarised in `reference/dialects.md` §1.7.

/// Most holes one pattern may produce (keeps bad input bounded).
const MAX_HOLES: f64 = 100_000.0;

/// Hole positions of `HOLES1` (row), `HOLES2` (circle) or `CYCLE801`
/// (grid), in the order they are drilled. Empty argument slots are 0.
pub fn pattern_positions(name: &str, args: &[Option<f64>]) -> Result<Vec<(f64, f64)>, String> {
    let a = |i: usize| args.get(i).copied().flatten().unwrap_or(0.0);
    match name.to_ascii_uppercase().as_str() {
        "HOLES1" => holes1(a(0), a(1), a(2), a(3), a(4), count(a(5), "NUM")?),
        "HOLES2" => holes2(a(0), a(1), a(2), a(3), a(4), count(a(5), "NUM")?),
        "CYCLE801" => grid(
            a(0),
            a(1),
            a(2),
            a(3),
            a(4),
            count(a(5), "NUM1")?,
            count(a(6), "NUM2")?,
        ),
        other => Err(format!(
            "{other} is not a hole pattern (HOLES1, HOLES2, CYCLE801)"
        )),
    }
}

fn count(v: f64, name: &str) -> Result<usize, String> {
    if v < 1.0 || v.fract() != 0.0 || v > MAX_HOLES {
        return Err(format!(
            "{name} must be a whole number from 1 to {MAX_HOLES}, not {v}"
        ));
    }
    Ok(v as usize)
}

fn polar(cx: f64, cy: f64, d: f64, deg: f64) -> (f64, f64) {
    let t = deg.to_radians();
    (cx + d * t.cos(), cy + d * t.sin())
}

/// A row through (SPCA, SPCO) at angle STA1; the first hole FDIS from the
/// reference point, then every DBH.
fn holes1(
    spca: f64,
    spco: f64,
    sta1: f64,
    fdis: f64,
    dbh: f64,
    num: usize,
) -> Result<Vec<(f64, f64)>, String> {
    Ok((0..num)
        .map(|i| polar(spca, spco, fdis + i as f64 * dbh, sta1))
        .collect())
}

/// A circle around (CPA, CPO) of radius RAD from angle STA1 in steps of
/// INDA (0: NUM holes spread evenly over the full circle).
fn holes2(
    cpa: f64,
    cpo: f64,
    rad: f64,
    sta1: f64,
    inda: f64,
    num: usize,
) -> Result<Vec<(f64, f64)>, String> {
    if rad < 0.0 {
        return Err(format!("RAD must not be negative, not {rad}"));
    }
    let step = if inda == 0.0 {
        360.0 / num as f64
    } else {
        inda
    };
    Ok((0..num)
        .map(|i| polar(cpa, cpo, rad, sta1 + i as f64 * step))
        .collect())
}

/// A grid from (SPCA, SPCO): NUM1 columns DIS1 apart along angle STA,
/// NUM2 rows DIS2 apart across it. [?] Drilled row by row, meandering
/// (every other row backwards), to keep travel short.
fn grid(
    spca: f64,
    spco: f64,
    sta: f64,
    dis1: f64,
    dis2: f64,
    n1: usize,
    n2: usize,
) -> Result<Vec<(f64, f64)>, String> {
    if (n1 as f64) * (n2 as f64) > MAX_HOLES {
        return Err(format!("a grid of {n1} x {n2} holes is too large"));
    }
    let t = sta.to_radians();
    let (ux, uy) = (t.cos(), t.sin());
    let mut out = Vec::with_capacity(n1 * n2);
    for row in 0..n2 {
        for k in 0..n1 {
            let col = if row % 2 == 0 { k } else { n1 - 1 - k };
            let (c, r) = (col as f64 * dis1, row as f64 * dis2);
            out.push((spca + c * ux - r * uy, spco + c * uy + r * ux));
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn show(v: &[(f64, f64)]) -> String {
        v.iter()
            .map(|(a, b)| format!("({a:.4}, {b:.4})"))
            .collect::<Vec<_>>()
            .join(" ")
    }

    #[test]
    fn row_as_in_corpus_call() {
        // holes1_test.mpf: HOLES1(SPCA=30, SPCO=20, STA1=0, FDIS=10, DBH=20, NUM=1000)
        let p = pattern_positions(
            "HOLES1",
            &[
                Some(30.0),
                Some(20.0),
                Some(0.0),
                Some(10.0),
                Some(20.0),
                Some(1000.0),
            ],
        )
        .unwrap();
        assert_eq!(p.len(), 1000);
        assert_eq!(
            show(&p[..3]),
            "(40.0000, 20.0000) (60.0000, 20.0000) (80.0000, 20.0000)"
        );
        let q = pattern_positions(
            "holes1",
            &[
                Some(0.0),
                Some(0.0),
                Some(90.0),
                Some(5.0),
                Some(10.0),
                Some(2.0),
            ],
        )
        .unwrap();
        assert_eq!(show(&q), "(0.0000, 5.0000) (0.0000, 15.0000)");
    }

    #[test]
    fn circle_spreads_evenly_when_inda_is_zero() {
        // holes2_test.mpf shape: HOLES2(CPA, CPO, RAD, STA1, 0, NUM)
        let p = pattern_positions(
            "HOLES2",
            &[
                Some(70.0),
                Some(60.0),
                Some(10.0),
                Some(45.0),
                Some(0.0),
                Some(4.0),
            ],
        )
        .unwrap();
        assert_eq!(
            show(&p),
            "(77.0711, 67.0711) (62.9289, 67.0711) (62.9289, 52.9289) (77.0711, 52.9289)"
        );
        let q = pattern_positions(
            "HOLES2",
            &[
                Some(0.0),
                Some(0.0),
                Some(10.0),
                Some(0.0),
                Some(30.0),
                Some(2.0),
            ],
        )
        .unwrap();
        assert_eq!(show(&q), "(10.0000, 0.0000) (8.6603, 5.0000)");
    }

    #[test]
    fn grid_meanders_with_empty_slots_as_zero() {
        // cycle801_test.mpf: CYCLE801(,,,10,15,10,5) -> 50 holes
        let p = pattern_positions(
            "CYCLE801",
            &[
                None,
                None,
                None,
                Some(10.0),
                Some(15.0),
                Some(10.0),
                Some(5.0),
            ],
        )
        .unwrap();
        assert_eq!(p.len(), 50);
        assert_eq!(
            show(&p[8..12]),
            "(80.0000, 0.0000) (90.0000, 0.0000) (90.0000, 15.0000) (80.0000, 15.0000)"
        );
        let r = pattern_positions(
            "CYCLE801",
            &[
                Some(1.0),
                Some(2.0),
                Some(90.0),
                Some(10.0),
                Some(5.0),
                Some(2.0),
                Some(2.0),
            ],
        )
        .unwrap();
        assert_eq!(
            show(&r),
            "(1.0000, 2.0000) (1.0000, 12.0000) (-4.0000, 12.0000) (-4.0000, 2.0000)"
        );
    }

    #[test]
    fn bad_counts_are_errors() {
        assert!(pattern_positions("HOLES1", &[Some(0.0); 6]).is_err());
        assert!(pattern_positions(
            "HOLES2",
            &[
                Some(0.0),
                Some(0.0),
                Some(1.0),
                Some(0.0),
                Some(0.0),
                Some(2.5)
            ]
        )
        .is_err());
        assert!(pattern_positions(
            "CYCLE801",
            &[None, None, None, Some(1.0), Some(1.0), Some(1e5), Some(1e5)]
        )
        .is_err());
        assert!(pattern_positions("POCKET1", &[]).is_err());
    }
}
