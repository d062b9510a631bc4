//! The English labels the control writes after cycle parameters
//! (`Q200=+2 ;SET-UP CLEARANCE`); labels carry no meaning, a port writes
//! them so the program reads as the control would show it.

/// The label for a Q parameter (empty when not known).
pub fn label(q: &str) -> &'static str {
    match q {
        "Q200" => "SET-UP CLEARANCE",
        "Q201" => "DEPTH",
        "Q202" => "PLUNGING DEPTH",
        "Q203" => "SURFACE COORDINATE",
        "Q204" => "2ND SET-UP CLEARANCE",
        "Q205" => "MIN. PLUNGING DEPTH",
        "Q206" => "FEED RATE FOR PLNGNG",
        "Q207" => "FEED RATE FOR MILLING",
        "Q208" => "RETRACTION FEED RATE",
        "Q210" => "DWELL TIME AT TOP",
        "Q211" => "DWELL TIME AT DEPTH",
        "Q212" => "DECREMENT",
        "Q213" => "NR OF BREAKS",
        "Q215" => "MACHINING OPERATION",
        "Q218" => "FIRST SIDE LENGTH",
        "Q219" => "2ND SIDE LENGTH",
        "Q220" => "CORNER RADIUS",
        "Q223" => "CIRCLE DIAMETER",
        "Q224" => "ANGLE OF ROTATION",
        "Q256" => "DIST FOR CHIP BRKNG",
        "Q338" => "INFEED FOR FINISHING",
        "Q351" => "CLIMB OR UP-CUT",
        "Q366" => "PLUNGE",
        "Q367" => "POCKET POSITION",
        "Q368" => "ALLOWANCE FOR SIDE",
        "Q369" => "ALLOWANCE FOR FLOOR",
        "Q370" => "TOOL PATH OVERLAP",
        "Q385" => "FINISHING FEED RATE",
        _ => "",
    }
}
