//! Klartext arcs about `CC` in the plane of the tool axis (issue 13): a
//! Fanuc arc in G18 or G19 goes to the TNC as `TOOL CALL Y`/`X`, `CC` in
//! that plane and `C ... DR`; the way back writes the centre as the
//! plane's words (K I, J K), not as I J. Each port is verified.

mod common;
use common::*;
use std::path::Path;

fn port(src: &Path, from: &str, to: &str, out: &Path) -> String {
    port_verified(src, Some(from), to, out).unwrap_or_else(|e| panic!("{from} -> {to}: {e}"))
}

#[test]
fn arcs_in_zx_and_yz_go_to_the_tnc_and_back() {
    for (plane, arc) in [
        ("G18", "G2 X20. Z-5. I5. K2."),
        ("G19", "G3 Y20. Z-5. J5. K2."),
    ] {
        let text = format!(
            "%\nO1000\nG21 G90 G17 G54\nT1 M6\nS1000 M3\nG0 X10. Y10. Z5.\nG1 Z-5. F100.\n{plane}\n{arc}\nG17\nG0 Z5.\nM30\n%\n"
        );
        let dir = tempfile::tempdir().unwrap();
        let src = dir.path().join("a.nc");
        std::fs::write(&src, text).unwrap();
        let tnc = dir.path().join("a.h");
        port(&src, "fanuc", "heidenhain", &tnc);
        for back in ["fanuc", "siemens840d", "linuxcnc"] {
            let out = dir.path().join(format!("b.{back}"));
            port(&tnc, "heidenhain", back, &out);
        }
    }
}
