//! Tests of the spec loader: extending a built-in, and one rendered
//! diagnostic per E04xx error.

use super::builtin::Registry;
use super::meaning::Meaning;
use crate::diag::render::human;
use crate::diag::Code;
use crate::ir::{Decimal, DwellUnit};
use crate::source::SourceMap;

fn load(
    text: &str,
) -> (
    Result<std::sync::Arc<super::DialectSpec>, Vec<crate::diag::Diagnostic>>,
    SourceMap,
) {
    let mut files = SourceMap::new();
    let f = files.add("my.xml", text);
    let mut reg = Registry::with_builtins();
    (reg.load(text, f), files)
}

fn errors(text: &str) -> (Vec<Code>, String) {
    let (r, files) = load(text);
    let d = r.expect_err("the spec should not load");
    (d.iter().map(|d| d.code).collect(), human(&d, &files, false))
}

fn num(s: &str) -> Decimal {
    Decimal::parse(s).unwrap()
}

const HAAS_VARIANT: &str = r#"<dialect id="my-haas" name="Our VF-2" extends="haas">
  <code letter="M" number="130" group="machine" meaning="aux" doc="pallet clamp"/>
  <remove letter="M" number="97"/>
  <remove capability="local-subprogram-call"/>
</dialect>"#;

#[test]
fn user_spec_extends_haas() {
    let (r, _) = load(HAAS_VARIANT);
    let s = r.unwrap();
    assert_eq!(s.extends.as_deref(), Some("haas"));
    assert_eq!(
        s.code('M', num("130")).map(|c| c.meaning),
        Some(Meaning::Aux)
    );
    assert!(s.code('M', num("97")).is_none());
    assert!(s.code('G', num("154")).is_some(), "inherited from haas");
    assert!(s.code('G', num("1")).is_some(), "inherited from iso6983");
    assert!(!s.has(super::Capability::LocalSubprogramCall));
    assert!(s.has(super::Capability::MacroB));
    assert_eq!(s.repeat_letter, 'L');
    assert!(s.aliases.is_empty(), "aliases are not inherited");
}

#[test]
fn builtin_tables_say_what_the_manuals_say() {
    let reg = Registry::with_builtins();
    let fanuc = reg.get("fanuc").unwrap();
    let g4 = fanuc.code('G', num("4")).unwrap();
    assert_eq!(
        g4.dwell_units,
        vec![('P', DwellUnit::Milliseconds), ('X', DwellUnit::Seconds)]
    );
    assert_eq!(fanuc.repeat_letter, 'K');
    assert!(fanuc.code('G', num("54.1")).is_some());
    let haas = reg.get("haas").unwrap();
    assert!(haas.code('G', num("54.1")).is_none());
    assert_eq!(
        haas.code('G', num("110")).unwrap().meaning,
        Meaning::WorkOffset(7)
    );
    assert_eq!(haas.code_for(Meaning::LocalCall).unwrap().code, num("97"));
    let lcnc = reg.get("linuxcnc").unwrap();
    assert_eq!(
        lcnc.code('G', num("4")).unwrap().dwell_units,
        vec![('P', DwellUnit::Seconds)]
    );
    assert!(lcnc.code('M', num("101")).is_some());
    assert!(lcnc.function("POW").is_none());
    let sie = reg.get("siemens840d").unwrap();
    assert_eq!(
        sie.code('G', num("599")).unwrap().meaning,
        Meaning::WorkOffset(99)
    );
    assert_eq!(
        sie.code('G', num("4")).unwrap().dwell_units,
        vec![('F', DwellUnit::Seconds), ('S', DwellUnit::Revolutions)]
    );
    assert_eq!(
        sie.code_for(Meaning::MachineCoords).unwrap().code,
        num("53")
    );
}

#[test]
fn corpus_cycle_calls_fit_their_signatures() {
    let sie = Registry::with_builtins().get("siemens840d").unwrap();
    // Argument counts of calls in shared/corpus/siemens840d.
    for (name, args) in [
        ("CYCLE81", 9),
        ("CYCLE83", 20),
        ("POCKET4", 25),
        ("CYCLE800", 16),
        ("CYCLE61", 16),
        ("WORKPIECE", 12),
        ("CYCLE82", 6),
        ("HOLES1", 6),
        ("HOLES2", 6),
        ("CYCLE801", 7),
    ] {
        let c = sie.cycle(name).unwrap_or_else(|| panic!("{name} missing"));
        assert!(
            c.params.len() >= args,
            "{name}: {} params < {args}",
            c.params.len()
        );
    }
}

#[test]
fn e0401_malformed() {
    let (codes, text) =
        errors("<dialect id=\"x\" family=\"word-address\">\n  <code letter=\"G\"\n</dialect>");
    assert_eq!(codes, vec![Code::SpecMalformed]);
    insta::assert_snapshot!(text);
}

#[test]
fn e0402_unknown_element_and_attribute() {
    let (codes, text) = errors(
        "<dialect id=\"x\" extends=\"fanuc\">\n  <kode letter=\"G\" number=\"1\"/>\n  <alias name=\"y\" colour=\"red\"/>\n</dialect>",
    );
    assert_eq!(codes, vec![Code::SpecUnknownItem, Code::SpecUnknownItem]);
    insta::assert_snapshot!(text);
}

#[test]
fn e0403_bad_value() {
    let (codes, text) = errors(
        "<dialect id=\"x\" extends=\"fanuc\">\n  <code letter=\"G\" number=\"1.2.3\" group=\"motion\" meaning=\"motion.warp\"/>\n</dialect>",
    );
    assert_eq!(codes, vec![Code::SpecBadValue, Code::SpecBadValue]);
    insta::assert_snapshot!(text);
}

#[test]
fn e0404_missing() {
    let (codes, _) = errors("<dialect id=\"x\">\n</dialect>");
    assert_eq!(
        codes,
        vec![Code::SpecMissing],
        "a spec without a base needs its family"
    );
    let (codes, text) = errors("<dialect id=\"x\" extends=\"fanuc\">\n  <code letter=\"M\" number=\"130\" meaning=\"aux\"/>\n</dialect>");
    assert_eq!(codes, vec![Code::SpecMissing]);
    insta::assert_snapshot!(text);
}

#[test]
fn e0405_unknown_base() {
    let (codes, text) = errors("<dialect id=\"x\" extends=\"okuma\">\n</dialect>");
    assert_eq!(codes, vec![Code::SpecUnknownBase]);
    insta::assert_snapshot!(text);
}

#[test]
fn e0406_duplicate() {
    let (codes, text) = errors(
        "<dialect id=\"x\" extends=\"fanuc\">\n  <code letter=\"M\" number=\"130\" group=\"machine\" meaning=\"aux\"/>\n  <code letter=\"M\" number=\"130.0\" group=\"machine\" meaning=\"aux\"/>\n</dialect>",
    );
    assert_eq!(codes, vec![Code::SpecDuplicate]);
    insta::assert_snapshot!(text);
}

#[test]
fn removing_what_is_not_there_is_an_error() {
    let (codes, _) =
        errors("<dialect id=\"x\" extends=\"fanuc\">\n  <remove cycle=\"CYCLE81\"/>\n</dialect>");
    assert_eq!(codes, vec![Code::SpecBadValue]);
}

#[test]
fn huge_range_is_refused() {
    let (codes, _) = errors(
        "<dialect id=\"x\" extends=\"fanuc\">\n  <code-range letter=\"M\" first=\"0\" last=\"4000000000\" group=\"machine\" meaning=\"aux\"/>\n</dialect>",
    );
    assert_eq!(codes, vec![Code::SpecBadValue]);
}

#[test]
fn garbage_never_panics() {
    for t in ["", "<", "<dialect", "&&&", "<dialect id='x' family='sinumerik'><cycle name='C' kind='drill'><param/></cycle></dialect>", "<a/><b/>"] {
        let (r, _) = load(t);
        assert!(r.is_err(), "{t:?} loaded");
    }
}

/// The schema's enumerations list exactly what the loader accepts.
#[test]
fn schema_matches_the_loader_tables() {
    use super::load_items::{ADDRESS_ROLES, CYCLE_KINDS, FUNCS};
    let xsd = include_str!("../../dialects/dialect.xsd");
    let root = super::xml::parse(xsd, crate::span::FileId(0)).expect("dialect.xsd is well-formed");
    let values = |type_name: &str| -> Vec<String> {
        fn walk(n: &super::xml::Node, out: &mut Vec<String>) {
            if n.name == "xs:enumeration" {
                out.extend(n.attr("value").map(|a| a.value.clone()));
            }
            n.children.iter().for_each(|c| walk(c, out));
        }
        let mut out = Vec::new();
        let t = root
            .children
            .iter()
            .find(|c| c.attr("name").is_some_and(|a| a.value == type_name));
        walk(t.unwrap_or_else(|| panic!("type {type_name}")), &mut out);
        out
    };
    let caps: Vec<String> = super::CAPABILITIES
        .iter()
        .map(|(n, _)| n.to_string())
        .collect();
    assert_eq!(values("capability"), caps);
    let meanings: Vec<String> = super::meaning::MEANINGS
        .iter()
        .map(|(n, _)| n.to_string())
        .collect();
    assert_eq!(values("meaning"), meanings);
    assert_eq!(
        values("cycleKind"),
        CYCLE_KINDS
            .iter()
            .map(|s| s.to_string())
            .collect::<Vec<_>>()
    );
    assert_eq!(
        values("addressRole"),
        ADDRESS_ROLES
            .iter()
            .map(|s| s.to_string())
            .collect::<Vec<_>>()
    );
    assert_eq!(
        values("func"),
        FUNCS.iter().map(|(n, _)| n.to_string()).collect::<Vec<_>>()
    );
    assert_eq!(
        values("postTemplate"),
        super::POST_TEMPLATES
            .iter()
            .map(|(n, _)| n.to_string())
            .collect::<Vec<_>>()
    );
}

/// Codes overridden, removed and defined again: the last definition, an
/// override in the inherited code's place; a spec of 20,000 codes loads whole (by key, not by
/// looking each one up in a list: 80k codes took 27 s).
#[test]
fn codes_overridden_removed_and_added_again_by_key() {
    let mut rows = String::new();
    for k in 0..20_000 {
        rows.push_str(&format!(
            "  <code letter=\"G\" number=\"{}\" group=\"non-modal\" meaning=\"aux\"/>\n",
            1000 + k
        ));
    }
    let text = format!(
        r#"<dialect id="many" name="many" extends="haas">
  <code letter="M" number="3" group="spindle" meaning="spindle.cw" doc="overridden"/>
  <remove letter="M" number="97"/>
  <code letter="M" number="97.0" group="machine" meaning="aux" doc="again"/>
  <remove letter="M" number="98"/>
{rows}</dialect>"#
    );
    let (r, files) = load(&text);
    let s = r.unwrap_or_else(|d| panic!("{}", human(&d, &files, false)));
    assert_eq!(
        s.code('M', num("3")).map(|c| c.doc.as_str()),
        Some("overridden")
    );
    assert_eq!(
        s.code('M', num("97")).map(|c| c.doc.as_str()),
        Some("again")
    );
    assert!(s.code('M', num("98")).is_none());
    assert!(s.code('G', num("1000")).is_some());
    assert!(s.code('G', num("20999")).is_some());
    let base = super::builtin::builtin("haas").unwrap();
    assert_eq!(s.codes.len(), base.codes.len() - 1 + 20_000);
    // An override keeps the inherited code's place.
    let at = |spec: &super::DialectSpec, n: &str| {
        spec.codes
            .iter()
            .position(|c| c.letter == 'M' && c.code.normalized() == num(n))
    };
    assert_eq!(at(&s, "3"), at(&base, "3"));
}

#[test]
fn oriented_boring_shift_is_spec_data() {
    use super::ShiftDir;
    use crate::ir::CycleKind;
    let reg = Registry::with_builtins();
    let fanuc = reg.get("fanuc").unwrap();
    let g76 = fanuc.code('G', num("76")).unwrap();
    assert_eq!(g76.shift, Some(ShiftDir::PlusFirst));
    assert_eq!(
        fanuc.code('G', num("87")).unwrap().shift,
        Some(ShiftDir::PlusFirst)
    );
    let haas = reg.get("haas").unwrap();
    let back = haas.code_for(Meaning::Cycle(CycleKind::BackBore)).unwrap();
    assert_eq!(
        (back.code.clone(), back.shift),
        (num("77"), Some(ShiftDir::PlusFirst))
    );
    // LinuxCNC's G87 is its own (I J K), with no shift.
    let lcnc = reg.get("linuxcnc").unwrap();
    assert_eq!(lcnc.code('G', num("87")).unwrap().shift, None);
    assert_eq!(ShiftDir::MinusSecond.vector(-2.0), (0.0, -2.0));
    let (codes, _) = errors(
        "<dialect id=\"x\" extends=\"fanuc\">\n  <code letter=\"G\" number=\"76\" group=\"canned-cycle\" meaning=\"cycle.fine-bore\" shift=\"+Z\"/>\n</dialect>",
    );
    assert_eq!(codes, vec![Code::SpecBadValue]);
}
