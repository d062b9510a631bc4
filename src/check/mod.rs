//! Program-level checks: structure (pairing, jump targets).
