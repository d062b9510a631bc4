//! Work offsets past G54..G59 (issue 13): Siemens `G515` is work offset
//! 15, which Fanuc writes `G54.1 P9` (P1 is offset 7, the spec's
//! `first-index`) and Haas `G118`; the way back is `G515` again. LinuxCNC
//! has nine offsets: offset 15 stays refused. Each port is verified.

mod common;
use common::*;
use std::path::Path;

fn port(src: &Path, from: &str, to: &str, out: &Path) -> Result<String, String> {
    port_verified(src, Some(from), to, out)
}

const G515: &str = "G17 G90 G515\nG0 X10 Y10 Z5\nG1 Z-1 F100\nX20\nG0 Z5\nM30\n";

#[test]
fn a_siemens_offset_past_g57_runs_and_ports_to_the_extended_code_and_back() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("a.mpf");
    std::fs::write(&src, G515).unwrap();
    let o = cncc(&["check", src.to_str().unwrap()]);
    assert!(!stderr(&o).contains("W0511"), "G515 runs: {}", stderr(&o));
    let fanuc = dir.path().join("a.nc");
    let text = port(&src, "siemens840d", "fanuc", &fanuc).unwrap();
    assert!(text.contains("G54.1 P9"), "{text}");
    let back = port(&fanuc, "fanuc", "siemens840d", &dir.path().join("b.mpf")).unwrap();
    assert!(back.contains("G515"), "{back}");
    let haas = port(&src, "siemens840d", "haas", &dir.path().join("a.haas.nc")).unwrap();
    assert!(haas.contains("G118"), "{haas}");
    let err = port(&src, "siemens840d", "linuxcnc", &dir.path().join("a.ngc")).unwrap_err();
    assert!(err.contains("work-offset.15"), "{err}");
}
