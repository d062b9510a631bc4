//! Raising programs into STEP-NC: CC2 feature recognition ([`cc2`]).

pub mod cc2;
