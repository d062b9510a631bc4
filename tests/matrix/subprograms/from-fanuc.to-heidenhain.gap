port: M98 subprograms to LBL / CALL LBL not mapped yet (E0601 from the writer)
