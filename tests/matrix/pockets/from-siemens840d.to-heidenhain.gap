port: POCKET1 to CYCL DEF 251 not mapped yet (E0601 from the writer)
