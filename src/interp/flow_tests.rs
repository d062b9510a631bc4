//! The walker on programs made only of variables and control flow: the
//! results are read back from the parameters.

use super::*;
use crate::dialect::builtin::builtin;
use crate::interp::Options;
use crate::span::FileId;

/// Runs `text` in `dialect`; returns the parameters and the stop.
fn run_with(
    dialect: &str,
    text: &str,
    opts: &Options,
) -> (crate::interp::params::Params, Option<Diagnostic>) {
    let spec = builtin(dialect).expect("dialect");
    let (program, diags) = crate::driver::read_program(text, FileId(0), &spec);
    assert!(
        !diags.iter().any(|d| d.is_error()),
        "read errors: {diags:?}"
    );
    let mut sink = |_: crate::canon::Canon, _: crate::span::Span| {};
    let mut it = Interp::new(&spec, opts, &mut sink);
    let r = Walker::new(std::rc::Rc::new(program), &mut NoLoader).run(&mut it);
    let err = match r {
        // M2/M30 while the core's statements are stubs: the end anyway.
        Err(Stop::Error(d)) if d.code == crate::diag::Code::UnsupportedHere && at_end(text, &d) => {
            None
        }
        Err(Stop::Error(d)) => Some(d),
        _ => None,
    };
    (it.params.clone(), err)
}

fn at_end(text: &str, d: &Diagnostic) -> bool {
    d.labels
        .first()
        .and_then(|l| text.get(l.span.start as usize..l.span.end as usize))
        .is_some_and(|w| matches!(w, "M2" | "M30"))
}

fn run(dialect: &str, text: &str) -> crate::interp::params::Params {
    let (p, e) = run_with(dialect, text, &Options::default());
    assert!(e.is_none(), "run error: {e:?}");
    p
}

fn g(p: &crate::interp::params::Params, name: &str) -> f64 {
    p.named(name).unwrap_or_else(|| panic!("#<{name}> unset"))
}

#[test]
fn linuxcnc_while_if_and_assignment_timing() {
    let p = run(
        "linuxcnc",
        "%\n#<_n> = 0\n#<_s> = 0\no1 while [#<_n> LT 5]\n#<_n> = [#<_n> + 1]\no2 if [#<_n> EQ 3]\no1 continue\no2 endif\n#<_s> = [#<_s> + #<_n>]\no1 endwhile\n#1 = 1\n#1 = 2 #2 = #1\n#<_t> = #2\n%\n",
    );
    assert_eq!(g(&p, "_n"), 5.0);
    assert_eq!(g(&p, "_s"), 12.0);
    assert_eq!(
        g(&p, "_t"),
        1.0,
        "values on a line are read before any is set"
    );
}

#[test]
fn linuxcnc_sub_call_args_locals_and_return_value() {
    let p = run(
        "linuxcnc",
        "%\no<sq> sub\n#<loc> = [#1 * #1]\n#5 = 99\no<sq> endsub [#<loc> + #2]\n#5 = 7\no<sq> call [3] [1]\n#<_r> = #<_value>\n#<_five> = #5\n%\n",
    );
    assert_eq!(g(&p, "_r"), 10.0);
    assert_eq!(g(&p, "_five"), 7.0, "#1-#30 are restored after the call");
}

#[test]
fn linuxcnc_do_repeat_elseif_and_eq_tolerance() {
    let p = run(
        "linuxcnc",
        "%\n#<_ta> = 0\no1 do\n#<_ta> = [#<_ta> + 1]\no1 while [#<_ta> LT 3]\no2 repeat [4]\n#<_ta> = [#<_ta> + 10]\no2 endrepeat\no3 if [#<_ta> EQ 0]\n#<_tb> = 1\no3 elseif [#<_ta> EQ 43.00005]\n#<_tb> = 2\no3 else\n#<_tb> = 3\no3 endif\n#<_tc> = [#3 EQ 0]\n%\n",
    );
    assert_eq!(g(&p, "_ta"), 43.0);
    assert_eq!(g(&p, "_tb"), 2.0, "EQ within 0.0001, as rs274");
    assert_eq!(g(&p, "_tc"), 1.0, "an unset LinuxCNC parameter is 0");
}

#[test]
fn undefined_named_parameter_and_division_by_zero_stop_the_run() {
    let (_, e) = run_with("linuxcnc", "#1 = #<nope>\n%\n", &Options::default());
    assert_eq!(e.expect("error").code, crate::diag::Code::UndefinedVariable);
    let (_, e) = run_with("linuxcnc", "#1 = #5602\n%\n", &Options::default());
    assert_eq!(e.expect("error").code, crate::diag::Code::UndefinedVariable);
    let (_, e) = run_with("linuxcnc", "#1 = [1 / 0]\n%\n", &Options::default());
    assert_eq!(e.expect("error").code, crate::diag::Code::DivisionByZero);
}

#[test]
fn endless_loops_and_recursion_end_in_e0506() {
    let mut opts = Options::default();
    opts.limits.loop_iterations = 1000;
    let (_, e) = run_with("linuxcnc", "o1 while [1]\no1 endwhile\n%\n", &opts);
    assert_eq!(e.expect("error").code, crate::diag::Code::LimitExceeded);
    let (_, e) = run_with(
        "linuxcnc",
        "o<r> sub\no<r> call\no<r> endsub\no<r> call\n%\n",
        &opts,
    );
    assert_eq!(e.expect("error").code, crate::diag::Code::LimitExceeded);
    let (_, e) = run_with("fanuc", "O1000\nN1 #1 = 1\nGOTO 1\nM30\n", &opts);
    assert_eq!(e.expect("error").code, crate::diag::Code::LimitExceeded);
}

#[test]
fn fanuc_macro_b_vacancy_goto_while_and_g65() {
    let p = run(
        "fanuc",
        "%\nO1000\n#100 = 0\n#101 = [#0 EQ #1]\n#102 = [#1 EQ 0]\nWHILE [#100 LT 4] DO 1\n#100 = #100 + 1\nEND 1\nIF [#100 EQ 4] GOTO 20\n#100 = 99\nN20 IF [#100 EQ 4] THEN #103 = 5\nG65 P2000 A2. B3.\nM98 P3000 L3\nM30\nO2000\n#104 = #1 * #2 + #3\nM99\nO3000\n#105 = #105 + 1\nM99\n%\n",
    );
    let n = |k: u32| p.numbered(k).unwrap_or(f64::NAN);
    assert_eq!(n(101), 1.0, "vacant equals vacant");
    assert_eq!(n(102), 0.0, "vacant is not 0 in EQ");
    assert_eq!(n(100), 4.0);
    assert_eq!(n(103), 5.0);
    assert_eq!(n(104), 6.0, "A→#1, B→#2, #3 vacant");
    assert_eq!(n(105), 3.0, "M98 L3 runs three times");
}

#[test]
fn siemens_r_parameters_loops_labels_and_repeat() {
    let p = run(
        "siemens840d",
        "R1=0\nR2=0\nFOR R3=1 TO 4\nR1=R1+R3\nENDFOR\nWHILE R2<3\nR2=R2+1\nENDWHILE\nR4=0\nSTART: R4=R4+1\nENDE: R5=1\nREPEAT START ENDE P=2\nIF R4==3 GOTOF DONE\nR6=1\nDONE: R7=R4\n",
    );
    assert_eq!(p.r(1), 10.0);
    assert_eq!(p.r(2), 3.0);
    assert_eq!(p.r(4), 3.0, "once in sequence, twice repeated");
    assert_eq!(p.r(6), 0.0);
    assert_eq!(p.r(7), 3.0);
}

#[test]
fn loop_limit_counts_per_run_of_a_loop() {
    let mut opts = Options::default();
    opts.limits.loop_iterations = 50;
    let (p, e) = run_with(
        "linuxcnc",
        "%\n#<_t> = 0\no<inner> sub\n#<i> = 0\no1 while [#<i> LT 40]\n#<i> = [#<i> + 1]\n#<_t> = [#<_t> + 1]\no1 endwhile\no<inner> endsub\no2 repeat [10]\no<inner> call\no2 endrepeat\n%\n",
        &opts,
    );
    assert!(e.is_none(), "{e:?}");
    assert_eq!(
        g(&p, "_t"),
        400.0,
        "ten runs of a 40-pass loop stay under a limit of 50"
    );
}

#[test]
fn exists_sees_predefined_names_and_value_returned_is_set() {
    let p = run(
        "linuxcnc",
        "%\n#<_e1> = EXISTS[#<_x>]\n#<_e2> = EXISTS[#<nothing>]\no<f> sub\no<f> endsub\no<f> call\n#<_r> = #<_value_returned>\n%\n",
    );
    assert_eq!(g(&p, "_e1"), 1.0);
    assert_eq!(g(&p, "_e2"), 0.0);
    assert_eq!(g(&p, "_r"), 0.0);
}

#[test]
fn fanuc_read_only_and_missing_variables_are_errors() {
    let (_, e) = run_with("fanuc", "%\nO1000\n#0 = 1\nM30\n%\n", &Options::default());
    assert!(e.expect("error").message.contains("read-only"));
    let (_, e) = run_with("fanuc", "%\nO1000\n#50 = 1\nM30\n%\n", &Options::default());
    assert_eq!(e.expect("error").code, crate::diag::Code::UndefinedVariable);
}

#[test]
fn siemens_def_case_loop_and_repeat_until() {
    let p = run(
        "siemens840d",
        "DEF REAL A=2\nDEF INT N\nR1=0\nCASE (A) OF 1 GOTOF ONE 2 GOTOF TWO DEFAULT GOTOF OTHER\nONE: R1=1\nTWO: R1=R1+2\nOTHER: R2=0\nREPEAT\nR2=R2+1\nUNTIL R2>=3\nN=0\nLOOP\nN=N+1\nIF N==4 GOTOF OUT\nENDLOOP\nOUT: R3=N\n",
    );
    assert_eq!(p.r(1), 2.0, "CASE jumps to TWO");
    assert_eq!(p.r(2), 3.0);
    assert_eq!(p.r(3), 4.0);
}

/// SGN, LOG and NEG; an FN 18 datum unknown at check time is held as
/// unknown, and the run-time checks stop (W0590, a warning) where it is
/// first used: no false division by zero or SQRT domain error.
#[test]
fn heidenhain_sgn_log_neg_and_unknown_system_data() {
    let (p, e) = run_with(
        "heidenhain",
        "0 BEGIN PGM T MM\n1 Q1 = SGN ( 0 - 3 )\n2 Q2 = LOG 1000\n3 Q3 = NEG Q2\n4 Q4 = SGN 0\n5 FN 18: SYSREAD Q5 = ID240 NR1 IDX1\n6 Q6 = SQRT ( Q5 - Q5 - 1 ) / ( Q5 - Q5 )\n7 END PGM T MM\n",
        &Options::default(),
    );
    assert!(e.is_none(), "{e:?}");
    let q = |n| p.q(crate::ir::QBank::Q, n);
    assert_eq!(q(1), -1.0);
    assert!((q(2) - 3.0).abs() < 1e-12);
    assert!((q(3) + 3.0).abs() < 1e-12);
    assert_eq!(q(4), 0.0);
    assert!(q(5).is_nan());
    assert!(
        !p.q_known(crate::ir::QBank::Q, 6),
        "the run stopped at Q5's first use"
    );
}
