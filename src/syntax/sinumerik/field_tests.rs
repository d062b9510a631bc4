//! Constructs met in real 840D programs (shared/field/siemens840d): the
//! standard cycles' own source (CYCLE83, CYCLE84), shop subprograms and
//! CAM output.

use super::tests::read;
use crate::diag::Code;

fn clean(text: &str) -> String {
    let (out, ds) = read(text);
    assert!(ds.is_empty(), "{text}: {ds:?}");
    out
}

#[test]
fn case_without_parentheses() {
    let out = clean("DEF INT _AXN\nCASE _AXN OF 1 GOTOF _AX1 2 GOTOF _AX2 DEFAULT GOTOF _AX3");
    assert!(out.contains("stmt Case {"), "{out}");
    assert!(out.contains("target: \"_AX2\""), "{out}");
    assert!(out.contains("default: Some((\"_AX3\""), "{out}");
    let out = clean("CASE (R1) OF 1 GOTOF A DEFAULT GOTOF B");
    assert!(out.contains("stmt Case {"), "{out}");
}

#[test]
fn several_conditional_jumps_in_one_block() {
    let out = clean("IF R1==0 GOTOF _MD1 IF R2==R3 GOTOF _FEHL1");
    assert_eq!(out.matches("stmt Goto {").count(), 2, "{out}");
    let out = clean("IF R1==0 GOTOF A IF R2==0 GOTOF B GOTOF C");
    assert_eq!(out.matches("stmt Goto {").count(), 3, "{out}");
    assert!(out.contains("cond: None"), "{out}");
}

#[test]
fn an_unknown_control_function_is_a_query_not_text() {
    let out = clean("DEF INT _ABS\nIF ISAXIS(_ABS)\nENDIF");
    assert!(out.contains("stmt If {"), "{out}");
    assert!(!out.contains("Raw"), "{out}");
    let (out, ds) = read("R1=FOO(3,)");
    assert!(out.contains("Raw"), "{out}");
    assert_eq!(ds[0].code, Code::KeptAsText);
}

#[test]
fn indirect_addresses_are_kept_as_text_with_a_warning() {
    for line in [
        "G[8]=R1",
        "M[R2]=3 S[R2]=1000",
        "G0 G90 AX[R3]=5",
        "ATRANS AX[R3]=1 AX[R4]=2",
    ] {
        let (out, ds) = read(line);
        assert!(out.contains("stmt Raw"), "{line}: {out}");
        assert_eq!(ds.len(), 1, "{line}: {ds:?}");
        assert_eq!(ds[0].code, Code::KeptAsText, "{line}");
        assert!(ds[0].message.contains("[..]="), "{}", ds[0].message);
    }
    // A declared array is still a variable.
    let out = clean("DEF REAL A[3]\nA[1]=2");
    assert!(out.contains("Assign { var: User(\"A\""), "{out}");
}

#[test]
fn a_multi_letter_address_before_assign_wins_over_a_command() {
    let out = clean("G0 X1 SPOS=90");
    assert!(out.contains("Spindle(Orient(Some(Number("), "{out}");
}

#[test]
fn rotary_positions_with_a_direction_are_functions() {
    let out = clean("C=ACP(90) SPOS=DC(R1)");
    assert!(out.contains("PosPlus"), "{out}");
    assert!(out.contains("PosShortest"), "{out}");
}

#[test]
fn elseif_is_a_located_error_not_text() {
    let text = "DEF REAL A\nIF A==1\nG0 X1\nELSEIF A==2\nG0 X2\nELSE\nG0 X3\nENDIF";
    let (out, ds) = read(text);
    assert_eq!(ds.len(), 1, "{ds:?}");
    assert_eq!(ds[0].code, Code::NotInDialect);
    assert!(ds[0].message.contains("ELSEIF"), "{}", ds[0].message);
    let help = ds[0].help.as_deref().unwrap_or("");
    assert!(help.contains("nested IF"), "{help}");
    // Not kept as text, and the IF / ELSE / ENDIF round it stay.
    assert!(!out.contains("Raw"), "{out}");
    assert!(
        out.contains("stmt If {") && out.contains("stmt Else") && out.contains("stmt EndIf"),
        "{out}"
    );
}
