//! POCKET3, POCKET4, SLOT1, SLOT2 and LONGHOLE on a recording host. The
//! expected moves follow the strategies documented in `milling/pocket34.rs`
//! and `milling/slots.rs` (there is no Siemens oracle); the snapshots were
//! checked by hand against them (positions, depths, feeds, directions).

use super::rec::mill;

#[test]
fn pocket3_climb_with_base_allowance() {
    // RTP 10, RFP 0, SDIS 2, DP -5, LENG 40, WID 24, CRAD 5, PA 30, PO 20,
    // STA 30, MID 2.5, FAL 0.5, FALD 0.3, FFP1 300, FFD 100, CDIR 0 (climb:
    // G3), VARI 0, MIDA 6; tool radius 4.
    let out = mill(
        "POCKET3",
        &[
            10.0, 0.0, 2.0, -5.0, 40.0, 24.0, 5.0, 30.0, 20.0, 30.0, 2.5, 0.5, 0.3, 300.0, 100.0,
            0.0, 0.0, 6.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        ],
        4.0,
    );
    insta::assert_snapshot!("pocket3", out);
}

#[test]
fn pocket4_rough_only_and_variants_not_expanded() {
    // RTP 10, RFP 0, SDIS 2, DP -3, PRAD 15, PA 0, PO 0, MID 3, FAL 0.2,
    // FALD 0, FFP1 250, FFD 80, CDIR 2, VARI 1, MIDA 5; tool radius 4.
    let rough = mill(
        "POCKET4",
        &[
            10.0, 0.0, 2.0, -3.0, 15.0, 0.0, 0.0, 3.0, 0.2, 0.0, 250.0, 80.0, 2.0, 1.0, 5.0, 0.0,
            0.0,
        ],
        4.0,
    );
    let helix = mill(
        "POCKET4",
        &[
            10.0, 0.0, 2.0, -3.0, 15.0, 0.0, 0.0, 3.0, 0.2, 0.0, 250.0, 80.0, 2.0, 21.0,
        ],
        4.0,
    );
    let blank = mill(
        "POCKET3",
        &[
            10.0, 0.0, 2.0, -5.0, 40.0, 24.0, 5.0, 30.0, 20.0, 30.0, 2.5, 0.5, 0.3, 300.0, 100.0,
            0.0, 0.0, 6.0, 30.0, 0.0, 0.0,
        ],
        4.0,
    );
    insta::assert_snapshot!(
        "pocket4",
        format!("== rough\n{rough}\n== helical\n{helix}\n== blank\n{blank}")
    );
}

#[test]
fn slot1_three_radial_slots() {
    let e = f64::NAN;
    // RTP 10, RFP 0, SDIS 1, DP -4, DPR -, NUM 3, LENG 20, WID 10, CPA 0,
    // CPO 0, RAD 15, STA1 0, INDA 0 (120), FFD 100, FFP1 200, MID 4, CDIR 3,
    // FAL 0, VARI 0, MIDF -, FFP2 150, SSF 0; tool radius 3.
    let out = mill(
        "SLOT1",
        &[
            10.0, 0.0, 1.0, -4.0, e, 3.0, 20.0, 10.0, 0.0, 0.0, 15.0, 0.0, 0.0, 100.0, 200.0, 4.0,
            3.0, 0.0, 0.0, e, 150.0, 0.0,
        ],
        3.0,
    );
    insta::assert_snapshot!("slot1", out);
}

#[test]
fn slot2_two_circumferential_slots() {
    let e = f64::NAN;
    // RTP 10, RFP 0, SDIS 1, DP -3, DPR -, NUM 2, AFSL 45, WID 12, CPA 0,
    // CPO 0, RAD 30, STA1 10, INDA 180, FFD 100, FFP1 200, MID 3, CDIR 2,
    // FAL 0.5, VARI 0, MIDF -, FFP2 150; tool radius 3.
    let out = mill(
        "SLOT2",
        &[
            10.0, 0.0, 1.0, -3.0, e, 2.0, 45.0, 12.0, 0.0, 0.0, 30.0, 10.0, 180.0, 100.0, 200.0,
            3.0, 2.0, 0.5, 0.0, e, 150.0,
        ],
        3.0,
    );
    insta::assert_snapshot!("slot2", out);
}

#[test]
fn longhole_four_holes_and_errors() {
    let e = f64::NAN;
    // RTP 10, RFP 0, SDIS 1, DP -6, DPR -, NUM 4, LENG 16, CPA 5, CPO 5,
    // RAD 10, STA1 45, INDA 90, FFD 50, FFP1 120, MID 2; tool radius 3.
    let holes = mill(
        "LONGHOLE",
        &[
            10.0, 0.0, 1.0, -6.0, e, 4.0, 16.0, 5.0, 5.0, 10.0, 45.0, 90.0, 50.0, 120.0, 2.0,
        ],
        3.0,
    );
    let short = mill(
        "LONGHOLE",
        &[
            10.0, 0.0, 1.0, -6.0, e, 1.0, 5.0, 0.0, 0.0, 10.0, 0.0, 0.0, 50.0, 120.0, 2.0,
        ],
        3.0,
    );
    let wide = mill(
        "SLOT2",
        &[10.0, 0.0, 1.0, -3.0, e, 1.0, 45.0, 4.0, 0.0, 0.0, 30.0],
        3.0,
    );
    let none = mill("SLOT1", &[10.0, 0.0, 1.0, -3.0, e, 0.0, 20.0, 10.0], 3.0);
    insta::assert_snapshot!(
        "longhole",
        format!("{holes}\n== errors\n{short}\n--\n{wide}\n--\n{none}")
    );
}
