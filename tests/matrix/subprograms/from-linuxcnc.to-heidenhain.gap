port: o-word subroutines and #n to LBL / CALL LBL and Q parameters not mapped yet (E0601)
