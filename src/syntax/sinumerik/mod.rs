//! The Sinumerik front end (Siemens 840D).
