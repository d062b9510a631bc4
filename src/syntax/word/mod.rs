//! The word-address front end (ISO 6983: Fanuc, Haas, LinuxCNC).
